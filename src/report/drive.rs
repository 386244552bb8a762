//! The report of a drive of several stages: what the drive is made of (stages, shafts, oil, laws),
//! every operating point's [`DrivePointReport`] (per law and formulation) with the readings it rests on,
//! the loss map over the ends' torque × speed, and the findings. Serde data; the renderers read it.

use serde::{Deserialize, Serialize};

use super::drive_inputs::{ShaftInputs, StageInputs};
pub use super::drive_map::{DriveMapBestReport, DriveMapReport};
use super::finding::Finding;
use super::number::DisplayUnit;
use crate::drive::ShaftEnd;
use crate::evaluate::drive::{DriveEvaluation, DriveRow};
use crate::model::{Scene, SceneDrive, Sweep};

pub use super::drive_point::DrivePointReport;

/// The thermal balance of one operating point, law and formulation (one sump).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct DriveBalanceReport {
    pub label: String,
    pub law: String,
    pub formulation: String,
    /// θ* (°C), P_V(θ*) = P_Q(θ*) (W); None (left out) without a balance up to 200 °C.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub temperature_c: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub loss: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dissipation: Option<f64>,
    /// "ok", "above the limit" or "no balance up to 200 °C", in words.
    pub status: String,
    /// In drive: the torque at the given end (N·m) that the box carries with the sump at the oil's
    /// limit, at this point's speed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rating: Option<f64>,
    /// The same with the sump at 95 °C (ISO/TR 14179-1's rating temperature).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rating_95: Option<f64>,
}

/// A step of the duty cycle.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct DriveDutyStep {
    /// `5 min, 1000 N*m, 1000 rpm`, as written.
    pub label: String,
    pub duration_s: f64,
    /// P_V at the scene's oil temperature (W).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub loss_at_oil_temperature: Option<f64>,
    /// P_V at the scene's oil temperature × the step's duration (J): the step's energy with the
    /// sump held at that temperature.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub energy_at_oil_temperature: Option<f64>,
    /// With a heat capacity: θ at the step's end (°C), energy lost and given off in the step (J).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub end_temperature_c: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub energy_lost: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub energy_dissipated: Option<f64>,
}

/// The duty cycle of a drive under its first law and formulation.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct DriveDutyReport {
    pub name: String,
    pub law: String,
    pub formulation: String,
    pub steps: Vec<DriveDutyStep>,
    /// The transient's highest θ (°C), its start (ambient, °C), the integrator's error estimate (K),
    /// or why it failed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_temperature_c: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start_temperature_c: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error_k: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub failure: Option<String>,
}

/// The report of a drive.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct DriveReport {
    pub title: String,
    pub slug: String,
    pub stages: Vec<StageInputs>,
    pub shafts: Vec<ShaftInputs>,
    /// ω_in/ω_out of the chain (signed: negative when the output turns the other way).
    pub overall_ratio: f64,
    /// The oil: temperature (°C), ν (mm²/s), ρ (kg/m³), η (mPa·s) as the losses read them.
    pub oil: Vec<(String, f64, String)>,
    pub laws: Vec<String>,
    /// Rows of the operating points (points × laws × formulations), all in drive_records.csv; the
    /// report shows the first `crate::evaluate::drive::DETAIL_ROWS` in full.
    pub rows: usize,
    /// The least and greatest η over every row where one end delivers, with the row's label, law
    /// and formulation; rows where both ends deliver.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub least_efficiency: Option<(f64, String)>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub greatest_efficiency: Option<(f64, String)>,
    pub both_ends_rows: usize,
    /// Rows where a stage's law leaves its validity range (drive_records.csv's
    /// `stage_<name>_validity_outside` say where).
    pub outside_rows: usize,
    /// Rows whose fixed point did not settle or whose books do not balance, and the first in words.
    #[serde(default, skip_serializing_if = "crate::evaluate::drive::is_zero")]
    pub unsettled_rows: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_unsettled: Option<String>,
    /// Values of the record files that are not finite numbers, and the first: its row in words
    /// and its column.
    #[serde(default, skip_serializing_if = "crate::evaluate::drive::is_zero")]
    pub non_finite_values: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_non_finite: Option<(String, String)>,
    /// At `oil_temperature = equilibrium`: rows whose sump settles above the limit or finds no
    /// balance, and the first in words.
    #[serde(default, skip_serializing_if = "crate::evaluate::drive::is_zero")]
    pub off_balance_rows: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_off_balance: Option<String>,
    pub torque_at: ShaftEnd,
    pub speed_at: ShaftEnd,
    /// The unit the scene wrote its speeds in, which report.md shows every speed in (report.json
    /// keeps rad/s, and rpm in the fields so named); left out when rpm.
    #[serde(default = "DisplayUnit::rpm", skip_serializing_if = "DisplayUnit::is_rpm")]
    pub speed_unit: DisplayUnit,
    /// The unit the scene wrote its torques in, likewise (report.json keeps N·m); left out when N·m.
    #[serde(default = "DisplayUnit::newton_metre", skip_serializing_if = "DisplayUnit::is_newton_metre")]
    pub torque_unit: DisplayUnit,
    /// The units report.md shows forces, powers, lengths and temperatures in: inch–pound when every
    /// stage's pair is sized in inches (as a pair's report), else SI; report.json stays SI.
    #[serde(default, skip_serializing_if = "super::number::UnitSystem::is_si")]
    pub unit_system: super::number::UnitSystem,
    pub points: Vec<DrivePointReport>,
    pub maps: Vec<DriveMapReport>,
    /// The housing as a thermal node (what, value, unit) and each point's balance.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub housing: Vec<(String, f64, String)>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub thermal: Vec<DriveBalanceReport>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub duty: Option<DriveDutyReport>,
    /// The vehicle over its drive cycle.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cycle: Option<super::drive_cycle::DriveCycleReport>,
    /// The analyses of one pair on the drive's stages' meshes, each with its own report folder.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub stage_pairs: Vec<super::drive_stage_pairs::StagePairReport>,
    pub findings: Vec<Finding>,
}

