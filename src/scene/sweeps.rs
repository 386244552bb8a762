//! Sweep values: a single value, a list `[a, b] unit` or a range `a..b unit step s | count n`, each
//! value checked finite and converted to SI through the unit table.

use super::ast::*;
use super::units::Dimension;
use super::values::{a, checked_scale, finite, MAX_SWEEP_LENGTH};
use crate::diagnostics::{Diagnostic, DiagnosticKind, Span};

/// The values of a single value, list or range: (SI values, unit as written, values as written).
pub(crate) fn sweep_values(
    key: &str,
    value: &Value,
    expected: Dimension,
    errors: &mut Vec<Diagnostic>,
) -> Option<(Vec<f64>, String, Vec<f64>, f64)> {
    let (numbers, unit): (Vec<(f64, Span)>, &Option<UnitExpr>) = match &value.kind {
        ValueKind::Quantity { number, unit } => (vec![(*number, value.span)], unit),
        ValueKind::List { items, unit } => {
            let mut numbers = Vec::new();
            for item in items {
                match item {
                    ListItem::Number(x, span) => numbers.push((*x, *span)),
                    ListItem::Name(n) => {
                        errors.push(
                            Diagnostic::new(
                                DiagnosticKind::WrongDimension,
                                n.span,
                                format!("`{key}` lists numbers, not names"),
                            )
                            .hint("write the values as numbers with one unit after the list, e.g. `[100, 1000] rpm`"),
                        );
                        return None;
                    }
                }
            }
            if numbers.len() > MAX_SWEEP_LENGTH {
                // The opening bracket: a span over the whole list would print every line of it.
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::OutOfRange,
                        Span::new(value.span.start, value.span.start + 1),
                        format!("`{key}` lists {} values, above the limit of {MAX_SWEEP_LENGTH}", numbers.len()),
                    )
                    .hint("a sweep holds at most that many values; split the study into several scenes or use shards"),
                );
                return None;
            }
            if numbers.is_empty() {
                errors.push(
                    Diagnostic::new(DiagnosticKind::OutOfRange, value.span, format!("`{key}` is an empty list"))
                        .hint("give at least one value"),
                );
                return None;
            }
            (numbers, unit)
        }
        ValueKind::Range { from, to, unit, step } => (range_values(key, *from, *to, step, value.span, errors)?, unit),
        _ => {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::WrongDimension,
                    value.span,
                    format!("`{key}` expects {}", a(expected.name())),
                )
                .hint("write a value, a list `[a, b] unit` or a range `a..b unit step s`"),
            );
            return None;
        }
    };
    // What is wrong with a number shows before its missing unit: NaN and infinities, and a sign
    // no unit could mend (`pinion_torque = -80` said only "no unit").
    for (x, span) in &numbers {
        finite(key, *x, *span, errors)?;
    }
    if unit.is_none() && expected != Dimension::NONE && super::limits::positive(key) {
        if let Some((x, span)) = numbers.iter().find(|(x, _)| *x < 0.0) {
            let example = super::units::example_units(expected);
            let unit = example.split(',').next().unwrap_or_default();
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    *span,
                    format!("`{key}` = {} is negative, and has no unit", super::values::format_number(*x)),
                )
                .hint(format!("`{key}` is zero or more, written with its unit, e.g. `{key} = 100 {unit}`")),
            );
            return None;
        }
    }
    let scale = checked_scale(key, unit.as_ref(), expected, value.span, errors)?;
    let mut si = Vec::with_capacity(numbers.len());
    let mut written = Vec::with_capacity(numbers.len());
    for (x, span) in numbers {
        let x = finite(key, x, span, errors)?;
        let v = finite(key, scale.to_si(x), span, errors)?;
        if !super::limits::plausible(key, v, span, errors) {
            return None;
        }
        si.push(v);
        written.push(x);
    }
    let unit_text = unit.as_ref().map_or(String::new(), |u| u.text.clone());
    Some((si, unit_text, written, scale.factor))
}

fn range_values(
    key: &str,
    from: f64,
    to: f64,
    step: &Option<RangeStep>,
    span: Span,
    errors: &mut Vec<Diagnostic>,
) -> Option<Vec<(f64, Span)>> {
    let from = finite(key, from, span, errors)?;
    let to = finite(key, to, span, errors)?;
    if to < from {
        errors.push(
            Diagnostic::new(DiagnosticKind::OutOfRange, span, format!("range {from}..{to} runs backwards"))
                .hint("write the smaller value first"),
        );
        return None;
    }
    let bad = |errors: &mut Vec<Diagnostic>, s: Span, reason: String| {
        errors.push(Diagnostic::new(DiagnosticKind::OutOfRange, s, reason).hint(format!(
            "a sweep holds 1 to {MAX_SWEEP_LENGTH} values: `a..b unit step s` (s > 0) or `a..b unit count n` (n ≥ 2)"
        )));
    };
    let values: Vec<f64> = match step {
        None | Some(RangeStep::Count(..)) => {
            let (n, s) = match step {
                Some(RangeStep::Count(n, s)) => (*n, *s),
                _ => (11.0, span),
            };
            if !(n >= 2.0 && n <= MAX_SWEEP_LENGTH as f64 && n.fract() == 0.0) {
                bad(errors, s, format!("count {n} is not a whole number from 2 to {MAX_SWEEP_LENGTH}"));
                return None;
            }
            let n = n as usize;
            (0..n).map(|i| from + (to - from) * i as f64 / (n - 1) as f64).collect()
        }
        Some(RangeStep::Step(st, s)) => {
            if st.is_nan() || *st <= 0.0 {
                bad(errors, *s, format!("range step {st} is not positive"));
                return None;
            }
            let count = ((to - from) / st + 1e-9).floor() + 1.0;
            if count.is_nan() || count > MAX_SWEEP_LENGTH as f64 {
                bad(errors, *s, format!("range step {st} gives {count} values"));
                return None;
            }
            (0..count as usize).map(|i| from + st * i as f64).collect()
        }
    };
    Some(values.into_iter().map(|v| (v, span)).collect())
}
