//! A drive run at several oil temperatures: one drive report per temperature (in its own folder)
//! and their comparison, row by row (operating point, law, formulation): the total loss and η at
//! each temperature, and the loss parts; the lubricant read at each.

use crate::losses::parts::LossColumn;
use serde::{Deserialize, Serialize};

use super::drive::DriveReport;

/// One temperature's run: where its report is and its rows.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub(crate) struct DriveOilRun {
    /// As written (`60 degC`), in K, and the run's folder.
    pub label: String,
    pub kelvin: f64,
    pub folder: String,
    /// The lubricant read at this temperature (as the run's own report gives it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lubricant: Option<super::losses::LubricantReport>,
    /// Per shown row: (total loss W, η, meshes W, bearings W).
    pub rows: Vec<(f64, f64, f64, f64)>,
    /// The run's report's warnings and notes, counted.
    #[serde(default)]
    pub warnings: usize,
    #[serde(default)]
    pub notes: usize,
}

/// The comparison.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub(crate) struct DriveOilSweepReport {
    pub title: String,
    pub slug: String,
    /// The shown rows' labels (point, law, formulation), the same in every run.
    pub rows: Vec<String>,
    pub runs: Vec<DriveOilRun>,
    /// The units report.md shows powers in (the runs' own).
    #[serde(default, skip_serializing_if = "super::number::UnitSystem::is_si")]
    pub unit_system: super::number::UnitSystem,
}

/// The comparison of `runs`: (temperature as written, in K, its folder, its report).
pub(crate) fn build_drive_oil_sweep(runs: &[(String, f64, String, DriveReport)]) -> DriveOilSweepReport {
    let first = &runs[0].3;
    DriveOilSweepReport {
        title: first.title.clone(),
        slug: first.slug.clone(),
        rows: first.points.iter().map(|p| format!("{} ({}, {})", p.label, p.law, p.formulation)).collect(),
        runs: runs
            .iter()
            .map(|(label, kelvin, folder, r)| DriveOilRun {
                label: label.clone(),
                kelvin: *kelvin,
                folder: folder.clone(),
                lubricant: r.lubricant.clone(),
                warnings: r.findings.iter().filter(|f| f.severity == super::finding::Severity::Warning).count(),
                notes: r.findings.iter().filter(|f| f.severity != super::finding::Severity::Warning).count(),
                rows: r
                    .points
                    .iter()
                    .map(|p| {
                        let l = &p.point.losses;
                        (
                            l.total(),
                            p.point.efficiency,
                            l.meshes,
                            l.part(LossColumn::BearingsNoLoad) + l.part(LossColumn::BearingsLoad),
                        )
                    })
                    .collect(),
            })
            .collect(),
        unit_system: first.unit_system,
    }
}

/// The folder of one temperature's report: `oil_temperature_90degC` (characters other than
/// letters, digits, `.` and `-` left out).
pub(crate) fn run_folder(label: &str) -> String {
    let kept: String = label.chars().filter(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '-')).collect();
    format!("oil_temperature_{kept}")
}
