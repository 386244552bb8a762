//! Each stage mesh's geometry in a drive's report, as a pair's report gives its own
//! (`super::geometry::pair_geometry_report`): the pair with the pinion in the pinion's place (a
//! planetary stage's sun–planet and planet–ring meshes each), its H_V as the walk integrates it,
//! E' and the load sharing the walk reads. A helical mesh's numbers without the plot data of a
//! pair's plane of action (a drive draws none) and without axial forces by point (each point's
//! stage table has F_a).

use serde::{Deserialize, Serialize};

use super::geometry::GeometryReport;
use crate::model::{LoadSharing, Lubricant, SceneDrive};

/// One stage mesh's geometry.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct StageGeometryReport {
    pub stage: String,
    /// A stage of several meshes: this mesh's gears (`sun–planet`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mesh: Option<String>,
    /// The gears in the pinion's and the wheel's places.
    pub gears: [String; 2],
    pub geometry: GeometryReport,
}

/// Every stage mesh's geometry; `loss_factors` are each stage's meshes' H_V as the evaluation's
/// walk integrates them (the pinion driving; a planetary stage's second mesh after its first).
pub(super) fn stage_geometry(
    drive: &SceneDrive,
    lubricant: Option<&Lubricant>,
    loss_factors: &[Vec<f64>],
) -> Vec<StageGeometryReport> {
    let mut out = Vec::new();
    for (k, stage) in drive.layout.stages.iter().enumerate() {
        let meshes = stage.model().mesh_gears();
        for (mesh, names) in meshes.iter().enumerate() {
            let (Ok(g), Some(h_v)) = (drive.mesh_pair(k, mesh).geometry(), loss_factors[k].get(mesh)) else {
                continue;
            };
            // The stage's own pair reads its load sharing; a planet–ring mesh shares equally.
            let (e_r, sharing) = match mesh {
                0 => (drive.mesh(k, lubricant).reduced_modulus(), drive.pairs[k].load_sharing),
                _ => (drive.ring_mesh(k, lubricant).map_or(0.0, |m| m.reduced_modulus()), LoadSharing::Equal),
            };
            let helical = super::helical::helical_report(&g, Vec::new()).map(|mut h| {
                h.lines_at.clear();
                h.length_curve = Default::default();
                h
            });
            out.push(StageGeometryReport {
                stage: stage.name.clone(),
                mesh: (meshes.len() > 1).then(|| format!("{}–{}", names[0], names[1])),
                gears: names.map(str::to_string),
                geometry: super::geometry::pair_geometry_report(&g, helical, *h_v, e_r, sharing),
            });
        }
    }
    out
}
