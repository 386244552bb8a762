//! The report of a drive of several stages built from its evaluation ([`build_drive_report`]): the
//! data type is [`DriveReport`] (`super::drive_report`), named here as library users know it.

pub use super::drive_map::{DriveMapBestReport, DriveMapReport};
use super::number::DisplayUnit;
use crate::drive::ShaftEnd;
use crate::evaluate::drive::{DriveEvaluation, DriveRow};
use crate::model::{Scene, SceneDrive, Sweep};

pub use super::drive_point::DrivePointReport;
pub use super::drive_report::DriveReport;

/// The rows shown beyond the first [`crate::evaluate::drive::DETAIL_ROWS`]: every row of each
/// detail point that has one there ([`super::drive_report::ShownRows`]); None where there are none.
fn shown_rows(scene: &Scene, rows: usize) -> Option<super::drive_report::ShownRows> {
    let first = rows.min(crate::evaluate::drive::DETAIL_ROWS);
    let per_point = rows.checked_div(scene.operating.count())?;
    let past = crate::evaluate::plan::detail_points_past(first, per_point, &scene.operating.detail_points);
    let detail_points: Vec<usize> = past.map(|p| p + 1).collect();
    (!detail_points.is_empty()).then_some(super::drive_report::ShownRows { first, detail_points })
}

/// The report of an evaluated drive scene.
pub fn build_drive_report(scene: &Scene, drive: &SceneDrive, eval: &DriveEvaluation) -> DriveReport {
    let layout = &drive.layout;
    let label = |r: &DriveRow| point_words(scene, drive, r.torque_index, r.speed_index);
    let laws: Vec<String> = scene.friction.iter().map(|l| l.label()).collect();
    let (heat_balance, duty_cycle) = thermal_parts(scene, drive, eval, &laws);
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
    let unit_system = super::drive_inputs::drive_unit_system(drive);
    let units = super::units::Units::of_system(unit_system);
    let mut report = DriveReport {
        title: scene.title.clone(),
        slug: super::slug::slug(&scene.title),
        stages: super::drive_inputs::stage_inputs(drive, units),
        shafts: super::drive_inputs::shaft_inputs(layout),
        overall_ratio: crate::drive::walk::overall_ratio(layout),
        oil: super::drive_inputs::oil_rows(scene),
        inputs: super::drive_inputs::scene_inputs(scene, drive),
        stage_geometry: super::drive_geometry::stage_geometry(drive, scene.lubricant.as_ref(), &eval.loss_factors),
        lubricant: scene.lubricant.as_ref().filter(|_| !drive.pairs.is_empty()).map(|l| {
            let mesh = drive.mesh(0, Some(l));
            super::losses::lubricant_report(l, &mesh.tribology(mesh.reduced_modulus()))
        }),
        laws: laws.clone(),
        rows: eval.tally.rows,
        shown_rows: shown_rows(scene, eval.tally.rows),
        least_efficiency: eval.tally.least.map(|(e, i)| (e, row_words(scene, drive, &laws, i))),
        greatest_efficiency: eval.tally.greatest.map(|(e, i)| (e, row_words(scene, drive, &laws, i))),
        both_ends_rows: eval.tally.both_ends,
        outside_rows: eval.tally.outside_rows,
        unsettled_rows: eval.tally.unsettled_rows,
        first_unsettled: eval.tally.first_unsettled.map(|i| row_words(scene, drive, &laws, i)),
        non_finite_values: eval.tally.non_finite,
        off_balance_rows: eval.tally.off_balance_rows,
        first_off_balance: eval.tally.first_off_balance.map(|i| row_words(scene, drive, &laws, i)),
        implausible_rows: eval.tally.implausible_rows,
        first_implausible: eval.tally.first_implausible.as_ref().map(|(i, what)| {
            format!(
                "{}: {}",
                row_words(scene, drive, &laws, *i),
                super::drive_findings::implausible_words(drive, what, units)
            )
        }),
        first_non_finite: eval.tally.first_non_finite.map(|(i, k)| {
            let column = crate::evaluate::drive_records::columns(drive).swap_remove(k).0;
            (row_words(scene, drive, &laws, i), column)
        }),
        torque_at: layout.operating.torque_at,
        speed_at: layout.operating.speed_at,
        speed_unit: unit_written(&scene.operating.pinion_speed, map.map(|m| &m.1), DisplayUnit::rpm),
        torque_unit: unit_written(&scene.operating.pinion_torque, map.map(|m| &m.0), DisplayUnit::newton_metre),
        unit_system,
        findings: super::drive_findings::findings(
            (drive, scene.gearbox.is_some()),
            (&points, &eval.tally.static_loads, &|i| row_point(scene, drive, &laws, i)),
            units,
        ),
        maps: super::drive_map::maps(scene, eval, &laws),
        heat: super::thermal_sections::ThermalSections {
            housing: scene
                .housing
                .as_ref()
                .filter(|_| !eval.balances.is_empty() || eval.heat_balance.is_some())
                .map(super::thermal::housing_report),
            thermal: thermal_records(scene, drive, eval),
            heat_balance,
            duty_cycle,
        },
        cycle: match (&drive.cycle, &eval.cycle) {
            (Some(spec), Some(c)) => Some(super::drive_cycle::build_cycle_report(scene, drive, spec, c)),
            _ => None,
        },
        stage_pairs: Vec::new(),
        one_pair: drive.one_pair,
        loss_readings: super::loss_readings::loss_readings(&drive.layout),
        points,
    };
    let (inputs, rest) = super::drive_findings::report_findings(scene, drive, eval, &report, units);
    report.findings.splice(0..0, inputs);
    report.findings.extend(rest);
    report
}

