//! Misharin (Bernard et al., Table 1): μ = 0.3865 (ν_k U² SR)^−1/4, ν_k in cSt, U in m/s.
//! Valid for SR ∈ [0.4, 1.3]; diverges at P as SR^−1/4 (integrable).

use super::friction_law::{signed, FrictionLaw, Parameter};
use super::needs::Needs;
use crate::geometry::ContactPoint;
use crate::tribology::{units, Tribology};

#[derive(Debug, Clone, Copy)]
pub struct Misharin {
    pub kinematic_viscosity_cst: f64,
}

impl Misharin {
    pub fn new(t: &Tribology) -> Result<Self, Needs> {
        Ok(Misharin {
            kinematic_viscosity_cst: Needs::KinematicViscosity.of(t.kinematic_viscosity)? * units::CST_PER_M2_S,
        })
    }
    pub fn magnitude(&self, c: &ContactPoint) -> f64 {
        0.3865 * (self.kinematic_viscosity_cst * c.entrainment_velocity.powi(2) * c.slide_to_roll).powf(-0.25)
    }
}

impl FrictionLaw for Misharin {
    fn id(&self) -> super::law_id::LawId {
        super::law_id::LawId::Misharin
    }
    fn mu(&self, c: &ContactPoint) -> f64 {
        signed(self.magnitude(c), c.s)
    }
    fn validity(&self, c: &ContactPoint) -> Result<(), &'static str> {
        if !(0.4..=1.3).contains(&c.slide_to_roll) {
            Err("SR outside [0.4, 1.3]")
        } else if !(0.02..=0.08).contains(&self.magnitude(c)) {
            Err("μ outside Misharin's 0.02–0.08")
        } else {
            Ok(())
        }
    }
    fn diverges_at_pitch(&self) -> bool {
        true
    }
    fn parameters(&self) -> Vec<Parameter> {
        vec![Parameter {
            name: "kinematic_viscosity",
            value: self.kinematic_viscosity_cst / units::CST_PER_M2_S,
            unit: "m^2/s",
        }]
    }
}
