//! The sweep as a whole: where its record files are, its extremes over every operating point, and
//! what the report leaves out of a large sweep (serde data).

use serde::{Deserialize, Serialize};

use super::finding::{Finding, Severity};
use super::number::{Num, Q};
use crate::evaluate::tally::AtPoint;
use crate::evaluate::{Plan, Tally};

/// The record files of the run.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct RecordsReport {
    pub csv: String,
    pub jsonl: String,
    /// Rows in each file (the CSV has a header line more).
    pub rows: usize,
    pub operating_points: usize,
    /// Operating points reported in full in report.md and report.json.
    pub reported_in_full: usize,
    /// Values that are not finite numbers (empty CSV cells, `null` in JSON Lines).
    pub non_finite_values: usize,
}

/// A value at an operating point (1-based, as in the record files), with the point's torque and
/// speed where a headline names it.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ValueAt<V> {
    pub value: V,
    pub point: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pinion_torque: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pinion_speed: Option<Q>,
}

/// Extremes of one law and formulation over every operating point.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct SweepExtremesReport {
    pub label: String,
    pub formulation: String,
    pub min_efficiency: Option<ValueAt<Num>>,
    pub max_efficiency: Option<ValueAt<Num>>,
    pub max_power_loss: Option<ValueAt<Q>>,
}

/// One dynamic formulation over every operating point.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct SweepDynamicsReport {
    pub formulation: String,
    pub unstable_points: usize,
    pub max_spectral_radius: Option<ValueAt<Num>>,
}

/// Over every operating point of a sweep: exact extremes over the evaluated points.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct SweepReport {
    pub operating_points: usize,
    pub efficiency: Vec<SweepExtremesReport>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub dynamics: Vec<SweepDynamicsReport>,
}

/// The record files: `records.csv` and `records.jsonl`.
pub(crate) use crate::evaluate::record_files::{RECORDS_CSV, RECORDS_JSONL};

pub(crate) fn records_report(tally: &Tally, plan: &Plan) -> Option<RecordsReport> {
    (tally.rows > 0).then_some(RecordsReport {
        csv: RECORDS_CSV.into(),
        jsonl: RECORDS_JSONL.into(),
        rows: tally.rows,
        operating_points: tally.points,
        reported_in_full: plan.detail.len(),
        non_finite_values: tally.non_finite,
    })
}

fn num(a: Option<AtPoint>) -> Option<ValueAt<Num>> {
    a.map(|(v, k)| ValueAt { value: Num(v), point: k + 1, pinion_torque: None, pinion_speed: None })
}

/// An efficiency extreme with its point's torque and speed (the headline names them).
fn efficiency_at(op: &crate::model::Operating, a: Option<AtPoint>) -> Option<ValueAt<Num>> {
    a.map(|(v, k)| {
        let s = crate::evaluate::state_at(op, k);
        ValueAt {
            value: Num(v),
            point: k + 1,
            pinion_torque: Some(Q::new(s.pinion_torque, "N*m")),
            pinion_speed: Some(Q::new(s.pinion_speed, "rad/s")),
        }
    })
}

pub(crate) fn sweep_report(tally: &Tally, plan: &Plan, op: &crate::model::Operating) -> Option<SweepReport> {
    (plan.count() > 1 && tally.rows > 0).then(|| SweepReport {
        operating_points: tally.points,
        efficiency: tally
            .extremes
            .iter()
            .map(|e| SweepExtremesReport {
                label: e.label.clone(),
                formulation: e.formulation.clone(),
                min_efficiency: efficiency_at(op, e.min_efficiency),
                max_efficiency: efficiency_at(op, e.max_efficiency),
                max_power_loss: e.max_power_loss.map(|(v, k)| ValueAt {
                    value: Q::new(v, "W"),
                    point: k + 1,
                    pinion_torque: None,
                    pinion_speed: None,
                }),
            })
            .collect(),
        dynamics: tally
            .dynamics
            .iter()
            .map(|d| SweepDynamicsReport {
                formulation: d.formulation.clone(),
                unstable_points: d.unstable_points,
                max_spectral_radius: num(d.max_spectral_radius),
            })
            .collect(),
    })
}

/// Whether the sweep gets map plots: at least this many values of both torque and speed.
pub(crate) const MAP_MIN_VALUES: usize = 4;

pub(crate) fn has_map(plan: &Plan) -> bool {
    plan.torques >= MAP_MIN_VALUES && plan.speeds >= MAP_MIN_VALUES
}

/// What the reader must know about the sweep as a whole: values that are not numbers, and what a
/// large sweep's report leaves to the record files.
pub(crate) fn sweep_findings(tally: &Tally, plan: &Plan) -> Vec<Finding> {
    let mut out = Vec::new();
    if let Some((k, column)) = &tally.first_non_finite {
        out.push(Finding {
            severity: Severity::Warning,
            message: format!(
                "{} values in the record files are not finite numbers (empty cells in {RECORDS_CSV}, null in {RECORDS_JSONL}); the first at operating point {}, column {column}",
                tally.non_finite,
                k + 1
            ),
        });
    }
    if !plan.everything_in_detail() && tally.rows > 0 {
        out.push(Finding {
            severity: Severity::Note,
            message: format!(
                "{} of {} operating points are reported in full here; the tables and plots keep a bounded set, and {RECORDS_CSV} / {RECORDS_JSONL} hold every point",
                plan.detail.len(),
                plan.count()
            ),
        });
    }
    out
}

/// Mean |μ| of every composite law at the kept points, one per point and law (the efficiency rows of
/// one law repeat it per formulation), for the composite plot.
pub(crate) fn composite_mu(problem: &crate::mesh::MeshProblem, tally: &Tally) -> Vec<(usize, f64, f64, String, f64)> {
    let mut out: Vec<(usize, f64, f64, String, f64)> = Vec::new();
    let mut last: Option<(usize, usize)> = None;
    for r in &tally.kept {
        let Some(i) = r.law_index else { continue };
        if problem.friction[i].law != crate::friction::catalog::LawId::Composite || last == Some((r.point, i)) {
            continue;
        }
        last = Some((r.point, i));
        if let Some(mu) = r.mean_abs_mu {
            out.push((r.torque_index, r.pinion_torque, r.pinion_speed, r.label.clone(), mu));
        }
    }
    out
}
