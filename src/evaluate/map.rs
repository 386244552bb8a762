//! `efficiency_map`: mean mesh efficiency, the loss budget and total efficiency over a torque × speed
//! grid of its own (not the scene's operating points), for every law and formulation; the cells go
//! to efficiency_map.csv, the report keeps the grid and the ranges over it. A pair's map is its
//! one-stage drive's: each cell the drive's walk (as a drive's map walks it), read as the pair's
//! budget reads a point.

use std::fmt::Write;

use serde::Serialize;

use super::drive_grid::GridCell;
use super::drive_setup::DriveSetup;
use super::setup::Setup;
use crate::drive::{DriveOperating, DrivePoint, ShaftEnd};
use crate::losses::parts::{LossColumn, COLUMNS};
use crate::losses::BudgetParts;
use crate::model::{Formulation, Scene};

/// One grid point, one law, one formulation.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct MapCell {
    pub torque_index: usize,
    pub speed_index: usize,
    /// Index of the law in the scene's friction list.
    pub law_index: usize,
    pub formulation: Formulation,
    /// η̄ of the mesh and its loss (W).
    pub mesh_efficiency: f64,
    pub mesh_loss: f64,
    /// The budget when the scene describes its gearbox.
    pub budget: Option<BudgetParts>,
}

/// The map over its grid.
#[derive(Debug, Clone, PartialEq)]
pub struct EfficiencyMap {
    /// Pinion torques (N·m) and speeds (rad/s) of the grid, and as written.
    pub torques: Vec<f64>,
    pub speeds: Vec<f64>,
    pub speeds_written: Vec<f64>,
    pub speed_unit: String,
    /// Torque-major, then law, then formulation.
    pub cells: Vec<MapCell>,
    /// The best point of every law and formulation, located ([`super::map_best`]).
    pub best: Vec<super::map_best::MapBest>,
}

/// Evaluates the scene's `efficiency_map`, if it asks for one: every cell is the scene's one-stage
/// drive walked at the cell's pinion torque (at the pinion gear) and speed under each law and
/// formulation (`DriveSetup::grid_points`, the walk a drive's map takes), read as the pair's map
/// reads it: the mesh's η̄ and loss as the budget charges them, and with a gearbox the parts beside
/// the mesh, the whole loss and the total efficiency 1 − P_total/(T_1 ω_1).
pub(crate) fn evaluate_map(scene: &Scene, eval: &Setup) -> Option<EfficiencyMap> {
    let (torques, speeds) = scene.analyses.efficiency_map.as_ref()?;
    // Every scene of one pair carries its one-stage drive (lowering attaches it).
    let drive = scene.drive.as_ref()?;
    let setup = DriveSetup::new(scene, drive);
    let (t, s) = (
        torques.values.iter().map(|t| t.value).collect::<Vec<_>>(),
        speeds.values.iter().map(|s| s.value).collect::<Vec<_>>(),
    );
    let columns = scene.gearbox.as_ref().map(crate::losses::Gearbox::columns);
    let ends = DriveOperating { torque_at: ShaftEnd::Input, speed_at: ShaftEnd::Input };
    let rows = t.len() * s.len() * setup.rows_per_point();
    let cells = setup.grid_points((&t, &s), ends, 0..rows, |c, p| {
        let input = c.torque.value * c.speed.value;
        map_cell(c, &p, input, columns.as_deref())
    });
    let mut fields = Vec::new();
    for law in 0..scene.friction.len() {
        for f in eval.formulations.iter().copied() {
            let mut values = vec![vec![f64::NEG_INFINITY; s.len()]; t.len()];
            let mut total = false;
            for c in cells.iter().filter(|c| c.law_index == law && c.formulation == f) {
                total = c.budget.is_some();
                values[c.torque_index][c.speed_index] =
                    c.budget.as_ref().map_or(c.mesh_efficiency, |b| b.total_efficiency);
            }
            fields.push((law, f, total, values));
        }
    }
    let best = super::map_best::best_points(&setup, &t, &s, &fields, columns.as_deref());
    Some(EfficiencyMap {
        torques: t,
        speeds: s,
        speeds_written: speeds.written_values.clone(),
        speed_unit: speeds.unit.clone(),
        cells,
        best,
    })
}

/// One cell of the pair's map from its one-stage drive's point `p` at input power `input` = T_1 ω_1
/// (W): the stage's mesh η̄ and loss, and with a gearbox (`columns`: the parts it describes) its
/// budget (`super::pair_budget::budget_of`).
fn map_cell(c: &GridCell, p: &DrivePoint, input: f64, columns: Option<&[LossColumn]>) -> MapCell {
    MapCell {
        torque_index: c.torque_index,
        speed_index: c.speed_index,
        law_index: c.law_index,
        formulation: c.formulation,
        mesh_efficiency: p.stages[0].mesh_efficiency,
        mesh_loss: p.stages[0].mesh_loss,
        budget: columns.map(|columns| super::pair_budget::budget_of(p, input, columns)),
    }
}

