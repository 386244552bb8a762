//! A drive's efficiency maps in its report: per law and formulation the total loss and η over the
//! ends' torque × speed, and the best point of each half, located (`evaluate/drive_map_best.rs`).

use serde::{Deserialize, Serialize};

use crate::drive::ShaftEnd;
use crate::evaluate::drive::DriveEvaluation;
use crate::model::Scene;

/// The map over the ends' torque × speed, for one law and formulation: the total loss (W) and η.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct DriveMapReport {
    pub law: String,
    pub formulation: String,
    pub torque_at: ShaftEnd,
    pub speed_at: ShaftEnd,
    /// Torques (N·m) and speeds (rpm) of the grid.
    pub torques: Vec<f64>,
    pub speeds_rpm: Vec<f64>,
    /// `[torque][speed]`: total loss (W) and η (0 where both ends deliver).
    #[serde(with = "super::floats")]
    pub loss: Vec<Vec<f64>>,
    #[serde(with = "super::floats")]
    pub efficiency: Vec<Vec<f64>>,
    /// `[torque][speed]` of each part of the loss (W): `meshes`, then each budget column by its key
    /// (`gear_no_load`, `bearings_no_load`, `bearings_load`, `seals`); they add up to `loss` where the
    /// cell's books balance.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub parts: Vec<MapPart>,
    /// A scene of one pair's map (its torque and speed the pinion's): `[torque][speed]` of the
    /// pair's own total efficiency, 1 − P_V/(T_1 ω_1), at the pinion gear (the drive's η,
    /// `efficiency`, takes the input's power: the pinion's plus its shaft's losses).
    #[serde(default, skip_serializing_if = "Vec::is_empty", with = "super::floats")]
    pub pinion_efficiency: Vec<Vec<f64>>,
    /// The largest passes of the fixed point over the grid.
    pub most_passes: usize,
    /// Where η peaks on the drive half and on the coast half, located (not the grid's best cell).
    #[serde(default)]
    pub best: Vec<DriveMapBestReport>,
}

/// One part of a map's loss over the grid: its key and `[torque][speed]` values (W).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct MapPart {
    pub key: String,
    #[serde(with = "super::floats")]
    pub values: Vec<Vec<f64>>,
}

/// The located best point of one half of a drive's map.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct DriveMapBestReport {
    /// "drive" or "coast".
    pub flow: String,
    /// The located point: torque (N·m) and speed (rpm) at the map's ends, and η (a scene of one
    /// pair's: its own η total, 1 − P_V/(T_1 ω_1), the map's `pinion_efficiency`).
    pub torque: f64,
    pub speed_rpm: f64,
    pub efficiency: f64,
    /// The half's best grid cell, where the search started.
    pub grid_torque: f64,
    pub grid_speed_rpm: f64,
    pub grid_efficiency: f64,
    /// Drive walks the search used.
    pub evaluations: usize,
}

/// The maps, one per law and formulation.
pub(super) fn maps(scene: &Scene, eval: &DriveEvaluation, laws: &[String]) -> Vec<DriveMapReport> {
    let (Some((t, s)), Some(ends)) = (&scene.analyses.efficiency_map, scene.analyses.map_ends) else {
        return Vec::new();
    };
    let formulations = scene.analyses.efficiency.clone().unwrap_or_default();
    let mut out = Vec::new();
    for (law_index, law) in laws.iter().enumerate() {
        for f in &formulations {
            let cells = eval.map.iter().filter(|r| r.law_index == law_index && r.formulation == *f);
            let mut loss = vec![vec![f64::NAN; s.values.len()]; t.values.len()];
            let mut efficiency = loss.clone();
            let keys = std::iter::once("meshes").chain(crate::losses::parts::COLUMNS.iter().map(|c| c.key));
            let mut parts: Vec<MapPart> = keys.map(|key| MapPart { key: key.into(), values: loss.clone() }).collect();
            let mut most_passes = 0;
            for c in cells {
                loss[c.torque_index][c.speed_index] = c.power_lost;
                efficiency[c.torque_index][c.speed_index] = c.efficiency;
                let by_part = std::iter::once(c.losses.meshes).chain(c.losses.parts);
                for (part, w) in parts.iter_mut().zip(by_part) {
                    part.values[c.torque_index][c.speed_index] = w;
                }
                most_passes = most_passes.max(c.iterations);
            }
            let one_pair = scene.drive.as_ref().is_some_and(|d| d.one_pair);
            let pinion_efficiency = if one_pair {
                let power = |i: usize, j: usize| t.values[i].value * s.values[j].value;
                let at = |i: usize, row: &Vec<f64>| {
                    (0..row.len()).map(|j| crate::losses::total_efficiency(row[j], power(i, j))).collect()
                };
                loss.iter().enumerate().map(|(i, row)| at(i, row)).collect()
            } else {
                Vec::new()
            };
            let rpm = 30.0 / std::f64::consts::PI;
            let best = eval
                .map_best
                .iter()
                .filter(|b| b.law_index == law_index && b.formulation == *f)
                .map(|b| DriveMapBestReport {
                    flow: b.flow.name().to_string(),
                    torque: b.located.0,
                    speed_rpm: b.located.1 * rpm,
                    efficiency: b.located.2,
                    grid_torque: t.values[b.grid.0].value,
                    grid_speed_rpm: s.values[b.grid.1].value * rpm,
                    grid_efficiency: b.grid.2,
                    evaluations: b.evaluations,
                })
                .collect();
            out.push(DriveMapReport {
                best,
                law: law.clone(),
                formulation: f.name().to_string(),
                torque_at: ends.torque_at,
                speed_at: ends.speed_at,
                torques: t.values.iter().map(|x| x.value).collect(),
                speeds_rpm: s.values.iter().map(|w| w.value * 30.0 / std::f64::consts::PI).collect(),
                loss,
                efficiency,
                parts,
                pinion_efficiency,
                most_passes,
            });
        }
    }
    out
}
