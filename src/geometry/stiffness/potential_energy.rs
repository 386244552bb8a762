//! The potential-energy method: the mesh stiffness computed from the teeth — bending, shear and
//! axial compression of both teeth over their involute and trochoid fillet, the fillet foundation
//! (Sainsot et al. 2004) and linearised Hertz (Yang & Lin 1987) — summed over the pairs in
//! contact (a helical pair's contact lines integrated exactly). The physics live in
//! [`crate::geometry::teeth`]; this file puts them behind [`MeshStiffness`]. The unmodified teeth:
//! a tip relief changes the load sharing and the transmission error, not this stiffness.

use super::mesh_stiffness::{MeshStiffness, StiffnessModel, StiffnessShape};
use super::stiffness_id::StiffnessId;
use crate::geometry::pair::PairGeometry;
use crate::geometry::teeth::pair_stiffness::{Bodies, PairStiffness};

/// The pair's potential-energy stiffness over the mesh cycle.
#[derive(Debug, Clone)]
pub(crate) struct PotentialEnergy(pub PairStiffness);

/// The model for the pair `g` with its bodies (lowering has checked that the teeth can be cut and
/// mesh without interference, `check_teeth`).
pub(crate) fn build(g: &PairGeometry, bodies: &Bodies) -> StiffnessModel {
    let pair = PairStiffness::new(g, bodies).expect("lowering checks the teeth before the stiffness is built");
    StiffnessModel::new(PotentialEnergy(pair))
}

impl MeshStiffness for PotentialEnergy {
    fn id(&self) -> StiffnessId {
        StiffnessId::PotentialEnergy
    }

    /// K at the reference pair's position s = p_b τ − b tan β_b/2.
    fn at(&self, _: &PairGeometry, tau: f64) -> f64 {
        self.0.mesh_at(self.0.position_at(tau))
    }

    fn slope(&self, _: &PairGeometry, tau: f64) -> f64 {
        self.0.base_pitch * self.0.mesh_slope(self.0.position_at(tau))
    }

    /// b ∫₀^{g_α} k_w ds / p_b: exact for the series.
    fn mean(&self, _: &PairGeometry, _: &[f64], _: f64) -> f64 {
        self.0.mean()
    }

    fn is_piecewise_constant(&self) -> bool {
        false
    }

    /// Σ|c_k| of the series bounds k_w; at most ⌈ε_γ⌉ + 1 pairs or lines.
    fn upper_bound(&self, _: &PairGeometry) -> f64 {
        let k = &self.0;
        let [lo, hi] = k.engagement();
        let most = ((hi - lo) / k.base_pitch).ceil() + 1.0;
        most * k.face_width * k.per_width_bound()
    }

    fn shape(&self) -> StiffnessShape {
        StiffnessShape::Computed { mean: self.0.mean() }
    }
}
