//! A drive's stages analysed as pairs alone: what each analysed mesh ran at (the drive's point, the
//! member in the pinion's place, its torque and speed from the power walk, the mesh efficiency the
//! walk charged) and where its own report is ([`crate::evaluate::stage_pairs`] says how the state
//! is taken). The pair's report itself is a report of one pair, in its folder.

use serde::{Deserialize, Serialize};

/// One analysed mesh at one of the drive's operating points.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StagePairReport {
    pub stage: String,
    /// A planetary stage's mesh (`sun–planet`, `planet–ring`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mesh: Option<String>,
    /// The drive's operating point, 1-based (torque-major), and in words; None for the stage of a
    /// scene of one pair, analysed over the scene's whole sweep (`point_words` says so).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub point: Option<usize>,
    pub point_words: String,
    /// The law and formulation the drive was solved under to give this state.
    pub law: String,
    pub formulation: String,
    /// The gears in the pinion's and in the wheel's places.
    pub pinion: String,
    pub wheel: String,
    /// The pinion's torque (N·m) and speed (rpm); None over the whole sweep (the scene's own).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pinion_torque: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pinion_speed_rpm: Option<f64>,
    /// The mesh efficiency the drive's walk charged; None over the whole sweep (each row's is in
    /// the drive's points).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mesh_efficiency: Option<f64>,
    /// The pair alone's η̄ under the same law and formulation (its report's line integral; absent
    /// when the scene asks for no `efficiency`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pair_mean_efficiency: Option<f64>,
    /// The pair alone's η with the mesh loss a loss budget charges (ISO/TR 14179-2's P_in μ̄ H_V for
    /// that law on a helical pair, else the line integral): what the drive's walk charged.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pair_charged_efficiency: Option<f64>,
    /// The pair alone's report folder, relative to this report's; None where no load goes through
    /// the mesh at this point (nothing to analyse).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub folder: Option<String>,
    /// Why the pair alone was not run at this state (what a scene of that pair would be refused
    /// for, such as dynamics at too low a speed).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub not_run: Option<String>,
}

/// The folder of an analysed mesh's report: `stages/<stage>[_<mesh>]_point_<n>` at point n (0-based
/// `point`), `stages/<stage>[_<mesh>]` over the whole sweep.
pub(crate) fn folder(stage: &str, mesh: Option<&str>, point: Option<usize>) -> String {
    let mesh = mesh.map_or_else(String::new, |m| format!("_{}", super::slug::slug(&m.replace('–', " "))));
    let point = point.map_or_else(String::new, |p| format!("_point_{}", p + 1));
    format!("stages/{}{mesh}{point}", super::slug::slug(stage))
}
