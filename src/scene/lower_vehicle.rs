//! A vehicle over a drive cycle: the `vehicle` and `drive_cycle` blocks of a drive's scene.
//!
//! ```text
//! vehicle "VW ID.3 Pro" {
//!     mass = 1976 kg  rotating_mass_factor = 1.07  wheel_radius = 0.335 m
//!     drag(coefficient = 0.267, frontal_area = 2.39 m^2, air_density = 1.225 kg/m^3)  rolling_resistance = 0.009
//!     # or: road_load(f0 = 165.34 N, f1 = 0.4677 N*s/m, f2 = 0.3205 N*s^2/m^2)
//!     recuperation_limit = 1200 N*m      # optional: the wheel torque the motor takes back
//!     final_ratio = 1                    # optional: a lossless final drive after the box
//! }
//! drive_cycle "WLTC class 3b" {
//!     trace = "cycles/wltc_3b.csv"       # next to the scene
//!     phase(name = "low", from = 0 s, to = 589 s)   # optional, any number
//!     start_temperature = 25 degC        # optional: where the sump's transient starts (default ambient)
//! }
//! ```

use std::path::Path;

use super::ast::*;
use super::fields::{call_fields, positive, Fields};
use crate::diagnostics::{Diagnostic, DiagnosticKind, Span};
use crate::model::{DriveCycleSpec, Force, Given, Length, Mass, MassDensity, MassPerLength, MassRate, Time, Torque};
use crate::vehicle::{Cycle, Phase, RoadLoad, Trace, Vehicle};

const VEHICLE: &[&str] =
    &["mass", "rotating_mass_factor", "wheel_radius", "rolling_resistance", "recuperation_limit", "final_ratio"];
const CYCLE: &[&str] = &["trace", "start_temperature"];
/// ISA sea-level air (kg/m³), when `drag(...)` gives no density.
const AIR_DENSITY: f64 = 1.225;

fn error(span: Span, reason: String, hint: &str) -> Diagnostic {
    Diagnostic::new(DiagnosticKind::OutOfRange, span, reason).hint(hint.to_string())
}

/// The vehicle and its cycle, when both blocks are there and read.
pub(super) fn lower_drive_cycle(
    vehicle: &Block,
    cycle: &Block,
    base_dir: Option<&Path>,
    errors: &mut Vec<Diagnostic>,
) -> Option<DriveCycleSpec> {
    let (car, written) = lower_vehicle(vehicle, errors)?;
    let f = Fields::read("the `drive_cycle` block", cycle.span, &cycle.items, CYCLE, &[], &["phase"], errors);
    let start: Option<Given<crate::model::ThermodynamicTemperature>> = f.optional("start_temperature", errors);
    let Some((_, file)) = f.values.get("trace") else {
        errors.push(f.missing("trace", "\"cycles/wltc_3b.csv\""));
        return None;
    };
    let ValueKind::Text(name) = &file.kind else {
        errors.push(
            Diagnostic::new(DiagnosticKind::WrongDimension, file.span, "`trace` expects a \"file name\"")
                .hint("write `trace = \"cycles/wltc_3b.csv\"`, a CSV file next to the scene"),
        );
        return None;
    };
    let trace = read_trace(name, file.span, base_dir, errors)?;
    let phases: Vec<Phase> = f.calls.iter().filter_map(|c| lower_phase(c, &trace, errors)).collect();
    if phases.len() != f.calls.len() {
        return None;
    }
    for (k, p) in phases.iter().enumerate() {
        if let Some(q) = phases[..k].iter().find(|q| q.name == p.name || (p.from < q.to && q.from < p.to)) {
            let what = if q.name == p.name { "is named twice" } else { "overlaps" };
            errors.push(error(
                f.calls[k].span,
                format!(
                    "the phase `{}` ({} s to {} s) {what}: `{}` ({} s to {} s)",
                    p.name, p.from, p.to, q.name, q.from, q.to
                ),
                "give each phase a name of its own and a stretch of the trace no other phase covers",
            ));
            return None;
        }
    }
    if let Some(t) = &start {
        let c = t.value.value - 273.15;
        if !(-50.0..=150.0).contains(&c) {
            errors.push(error(
                t.span,
                format!("a start temperature of {} is outside the plausible range", t.written),
                "the sump starts between -50 °C and 150 °C (the ambient, or a warm box)",
            ));
            return None;
        }
    }
    Some(DriveCycleSpec {
        vehicle_name: vehicle.label.as_ref().map_or_else(|| "vehicle".into(), |l| l.text.clone()),
        name: cycle.label.as_ref().map_or_else(|| "drive cycle".into(), |l| l.text.clone()),
        trace_file: name.clone(),
        cycle: Cycle { vehicle: car, trace, phases },
        start_temperature: start.map(|s| s.value.value),
        written,
        span: cycle.span,
    })
}

