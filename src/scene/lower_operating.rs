//! The `operating` block: the pinion torque and speed sweeps, the oil temperature, the detail
//! points; and the limit on the summary rows a run writes.

use super::ast::*;
use super::fields::{positive, Fields};
use super::units::Dimension;
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::model::*;

const OPERATING_KEYS: &[&str] = &["pinion_torque", "pinion_speed", "oil_temperature", "detail_points"];
/// Most operating points a scene may name in `detail_points`.
pub const MAX_DETAIL_POINTS: usize = 20;
/// Most oil temperatures a scene may run at (each is a whole run of the scene).
pub(crate) const MAX_OIL_TEMPERATURES: usize = 25;

pub(super) fn lower_operating(block: &Block, errors: &mut Vec<Diagnostic>) -> Option<Operating> {
    let f = Fields::read("the `operating` block", block.span, &block.items, OPERATING_KEYS, &[], &[], errors);
    let torque: Option<Sweep<Torque>> = f.sweep("pinion_torque", "[100, 200] N*m", errors);
    let speed: Option<Sweep<AngularVelocity>> = f.sweep("pinion_speed", "1000 rpm", errors);
    let check = |key: &str, values: &[f64], span: Span, errors: &mut Vec<Diagnostic>| -> bool {
        match values.iter().find(|v| **v <= 0.0) {
            Some(_) => {
                errors.push(
                    Diagnostic::new(DiagnosticKind::OutOfRange, span, format!("`{key}` must be positive"))
                        .hint("the pinion drives: give a positive torque and speed"),
                );
                false
            }
            None => true,
        }
    };
    let torque = torque
        .filter(|t| check("pinion_torque", &t.values.iter().map(|v| v.value).collect::<Vec<_>>(), t.span, errors));
    let speed =
        speed.filter(|s| check("pinion_speed", &s.values.iter().map(|v| v.value).collect::<Vec<_>>(), s.span, errors));
    let (torque, speed) = (torque?, speed?);
    let count = torque.values.len() as u128 * speed.values.len() as u128;
    if count > MAX_OPERATING_POINTS as u128 {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                speed.span,
                format!(
                    "{} torques × {} speeds = {count} operating points, above the limit of {MAX_OPERATING_POINTS}",
                    torque.values.len(),
                    speed.values.len()
                ),
            )
            .hint("use fewer values, or split the map into several scenes (or shards: `gearloss run --shard K/N`)"),
        );
        return None;
    }
    let detail_points = detail_points(&f, count as usize, errors)?;
    let equilibrium = equilibrium_of(&f);
    let (oil_temperature, oil_temperatures) =
        if equilibrium.is_some() { (None, None) } else { oil_temperatures(&f, errors) };
    Some(Operating {
        pinion_torque: torque,
        pinion_speed: speed,
        oil_temperature,
        oil_temperatures,
        detail_points,
        equilibrium,
    })
}

/// Most summary rows a run may write (points × laws × formulations, and the dynamics rows): about
/// 20 GB of records.csv.
pub const MAX_RECORD_ROWS: u128 = 100_000_000;

pub(super) fn check_record_rows(problem: &crate::mesh::MeshProblem, errors: &mut Vec<Diagnostic>) {
    let a = &problem.analyses;
    let per_law = a.efficiency.as_ref().map_or(usize::from(a.friction_along_loa), |f| f.len().max(1));
    let dynamics = if a.dynamics { problem.dynamics.as_ref().map_or(0, |d| d.formulations.len()) } else { 0 };
    let per_point = (problem.friction.len() * per_law + dynamics) as u128;
    let rows = problem.operating.count() as u128 * per_point;
    if rows > MAX_RECORD_ROWS {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                problem.operating.pinion_speed.span,
                format!(
                    "{} operating points × {per_point} rows each (laws × formulations, dynamics) = {rows} summary rows, above the limit of {MAX_RECORD_ROWS}",
                    problem.operating.count()
                ),
            )
            .hint("fewer operating points or fewer laws; or split the study into several scenes"),
        );
    }
}

