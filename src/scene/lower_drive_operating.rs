//! A drive's `operating` block and map: torques and speeds given at the input or at the output.
//!
//! ```text
//! operating {
//!     output_torque = [-500, 150, 1000] N*m    # or input_torque; negative: the output drives (coast)
//!     output_speed  = [500, 1000] rpm          # or input_speed
//!     oil_temperature = 80 degC              # or `equilibrium`: each row at its own balance
//!     detail_points = [1, 4]                   # where the analyses of one pair run on the stages
//! }
//! ```

use super::ast::*;
use super::fields::{call_fields, Fields};
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::drive::{DriveOperating, ShaftEnd};
use crate::model::{AngularVelocity, Operating, Sweep, Torque, MAX_OPERATING_POINTS};

const KEYS: &[&str] =
    &["input_torque", "output_torque", "input_speed", "output_speed", "oil_temperature", "detail_points"];

/// The drive's `operating` block; with a drive cycle (`cycle`) torques and speeds may be left out
/// (the cycle gives them), the ends then the output's.
pub(super) fn lower_drive_operating(
    block: &Block,
    cycle: bool,
    errors: &mut Vec<Diagnostic>,
) -> Option<(Operating, DriveOperating)> {
    if let Some(key) = block.items.iter().map(Item::head).find(|k| k.text.starts_with("pinion_")) {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::UnknownName,
                key.span,
                format!("`{}` names one pair's pinion; a drive is driven at its ends", key.text),
            )
            .hint("write `input_torque` or `output_torque`, and `input_speed` or `output_speed`"),
        );
        return None;
    }
    let f = Fields::read("the `operating` block", block.span, &block.items, KEYS, &[], &[], errors);
    if cycle && !KEYS[..4].iter().any(|k| f.has(k)) {
        let (oil_temperature, oil_temperatures) = super::lower_operating::oil_temperatures(&f, errors);
        let operating = Operating {
            pinion_torque: Sweep {
                values: Vec::new(),
                unit: "N*m".into(),
                factor: 1.0,
                written_values: Vec::new(),
                span: block.span,
            },
            pinion_speed: Sweep {
                values: Vec::new(),
                unit: "rpm".into(),
                factor: 1.0,
                written_values: Vec::new(),
                span: block.span,
            },
            oil_temperature,
            oil_temperatures,
            detail_points: Vec::new(),
            equilibrium: None,
        };
        return Some((operating, DriveOperating { torque_at: ShaftEnd::Output, speed_at: ShaftEnd::Output }));
    }
    let (torque, torque_at) = at_one_end::<Torque>(&f, "torque", "[150, 1000] N*m", errors)?;
    let (speed, speed_at) = at_one_end::<AngularVelocity>(&f, "speed", "[500, 1000] rpm", errors)?;
    if let Some(bad) =
        speed.values.iter().position(|w| w.value == 0.0 || (speed_at == ShaftEnd::Output && w.value < 0.0))
    {
        errors.push(
            Diagnostic::new(DiagnosticKind::OutOfRange, speed.span, format!("speed {} cannot drive the box", speed.label(bad)))
                .hint("give speeds above zero (an output speed is a magnitude; a negative input speed turns every shaft the other way)"),
        );
        return None;
    }
    let count = torque.values.len() * speed.values.len();
    if count > MAX_OPERATING_POINTS {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                speed.span,
                format!("{count} operating points, above the limit of {MAX_OPERATING_POINTS}"),
            )
            .hint("use fewer values"),
        );
        return None;
    }
    // At `oil_temperature = equilibrium` every row is evaluated at its own balance (a drive cycle's
    // sump is held at a given temperature or follows the cycle: refused there).
    let equilibrium = if cycle { None } else { super::lower_operating::equilibrium_of(&f) };
    let (oil_temperature, oil_temperatures) = match equilibrium {
        Some(_) => (None, None),
        None => super::lower_operating::oil_temperatures(&f, errors),
    };
    let mut detail_points = super::lower_operating::detail_points(&f, count, errors)?;
    detail_points.sort_unstable();
    detail_points.dedup();
    let operating = Operating {
        pinion_torque: torque,
        pinion_speed: speed,
        oil_temperature,
        oil_temperatures,
        detail_points,
        equilibrium,
    };
    Some((operating, DriveOperating { torque_at, speed_at }))
}