/// The trace file next to the scene; its faults at the `trace` value, naming the file's line and column.
fn read_trace(name: &str, span: Span, base_dir: Option<&Path>, errors: &mut Vec<Diagnostic>) -> Option<Trace> {
    let path = base_dir.map_or_else(|| Path::new(name).to_path_buf(), |d| d.join(name));
    let text = match super::source::read_text(&path, super::source::MAX_TABLE_BYTES) {
        Ok(t) => t,
        Err(e) => {
            errors.push(
                Diagnostic::new(DiagnosticKind::Undefined, span, format!("cannot read the trace `{name}`: {e}"))
                    .hint("a CSV file of at most 4 MiB and 36 000 samples; the path is relative to the folder of the scene file"),
            );
            return None;
        }
    };
    Trace::read(&text)
        .map_err(|e| {
            errors.push(error(span, format!("`{name}` line {}, column {}: {}", e.line, e.column, e.message), &e.hint));
        })
        .ok()
}

fn lower_phase(call: &Call, trace: &Trace, errors: &mut Vec<Diagnostic>) -> Option<Phase> {
    let mut items = Vec::new();
    let f = call_fields(call, "`phase(...)`", &["name", "from", "to"], &mut items, errors);
    let name = match f.values.get("name").map(|(_, v)| &v.kind) {
        Some(ValueKind::Text(n)) => n.clone(),
        _ => {
            errors.push(f.missing("name", "\"low\""));
            return None;
        }
    };
    let from: Option<Given<Time>> = f.required("from", "0 s", errors);
    let to: Option<Given<Time>> = f.required("to", "589 s", errors);
    let (from, to) = (from?.value.value, to?.value.value);
    let (first, last) = (trace.time[0], trace.time[trace.time.len() - 1]);
    if !(first <= from && from < to && to <= last) {
        errors.push(error(
            call.span,
            format!("the phase `{name}` from {from} s to {to} s does not lie inside the trace ({first} s to {last} s)"),
            "give `from` before `to`, both within the trace's times",
        ));
        return None;
    }
    Some(Phase { name, from, to })
}

