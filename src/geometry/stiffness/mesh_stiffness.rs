//! What every mesh stiffness model answers, and the shared handle the dynamics hold.

use std::sync::Arc;

use super::stiffness_id::StiffnessId;
use crate::geometry::pair::PairGeometry;

/// A mesh stiffness along the path of contact over one mesh cycle, τ ∈ [0, 1) the fraction of the
/// mesh period with τ = 0 when a pair enters at A.
///
/// ```
/// use gearloss::geometry::stiffness::{MeshStiffness, PairsInContact};
/// let k = PairsInContact { single: 2e8, double: 4e8, triple: 6e8 };
/// assert_eq!(k.at_pairs(2), 4e8);
/// assert!(k.is_piecewise_constant());
/// ```
pub trait MeshStiffness: std::fmt::Debug + Send + Sync {
    /// The catalogue identity.
    fn id(&self) -> StiffnessId;
    /// k (N/m) at τ on the pair `g`.
    fn at(&self, g: &PairGeometry, tau: f64) -> f64;
    /// dk/dτ (N/m per mesh period) at τ on the pair `g`.
    fn slope(&self, g: &PairGeometry, tau: f64) -> f64;
    /// k̄ over one period of `period` s, `taus` the cycle's break times (fractions of the period).
    fn mean(&self, g: &PairGeometry, taus: &[f64], period: f64) -> f64;
    /// Whether k is constant between the cycle's break times (the exact propagator applies).
    fn is_piecewise_constant(&self) -> bool;
    /// Whether k = k_density cos²β_b L(τ), linear in the contact length (the Airy route of the
    /// base formulation relies on it).
    fn follows_contact_length(&self) -> bool {
        false
    }
    /// Fractions of the period, besides the cycle's break times, where dk/dτ jumps.
    fn smooth_cuts(&self) -> Vec<f64> {
        Vec::new()
    }
    /// An upper bound of k over the cycle (N/m).
    fn upper_bound(&self, g: &PairGeometry) -> f64;
    /// The model's numbers as the report shows them.
    fn shape(&self) -> StiffnessShape;
}

/// The numbers behind a model, by the shape the report prints them in.
#[derive(Debug, Clone, PartialEq)]
pub enum StiffnessShape {
    /// One value per number of pairs in contact (N/m).
    Pairs { single: f64, double: f64, triple: f64 },
    /// Values at equally spaced times over one cycle (N/m).
    Table(Vec<f64>),
    /// A density along the contact lines (N/m²) and cos²β_b.
    PerLength { density: f64, cos2_base_helix: f64 },
    /// Computed from the teeth: its mean over a cycle (N/m); the curve is in the report's
    /// stiffness section.
    Computed { mean: f64 },
}

/// A shared handle on a mesh stiffness model (cheap to clone).
#[derive(Debug, Clone)]
pub struct StiffnessModel(pub Arc<dyn MeshStiffness>);

impl StiffnessModel {
    pub fn new(model: impl MeshStiffness + 'static) -> Self {
        StiffnessModel(Arc::new(model))
    }
}

impl std::ops::Deref for StiffnessModel {
    type Target = dyn MeshStiffness;

    fn deref(&self) -> &Self::Target {
        &*self.0
    }
}
