//! One value of the language checked and converted: its unit against the expected dimension, its
//! number finite, and the words and number formats the diagnostics use.

use super::ast::*;
use super::units::{self, Dimension, Scale, UnitError};
use crate::diagnostics::{Diagnostic, DiagnosticKind, Span};

/// Sweeps longer than this are refused (a typo in a step, not a study).
pub(crate) const MAX_SWEEP_LENGTH: usize = 100_000;

/// Evaluates a unit (None: dimensionless) and checks it against the expected dimension.
pub(crate) fn checked_scale(
    key: &str,
    unit: Option<&UnitExpr>,
    expected: Dimension,
    value_span: Span,
    errors: &mut Vec<Diagnostic>,
) -> Option<Scale> {
    let scale = match unit {
        None => Scale::ONE,
        Some(u) => match units::evaluate(u.factors.iter().map(|(n, _, e)| (n.as_str(), *e))) {
            Ok(s) => s,
            Err(e) => {
                let (index, hint) = match &e {
                    UnitError::Unknown { index, suggestion, .. } => (
                        *index,
                        match suggestion {
                            Some(s) => {
                                format!("did you mean `{s}`? `gearloss units` lists every unit")
                            }
                            None => "`gearloss units` lists every unit".to_string(),
                        },
                    ),
                    UnitError::OffsetInCompound { index, .. } => {
                        (*index, "write the temperature on its own, e.g. `90 degC`".into())
                    }
                    UnitError::ExponentOverflow { index } => {
                        (*index, "no physical quantity needs such powers: check the unit for a repeated factor".into())
                    }
                };
                let kind = match e {
                    UnitError::Unknown { .. } => DiagnosticKind::UnknownUnit,
                    UnitError::OffsetInCompound { .. } | UnitError::ExponentOverflow { .. } => {
                        DiagnosticKind::WrongDimension
                    }
                };
                errors.push(Diagnostic::new(kind, u.factors[index].1, e.to_string()).hint(hint));
                return None;
            }
        },
    };
    if scale.dimension != expected {
        let (span, reason) = match unit {
            None => (value_span, format!("`{key}` expects {}, but the value has no unit", a(expected.name()))),
            Some(u) => (
                u.span,
                format!("`{key}` expects {}, but `{}` is {}", a(expected.name()), u.text, a(scale.dimension.name())),
            ),
        };
        let hint = if expected == Dimension::NONE {
            format!("`{key}` is a plain number: drop the unit")
        } else {
            format!("use a unit of {} such as {}", expected.name(), super::units::example_units(expected))
        };
        errors.push(Diagnostic::new(DiagnosticKind::WrongDimension, span, reason).hint(hint));
        return None;
    }
    if let Some(u) = unit.filter(|_| expected == Dimension::TORQUE) {
        // J, kWh: the torque's SI dimension, but an energy (a torque is a force times a length).
        if let Some((name, span, _)) = u.factors.iter().find(|(n, _, _)| units::lookup(n).is_some_and(|d| d.energy)) {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::WrongDimension,
                    *span,
                    format!("`{key}` expects a torque, but `{name}` is an energy"),
                )
                .hint(format!(
                    "a torque is a force times a length: use {}",
                    super::units::example_units(Dimension::TORQUE)
                )),
            );
            return None;
        }
    }
    Some(scale)
}

pub(crate) fn finite(key: &str, x: f64, span: Span, errors: &mut Vec<Diagnostic>) -> Option<f64> {
    if x.is_finite() {
        Some(x)
    } else {
        let reason = if x.is_nan() {
            format!("`{key}` is NaN: not a number")
        } else {
            format!("`{key}` is infinite: not a finite number")
        };
        errors.push(
            Diagnostic::new(DiagnosticKind::OutOfRange, span, reason)
                .hint("give a finite number (within ±1.7e308, and within the quantity's plausible range)"),
        );
        None
    }
}

/// A single value in SI, and the text as written.
pub(crate) fn scalar(
    key: &str,
    value: &Value,
    expected: Dimension,
    errors: &mut Vec<Diagnostic>,
) -> Option<(f64, String)> {
    match &value.kind {
        ValueKind::Quantity { number, unit } => {
            let n = finite(key, *number, value.span, errors)?;
            let scale = checked_scale(key, unit.as_ref(), expected, value.span, errors)?;
            let si = finite(key, scale.to_si(n), value.span, errors)?;
            if !super::limits::plausible(key, si, value.span, errors) {
                return None;
            }
            let written = match unit {
                Some(u) => format!("{} {}", format_number(n), u.text),
                None => format_number(n),
            };
            Some((si, written))
        }
        _ => {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::WrongDimension,
                    value.span,
                    format!("`{key}` expects a single {}", expected.name()),
                )
                .hint(format!("write one value, e.g. `{key} = 1 {}`", expected.si_unit())),
            );
            None
        }
    }
}

/// "a length", "an angle".
pub(crate) fn a(noun: &str) -> String {
    match noun.chars().next() {
        Some('a' | 'e' | 'i' | 'o' | 'u') => format!("an {noun}"),
        _ => format!("a {noun}"),
    }
}

/// A number as a user would write it back: shortest round-trip form.
pub(crate) fn format_number(x: f64) -> String {
    if x != 0.0 && (x.abs() < 1e-3 || x.abs() >= 1e7) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}
