//! Lubricant and surface inputs in SI, and EHL film thickness along the line of action.

pub(crate) mod d2270;
pub(crate) mod film;
pub mod lubricant;

pub use d2270::l_and_h;
pub use film::{Film, FilmInputs};

/// What the friction laws read from the scene besides the contact state, in SI.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Tribology {
    /// Dynamic viscosity η at the inlet (Pa·s); 0 when the scene has no lubricant.
    pub dynamic_viscosity: f64,
    /// Kinematic viscosity ν (m²/s), given or η/ρ.
    pub kinematic_viscosity: Option<f64>,
    /// Pressure–viscosity coefficient α (1/Pa).
    pub pressure_viscosity: Option<f64>,
    /// Mean of the two Ra (m).
    pub ra_mean: Option<f64>,
    /// Mean of the two Rq (m).
    pub rq_mean: Option<f64>,
    /// Composite roughness sqrt(Rq1² + Rq2²) (m).
    pub rq_composite: Option<f64>,
    /// Mean of the two Rz (m).
    pub rz_mean: Option<f64>,
    /// Reduced modulus E' (Pa).
    pub reduced_modulus: f64,
    /// ISO/TR 14179-2 lubricant factor X_L and the oil family's name.
    pub lubricant_factor: f64,
    pub lubricant_family: &'static str,
}

impl Tribology {
    /// ρ = η/ν (kg/m³), when the kinematic viscosity is known.
    pub fn density(&self) -> Option<f64> {
        self.kinematic_viscosity.map(|nu| self.dynamic_viscosity / nu)
    }
}

/// Unit conversions used by the empirical laws, in one place.
pub mod units {
    /// Pa·s → cP (= mPa·s).
    pub const CP_PER_PA_S: f64 = 1e3;
    /// m²/s → cSt (= mm²/s).
    pub const CST_PER_M2_S: f64 = 1e6;
    /// m → µm.
    pub const UM_PER_M: f64 = 1e6;
    /// m → mm.
    pub const MM_PER_M: f64 = 1e3;
    /// N/m → N/mm.
    pub const N_PER_MM_PER_N_PER_M: f64 = 1e-3;
    /// Pa → GPa.
    pub const GPA_PER_PA: f64 = 1e-9;
}
