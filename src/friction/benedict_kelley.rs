//! Benedict–Kelley, Model II, in He–Cho–Singh's form (eq 14):
//! μ = 0.0127 · 1.13/(1.13 − S_avg) · log10[29700 w / (η v_s v_Σ²)],
//! w in N/mm, η in cP, v in m/s, S_avg = mean Ra in µm. 29700 is Benedict and Kelley's 3.17e8
//! (lb/in, cP, in/s) converted ([`BenedictKelley::CONSTANT_FROM_IMPERIAL`]). Diverges (logarithmically) at P.
//!
//! ```
//! use gearloss::friction::{FrictionLaw, BenedictKelley};
//! let law = BenedictKelley { viscosity_cp: 95.0, roughness_um: 0.3 };
//! let c = gearloss::friction::testing::contact(); // approach
//! let mu = law.mu(&c);
//! assert!(mu < 0.0 && mu > -0.1, "{mu}");
//! ```

use super::friction_law::{signed, FrictionLaw, Parameter};
use super::needs::Needs;
use crate::geometry::ContactPoint;
use crate::tribology::{units, Tribology};

#[derive(Debug, Clone, Copy)]
pub struct BenedictKelley {
    pub viscosity_cp: f64,
    pub roughness_um: f64,
}

impl BenedictKelley {
    /// Benedict and Kelley's constant in lb/in, cP and in/s.
    pub const IMPERIAL_CONSTANT: f64 = 3.17e8;

    /// 3.17e8 × (lbf/in per N/mm) / (in/s per m/s)³: the constant for N/mm, cP and m/s.
    /// 1 N/mm = 25.4/4.4482216152605 lbf/in and 1 m/s = 1/0.0254 in/s; the result is 29 662, printed as 29 700.
    pub const CONSTANT_FROM_IMPERIAL: f64 =
        Self::IMPERIAL_CONSTANT * (25.4 / 4.448_221_615_260_5) * (0.0254 * 0.0254 * 0.0254);

    /// The constant as He–Cho–Singh print it.
    pub const CONSTANT: f64 = 29_700.0;

    pub fn new(t: &Tribology) -> Result<Self, Needs> {
        Ok(BenedictKelley {
            viscosity_cp: t.dynamic_viscosity * units::CP_PER_PA_S,
            roughness_um: Needs::RoughnessRa.of(t.ra_mean)? * units::UM_PER_M,
        })
    }

    /// The log argument, 29700 w / (η v_s v_Σ²).
    fn argument(&self, c: &ContactPoint) -> f64 {
        Self::CONSTANT * c.load_per_width * units::N_PER_MM_PER_N_PER_M
            / (self.viscosity_cp * c.sliding_velocity * c.sum_velocity.powi(2))
    }

    /// |μ| (may be ≤ 0 where the log argument is ≤ 1: flagged by `validity`).
    pub fn magnitude(&self, c: &ContactPoint) -> f64 {
        0.0127 * 1.13 / (1.13 - self.roughness_um) * self.argument(c).log10()
    }
}

impl FrictionLaw for BenedictKelley {
    fn id(&self) -> super::law_id::LawId {
        super::law_id::LawId::BenedictKelley
    }
    fn mu(&self, c: &ContactPoint) -> f64 {
        signed(self.magnitude(c).max(0.0), c.s)
    }
    fn validity(&self, c: &ContactPoint) -> Result<(), &'static str> {
        if self.roughness_um >= 1.13 {
            Err("S_avg ≥ 1.13 µm makes the roughness factor 1.13/(1.13 − S) infinite or negative")
        } else {
            super::friction_law::log_argument_validity(c, self.argument(c))
        }
    }
    fn diverges_at_pitch(&self) -> bool {
        true
    }
    fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter { name: "viscosity", value: self.viscosity_cp / units::CP_PER_PA_S, unit: "Pa*s" },
            Parameter { name: "roughness_ra_mean", value: self.roughness_um / units::UM_PER_M, unit: "m" },
        ]
    }
}