/// The `vehicle` block, with what it gives as written.
fn lower_vehicle(block: &Block, errors: &mut Vec<Diagnostic>) -> Option<(Vehicle, Vec<(String, String)>)> {
    let f = Fields::read("the `vehicle` block", block.span, &block.items, VEHICLE, &[], &["drag", "road_load"], errors);
    let before = errors.len();
    let mass: Option<Given<Mass>> = positive(f.required("mass", "1976 kg", errors), "mass", errors);
    let radius: Option<Given<Length>> = positive(f.required("wheel_radius", "0.335 m", errors), "wheel_radius", errors);
    let factor = f.number("rotating_mass_factor", 1.0, 2.0, errors);
    let limit: Option<Given<Torque>> = positive(f.optional("recuperation_limit", errors), "recuperation_limit", errors);
    let final_ratio = f.number("final_ratio", 1e-3, 1e3, errors);
    let rolling = f.number("rolling_resistance", 0.0, 0.1, errors);
    let mut written: Vec<(String, String)> = Vec::new();
    let mut note = |key: &str, text: Option<&String>| {
        if let Some(t) = text {
            written.push((key.to_string(), t.clone()));
        }
    };
    note("mass", mass.as_ref().map(|g| &g.written));
    note("rotating_mass_factor", factor.as_ref().map(|g| &g.written));
    note("wheel_radius", radius.as_ref().map(|g| &g.written));
    note("rolling_resistance", rolling.as_ref().map(|g| &g.written));
    note("recuperation_limit", limit.as_ref().map(|g| &g.written));
    note("final_ratio", final_ratio.as_ref().map(|g| &g.written));
    let road = road_load(&f, block.span, rolling.as_ref().map(|r| r.value), &mut written, errors);
    let (mass, radius, road) = (mass?, radius?, road?);
    // A vehicle, not a gear: from a pedelec (10 kg) to a train car (10⁶ kg), wheels of 5 cm to 3 m.
    for (what, given, lo, hi, range) in [
        ("mass", (mass.value.value, &mass.written, mass.span), 10.0, 1e6, "10 kg to 1000 t"),
        ("wheel_radius", (radius.value.value, &radius.written, radius.span), 0.05, 3.0, "0.05 m to 3 m"),
    ] {
        let (value, written, span) = given;
        if !(lo..=hi).contains(&value) {
            errors.push(error(
                span,
                format!("a vehicle's {what} of {written} is outside the plausible range, {range}"),
                "check the value's unit and exponent",
            ));
        }
    }
    (errors.len() == before).then(|| {
        let vehicle = Vehicle {
            mass: mass.value.value,
            rotating_mass_factor: factor.map_or(1.0, |f| f.value),
            wheel_radius: radius.value.value,
            road_load: road,
            recuperation_limit: limit.map(|l| l.value.value),
            final_ratio: final_ratio.map_or(1.0, |r| r.value),
        };
        (vehicle, written)
    })
}

