//! Smoothed Coulomb, Model IV (He–Cho–Singh eq 19, after Duan & Singh):
//! μ = (2μ_avg/π) [atan(Φx) + Φx / (1 + Φ²x²)], x = s. The printed σ in the second term is read
//! as Φ (physics notes: σ would make it dimensionally wrong). Φ = 50 1/mm by default.
//!
//! ```
//! use gearloss::friction::{FrictionLaw, SmoothedCoulomb};
//! let law = SmoothedCoulomb { mu: 0.05, phi: 50e3 };
//! let mut c = gearloss::friction::testing::contact();
//! c.s = 0.0;
//! assert_eq!(law.mu(&c), 0.0);
//! c.s = 5e-3; // Φx = 250: within 0.1 % of μ_avg
//! assert!((law.mu(&c) - 0.05).abs() < 5e-5);
//! ```

use std::f64::consts::PI;

use super::friction_law::{FrictionLaw, Parameter};
use crate::geometry::ContactPoint;

#[derive(Debug, Clone, Copy)]
pub struct SmoothedCoulomb {
    pub mu: f64,
    /// Φ in 1/m (50 1/mm = 5e4 1/m).
    pub phi: f64,
}

impl SmoothedCoulomb {
    /// μ at position s (m) from the pitch point.
    pub fn at(&self, s: f64) -> f64 {
        let px = self.phi * s;
        2.0 * self.mu / PI * (px.atan() + px / (1.0 + px * px))
    }
}

impl FrictionLaw for SmoothedCoulomb {
    fn id(&self) -> super::law_id::LawId {
        super::law_id::LawId::SmoothedCoulomb
    }
    fn mu(&self, c: &ContactPoint) -> f64 {
        self.at(c.s)
    }
    fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter { name: "mu", value: self.mu, unit: "1" },
            Parameter { name: "phi", value: self.phi, unit: "1/m" },
        ]
    }
}