/// `detail_points = [1, 57]`: operating points (1-based, torque-major: every speed of the first
/// torque, then of the next; a pair's records.csv `point`) reported in full besides the default
/// ones, a pair's or each of a drive's stage meshes'; returned 0-based.
pub(super) fn detail_points(f: &Fields, count: usize, errors: &mut Vec<Diagnostic>) -> Option<Vec<usize>> {
    let Some((_, value)) = f.values.get("detail_points") else {
        return Some(Vec::new());
    };
    let (numbers, _, _, _) = super::sweeps::sweep_values("detail_points", value, Dimension::NONE, errors)?;
    let bad = |reason: String| {
        Diagnostic::new(DiagnosticKind::OutOfRange, value.span, reason).hint(format!(
            "list up to {MAX_DETAIL_POINTS} point numbers from 1 to {count} (1-based, torque-major: every speed of the first torque, then of the next), e.g. `detail_points = [1, {count}]`"
        ))
    };
    if numbers.len() > MAX_DETAIL_POINTS {
        errors.push(bad(format!(
            "`detail_points` lists {} points, above the limit of {MAX_DETAIL_POINTS}",
            numbers.len()
        )));
        return None;
    }
    match numbers.iter().find(|x| !(x.fract() == 0.0 && **x >= 1.0 && **x <= count as f64)) {
        Some(x) => {
            errors.push(bad(format!("`detail_points` names point {x}; the sweep has points 1 to {count}")));
            None
        }
        None => {
            if let Some(x) = numbers.iter().enumerate().find_map(|(i, x)| numbers[..i].contains(x).then_some(x)) {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::DuplicateKey,
                        value.span,
                        format!("`detail_points` names point {x} twice"),
                    )
                    .hint("name each point once"),
                );
                return None;
            }
            Some(numbers.iter().map(|x| *x as usize - 1).collect())
        }
    }
}

/// `oil_temperature = equilibrium`: where it is written (a pair's and a drive's alike).
pub(super) fn equilibrium_of(f: &Fields) -> Option<crate::diagnostics::Span> {
    f.values.get("oil_temperature").and_then(|(_, v)| match &v.kind {
        ValueKind::Call(c) if c.name.text == "equilibrium" && c.arguments.is_empty() => Some(v.span),
        _ => None,
    })
}

/// `oil_temperature = 90 degC`, or a list or range of temperatures the scene runs at one after the
/// other: the first value (at which the scene lowers) and, for two values or more, the sweep.
pub(super) fn oil_temperatures(
    f: &Fields,
    errors: &mut Vec<Diagnostic>,
) -> (Option<Given<ThermodynamicTemperature>>, Option<Sweep<ThermodynamicTemperature>>) {
    let Some((_, value)) = f.values.get("oil_temperature") else {
        return (None, None);
    };
    // (`equilibrium` is read before this where a scene may have it; here it is a drive cycle's.)
    if matches!(&value.kind, ValueKind::Call(c) if c.name.text == "equilibrium") {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                value.span,
                "`oil_temperature = equilibrium` puts each operating point at its own balance; over a drive cycle the sump is held at a given temperature or follows the cycle",
            )
            .hint("write `oil_temperature = 80 degC` (held over the cycle), or give the housing a `heat_capacity`: the sump then follows the drive cycle"),
        );
        return (None, None);
    }
    if !matches!(value.kind, ValueKind::List { .. } | ValueKind::Range { .. }) {
        return (positive(f.optional("oil_temperature", errors), "oil_temperature", errors), None);
    }
    let Some(sweep) = f.sweep::<ThermodynamicTemperature>("oil_temperature", "[60, 90] degC", errors) else {
        return (None, None);
    };
    let n = sweep.values.len();
    let written: Vec<String> = (0..n).map(|i| sweep.label(i)).collect();
    let bad = |reason: String, hint: &str| Diagnostic::new(DiagnosticKind::OutOfRange, value.span, reason).hint(hint);
    if n > MAX_OIL_TEMPERATURES {
        errors.push(bad(
            format!("`oil_temperature` lists {n} temperatures, above the limit of {MAX_OIL_TEMPERATURES}"),
            "each temperature is a whole run of the scene: give fewer, e.g. `oil_temperature = 40..120 degC step 20`",
        ));
        return (None, None);
    }
    if let Some(i) = (1..n).find(|i| written[..*i].contains(&written[*i])) {
        errors.push(bad(format!("`oil_temperature` lists {} twice", written[i]), "give each temperature once"));
        return (None, None);
    }
    let first = Given { value: sweep.values[0], written: written[0].clone(), span: sweep.span };
    (Some(first), (n > 1).then_some(sweep))
}

/// A sweep of oil temperatures moves the lubricant in temperature: only an oil given by grade or by
/// ν40, ν100 and ρ15 can be moved.
pub(super) fn check_oil_sweep(operating: &Operating, lubricant: Option<&Lubricant>, errors: &mut Vec<Diagnostic>) {
    let Some(sweep) = &operating.oil_temperatures else {
        return;
    };
    if lubricant.is_some_and(|l| l.oil.is_some()) {
        return;
    }
    let reason = match lubricant {
        None => "the scene sweeps `oil_temperature` but has no lubricant to read at those temperatures",
        Some(_) => "the lubricant's values hold at one temperature and cannot follow an `oil_temperature` sweep",
    };
    errors.push(Diagnostic::new(DiagnosticKind::OutOfRange, sweep.span, reason).hint(
        "give the oil by grade (`lubricant = iso_vg(100, mineral)`) or by `nu_40`, `nu_100` and `density_15`, or write one `oil_temperature`",
    ));
}
