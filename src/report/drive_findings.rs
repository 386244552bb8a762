//! What a drive's report tells the reader beyond its numbers: a shaft whose axial force goes to its
//! first place by default, points where both ends deliver, a fixed point that did not settle, a
//! bearing beyond its static rating, and the laws' notes on each stage (an input read at a bound of
//! its range).

use super::bearing_checks::place_at;
use super::drive_point::DrivePointReport;
use super::drive_report::DriveReport;
use super::finding::{Finding, Severity};
use super::units::Units;
use crate::drive::PowerFlow;
use crate::evaluate::drive::DriveEvaluation;
use crate::evaluate::static_loads::StaticLoads;
use crate::model::{Scene, SceneDrive};

/// What the reader must know (`described_gearbox`: whether the scene has a `gearbox` block): how one
/// pair on a drive cycle was read as its one-stage drive, a drive without bearings (a note where one
/// pair was written without a gearbox), a shaft whose axial force goes to its first place by
/// default, points where both ends deliver, a fixed point that did not settle, a bearing beyond its
/// static rating at any row (`static_loads`, the tally's; `row_point` names a row's operating point).
pub(super) fn findings(
    (drive, described_gearbox): (&SceneDrive, bool),
    (points, static_loads, row_point): (&[DrivePointReport], &StaticLoads, &dyn Fn(usize) -> String),
    units: Units,
) -> Vec<Finding> {
    let layout = &drive.layout;
    let mut out = Vec::new();
    if drive.one_pair {
        // A pair on a drive cycle runs so; any scene of one pair lowers so for the one pipeline.
        let vehicle = if drive.cycle.is_some() { " with a vehicle" } else { "" };
        out.push(Finding {
            severity: Severity::Note,
            message: format!(
                "the scene is one pair{vehicle}: it runs as the one-stage drive it is, stage `{}` from shaft `{}` (the pinion's, the input: `pinion_torque` is the torque at the pinion gear, the input's that plus its shaft's losses, and `pinion_speed` the input's) to shaft `{}` (the wheel's, the output); a bearing's `at` is from the mesh mid-plane, and bearings written without `at` each carry an equal share of the gear force (README, \"One pair over a drive cycle\")",
                crate::scene::pair_stage::STAGE,
                layout.shafts[layout.input].name,
                layout.shafts[layout.output].name
            ),
        });
    }
    out.extend(mesh_findings(drive, units));
    // What a stage's kind notes of the shafts it sits on (a floating sun on one bearing place).
    let places = |j: usize| layout.shafts[j].bearings.len();
    for stage in &layout.stages {
        for (j, what, why) in stage.model().shaft_notes(stage, &places) {
            let shaft = &layout.shafts[j];
            out.push(Finding {
                severity: Severity::Note,
                message: format!(
                    "shaft `{}` carries {what} ({}): {why}",
                    shaft.name,
                    place_at(shaft.bearings[0].position, units)
                ),
            });
        }
    }
    // Every row's loads, from the tally: the worst row of each place beyond its static rating.
    let places = super::bearing_checks::drive_places(layout, units);
    out.extend(super::bearing_checks::overloaded(places, static_loads, row_point));
    for (j, shaft) in layout.shafts.iter().enumerate() {
        let helical = layout.stages.iter().any(|s| s.hand.is_some() && s.member_on(j).is_some());
        if helical && !shaft.locating_given && !shaft.bearings.is_empty() {
            out.push(Finding {
                severity: Severity::Warning,
                message: format!(
                    "shaft `{}`: no bearing says `locating`; the first place ({}) takes the axial force of its helical gears",
                    shaft.name,
                    place_at(shaft.bearings[0].position, units)
                ),
            });
        }
    }
    for p in points.iter().filter(|p| p.point.both_ends_deliver) {
        out.push(Finding {
            severity: Severity::Warning,
            message: format!(
                "{} ({}, {}): the {} does not cover the box's losses, so both ends deliver power; η is reported as 0",
                p.label,
                p.law,
                p.formulation,
                if p.point.flow == PowerFlow::Drive { "input" } else { "output" }
            ),
        });
    }
    for p in points.iter() {
        for ((outside, samples, reason), stage) in p.validity.iter().zip(&p.point.stages) {
            if *outside > 0 {
                out.push(Finding {
                    severity: Severity::Warning,
                    message: format!(
                        "{} ({}, {}): stage `{}`: the law is outside its validity range at {outside} of {samples} contacts along A–E ({reason})",
                        p.label, p.law, p.formulation, stage.name
                    ),
                });
            }
        }
    }
    if layout.shafts.iter().all(|s| s.bearings.is_empty()) {
        out.push(if drive.one_pair && !described_gearbox {
            // One pair written without a gearbox: what its own report always was, not an omission.
            Finding {
                severity: Severity::Note,
                message: "the scene describes no gearbox: the drive's losses are its mesh's only (no bearings, seals or churning; a `gearbox` block adds them)".to_string(),
            }
        } else {
            Finding {
                severity: Severity::Warning,
                message: "no shaft of the drive has bearings: its losses are the meshes', the seals' and the gears' no-load parts only (no bearing loads, no bearing losses, no shaft statics)".to_string(),
            }
        });
    }
    for p in points.iter().filter(|p| !p.point.settled()) {
        out.push(Finding {
            severity: Severity::Warning,
            message: format!("{} ({}, {}): {}", p.label, p.law, p.formulation, p.point.unsettled_words()),
        });
    }
    out
}