/// Inch–pound when every stage's pair is sized in inches, else SI.
fn drive_unit_system(drive: &SceneDrive) -> super::number::UnitSystem {
    use super::number::UnitSystem;
    let inch = |g: &crate::model::GearPair| super::scene::pair_unit_system(g) == UnitSystem::Inch;
    if !drive.pairs.is_empty() && drive.pairs.iter().all(inch) {
        UnitSystem::Inch
    } else {
        UnitSystem::Si
    }
}

/// The report of an evaluated drive scene.
pub fn build_drive_report(scene: &Scene, drive: &SceneDrive, eval: &DriveEvaluation) -> DriveReport {
    let layout = &drive.layout;
    let label = |r: &DriveRow| point_words(scene, drive, r.torque_index, r.speed_index);
    let laws: Vec<String> = scene.friction.iter().map(|l| l.label()).collect();
    let points: Vec<DrivePointReport> = eval
        .rows
        .iter()
        .zip(&eval.validity)
        .map(|(r, v)| DrivePointReport {
            label: label(r),
            law: laws[r.law_index].clone(),
            formulation: r.formulation.name().to_string(),
            total_loss: r.point.power_lost(),
            point: r.point.clone(),
            validity: v
                .iter()
                .map(|s| (s.outside, s.samples, s.intervals.first().map_or_else(String::new, |i| i.2.to_string())))
                .collect(),
            balance: r.balance.map(|b| super::drive_point::PointBalance::of(scene, b)),
        })
        .collect();
    let map = scene.analyses.efficiency_map.as_ref();
    let unit_system = drive_unit_system(drive);
    let units = super::units::Units::of_system(unit_system);
    let mut report = DriveReport {
        title: scene.title.clone(),
        slug: super::slug::slug(&scene.title),
        stages: super::drive_inputs::stage_inputs(drive, units),
        shafts: super::drive_inputs::shaft_inputs(layout),
        overall_ratio: crate::drive::walk::overall_ratio(layout),
        oil: super::drive_inputs::oil_rows(scene),
        laws: laws.clone(),
        rows: eval.tally.rows,
        least_efficiency: eval.tally.least.map(|(e, i)| (e, row_words(scene, drive, &laws, i))),
        greatest_efficiency: eval.tally.greatest.map(|(e, i)| (e, row_words(scene, drive, &laws, i))),
        both_ends_rows: eval.tally.both_ends,
        outside_rows: eval.tally.outside_rows,
        unsettled_rows: eval.tally.unsettled_rows,
        first_unsettled: eval.tally.first_unsettled.map(|i| row_words(scene, drive, &laws, i)),
        non_finite_values: eval.tally.non_finite,
        off_balance_rows: eval.tally.off_balance_rows,
        first_off_balance: eval.tally.first_off_balance.map(|i| row_words(scene, drive, &laws, i)),
        first_non_finite: eval.tally.first_non_finite.map(|(i, k)| {
            let column = crate::evaluate::drive_records::columns(drive).swap_remove(k).0;
            (row_words(scene, drive, &laws, i), column)
        }),
        torque_at: layout.operating.torque_at,
        speed_at: layout.operating.speed_at,
        speed_unit: unit_written(&scene.operating.pinion_speed, map.map(|m| &m.1), DisplayUnit::rpm),
        torque_unit: unit_written(&scene.operating.pinion_torque, map.map(|m| &m.0), DisplayUnit::newton_metre),
        unit_system,
        findings: super::drive_findings::findings(drive, &points, units),
        maps: super::drive_map::maps(scene, eval, &laws),
        housing: scene
            .housing
            .as_ref()
            .filter(|_| !eval.balances.is_empty())
            .map_or_else(Vec::new, super::drive_inputs::housing_rows),
        thermal: eval
            .balances
            .iter()
            .map(|b| DriveBalanceReport {
                label: points
                    .iter()
                    .zip(&eval.rows)
                    .find(|(_, r)| (r.torque_index, r.speed_index) == (b.torque_index, b.speed_index))
                    .map_or_else(String::new, |(p, _)| p.label.clone()),
                law: laws[b.law_index].clone(),
                formulation: b.formulation.name().to_string(),
                temperature_c: b.balance.temperature.map(|t| t - 273.15),
                loss: b.loss,
                dissipation: b.dissipation,
                status: b.balance.status.words().to_string(),
                rating: b.rating,
                rating_95: b.rating_95,
            })
            .collect(),
        duty: duty_report(scene, eval, &laws),
        cycle: match (&drive.cycle, &eval.cycle) {
            (Some(spec), Some(c)) => Some(super::drive_cycle::build_cycle_report(scene, drive, spec, c)),
            _ => None,
        },
        stage_pairs: Vec::new(),
        points,
    };
    let (inputs, rest) = super::drive_findings::report_findings(scene, drive, eval, &report, units);
    report.findings.splice(0..0, inputs);
    report.findings.extend(rest);
    report
}

