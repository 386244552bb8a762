//! Coulomb friction, Model I: μ = μ_avg sgn(s) (He–Cho–Singh eq 10; Fernandes §2.1).

use super::friction_law::{signed, FrictionLaw, Parameter};
use crate::geometry::ContactPoint;

/// Constant magnitude, sign of the sliding direction.
#[derive(Debug, Clone, Copy)]
pub struct Coulomb {
    pub mu: f64,
}

impl FrictionLaw for Coulomb {
    fn constant_magnitude(&self) -> bool {
        true
    }
    fn id(&self) -> super::law_id::LawId {
        super::law_id::LawId::Coulomb
    }
    fn mu(&self, c: &ContactPoint) -> f64 {
        signed(self.mu, c.s)
    }
    fn parameters(&self) -> Vec<Parameter> {
        vec![Parameter { name: "mu", value: self.mu, unit: "1" }]
    }
}