/// The laws' notes on each stage at the points shown (an input read at a bound of its range, e.g.
/// ISO/TR 14179-2's F_bt/b raised to 150 N/mm), one note a stage and kind: its figures the first
/// row's that has it (said where it has figures), then the operating points (of those shown) where
/// it holds, under each law.
pub(super) fn stage_notes(
    drive: &SceneDrive,
    rows: &[crate::evaluate::drive::DriveRow],
    validity: &[Vec<crate::evaluate::laws::ValiditySummary>],
    points: &[DrivePointReport],
) -> Vec<Finding> {
    use crate::evaluate::drive_cycle::note_kind;
    // (stage, kind, the first note, [(law, [point labels])]).
    type Group<'a> = (usize, String, String, Vec<(&'a str, Vec<&'a str>)>);
    let mut groups: Vec<Group> = Vec::new();
    for ((_, stages), p) in rows.iter().zip(validity).zip(points) {
        for (k, v) in stages.iter().enumerate() {
            for note in &v.notes {
                let kind = note_kind(note);
                let g = match groups.iter().position(|g| g.0 == k && g.1 == kind) {
                    Some(i) => &mut groups[i],
                    None => {
                        groups.push((k, kind, note.clone(), Vec::new()));
                        groups.last_mut().expect("just pushed")
                    }
                };
                let law = match g.3.iter().position(|(l, _)| *l == p.law) {
                    Some(i) => &mut g.3[i],
                    None => {
                        g.3.push((&p.law, Vec::new()));
                        g.3.last_mut().expect("just pushed")
                    }
                };
                if !law.1.contains(&p.label.as_str()) {
                    law.1.push(&p.label);
                }
            }
        }
    }
    let mut shown: Vec<&str> = points.iter().map(|p| p.label.as_str()).collect();
    shown.sort_unstable();
    shown.dedup();
    groups
        .into_iter()
        .map(|(k, _, note, laws)| {
            let mut at: Vec<&str> = laws.iter().flat_map(|(_, l)| l.iter().copied()).collect();
            at.sort_unstable();
            at.dedup();
            let under: Vec<String> = laws.iter().map(|(law, l)| format!("under {law}: {}", l.join("; "))).collect();
            // The kind groups notes that differ in their figures only: those shown are the first's.
            let figures = if note.chars().any(|c| c.is_ascii_digit()) { "figures at the first; " } else { "" };
            Finding {
                severity: Severity::Note,
                message: format!(
                    "stage `{}`: {note} ({figures}at {} of the {} operating points shown, {})",
                    drive.layout.stages[k].name,
                    at.len(),
                    shown.len(),
                    under.join("; ")
                ),
            }
        })
        .collect()
}

/// The rows beyond those the report shows that did not settle or do not balance their books, with
/// the first of them named.
/// `(unsettled, rows)`: how many rows did not settle, of how many; `first`: the first in words.
pub(super) fn unsettled_rows(
    points: &[DrivePointReport],
    (unsettled, rows): (usize, usize),
    first: Option<&String>,
) -> Option<Finding> {
    let shown = points.iter().filter(|p| !p.point.settled()).count();
    let first = first.filter(|_| unsettled > shown)?;
    Some(Finding {
        severity: Severity::Warning,
        message: format!(
            "{unsettled} of {rows} rows did not settle or do not balance their books (drive_records.csv: `passes` = 100, or P_source − P_sink ≠ the sum of the parts); the first: row {first}"
        ),
    })
}

