//! `efficiency_map`: mean mesh efficiency, the loss budget and total efficiency over a torque × speed
//! grid of its own (not the scene's operating points), for every law and formulation; the cells go
//! to efficiency_map.csv, the report keeps the grid and the ranges over it.

use rayon::prelude::*;
use serde::Serialize;

use super::cases::state_at;
use super::laws::evaluate_law;
use super::setup::{contact_table, Setup};
use crate::losses::BudgetParts;
use crate::model::{Formulation, Operating, Scene};

/// One grid point, one law, one formulation.
#[derive(Debug, Clone, PartialEq, Serialize)]
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
}

/// Evaluates the scene's `efficiency_map`, if it asks for one.
pub fn evaluate_map(scene: &Scene, eval: &Setup) -> Option<EfficiencyMap> {
    let (torques, speeds) = scene.analyses.efficiency_map.as_ref()?;
    let grid = Operating {
        pinion_torque: torques.clone(),
        pinion_speed: speeds.clone(),
        oil_temperature: scene.operating.oil_temperature.clone(),
        oil_temperatures: None,
        detail_points: Vec::new(),
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
                    out.push(MapCell {
                        torque_index: k / speeds.values.len(),
                        speed_index: k % speeds.values.len(),
                        law_index: i,
                        formulation: e.formulation,
                        mesh_efficiency: e.mean.value,
                        mesh_loss: e.power_loss,
                        budget: budget.as_ref().map(|b| b.with_mesh(e.power_loss, input)),
                    });
                }
            }
            out
        })
        .collect();
    Some(EfficiencyMap {
        torques: torques.values.iter().map(|t| t.value).collect(),
        speeds: speeds.values.iter().map(|s| s.value).collect(),
        speeds_written: speeds.written_values.clone(),
        speed_unit: speeds.unit.clone(),
        cells: cells.into_iter().flatten().collect(),
    })
}