impl EfficiencyMap {
    /// efficiency_map.csv: one row per grid point, law and formulation (SI: N·m, rad/s, W).
    pub fn csv(&self, labels: &[String]) -> String {
        let parts: Vec<String> = COLUMNS.iter().map(|c| format!("{}_W", c.key)).collect();
        let mut out = format!(
            "pinion_torque_N_m,pinion_speed_rad_s,pinion_speed_written,law,formulation,mesh_efficiency,mesh_loss_W,{},total_loss_W,total_efficiency\n",
            parts.join(",")
        );
        let num =
            |x: Option<f64>| x.map_or(String::new(), |x| format!("{:e}", crate::numerics::rounding::round_sig(x)));
        for c in &self.cells {
            let b = c.budget.as_ref();
            let _ = writeln!(
                out,
                "{},{},{},\"{}\",{},{},{},{},{},{}",
                num(Some(self.torques[c.torque_index])),
                num(Some(self.speeds[c.speed_index])),
                self.speeds_written[c.speed_index],
                labels[c.law_index].replace('"', "\"\""),
                c.formulation.name(),
                num(Some(c.mesh_efficiency)),
                num(Some(c.mesh_loss)),
                COLUMNS.iter().map(|col| num(b.and_then(|b| b.part(col.column)))).collect::<Vec<_>>().join(","),
                num(b.map(|b| b.total_loss)),
                num(b.map(|b| b.total_efficiency)),
            );
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::evaluate::cases::state_at;
    use crate::evaluate::laws::evaluate_law;
    use crate::evaluate::setup::contact_table;

    /// The map's cells are the pair's own budget: at every cell, law and formulation of
    /// `specs/fzg_c14_gearbox.gear`'s 40 × 40 map (bearings, seals, dip churning; four laws, both
    /// formulations) the mesh's η̄ is the pair's law as its budget charges it (to 1e-15) and the
    /// mesh loss, each part beside the mesh and the whole loss are the pair's loss budget at the
    /// cell's pinion torque and speed on the pair's own two shafts (`losses::loss_budget`: the
    /// parts catalogue on the pair's statics, `losses::pair_statics`, not the drive's walk or its
    /// statics) to 1e-13 relative; the total efficiency follows to 1e-13.
    #[test]
    fn cells_are_the_pairs_own_budget() {
        let source =
            std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/specs/fzg_c14_gearbox.gear")).unwrap();
        let scene = crate::scene::check::check("fzg_c14_gearbox.gear", &source).unwrap();
        let plan = crate::evaluate::Plan::new(&scene.operating, None, &scene.operating.detail_points);
        let eval = crate::evaluate::prepare(&scene, &plan);
        let map = evaluate_map(&scene, &eval).expect("the scene asks for a map");
        let (torques, speeds) = scene.analyses.efficiency_map.as_ref().unwrap();
        let grid = crate::model::Operating {
            pinion_torque: torques.clone(),
            pinion_speed: speeds.clone(),
            oil_temperature: scene.operating.oil_temperature.clone(),
            oil_temperatures: None,
            detail_points: Vec::new(),
            equilibrium: None,
        };
        let close = |a: f64, b: f64, tol: f64| (a - b).abs() <= tol * b.abs().max(1e-300);
        let mut compared = 0;
        for k in 0..grid.count() {
            let state = state_at(&grid, k);
            let table = contact_table(&eval, &state);
            let oil = scene.mesh().budget_oil(&eval.tribology);
            let gearbox = scene.gearbox.as_ref().expect("a gearbox");
            let budget =
                crate::losses::loss_budget(gearbox, &eval.geometry, state.pinion_torque, state.pinion_speed, &oil);
            let input = state.pinion_torque * state.pinion_speed;
            let (t, s) = (k / speeds.values.len(), k % speeds.values.len());
            for (i, spec) in scene.friction.iter().enumerate() {
                let law = evaluate_law(&eval, spec, state, &table, false, false);
                for e in &law.efficiency {
                    let (mesh, eta) = law.charged_mesh(e, &eval, input);
                    let want = budget.with_mesh(mesh, input);
                    let c = map
                        .cells
                        .iter()
                        .find(|c| {
                            (c.torque_index, c.speed_index, c.law_index, c.formulation) == (t, s, i, e.formulation)
                        })
                        .expect("every cell");
                    let got = c.budget.as_ref().expect("a budget");
                    assert!(close(c.mesh_efficiency, eta, 1e-15), "η̄ {} vs {eta}", c.mesh_efficiency);
                    assert!(close(c.mesh_loss, mesh, 1e-13), "mesh loss {} vs {mesh}", c.mesh_loss);
                    assert_eq!(got.parts.len(), want.parts.len());
                    for ((col, p), (want_col, w)) in got.parts.iter().zip(&want.parts) {
                        assert_eq!(col, want_col);
                        assert!(close(*p, *w, 1e-13), "{col:?} at ({t}, {s}): {p} vs {w}");
                    }
                    assert!(close(got.total_loss, want.total_loss, 1e-13));
                    assert!(close(got.total_efficiency, want.total_efficiency, 1e-13));
                    compared += 1;
                }
            }
        }
        assert_eq!(compared, map.cells.len());
        assert!(compared >= 6000, "{compared}");
    }
}
