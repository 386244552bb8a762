//! What a scene's `gearbox` block describes, in SI.

use super::bearings::Bearing;
use super::gear_no_load::{GearsRunning, Lubrication};
use super::parts::catalog::columns_of;
use super::parts::{LossColumn, PartState, ShaftParts, StageGears};
use super::seals::Seal;

/// The housing, shafts, bearings and seals of a single-stage gearbox, in SI.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Gearbox {
    pub lubrication: Option<Lubrication>,
    /// [pinion shaft, wheel shaft].
    pub bearings: [Vec<Bearing>; 2],
    pub seals: [Vec<Seal>; 2],
}

impl Gearbox {
    /// The budget's columns its parts fill, in order.
    pub fn columns(&self) -> Vec<LossColumn> {
        let running = GearsRunning { omega: [0.0; 2], pitch_radius: [0.0; 2], face_width: 0.0 };
        let (shafts, stages) = self.parts_on(running, &[&[], &[]]);
        columns_of(&PartState { shafts: &shafts, stages: &stages })
    }

    /// Its two shafts and one stage as the loss parts read them: the shafts at the gears' speeds
    /// `running.omega`, `loads` on one bearing of each place of [pinion shaft, wheel shaft] (empty:
    /// read without loads).
    pub(crate) fn parts_on<'a>(
        &'a self,
        running: GearsRunning,
        loads: &[&'a [[f64; 2]]; 2],
    ) -> ([ShaftParts<'a>; 2], [StageGears<'a>; 1]) {
        let shafts = [0, 1].map(|s| ShaftParts {
            speed: running.omega[s],
            bearings: &self.bearings[s],
            loads: loads[s],
            seals: &self.seals[s],
        });
        (shafts, [StageGears { lubrication: self.lubrication.as_ref(), running, shafts: [0, 1] }])
    }

    /// Whether the scene gives anything beyond the mesh.
    pub fn is_empty(&self) -> bool {
        self.lubrication.is_none() && self.bearings.iter().all(Vec::is_empty) && self.seals.iter().all(Vec::is_empty)
    }
}
