//! A drive's efficiency map, cell by cell: each grid point walked through and at once reduced to
//! what the map's report and its best-point search read (η, the loss and its parts, whether both
//! ends deliver, the passes), the point itself dropped. The map's memory is then a few numbers a cell, not a
//! whole `DrivePoint` (its shafts, bearings and forces) a cell.

use super::drive_setup::DriveSetup;
use crate::drive::DriveOperating;
use crate::efficiency::Formulation;

/// One cell of a drive's map under one law and formulation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DriveMapCell {
    pub torque_index: usize,
    pub speed_index: usize,
    pub law_index: usize,
    pub formulation: Formulation,
    /// P_sink/P_source (0 where both ends deliver).
    pub efficiency: f64,
    /// P_source − P_sink (W).
    pub power_lost: f64,
    /// The loss by part (W): the meshes', then each budget column's.
    pub losses: crate::drive::LossParts,
    pub both_ends_deliver: bool,
    /// Passes of the power walk's fixed point.
    pub iterations: usize,
}

/// Every (torque, speed, law, formulation) of the grid `torques` × `speeds` (SI, at `ends`), in
/// parallel, in that order (torque-major, then law, then formulation).
pub(crate) fn map_cells(
    setup: &DriveSetup,
    torques: &[f64],
    speeds: &[f64],
    ends: DriveOperating,
) -> Vec<DriveMapCell> {
    let rows = torques.len() * speeds.len() * setup.rows_per_point();
    setup.grid_points((torques, speeds), ends, 0..rows, |c, p| DriveMapCell {
        torque_index: c.torque_index,
        speed_index: c.speed_index,
        law_index: c.law_index,
        formulation: c.formulation,
        efficiency: p.efficiency,
        power_lost: p.power_lost(),
        losses: p.losses,
        both_ends_deliver: p.both_ends_deliver,
        iterations: p.iterations,
    })
}
