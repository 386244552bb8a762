//! Matsumoto's mixed-regime blend (physics notes, "Beyond the papers"):
//! μ = ξ μ_bl + (1 − ξ) μ_EHL, ξ = 0.5 log10(Rz_comp / h_min) clamped to [0, 1], Rz_comp the mean
//! Rz, h_min by Dowson–Higginson. Defaults μ_bl = 0.1, μ_EHL = 0.02. Signed with the sliding direction.

use super::friction_law::{signed, FrictionLaw, Parameter};
use super::needs::Needs;
use crate::geometry::ContactPoint;
use crate::tribology::{FilmInputs, Tribology};

#[derive(Debug, Clone, Copy)]
pub struct Matsumoto {
    pub mu_boundary: f64,
    pub mu_ehl: f64,
    pub rz_mean: f64,
    pub film: FilmInputs,
}

impl Matsumoto {
    pub fn new(t: &Tribology, mu_boundary: f64, mu_ehl: f64) -> Result<Self, Needs> {
        Ok(Matsumoto {
            mu_boundary,
            mu_ehl,
            rz_mean: Needs::RoughnessRz.of(t.rz_mean)?,
            film: FilmInputs {
                dynamic_viscosity: t.dynamic_viscosity,
                pressure_viscosity: Needs::PressureViscosity.of(t.pressure_viscosity)?,
                reduced_modulus: t.reduced_modulus,
            },
        })
    }

    /// ξ before clamping.
    pub fn xi_raw(&self, c: &ContactPoint) -> f64 {
        0.5 * (self.rz_mean / self.film.minimum(c)).log10()
    }

    pub fn magnitude(&self, c: &ContactPoint) -> f64 {
        let xi = self.xi_raw(c).clamp(0.0, 1.0);
        xi * self.mu_boundary + (1.0 - xi) * self.mu_ehl
    }
}

impl FrictionLaw for Matsumoto {
    fn id(&self) -> super::law_id::LawId {
        super::law_id::LawId::Matsumoto
    }
    fn mu(&self, c: &ContactPoint) -> f64 {
        signed(self.magnitude(c), c.s)
    }
    fn validity(&self, c: &ContactPoint) -> Result<(), &'static str> {
        let xi = self.xi_raw(c);
        if (0.0..=1.0).contains(&xi) {
            Ok(())
        } else {
            Err("ξ outside [0, 1], clamped (pure boundary or pure EHL friction)")
        }
    }
    fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter { name: "mu_boundary", value: self.mu_boundary, unit: "1" },
            Parameter { name: "mu_ehl", value: self.mu_ehl, unit: "1" },
            Parameter { name: "roughness_rz_mean", value: self.rz_mean, unit: "m" },
        ]
    }
}
