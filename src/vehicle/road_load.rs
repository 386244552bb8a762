//! A vehicle on the road: its tractive force at the wheels from its speed and acceleration
//! (README, "Vehicles and drive cycles").
//!
//! F = f0 + f1 v + f2 v² + m_eff a + m g sin γ (coastdown form, f0…f2 the coastdown coefficients
//! of the regulations: UN GTR 15 Annex 4, US 40 CFR 1066.210), or
//! F = f_r m g cos γ + ½ ρ_air c_w A v² + m_eff a + m g sin γ (physical form), with
//! m_eff = m × the rotating-mass factor, g = 9.80665 m/s² and γ = atan(grade). On an interval of
//! the trace v = v₀ + a τ, so F is a quadratic in τ. No rolling or air force acts while standing.
//!
//! ```
//! use gearloss::vehicle::{RoadLoad, Vehicle};
//! let car = Vehicle {
//!     mass: 1000.0, rotating_mass_factor: 1.0, wheel_radius: 0.3, final_ratio: 1.0,
//!     road_load: RoadLoad::Coastdown { f0: 100.0, f1: 0.0, f2: 0.5 }, recuperation_limit: None,
//! };
//! // 20 m/s, accelerating at 1 m/s² on the level: 100 + 0.5 × 400 + 1000 × 1 = 1300 N.
//! assert_eq!(car.force_on(20.0, 1.0, 0.0), [1300.0, 20.0, 0.5]);
//! ```

/// Standard gravity (m/s², ISO 80000-3).
pub const GRAVITY: f64 = 9.80665;

/// How the road load is given.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub enum RoadLoad {
    /// Coastdown coefficients f0 (N), f1 (N·s/m), f2 (N·s²/m²).
    Coastdown { f0: f64, f1: f64, f2: f64 },
    /// Rolling-resistance coefficient f_r, drag coefficient c_w, frontal area A (m²), air density (kg/m³).
    Physical { rolling: f64, drag_coefficient: f64, frontal_area: f64, air_density: f64 },
}

/// A vehicle as its drive cycle reads it (SI).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Vehicle {
    /// m (kg), the test mass.
    pub mass: f64,
    /// m_eff/m: the rotating masses' share of the inertia.
    pub rotating_mass_factor: f64,
    /// r_dyn (m).
    pub wheel_radius: f64,
    pub road_load: RoadLoad,
    /// The wheel torque (N·m, > 0) the drive can take back while recuperating; beyond it the
    /// friction brakes take the rest.
    pub recuperation_limit: Option<f64>,
    /// ω_box output / ω_wheel: a lossless final drive after the gearbox (1: the box's output is the wheel).
    pub final_ratio: f64,
}

impl Vehicle {
    /// m_eff (kg).
    pub fn effective_mass(&self) -> f64 {
        self.mass * self.rotating_mass_factor
    }

    /// The road load's (f0, f1, f2) on `grade` (rise/run): the coastdown coefficients as given, or
    /// the physical form's f_r m g cos γ, 0, ½ ρ c_w A.
    pub fn road_coefficients(&self, grade: f64) -> (f64, f64, f64) {
        match self.road_load {
            RoadLoad::Coastdown { f0, f1, f2 } => (f0, f1, f2),
            RoadLoad::Physical { rolling, drag_coefficient, frontal_area, air_density } => {
                let cos = 1.0 / grade.hypot(1.0);
                (rolling * self.mass * GRAVITY * cos, 0.0, 0.5 * air_density * drag_coefficient * frontal_area)
            }
        }
    }

    /// F(τ) = c₀ + c₁ τ + c₂ τ² (N) on an interval starting at speed `v0` (m/s) with acceleration
    /// `a` (m/s²) on `grade`, τ (s) from the interval's start: the coefficients [c₀, c₁, c₂].
    pub fn force_on(&self, v0: f64, a: f64, grade: f64) -> [f64; 3] {
        let (f0, f1, f2) = self.road_coefficients(grade);
        let sin = grade / grade.hypot(1.0);
        [
            f0 + f1 * v0 + f2 * v0 * v0 + self.effective_mass() * a + self.mass * GRAVITY * sin,
            (f1 + 2.0 * f2 * v0) * a,
            f2 * a * a,
        ]
    }
}
