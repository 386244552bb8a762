//! `efficiency_map`: mean mesh efficiency, the loss budget and total efficiency over a torque × speed
//! grid of its own (not the scene's operating points), for every law and formulation; the cells go
//! to efficiency_map.csv, the report keeps the grid and the ranges over it.

use std::fmt::Write;

use rayon::prelude::*;
use serde::Serialize;

use super::cases::state_at;
use super::laws::evaluate_law;
use super::setup::{contact_table, Setup};
use crate::losses::parts::COLUMNS;
use crate::losses::BudgetParts;
use crate::model::{Formulation, Operating, Scene};

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

/// Evaluates the scene's `efficiency_map`, if it asks for one.
pub(crate) fn evaluate_map(scene: &Scene, eval: &Setup) -> Option<EfficiencyMap> {
    let (torques, speeds) = scene.analyses.efficiency_map.as_ref()?;
    let grid = Operating {
        pinion_torque: torques.clone(),
        pinion_speed: speeds.clone(),
        oil_temperature: scene.operating.oil_temperature.clone(),
        oil_temperatures: None,
        detail_points: Vec::new(),
        equilibrium: None,
    };
    let n = grid.count();
    let cells: Vec<Vec<MapCell>> = (0..n)
        .into_par_iter()
        .map(|k| {
            let state = state_at(&grid, k);
            let table = contact_table(eval, &state);
            let budget = eval.loss_budget(scene, &state);
            let input = state.pinion_torque * state.pinion_speed;
            let mut out = Vec::new();
            for (i, spec) in scene.friction.iter().enumerate() {
                let law = evaluate_law(eval, spec, state, &table, false, false);
                for e in &law.efficiency {
                    let (mesh, mesh_efficiency) = law.charged_mesh(e, eval, input);
                    out.push(MapCell {
                        torque_index: k / speeds.values.len(),
                        speed_index: k % speeds.values.len(),
                        law_index: i,
                        formulation: e.formulation,
                        mesh_efficiency,
                        mesh_loss: mesh,
                        budget: budget.as_ref().map(|b| b.with_mesh(mesh, input)),
                    });
                }
            }
            out
        })
        .collect();
    let cells: Vec<MapCell> = cells.into_iter().flatten().collect();
    let (t, s) = (
        torques.values.iter().map(|t| t.value).collect::<Vec<_>>(),
        speeds.values.iter().map(|s| s.value).collect::<Vec<_>>(),
    );
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
    let best = super::map_best::best_points(scene, eval, &t, &s, &fields);
    Some(EfficiencyMap {
        torques: t,
        speeds: s,
        speeds_written: speeds.written_values.clone(),
        speed_unit: speeds.unit.clone(),
        cells,
        best,
    })
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
