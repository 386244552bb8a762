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
    let oil_temperature = match f.values.get("oil_temperature") {
        Some((_, v)) if matches!(v.kind, ValueKind::List { .. } | ValueKind::Range { .. }) => {
            errors.push(
                Diagnostic::new(DiagnosticKind::OutOfRange, v.span, "`oil_temperature` takes one value per scene")
                    .hint(
                    "write `oil_temperature = 90 degC`; for several temperatures run the scene once per temperature",
                ),
            );
            None
        }
        _ => positive(f.optional("oil_temperature", errors), "oil_temperature", errors),
    };
    Some(Operating { pinion_torque: torque, pinion_speed: speed, oil_temperature, detail_points })
}

/// Most summary rows a run may write (points × laws × formulations, and the dynamics rows): about
/// 20 GB of records.csv.
pub const MAX_RECORD_ROWS: u128 = 100_000_000;

pub(super) fn check_record_rows(scene: &Scene, errors: &mut Vec<Diagnostic>) {
    let a = &scene.analyses;
    let per_law = a.efficiency.as_ref().map_or(usize::from(a.friction_along_loa), |f| f.len().max(1));
    let dynamics = if a.dynamics { scene.dynamics.as_ref().map_or(0, |d| d.formulations.len()) } else { 0 };
    let per_point = (scene.friction.len() * per_law + dynamics) as u128;
    let rows = scene.operating.count() as u128 * per_point;
    if rows > MAX_RECORD_ROWS {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                scene.operating.pinion_speed.span,
                format!(
                    "{} operating points × {per_point} rows each (laws × formulations, dynamics) = {rows} summary rows, above the limit of {MAX_RECORD_ROWS}",
                    scene.operating.count()
                ),
            )
            .hint("fewer operating points or fewer laws; or split the study into several scenes"),
        );
    }
}

/// `detail_points = [1, 57]`: operating points (1-based, torque-major, as in records.csv) reported in
/// full besides the default ones; returned 0-based.
fn detail_points(f: &Fields, count: usize, errors: &mut Vec<Diagnostic>) -> Option<Vec<usize>> {
    let Some((_, value)) = f.values.get("detail_points") else {
        return Some(Vec::new());
    };
    let (numbers, _, _, _) = super::sweeps::sweep_values("detail_points", value, Dimension::NONE, errors)?;
    let bad = |reason: String| {
        Diagnostic::new(DiagnosticKind::OutOfRange, value.span, reason).hint(format!(
            "list up to {MAX_DETAIL_POINTS} point numbers from 1 to {count} (1-based, torque-major, as in records.csv), e.g. `detail_points = [1, {count}]`"
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
        None => Some(numbers.iter().map(|x| *x as usize - 1).collect()),
    }
}