/// Every warning on each stage's meshes' geometry, as a pair's report gives it of its own mesh
/// ([`super::mesh_checks::mesh_warnings`]), each naming its stage.
fn mesh_findings(drive: &SceneDrive, units: Units) -> Vec<Finding> {
    let mut out = Vec::new();
    for m in super::drive_geometry::stage_meshes(drive) {
        // A stage of several meshes names the mesh (`sun–planet`).
        let mesh_words = m.label.map_or_else(String::new, |l| format!(", {l} mesh"));
        out.extend(super::mesh_checks::mesh_warnings(&m.geometry, m.gears, units.length()).into_iter().map(|mut f| {
            f.message = format!("stage `{}`{mesh_words}: {}", m.stage, f.message);
            f
        }));
    }
    out
}

/// The findings of a drive's report beyond [`findings`]: those on the scene's inputs (blocks
/// nothing reads, the oil, the housing), which the report lists first, and the rest after
/// [`findings`]: the duty cycle's (as a pair's: no heat capacity, a failed transient, the limit
/// passed), the drive cycle's, each sump off its balance,
/// the laws' notes by stage, the rows outside a law's validity, unsettled or off balance beyond
/// those shown, values that are not finite numbers.
pub(super) fn report_findings(
    scene: &Scene,
    drive: &SceneDrive,
    eval: &DriveEvaluation,
    report: &DriveReport,
    units: Units,
) -> (Vec<Finding>, Vec<Finding>) {
    let mut rest = Vec::new();
    // The balances' and the duty cycle's warnings, as a pair's report gives them.
    let (records, duty) = (&report.heat.thermal, report.heat.duty_cycle.as_ref());
    rest.extend(super::thermal::thermal_findings(scene, records, duty, eval.duty.as_ref()));
    // What a scene's inputs are warned of, as a pair's report warns: blocks nothing reads, the
    // oil (its service limit, an implied density no oil has) and the housing's inputs.
    let mut inputs: Vec<Finding> = crate::scene::summary::unused_blocks(scene)
        .into_iter()
        .map(|message| Finding { severity: Severity::Warning, message })
        .collect();
    inputs.extend(super::oil_checks::oil_warnings(scene.lubricant.as_ref(), &scene.operating, units));
    inputs.extend(super::housing_checks::housing_findings(scene, units));
    if let Some(c) = &report.cycle {
        rest.extend(c.findings.iter().cloned());
    }
    rest.extend(stage_notes(drive, &eval.rows, &eval.validity, &report.points));
    // A stage's churning read beyond the speeds its model was tested at, as a pair's report warns.
    let cycle_speeds: Vec<f64> = match (&drive.cycle, &eval.cycle) {
        (Some(spec), Some(c)) => c
            .pieces
            .iter()
            .flat_map(|p| [p.from, p.to].map(|t| crate::evaluate::cycle_pieces::box_load(spec, p, t).1))
            .collect(),
        _ => Vec::new(),
    };
    rest.extend(super::churning_checks::churning_findings(scene, &cycle_speeds));
    let shown = report.points.iter().filter(|p| p.validity.iter().any(|v| v.0 > 0)).count();
    if report.outside_rows > shown {
        rest.push(Finding {
            severity: Severity::Warning,
            message: format!(
                "{} of {} rows have a stage whose law is outside its validity range (drive_records.csv: `stage_<name>_validity_outside`)",
                report.outside_rows, report.rows
            ),
        });
    }
    let unsettled =
        unsettled_rows(&report.points, (report.unsettled_rows, report.rows), report.first_unsettled.as_ref());
    rest.extend(unsettled);
    if let Some(first) = &report.first_off_balance {
        rest.push(Finding {
            severity: Severity::Warning,
            message: format!(
                "at `oil_temperature = equilibrium` {} of {} rows settle above the oil's limit or find no balance (drive_records.csv's `thermal_status`); the first: {first}",
                report.off_balance_rows, report.rows
            ),
        });
    }
    if let Some(first) = &report.first_implausible {
        rest.push(Finding {
            severity: Severity::Warning,
            message: format!(
                "{} of {} rows have a stage result no gear mesh can have or whose formulas no longer hold; the first, {first}",
                report.implausible_rows, report.rows
            ),
        });
    }
    if let Some((row, column)) = &report.first_non_finite {
        rest.push(Finding {
            severity: Severity::Warning,
            message: format!(
                "{} values in the record files are not finite numbers (empty cells in drive_records.csv, null in drive_records.jsonl); the first at {row}, column {column}",
                report.non_finite_values
            ),
        });
    }
    for path in super::non_finite::non_finite_paths(report) {
        rest.push(Finding { severity: Severity::Warning, message: format!("not a finite number: {path}") });
    }
    (inputs, rest)
}