/// `input_<what>` or `output_<what>`, exactly one of them.
fn at_one_end<Q: super::units::SiQuantity>(
    f: &Fields,
    what: &str,
    example: &str,
    errors: &mut Vec<Diagnostic>,
) -> Option<(Sweep<Q>, ShaftEnd)> {
    let (input, output) = (format!("input_{what}"), format!("output_{what}"));
    match (f.values.get(input.as_str()), f.values.get(output.as_str())) {
        (Some(_), Some((key, _))) => {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::DuplicateKey,
                    key.span,
                    format!("the {what} is given at both the input and the output"),
                )
                .hint(format!("give `{input}` or `{output}`: the other follows from the drive")),
            );
            None
        }
        (Some(_), None) => {
            f.sweep(&input, example, errors).and_then(|s| plausible(s, &input, errors)).map(|s| (s, ShaftEnd::Input))
        }
        (None, Some(_)) => {
            f.sweep(&output, example, errors).and_then(|s| plausible(s, &output, errors)).map(|s| (s, ShaftEnd::Output))
        }
        (None, None) => {
            errors.push(
                Diagnostic::new(DiagnosticKind::MissingKey, f.span, format!("the `operating` block gives no {what}"))
                    .hint(format!("add `{output} = {example}` (or `{input}`)")),
            );
            None
        }
    }
}

/// The plausible magnitudes of a drive's signed torques and speeds: those of one pair's
/// `pinion_torque` and `pinion_speed` ([`super::limits`]: up to 1e8 N·m, up to 10⁶ rpm), so that a
/// typo in a unit or an exponent is refused at its line instead of giving NaN losses.
const MAGNITUDES: [(&str, f64, &str); 2] = [("torque", 1e8, "1e8 N·m"), ("speed", 1.05e5, "1 000 000 rpm")];

/// `sweep` of `key` when every value's magnitude is within [`MAGNITUDES`].
fn plausible<Q: super::units::SiQuantity>(
    sweep: Sweep<Q>,
    key: &str,
    errors: &mut Vec<Diagnostic>,
) -> Option<Sweep<Q>> {
    let (_, most, shown) = MAGNITUDES.iter().find(|(w, _, _)| key.ends_with(w))?;
    match sweep.values.iter().position(|v| v.si().is_nan() || v.si().abs() > *most) {
        None => Some(sweep),
        Some(i) => {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    sweep.span,
                    format!(
                        "`{key}` = {:e} {} is outside the plausible range: up to {shown} either way",
                        sweep.written_values[i],
                        crate::quantity::shown_written_unit(&sweep.unit)
                    ),
                )
                .hint(
                    "check the value's unit and exponent (a drive's torques and speeds are held to one pair's ranges)",
                ),
            );
            None
        }
    }
}

/// `efficiency_map(output_torque = -1000..1000 N*m count 41, output_speed = 10..1500 rpm count 30)`:
/// torques of both signs (drive and coast halves), positive speeds.
pub(super) fn lower_drive_map(
    call: &Call,
    errors: &mut Vec<Diagnostic>,
) -> Option<(Sweep<Torque>, Sweep<AngularVelocity>, DriveOperating)> {
    let mut items = Vec::new();
    let f = call_fields(call, "`efficiency_map(...)`", &KEYS[..4], &mut items, errors);
    let (t, torque_at) = at_one_end::<Torque>(&f, "torque", "-1000..1000 N*m count 41", errors)?;
    let (s, speed_at) = at_one_end::<AngularVelocity>(&f, "speed", "10..1500 rpm count 30", errors)?;
    let max = super::lower_gearbox::MAX_MAP_VALUES;
    if !(2..=max).contains(&t.values.len())
        || !(2..=max).contains(&s.values.len())
        || s.values.iter().any(|w| w.value <= 0.0)
    {
        errors.push(
            Diagnostic::new(DiagnosticKind::OutOfRange, call.span, format!("the map needs 2 to {max} torques and 2 to {max} positive speeds"))
                .hint("write `efficiency_map(output_torque = -1000..1000 N*m count 41, output_speed = 10..1500 rpm count 30)`"),
        );
        return None;
    }
    Some((t, s, DriveOperating { torque_at, speed_at }))
}
