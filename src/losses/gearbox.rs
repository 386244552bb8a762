//! What a scene's `gearbox` block describes, in SI.

use super::bearings::Bearing;
use super::gear_no_load::Lubrication;
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
    pub fn is_empty(&self) -> bool {
        self.lubrication.is_none() && self.bearings.iter().all(Vec::is_empty) && self.seals.iter().all(Vec::is_empty)
    }
}
