//! A mesh stiffness given as values at equally spaced times over one mesh cycle (inline or from a
//! CSV file, e.g. a loaded contact analysis), t = 0 when a pair enters at A, read between the values
//! by periodic linear interpolation.

use super::mesh_stiffness::{MeshStiffness, StiffnessShape};
use super::stiffness_id::StiffnessId;
use crate::geometry::pair::PairGeometry;

/// k at n equally spaced times over one cycle (N/m).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Table(pub Vec<f64>);

impl MeshStiffness for Table {
    fn id(&self) -> StiffnessId {
        StiffnessId::Table
    }

    fn at(&self, _: &PairGeometry, tau: f64) -> f64 {
        let k = &self.0;
        let n = k.len();
        let x = tau.rem_euclid(1.0) * n as f64;
        let i = (x.floor() as usize).min(n - 1);
        let frac = x - i as f64;
        k[i] * (1.0 - frac) + k[(i + 1) % n] * frac
    }

    /// The slope of the table's cell at τ.
    fn slope(&self, _: &PairGeometry, tau: f64) -> f64 {
        let k = &self.0;
        let n = k.len();
        let i = ((tau.rem_euclid(1.0) * n as f64).floor() as usize).min(n - 1);
        (k[(i + 1) % n] - k[i]) * n as f64
    }

    /// The mean of the periodic piecewise-linear interpolant: the mean of the values (exact).
    fn mean(&self, _: &PairGeometry, _: &[f64], _: f64) -> f64 {
        self.0.iter().sum::<f64>() / self.0.len() as f64
    }

    fn is_piecewise_constant(&self) -> bool {
        false
    }

    fn smooth_cuts(&self) -> Vec<f64> {
        let n = self.0.len();
        (1..n).map(|i| i as f64 / n as f64).collect()
    }

    fn upper_bound(&self, _: &PairGeometry) -> f64 {
        self.0.iter().copied().fold(0.0, f64::max)
    }

    fn shape(&self) -> StiffnessShape {
        StiffnessShape::Table(self.0.clone())
    }
}