/// The heat balance at the first row and the duty cycle, in a pair's report types; a duty cycle's
/// energy in and efficiency only where its steps give the input's torque and speed.
fn thermal_parts(
    scene: &Scene,
    drive: &SceneDrive,
    eval: &DriveEvaluation,
    laws: &[String],
) -> (Option<super::thermal::HeatBalanceReport>, Option<super::thermal::DutyCycleReport>) {
    let Some(housing) = scene.housing.as_ref() else { return (None, None) };
    let balance = eval.heat_balance.as_ref().map(|c| {
        let n = scene.operating.pinion_speed.values.len();
        let at = point_words(scene, drive, c.case / n, c.case % n);
        super::thermal::heat_balance_at(format!("{at}, {}, {}", laws[c.law_index], c.formulation.name()), c, housing)
    });
    let ends = drive.layout.operating;
    let at_input = ends.torque_at == ShaftEnd::Input && ends.speed_at == ShaftEnd::Input;
    let duty = eval.duty.as_ref().and_then(|d| super::thermal::duty_cycle_report(scene, d, housing, at_input));
    (balance, duty)
}

/// Each balance of the shown rows as a pair's report gives a point's: the given ends' torque and
/// speed, the point in words, the ratings' power at the torque's end.
fn thermal_records(scene: &Scene, drive: &SceneDrive, eval: &DriveEvaluation) -> Vec<super::thermal::ThermalRecord> {
    use super::number::Q;
    let op = &scene.operating;
    let torque_at = drive.layout.operating.torque_at;
    eval.balances
        .iter()
        .map(|b| {
            let row = eval.rows.iter().find(|r| (r.torque_index, r.speed_index) == (b.torque_index, b.speed_index));
            // The speed of the end the torque is given at (the ratings' power).
            let omega = row.map_or(0.0, |r| match torque_at {
                ShaftEnd::Input => r.point.input_speed.abs(),
                ShaftEnd::Output => r.point.output_speed.abs(),
            });
            let rating = |t: Option<f64>| {
                t.map(|t| super::thermal::Rating { torque: Q::new(t, "N*m"), power: Q::new(t * omega, "W") })
            };
            let d = &b.dissipation;
            super::thermal::ThermalRecord {
                case: b.torque_index * op.pinion_speed.values.len() + b.speed_index,
                point: Some(point_words(scene, drive, b.torque_index, b.speed_index)),
                law: scene.friction[b.law_index].law,
                label: scene.friction[b.law_index].label(),
                formulation: b.formulation,
                pinion_torque: Q::new(op.pinion_torque.values[b.torque_index].value, "N*m"),
                pinion_speed: Q::new(op.pinion_speed.values[b.speed_index].value, "rad/s"),
                oil_temperature: b.balance.temperature.map(|t| Q::new(t, "K")),
                status: b.balance.status,
                power_loss: Q::new(b.loss, "W"),
                dissipation: super::thermal::DissipationReport {
                    convection: Q::new(d.convection, "W"),
                    radiation: Q::new(d.radiation, "W"),
                    foundation: Q::new(d.foundation, "W"),
                    cooler: Q::new(d.cooler, "W"),
                    total: Q::new(d.total, "W"),
                },
                heat_transfer_coefficient: Q::new(b.heat_transfer_coefficient, "W/(m^2*K)"),
                thermal_rating: rating(b.rating),
                thermal_rating_95: rating(b.rating_95),
            }
        })
        .collect()
}

/// The operating point of row `i` (torque-major, then law, then formulation), in words.
fn row_point(scene: &Scene, drive: &SceneDrive, laws: &[String], i: usize) -> String {
    let per_point = laws.len() * scene.analyses.efficiency.as_ref().map_or(0, Vec::len);
    let point = i / per_point.max(1);
    let n = scene.operating.pinion_speed.values.len();
    point_words(scene, drive, point / n, point % n)
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
        "T_{} = {}, n_{} = {}",
        torque_at,
        op.pinion_torque.point_label(torque_index),
        end(ends.speed_at),
        op.pinion_speed.point_label(speed_index)
    )
}

/// The unit the scene wrote a quantity in: its operating points' (`op`), else its map's, else
/// `default`.
fn unit_written<T>(op: &Sweep<T>, map: Option<&Sweep<T>>, default: fn() -> DisplayUnit) -> DisplayUnit {
    [Some(op), map].into_iter().flatten().find(|s| !s.values.is_empty()).map_or_else(default, DisplayUnit::of)
}