/// The duty cycle's steps with their losses and, with a heat capacity, the transient.
fn duty_report(scene: &Scene, eval: &DriveEvaluation, laws: &[String]) -> Option<DriveDutyReport> {
    let (d, cycle, housing) = (eval.duty.as_ref()?, scene.duty_cycle.as_ref()?, scene.housing.as_ref()?);
    let transient = d.transient.as_ref().and_then(|t| t.as_ref().ok());
    let c = |k: f64| k - 273.15;
    Some(DriveDutyReport {
        name: cycle.name.clone(),
        law: laws[d.law_index].clone(),
        formulation: d.formulation.name().to_string(),
        steps: cycle
            .steps
            .iter()
            .enumerate()
            .map(|(k, s)| DriveDutyStep {
                label: s.label.clone(),
                duration_s: s.duration,
                loss_at_oil_temperature: d.fixed.as_ref().map(|f| f[k]),
                energy_at_oil_temperature: d.fixed.as_ref().map(|f| f[k] * s.duration),
                end_temperature_c: transient.map(|t| c(t.steps[k].temperature)),
                energy_lost: transient.map(|t| t.steps[k].energy_lost),
                energy_dissipated: transient.map(|t| t.steps[k].energy_dissipated),
            })
            .collect(),
        max_temperature_c: transient.map(|t| c(t.max_temperature(housing.ambient))),
        start_temperature_c: transient.map(|_| c(housing.ambient)),
        error_k: transient.map(|t| t.error),
        failure: d.transient.as_ref().and_then(|t| t.as_ref().err().cloned()),
    })
}

/// Row `i` of the operating points in words: its point, law and formulation.
fn row_words(scene: &Scene, drive: &SceneDrive, laws: &[String], i: usize) -> String {
    let formulations = scene.analyses.efficiency.clone().unwrap_or_default();
    let per_point = laws.len() * formulations.len();
    let (point, rest) = (i / per_point, i % per_point);
    let n = scene.operating.pinion_speed.values.len();
    format!(
        "{} ({}, {})",
        point_words(scene, drive, point / n, point % n),
        laws[rest / formulations.len()],
        formulations[rest % formulations.len()].name()
    )
}

/// An operating point in words, as the scene gives it: `T_out = 150 N·m, n_out = 500 rpm`.
pub(crate) fn point_words(scene: &Scene, drive: &SceneDrive, torque_index: usize, speed_index: usize) -> String {
    let op = &scene.operating;
    let end = |e: ShaftEnd| if e == ShaftEnd::Input { "in" } else { "out" };
    let ends = drive.layout.operating;
    // A scene of one pair gives its torque at the pinion gear (evaluate/drive_setup.rs).
    let torque_at = if drive.one_pair && ends.torque_at == ShaftEnd::Input { "pinion" } else { end(ends.torque_at) };
    format!(
        "T_{} = {} {}, n_{} = {} {}",
        torque_at,
        op.pinion_torque.written_values[torque_index],
        crate::quantity::shown_written_unit(&op.pinion_torque.unit),
        end(ends.speed_at),
        op.pinion_speed.written_values[speed_index],
        crate::quantity::shown_written_unit(&op.pinion_speed.unit)
    )
}

/// The unit the scene wrote a quantity in: its operating points' (`op`), else its map's, else
/// `default`.
fn unit_written<T>(op: &Sweep<T>, map: Option<&Sweep<T>>, default: fn() -> DisplayUnit) -> DisplayUnit {
    [Some(op), map].into_iter().flatten().find(|s| !s.values.is_empty()).map_or_else(default, DisplayUnit::of)
}
