//! Benedict–Kelley in the form of Bernard et al., Table 1:
//! μ = 0.0127 · 50/(50 − S_rms) · log10[3.98e9 p_H² R / (η SR U³ E')],
//! p_H in Pa, R in m, η in cP, U in m/s, E' in Pa, S_rms = mean Rq in µm. Valid while
//! 50/(50 − S_rms) ≤ 3. Not equivalent to He–Cho–Singh's eq 14 (it runs ≈ 0.08 higher), so both
//! are kept, named apart. Diverges (logarithmically) at P.

use super::friction_law::{signed, FrictionLaw, Parameter};
use super::needs::Needs;
use crate::geometry::ContactPoint;
use crate::tribology::{units, Tribology};

#[derive(Debug, Clone, Copy)]
pub(crate) struct BenedictKelleyBernard {
    pub viscosity_cp: f64,
    pub roughness_rms_um: f64,
    pub reduced_modulus: f64,
}

impl BenedictKelleyBernard {
    pub(crate) fn new(t: &Tribology) -> Result<Self, Needs> {
        Ok(BenedictKelleyBernard {
            viscosity_cp: t.dynamic_viscosity * units::CP_PER_PA_S,
            roughness_rms_um: Needs::RoughnessRq.of(t.rq_mean)? * units::UM_PER_M,
            reduced_modulus: t.reduced_modulus,
        })
    }

    fn argument(&self, c: &ContactPoint) -> f64 {
        3.98e9 * c.hertz_pressure.powi(2) * c.reduced_radius
            / (self.viscosity_cp * c.slide_to_roll * c.entrainment_velocity.powi(3) * self.reduced_modulus)
    }

    pub(crate) fn magnitude(&self, c: &ContactPoint) -> f64 {
        0.0127 * 50.0 / (50.0 - self.roughness_rms_um) * self.argument(c).log10()
    }
}

impl FrictionLaw for BenedictKelleyBernard {
    fn id(&self) -> super::law_id::LawId {
        super::law_id::LawId::BenedictKelleyBernard
    }
    fn mu(&self, c: &ContactPoint) -> f64 {
        signed(self.magnitude(c).max(0.0), c.s)
    }
    fn validity(&self, c: &ContactPoint) -> Result<(), &'static str> {
        let factor = 50.0 / (50.0 - self.roughness_rms_um);
        if !(factor > 0.0 && factor <= 3.0) {
            Err("roughness factor 50/(50 − S_rms) outside (0, 3]")
        } else if self.magnitude(c) > 0.1 {
            Err("μ above 0.1, which Bernard say the law approaches")
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
            Parameter { name: "roughness_rq_mean", value: self.roughness_rms_um / units::UM_PER_M, unit: "m" },
        ]
    }
}