/// `road_load(f0, f1, f2)` or `drag(...)` with `rolling_resistance`: exactly one of them.
fn road_load(
    f: &Fields,
    span: Span,
    rolling: Option<f64>,
    written: &mut Vec<(String, String)>,
    errors: &mut Vec<Diagnostic>,
) -> Option<RoadLoad> {
    let find = |name: &str| f.calls.iter().find(|c| c.name.text == name);
    match (find("road_load"), find("drag")) {
        (Some(a), Some(b)) => {
            let later = if a.span.start > b.span.start { a.span } else { b.span };
            errors.push(
                Diagnostic::new(DiagnosticKind::DuplicateKey, later, "the vehicle gives both road-load forms")
                    .hint("give either `road_load(f0, f1, f2)` (coastdown coefficients) or `drag(...)` with `rolling_resistance`"),
            );
            None
        }
        (Some(call), None) => {
            if let Some((key, _)) = f.values.get("rolling_resistance") {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::DuplicateKey,
                        key.span,
                        "`rolling_resistance` with `road_load(...)`",
                    )
                    .hint("the coastdown coefficient f0 holds the rolling resistance: leave one out"),
                );
                return None;
            }
            let mut items = Vec::new();
            let g = call_fields(call, "`road_load(...)`", &["f0", "f1", "f2"], &mut items, errors);
            let f0: Option<Given<Force>> = g.required("f0", "165.34 N", errors);
            let f1: Option<Given<MassRate>> = g.required("f1", "0.4677 N*s/m", errors);
            let f2: Option<Given<MassPerLength>> = g.required("f2", "0.3205 N*s^2/m^2", errors);
            let (f0, f1, f2) = (f0?, f1?, f2?);
            if f0.value.value < 0.0 || f2.value.value < 0.0 {
                let bad =
                    if f0.value.value < 0.0 { (&f0.written, f0.span, "f0") } else { (&f2.written, f2.span, "f2") };
                errors.push(error(
                    bad.1,
                    format!("the coastdown coefficient {} = {} is negative", bad.2, bad.0),
                    "f0 (rolling) and f2 (aerodynamic) resist the motion: both ≥ 0 (f1 may take either sign)",
                ));
                return None;
            }
            written
                .push(("road_load".into(), format!("f0 = {}, f1 = {}, f2 = {}", f0.written, f1.written, f2.written)));
            Some(RoadLoad::Coastdown { f0: f0.value.value, f1: f1.value.value, f2: f2.value.value })
        }
        (None, Some(call)) => {
            let mut items = Vec::new();
            let g =
                call_fields(call, "`drag(...)`", &["coefficient", "frontal_area", "air_density"], &mut items, errors);
            let cw = g.number("coefficient", 0.05, 2.0, errors);
            if !g.has("coefficient") {
                errors.push(g.missing("coefficient", "0.267"));
            }
            let area: Option<Given<crate::model::Area>> =
                positive(g.required("frontal_area", "2.39 m^2", errors), "frontal_area", errors);
            let rho: Option<Given<MassDensity>> = positive(g.optional("air_density", errors), "air_density", errors);
            let Some(rolling) = rolling else {
                errors.push(f.missing("rolling_resistance", "0.009"));
                return None;
            };
            let (cw, area) = (cw?, area?);
            let rho_text =
                rho.as_ref().map_or_else(|| format!("{AIR_DENSITY} kg/m^3 (ISA sea level)"), |r| r.written.clone());
            written.push((
                "drag".into(),
                format!("coefficient = {}, frontal_area = {}, air_density = {rho_text}", cw.written, area.written),
            ));
            Some(RoadLoad::Physical {
                rolling,
                drag_coefficient: cw.value,
                frontal_area: area.value.value,
                air_density: rho.map_or(AIR_DENSITY, |r| r.value.value),
            })
        }
        (None, None) => {
            errors.push(
                Diagnostic::new(DiagnosticKind::MissingKey, span, "the vehicle has no road load")
                    .hint("add `drag(coefficient = 0.267, frontal_area = 2.39 m^2)` with `rolling_resistance = 0.009`, or `road_load(f0 = 165 N, f1 = 0.47 N*s/m, f2 = 0.32 N*s^2/m^2)`"),
            );
            None
        }
    }
}

/// The scene's cycle: a `vehicle` and a `drive_cycle` block, with or without the `drive_cycle`
/// analysis (without it the blocks are checked and kept, and the scene's check warns that no
/// analysis reads them, as it does for every other unused block); the analysis needs both blocks.
pub(super) fn cycle_of_scene(
    (vehicle, cycle): (Option<&&Block>, Option<&&Block>),
    analysis: Option<Span>,
    base_dir: Option<&Path>,
    errors: &mut Vec<Diagnostic>,
) -> Option<DriveCycleSpec> {
    let missing = |span: Span, reason: &str, hint: &str| {
        Diagnostic::new(DiagnosticKind::MissingKey, span, reason.to_string()).hint(hint.to_string())
    };
    match (vehicle, cycle, analysis) {
        (Some(v), Some(c), _) => lower_drive_cycle(v, c, base_dir, errors),
        (None, None, None) => None,
        (None, _, _) => {
            let span = cycle.map(|c| c.kind.span).or(analysis).expect("one of them is there");
            errors.push(missing(
                span,
                "a drive cycle needs the vehicle that drives it",
                "add `vehicle \"name\" { mass = 1976 kg  wheel_radius = 0.335 m  drag(...)  rolling_resistance = 0.009 }`",
            ));
            None
        }
        (Some(v), None, _) => {
            errors.push(missing(
                v.kind.span,
                "the vehicle has no `drive_cycle` to drive",
                "add `drive_cycle \"WLTC class 3b\" { trace = \"cycles/wltc_3b.csv\" }` and `drive_cycle` in `analyses`",
            ));
            None
        }
    }
}
