//! The housing as a single thermal node: its wall is at the oil temperature θ and gives the heat
//! away to still or moving air (convection), to the surroundings (radiation), through its foundation
//! and, above a set temperature, through an oil cooler.
//!
//! P_Q(θ) = h_c A Δθ + ε σ A (T⁴ − T_a⁴) + G_f Δθ + G_c max(0, θ − θ_set), Δθ = θ − θ_a, T in K.
//!
//! Convection is the DOE-2 exterior model (as EnergyPlus implements it, *EnergyPlus Engineering
//! Reference*, "Exterior convection: DOE-2"): h_c = √(h_n² + h_f²) with the natural part of ASHRAE's
//! simplified vertical-wall correlation h_n = 1.31 |Δθ|^(1/3) and the MoWiTT forced part
//! h_f = 3.26 v^0.89 (Yazdanian & Klems 1994), W/(m² K), v the air speed in m/s. Radiation: a grey
//! wall of emissivity ε seeing surroundings at the air temperature (view factor 1, same area A),
//! σ = 5.670374419·10⁻⁸ W/(m² K⁴) (CODATA 2018).
//!
//! ```
//! use gearloss::thermal::Housing;
//! let h = Housing::still_air(0.42, 298.15);
//! // At 80 °C: h_n = 1.31 · 55^(1/3) = 4.9819 W/(m² K); convection h_n A Δθ = 115.08 W.
//! let q = h.dissipation(353.15);
//! assert!((q.convection - 1.31 * 55f64.cbrt() * 0.42 * 55.0).abs() < 1e-9);
//! assert!((q.total - (q.convection + q.radiation)).abs() < 1e-9);
//! ```

use serde::{Deserialize, Serialize};

/// The Stefan–Boltzmann constant σ (W/(m² K⁴)), CODATA 2018 (exact in the 2019 SI).
pub(crate) const STEFAN_BOLTZMANN: f64 = 5.670374419e-8;

/// An oil cooler that takes G_c (θ − θ_set) above its set temperature.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Cooler {
    /// G_c (W/K).
    pub conductance: f64,
    /// θ_set (K).
    pub above: f64,
}

/// The housing of a gearbox as a thermal node, in SI (temperatures in K).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Housing {
    /// Surface area A that gives off heat (m²).
    pub area: f64,
    /// Ambient air (and surroundings) temperature T_a (K).
    pub ambient: f64,
    /// Air speed v along the housing (m/s); 0 for still air.
    pub air_speed: f64,
    /// Emissivity ε of the housing's surface (0, 1].
    pub emissivity: f64,
    /// Heat capacity C of housing and oil (J/K), for transients.
    pub heat_capacity: Option<f64>,
    /// Foundation conductance G_f (W/K).
    pub foundation_conductance: f64,
    pub cooler: Option<Cooler>,
    /// The oil's temperature limit (K).
    pub max_oil_temperature: f64,
}

/// The heat a housing gives off at one oil temperature, by path (W).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Dissipation {
    pub convection: f64,
    pub radiation: f64,
    pub foundation: f64,
    pub cooler: f64,
    pub total: f64,
}

impl Housing {
    /// A painted housing (ε = 0.9) of area `area` in still air at `ambient` (K), limit 120 °C.
    pub fn still_air(area: f64, ambient: f64) -> Housing {
        Housing {
            area,
            ambient,
            air_speed: 0.0,
            emissivity: 0.9,
            heat_capacity: None,
            foundation_conductance: 0.0,
            cooler: None,
            max_oil_temperature: 393.15,
        }
    }

    /// The convective coefficient h_c = √(h_n² + h_f²) (W/(m² K)) at oil temperature `t` (K).
    pub fn heat_transfer_coefficient(&self, t: f64) -> f64 {
        let natural = 1.31 * (t - self.ambient).abs().cbrt();
        let forced = 3.26 * self.air_speed.powf(0.89);
        natural.hypot(forced)
    }

    /// P_Q at oil temperature `t` (K), by path.
    pub fn dissipation(&self, t: f64) -> Dissipation {
        let dt = t - self.ambient;
        let convection = self.heat_transfer_coefficient(t) * self.area * dt;
        let radiation = self.emissivity * STEFAN_BOLTZMANN * self.area * (t.powi(4) - self.ambient.powi(4));
        let foundation = self.foundation_conductance * dt;
        let cooler = self.cooler.map_or(0.0, |c| c.conductance * (t - c.above).max(0.0));
        Dissipation { convection, radiation, foundation, cooler, total: convection + radiation + foundation + cooler }
    }

    /// The oil temperature (K) at which the housing gives off `p` (W), between ambient and `top`:
    /// P_Q rises with θ (every path grows with θ − θ_a), so this is a root of P_Q(θ) − p, located by
    /// Brent's method to 1e-12 K (P_Q costs nanoseconds). Ambient for `p` ≤ P_Q(θ_a), `top` for
    /// `p` ≥ P_Q(top).
    ///
    /// ```
    /// use gearloss::thermal::Housing;
    /// let h = Housing::still_air(0.42, 298.15);
    /// let t = h.temperature_giving_off(300.0, 473.15);
    /// assert!((h.dissipation(t).total - 300.0).abs() < 1e-9);
    /// ```
    pub fn temperature_giving_off(&self, p: f64, top: f64) -> f64 {
        let gap = |t: f64| self.dissipation(t).total - p;
        if gap(self.ambient) >= 0.0 {
            self.ambient
        } else if gap(top) <= 0.0 {
            top
        } else {
            crate::numerics::roots::brent(gap, self.ambient, top, 1e-12)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A hand-checked P_Q: A = 0.42 m², ambient 25 °C, v = 2 m/s, ε = 0.9, G_f = 2 W/K, cooler
    /// 40 W/K above 70 °C, at 80 °C. h_n = 1.31·55^(1/3) = 4.98187, h_f = 3.26·2^0.89 = 6.04135,
    /// h_c = 7.83052; convection 180.885 W; radiation 0.9σ·0.42·(353.15⁴ − 298.15⁴) = 164.008 W;
    /// foundation 110 W; cooler 400 W. Values worked on a calculator to 5 digits; tolerance 1e-4 relative.
    #[test]
    fn dissipation_by_hand() {
        let h = Housing {
            air_speed: 2.0,
            foundation_conductance: 2.0,
            cooler: Some(Cooler { conductance: 40.0, above: 343.15 }),
            ..Housing::still_air(0.42, 298.15)
        };
        let q = h.dissipation(353.15);
        let close = |a: f64, b: f64| (a - b).abs() < 1e-4 * b;
        assert!(close(h.heat_transfer_coefficient(353.15), 7.83052), "{}", h.heat_transfer_coefficient(353.15));
        assert!(close(q.convection, 180.885), "{q:?}");
        assert!(close(q.radiation, 164.008), "{q:?}");
        assert_eq!((q.foundation, q.cooler), (110.0, 400.0));
        assert!(close(q.total, 180.885 + 164.008 + 510.0));
    }

    /// In still air the coefficient is the natural one exactly, and nothing is given off at ambient.
    #[test]
    fn still_air_is_natural_convection() {
        let h = Housing::still_air(1.0, 293.15);
        for dt in [0.5, 10.0, 60.0] {
            assert_eq!(h.heat_transfer_coefficient(293.15 + dt), 1.31 * dt.cbrt());
        }
        assert_eq!(h.dissipation(293.15).total, 0.0);
    }
}
