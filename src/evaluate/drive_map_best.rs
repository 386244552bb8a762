//! A drive's loss map's best points, located: per law and formulation, where η peaks on the drive
//! half of the map (torque > 0 at the end the map names) and on the coast half (torque < 0), each
//! by [`super::map_best::locate_max`] (coordinate ascent by golden sections over the box of the
//! half's best grid cell's neighbours), every evaluation the
//! drive walked afresh at that torque and speed — a point of the model, not of the grid. The box
//! stays inside its half (the grid's torques of one sign), where η is smooth; zero torque, where no
//! power passes and η is 0, is never a candidate.

use super::drive_map_cell::DriveMapCell;
use super::drive_setup::DriveSetup;
use super::map_best::locate_max;
use crate::drive::{DriveOperating, EndValue, PowerFlow};
use crate::efficiency::Formulation;

/// The best point of one half of a drive's map, for one law and formulation.
#[derive(Debug, Clone, PartialEq)]
pub struct DriveMapBest {
    pub law_index: usize,
    pub formulation: Formulation,
    /// Drive (torque > 0) or coast (torque < 0).
    pub flow: PowerFlow,
    /// The located point: torque (N·m) and speed (rad/s) at the map's ends, and η there
    /// ([`map_objective`]'s: a scene of one pair's own η total).
    pub located: (f64, f64, f64),
    /// The half's best grid cell: torque index, speed index, η.
    pub grid: (usize, usize, f64),
    /// Drive walks the search used.
    pub evaluations: usize,
}

/// The η a map's best point maximises at torque `t` and speed `n` (the map's ends): the drive's
/// P_sink/P_source (`efficiency`); for a scene of one pair (`one_pair`: its map given at the pinion
/// gear) its own total efficiency 1 − P_V/(T_1 ω_1) from the loss `lost`, as its map has always
/// located its best point. 0 where no power passes.
pub(crate) fn map_objective(one_pair: bool, (efficiency, lost): (f64, f64), (t, n): (f64, f64)) -> f64 {
    if one_pair {
        crate::losses::total_efficiency(lost, t * n)
    } else {
        efficiency
    }
}

/// The best point of each half of the map (`torques` × `speeds` in SI at `ends`, the map's rows
/// `map`) for every law and formulation the rows hold, of η by [`map_objective`]; a half without a
/// cell that passes power has none.
pub(crate) fn drive_map_best(
    setup: &DriveSetup,
    (torques, speeds): (&[f64], &[f64]),
    (ends, one_pair): (DriveOperating, bool),
    map: &[DriveMapCell],
) -> Vec<DriveMapBest> {
    let cell_eta = |r: &DriveMapCell| {
        map_objective(one_pair, (r.efficiency, r.power_lost), (torques[r.torque_index], speeds[r.speed_index]))
    };
    let mut keys: Vec<(usize, Formulation)> = Vec::new();
    for r in map {
        if !keys.contains(&(r.law_index, r.formulation)) {
            keys.push((r.law_index, r.formulation));
        }
    }
    let mut order: Vec<usize> = (0..speeds.len()).collect();
    order.sort_by(|a, b| speeds[*a].total_cmp(&speeds[*b]));
    let sorted_speeds: Vec<f64> = order.iter().map(|i| speeds[*i]).collect();
    let mut out = Vec::new();
    for (law_index, formulation) in keys {
        for (flow, sign) in [(PowerFlow::Drive, 1.0), (PowerFlow::Coast, -1.0)] {
            let mut half: Vec<usize> = (0..torques.len()).filter(|i| sign * torques[*i] > 0.0).collect();
            half.sort_by(|a, b| torques[*a].total_cmp(&torques[*b]));
            let cells = map.iter().filter(|r| r.law_index == law_index && r.formulation == formulation);
            let best = cells
                .filter(|r| half.contains(&r.torque_index) && !r.both_ends_deliver && r.efficiency > 0.0)
                .max_by(|a, b| cell_eta(a).total_cmp(&cell_eta(b)));
            let Some(best) = best else { continue };
            let half_torques: Vec<f64> = half.iter().map(|i| torques[*i]).collect();
            let at = |index: &[usize], i: usize| index.iter().position(|k| *k == i).unwrap_or(0);
            let start = (at(&half, best.torque_index), at(&order, best.speed_index));
            let eta = |t: f64, n: f64| {
                let torque = EndValue { at: ends.torque_at, value: t };
                let speed = EndValue { at: ends.speed_at, value: n };
                let p = setup.point(law_index, formulation, torque, speed);
                let eta = map_objective(one_pair, (p.efficiency, p.power_lost()), (t, n));
                if p.both_ends_deliver || !eta.is_finite() {
                    0.0
                } else {
                    eta
                }
            };
            let (located, evaluations) = locate_max(&half_torques, &sorted_speeds, start, eta);
            let grid = (best.torque_index, best.speed_index, cell_eta(best));
            out.push(DriveMapBest { law_index, formulation, flow, located, grid, evaluations });
        }
    }
    out
}
