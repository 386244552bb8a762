//! Constant stiffness density k along the contact lines (N/m²): k(τ) = k cos²β_b L(τ), the
//! transverse mesh stiffness of He & Singh's K_e at μ = 0 (He & Singh, seed 003, eq 24 with eqs
//! 19–21). For a spur pair L = n b, so k(τ) = n k b: k b is the stiffness of one pair.

use super::mesh_stiffness::{MeshStiffness, StiffnessShape};
use super::stiffness_id::StiffnessId;
use crate::geometry::pair::PairGeometry;

/// A stiffness density and the pair's cos²β_b (1 for a spur pair).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PerLength {
    pub density: f64,
    pub cos2_base_helix: f64,
}

impl PerLength {
    /// The density k (N/m²) on the pair `g`.
    pub(crate) fn on(density: f64, g: &PairGeometry) -> Self {
        let c = if g.is_helical() { g.base_helix_angle.cos().powi(2) } else { 1.0 };
        PerLength { density, cos2_base_helix: c }
    }
}

impl MeshStiffness for PerLength {
    fn id(&self) -> StiffnessId {
        StiffnessId::PerLength
    }

    fn at(&self, g: &PairGeometry, tau: f64) -> f64 {
        self.density * self.cos2_base_helix * g.contact_length(tau)
    }

    fn slope(&self, g: &PairGeometry, tau: f64) -> f64 {
        self.density * self.cos2_base_helix * g.contact_length_rate(tau)
    }

    /// k cos²β_b L̄, L̄ the exact mean contact length.
    fn mean(&self, g: &PairGeometry, _: &[f64], _: f64) -> f64 {
        self.density * self.cos2_base_helix * g.mean_contact_length()
    }

    /// A spur pair's L steps with the pairs in contact; a helical pair's varies in between.
    fn is_piecewise_constant(&self) -> bool {
        self.cos2_base_helix == 1.0
    }

    fn follows_contact_length(&self) -> bool {
        true
    }

    /// L ≤ (⌈ε_α⌉ + ⌈ε_β⌉) b / cos β_b.
    fn upper_bound(&self, g: &PairGeometry) -> f64 {
        self.density * self.cos2_base_helix * (g.contact_ratio.ceil() + g.overlap_ratio.ceil()) * g.face_width
            / g.base_helix_angle.cos()
    }

    fn shape(&self) -> StiffnessShape {
        StiffnessShape::PerLength { density: self.density, cos2_base_helix: self.cos2_base_helix }
    }
}
