//! Each stage mesh's geometry in a drive's report, as a pair's report gives its own
//! (`super::geometry::pair_geometry_report`): the pair with the pinion in the pinion's place (a
//! planetary stage's sun–planet and planet–ring meshes each), its H_V as the walk integrates it,
//! E' and the load sharing the walk reads. A helical mesh's plane of action is drawn as a pair's
//! is (its own plot, named in [`StageGeometryReport::plot`]); its axial forces by point are left to
//! each point's stage table, which has F_a.

use serde::{Deserialize, Serialize};

use super::geometry::GeometryReport;
use super::scene_report::{PlotKind, PlotRef};
use crate::geometry::PairGeometry;
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
    /// A helical mesh's plane of action: its plot's file and title.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PlotRef>,
}

/// One mesh of a drive's stage with its pair's geometry (the pinion in the pinion's place).
pub(super) struct StageMeshGeometry<'a> {
    /// The stage's index and name, and the mesh's index in its stage.
    pub k: usize,
    pub stage: &'a str,
    pub mesh: usize,
    /// The mesh's name where its stage has several (`sun–planet`), and its gears.
    pub label: Option<String>,
    pub gears: [&'static str; 2],
    pub geometry: PairGeometry,
}

/// Every stage mesh of `drive` whose pair has a geometry (lowering has built each), in the
/// drive's order: what its geometry warnings and its geometry report are read from.
pub(super) fn stage_meshes(drive: &SceneDrive) -> Vec<StageMeshGeometry<'_>> {
    let mut out = Vec::new();
    for (k, stage) in drive.layout.stages.iter().enumerate() {
        let meshes = stage.model().mesh_gears();
        for (mesh, names) in meshes.iter().enumerate() {
            let Ok(geometry) = drive.mesh_pair(k, mesh).geometry() else { continue };
            let label = (meshes.len() > 1).then(|| format!("{}–{}", names[0], names[1]));
            out.push(StageMeshGeometry { k, stage: &stage.name, mesh, label, gears: *names, geometry });
        }
    }
    out
}

/// Every stage mesh's geometry; `loss_factors` are each stage's meshes' H_V as the evaluation's
/// walk integrates them (the pinion driving; a planetary stage's second mesh after its first).
pub(super) fn stage_geometry(
    drive: &SceneDrive,
    lubricant: Option<&Lubricant>,
    loss_factors: &[Vec<f64>],
) -> Vec<StageGeometryReport> {
    let mut out = Vec::new();
    for m in stage_meshes(drive) {
        let Some(h_v) = loss_factors[m.k].get(m.mesh) else { continue };
        // The stage's own pair reads its load sharing; a planet–ring mesh shares equally.
        let (e_r, sharing) = match m.mesh {
            0 => (drive.mesh(m.k, lubricant).reduced_modulus(), drive.pairs[m.k].load_sharing),
            n => (drive.further_mesh(m.k, n, lubricant).map_or(0.0, |r| r.reduced_modulus()), LoadSharing::Equal),
        };
        let helical = super::helical::helical_report(&m.geometry, Vec::new());
        let plot = helical.is_some().then(|| plane_of_action_plot(m.stage, m.label.as_deref()));
        out.push(StageGeometryReport {
            stage: m.stage.to_string(),
            mesh: m.label,
            gears: m.gears.map(str::to_string),
            geometry: super::geometry::pair_geometry_report(&m.geometry, helical, *h_v, e_r, sharing),
            plot,
        });
    }
    out
}

/// The plane-of-action plot of a helical stage mesh: `plane_of_action_<stage>[_<mesh>].svg`.
fn plane_of_action_plot(stage: &str, mesh: Option<&str>) -> PlotRef {
    let slug = super::slug::slug;
    let file = match mesh {
        Some(m) => format!("plane_of_action_{}_{}.svg", slug(stage), slug(&m.replace('–', " "))),
        None => format!("plane_of_action_{}.svg", slug(stage)),
    };
    let mesh = mesh.map_or_else(String::new, |m| format!(", {m} mesh"));
    PlotRef {
        kind: PlotKind::PlaneOfAction,
        file,
        title: format!("Stage `{stage}`{mesh}: contact lines and their length"),
    }
}
