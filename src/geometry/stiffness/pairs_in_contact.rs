//! Rectangular mesh stiffness: one value while one pair is in contact, one for two, one for three
//! (Fernandes et al.'s k(t), Fig. 3: the stiffness steps where a pair enters or leaves).

use super::mesh_stiffness::{MeshStiffness, StiffnessShape};
use super::stiffness_id::StiffnessId;
use crate::geometry::pair::PairGeometry;

/// k with 1, 2 and 3 (or more) pairs in contact (N/m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairsInContact {
    pub single: f64,
    pub double: f64,
    pub triple: f64,
}

impl PairsInContact {
    /// k with `pairs` pairs in contact (0 reads as 1).
    pub fn at_pairs(&self, pairs: usize) -> f64 {
        match pairs {
            0 | 1 => self.single,
            2 => self.double,
            _ => self.triple,
        }
    }
}

impl MeshStiffness for PairsInContact {
    fn id(&self) -> StiffnessId {
        StiffnessId::PairsInContact
    }

    fn at(&self, g: &PairGeometry, tau: f64) -> f64 {
        self.at_pairs(g.pairs_at(tau))
    }

    fn slope(&self, _: &PairGeometry, _: f64) -> f64 {
        0.0
    }

    /// Exact: Σ k_n (duration with n pairs) / T over the cycle's segments.
    fn mean(&self, g: &PairGeometry, taus: &[f64], period: f64) -> f64 {
        taus.windows(2)
            .map(|w| self.at_pairs(g.pairs_at(0.5 * (w[0] + w[1]))) * (w[1] * period - w[0] * period))
            .sum::<f64>()
            / period
    }

    fn is_piecewise_constant(&self) -> bool {
        true
    }

    fn upper_bound(&self, _: &PairGeometry) -> f64 {
        self.single.max(self.double).max(self.triple)
    }

    fn shape(&self) -> StiffnessShape {
        StiffnessShape::Pairs { single: self.single, double: self.double, triple: self.triple }
    }
}
