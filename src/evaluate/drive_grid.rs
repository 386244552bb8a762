//! A grid of a drive's operating points walked in parallel (a sweep's rows, a map's cells): each
//! row's indices and the ends' values it is walked at, a point's rows under one law walked together
//! so that they share their meshes' integrals.

use rayon::prelude::*;

use super::drive_setup::{DriveRow, DriveSetup};
use super::stage_mesh::MeshMemo;
use crate::drive::{DrivePoint, EndValue};
use crate::efficiency::Formulation;

impl DriveSetup<'_> {
    /// The rows `range` of a grid (torque-major, then law, then formulation), in parallel.
    pub(crate) fn grid_rows(
        &self,
        torques: &[f64],
        speeds: &[f64],
        ends: crate::drive::DriveOperating,
        range: std::ops::Range<usize>,
    ) -> Vec<DriveRow> {
        self.grid_points((torques, speeds), ends, range, |c, point| DriveRow {
            torque_index: c.torque_index,
            speed_index: c.speed_index,
            law_index: c.law_index,
            formulation: c.formulation,
            point,
            balance: None,
        })
    }

    /// The rows `range` of a grid walked in parallel, each reduced at once by `keep` to what the
    /// caller holds of it. A point's rows under one law (its formulations, consecutive) are walked
    /// together, sharing their meshes' integrals (`MeshMemo`).
    pub(crate) fn grid_points<T: Send>(
        &self,
        grid: (&[f64], &[f64]),
        ends: crate::drive::DriveOperating,
        range: std::ops::Range<usize>,
        keep: impl Fn(&GridCell, DrivePoint) -> T + Sync,
    ) -> Vec<T> {
        let formulations = self.formulations();
        let nf = formulations.len().max(1);
        (range.start / nf..range.end.div_ceil(nf))
            .into_par_iter()
            .flat_map_iter(|group| {
                let memo = MeshMemo::default();
                let kept: Vec<T> = (group * nf..(group + 1) * nf)
                    .filter(|i| range.contains(i))
                    .map(|i| {
                        let c = self.grid_cell(i, grid, ends, &formulations);
                        let point = self.point_in(&memo, c.law_index, c.formulation, c.torque, c.speed);
                        keep(&c, point)
                    })
                    .collect();
                kept
            })
            .collect()
    }

    /// The grid's `i`-th row (torque-major, then law, then formulation): its indices and the ends'
    /// values it is evaluated at.
    pub(crate) fn grid_cell(
        &self,
        i: usize,
        (torques, speeds): (&[f64], &[f64]),
        ends: crate::drive::DriveOperating,
        formulations: &[Formulation],
    ) -> GridCell {
        let per_point = self.rows_per_point();
        let (point, rest) = (i / per_point, i % per_point);
        let (law_index, f) = (rest / formulations.len(), rest % formulations.len());
        let (torque_index, speed_index) = (point / speeds.len(), point % speeds.len());
        GridCell {
            torque_index,
            speed_index,
            law_index,
            formulation: formulations[f],
            torque: EndValue { at: ends.torque_at, value: torques[torque_index] },
            speed: EndValue { at: ends.speed_at, value: speeds[speed_index] },
        }
    }
}

/// One row of a grid: its torque, speed and law indices, its formulation and the ends' values.
pub(crate) struct GridCell {
    pub(crate) torque_index: usize,
    pub(crate) speed_index: usize,
    pub(crate) law_index: usize,
    pub(crate) formulation: Formulation,
    pub(crate) torque: EndValue,
    pub(crate) speed: EndValue,
}
