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
    /// Whether the scene gives anything beyond the mesh.
    /// The budget's columns its parts fill, in order.
    pub fn columns(&self) -> Vec<LossColumn> {
        let shafts: [ShaftParts; 2] =
            [0, 1].map(|s| ShaftParts { speed: 0.0, bearings: &self.bearings[s], loads: &[], seals: &self.seals[s] });
        let running = GearsRunning { omega: [0.0; 2], pitch_radius: [0.0; 2], face_width: 0.0 };
        let stages = [StageGears { lubrication: self.lubrication.as_ref(), running, shafts: [0, 1] }];
        columns_of(&PartState { shafts: &shafts, stages: &stages })
    }

    pub fn is_empty(&self) -> bool {
        self.lubrication.is_none() && self.bearings.iter().all(Vec::is_empty) && self.seals.iter().all(Vec::is_empty)
    }
}