/// What is implausible on a stage, in the words a pair's report gives it of its own mesh
/// (`super::plausibility`), naming the stage (and its mesh).
pub(super) fn implausible_words(
    drive: &SceneDrive,
    at: &crate::evaluate::drive_plausibility::StageImplausible,
    units: Units,
) -> String {
    use crate::evaluate::drive_plausibility::Implausibility;
    let len = units.length();
    let stage = &drive.layout.stages[at.stage].name;
    let mesh = at.mesh.as_ref().map_or_else(String::new, |m| format!(", {m} mesh"));
    let what = match &at.what {
        Implausibility::Efficiency(eta) => format!(
            "mesh efficiency η = {eta:.6} outside [0, 1] by more than rounding (4 ulps): the law gives friction no gear mesh can have here"
        ),
        Implausibility::HalfWidth { half_width, limit, u, named } => {
            super::plausibility::half_width_words((*half_width, *limit, *u), named, len)
        }
    };
    format!("stage `{stage}`{mesh}: {what}")
}

#[cfg(test)]
mod tests {
    /// Values of the record files that are not finite numbers reach the report as a warning
    /// naming the first row in words and its column (the tally's count from the shards, as a merge
    /// folds it).
    #[test]
    fn non_finite_record_values_are_a_finding() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/specs/ev_two_stage_reducer.gear");
        let scene = crate::check("ev.gear", &std::fs::read_to_string(path).unwrap()).unwrap();
        let drive = scene.drive.as_ref().unwrap();
        let tally = crate::evaluate::drive::DriveTally {
            rows: 12,
            non_finite: 3,
            first_non_finite: Some((4, 6)),
            ..Default::default()
        };
        let eval = crate::evaluate::drive::evaluate_drive_merged(&scene, drive, tally);
        let report = super::super::drive::build_drive_report(&scene, drive, &eval);
        let (row, column) = report.first_non_finite.clone().unwrap();
        assert_eq!(column, "input_torque_N_m");
        // Row 5 of torque-major rows (three torques at two speeds, one law, one formulation).
        assert!(row.starts_with("T_out = 1000 N·m, n_out = 500 rpm"), "{row}");
        let finding = report.findings.iter().find(|f| f.message.contains("not finite numbers")).unwrap();
        assert!(finding.message.starts_with("3 values in the record files"), "{}", finding.message);
        assert!(finding.message.contains(&format!("the first at {row}, column input_torque_N_m")));
        // None without them: the report and its JSON as before.
        let clean = super::super::drive::build_drive_report(
            &scene,
            drive,
            &crate::evaluate::drive::evaluate_drive_merged(&scene, drive, Default::default()),
        );
        assert!(clean.first_non_finite.is_none() && !clean.findings.iter().any(|f| f.message.contains("not finite")));
    }

    /// A scene of one pair lowered as its one-stage drive says so, with a vehicle only when it has one.
    #[test]
    fn a_pair_as_its_one_stage_drive_is_noted_as_it_is() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/specs/fzg_c14_gearbox.gear");
        let source = std::fs::read_to_string(path).unwrap();
        let ast = crate::parse("fzg.gear", &source).unwrap();
        let dir = std::path::Path::new(path).parent();
        let scene = crate::scene::lower::lower_as_one_stage_drive(&ast, dir).unwrap();
        let drive = scene.drive.as_ref().unwrap();
        let eval = crate::evaluate::drive::evaluate_drive_merged(&scene, drive, Default::default());
        let report = super::super::drive::build_drive_report(&scene, drive, &eval);
        let note = report.findings.iter().find(|f| f.message.contains("one-stage drive it is")).unwrap();
        assert!(note.message.starts_with("the scene is one pair: it runs as"), "{}", note.message);
    }
}
