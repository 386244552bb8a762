//! A scene run at several oil temperatures (`oil_temperature = [60, 90, 120] degC`): each
//! temperature's full report lives in its own folder; this report sets side by side what the
//! temperature changes — the lubricant's values, and per operating point, law and formulation the
//! mean mesh efficiency, the mesh loss and (with a gearbox) the loss budget's total.

use serde::{Deserialize, Serialize};

use super::finding::Severity;
use super::friction::EfficiencyRecord;
use super::losses::LubricantReport;
use super::number::{Num, Q};
use super::scene_report::Report;
use crate::efficiency::Formulation;
use crate::friction::catalog::LawId;

/// The comparison across oil temperatures.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub(crate) struct OilSweepReport {
    pub title: String,
    pub slug: String,
    /// One run per temperature, in the order the scene wrote them.
    pub runs: Vec<OilRun>,
    /// One row per operating point, law and formulation of the runs' efficiency records, with one
    /// value per run in each column.
    pub efficiency: Vec<OilSweepRow>,
    /// Whether the rows carry the loss budget's total (the scene describes its gearbox).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub loss_budget: bool,
    /// The unit the scene wrote the pinion speed in (for the tables).
    pub speed_unit: super::number::DisplayUnit,
    /// The unit the scene wrote the pinion torque in: operating points are named in it.
    #[serde(default = "super::number::DisplayUnit::newton_metre")]
    pub torque_unit: super::number::DisplayUnit,
    /// The unit system the Markdown shows results in (as each temperature's report).
    #[serde(default, skip_serializing_if = "super::number::UnitSystem::is_si")]
    pub unit_system: super::number::UnitSystem,
}

/// One temperature's run.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub(crate) struct OilRun {
    /// As written (`90 degC`).
    pub label: String,
    pub oil_temperature: Q,
    /// The folder of its full report, relative to this report.
    pub folder: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lubricant: Option<LubricantReport>,
    pub warnings: usize,
    pub notes: usize,
}

/// One operating point, law and formulation: its values at each temperature (in run order).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub(crate) struct OilSweepRow {
    pub law: LawId,
    pub label: String,
    pub formulation: Formulation,
    pub pinion_torque: Q,
    pub pinion_speed: Q,
    /// The mesh efficiency and loss at each temperature, as the budget charges them (ISO/TR
    /// 14179-2's own for `iso_14179_2` on a helical pair, else the law's line integral).
    pub mean_efficiency: Vec<Num>,
    pub power_loss: Vec<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub total_loss: Option<Vec<Q>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub total_efficiency: Option<Vec<Num>>,
}

/// The folder of one temperature's report: `oil_temperature_90degC` (characters other than
/// letters, digits, `.` and `-` left out).
pub(crate) fn run_folder(label: &str) -> String {
    let kept: String = label.chars().filter(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '-')).collect();
    format!("oil_temperature_{kept}")
}

/// The comparison of the runs' reports, `runs` as (temperature as written, in K, report), in the
/// scene's order.
/// Every run evaluates the same operating points, laws and formulations, so their records match
/// one to one.
pub(crate) fn build_oil_sweep(runs: &[(String, f64, Report)]) -> OilSweepReport {
    let (_, _, first) = &runs[0];
    let efficiency = first
        .efficiency
        .iter()
        .enumerate()
        .map(|(i, e)| {
            let at: Vec<&EfficiencyRecord> = runs.iter().map(|(_, _, r)| &r.efficiency[i]).collect();
            let budget = e.budget.is_some();
            OilSweepRow {
                law: e.law,
                label: e.label.clone(),
                formulation: e.formulation,
                pinion_torque: e.pinion_torque,
                pinion_speed: e.pinion_speed,
                mean_efficiency: at.iter().map(|r| Num(r.budget_mesh_efficiency())).collect(),
                power_loss: at.iter().map(|r| r.budget_mesh_loss()).collect(),
                // Every run has the same gearbox: each record has its budget or none has.
                total_loss: budget.then(|| at.iter().filter_map(|r| r.budget.as_ref().map(|b| b.total_loss)).collect()),
                total_efficiency: budget
                    .then(|| at.iter().filter_map(|r| r.budget.as_ref().map(|b| b.total_efficiency)).collect()),
            }
        })
        .collect();
    OilSweepReport {
        title: first.title.clone(),
        slug: first.slug.clone(),
        runs: runs
            .iter()
            .map(|(label, kelvin, r)| {
                let warnings = r.findings.iter().filter(|f| f.severity == Severity::Warning).count();
                OilRun {
                    label: label.clone(),
                    oil_temperature: Q::new(*kelvin, "K"),
                    folder: run_folder(label),
                    lubricant: r.lubricant.clone(),
                    warnings,
                    notes: r.findings.len() - warnings,
                }
            })
            .collect(),
        efficiency,
        loss_budget: first.loss_budget,
        speed_unit: first.speed_unit.clone(),
        torque_unit: first.torque_unit.clone(),
        unit_system: first.unit_system,
    }
}
