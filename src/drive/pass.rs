//! The powers of one pass of the drive's walk and how far a pass moved from the one before.

use super::kind_state::KindState;

/// The powers of one pass (W), indexed by shaft and by stage, with the driving torques (N·m).
#[derive(Debug, Clone)]
pub(crate) struct Pass {
    pub(crate) received: Vec<f64>,
    pub(crate) passed: Vec<f64>,
    /// By stage: the driving gear's torque, the mesh efficiency and the power the mesh loses.
    pub(crate) driving_torque: Vec<f64>,
    pub(crate) efficiency: Vec<f64>,
    pub(crate) mesh_loss: Vec<f64>,
    /// By stage: what its kind keeps of the pass for its point (its efficiency is `efficiency`'s).
    pub(crate) kind_state: Vec<Option<KindState>>,
}

impl Pass {
    pub(crate) fn largest_torque(&self) -> f64 {
        self.driving_torque.iter().fold(0.0f64, |m, t| m.max(t.abs()))
    }

    pub(crate) fn is_finite(&self) -> bool {
        [&self.received, &self.passed, &self.driving_torque, &self.efficiency, &self.mesh_loss]
            .iter()
            .all(|v| v.iter().all(|x| x.is_finite()))
    }

    /// The largest move of a driving torque from `self` to `next`, relative to the largest (the
    /// ends' torques follow from them and the speeds).
    pub(crate) fn moved(&self, next: &Pass) -> f64 {
        let scale = next.driving_torque.iter().fold(0.0f64, |m, t| m.max(t.abs()));
        if scale == 0.0 {
            return 0.0;
        }
        let moved = self.driving_torque.iter().zip(&next.driving_torque).fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        moved / scale
    }
}
