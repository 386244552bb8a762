//! Reading one block's entries: unknown and duplicate names, missing keys, and values turned into
//! unit-checked quantities through the unit table.

use std::collections::BTreeMap;

use super::ast::*;
use super::units::{self, Dimension, Scale, SiQuantity, UnitError};
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::model::{Given, Sweep};

/// Sweeps longer than this are refused (a typo in a step, not a study).
pub const MAX_SWEEP_LENGTH: usize = 100_000;

/// The nearest of `candidates` to `name`, for "did you mean" hints.
pub fn nearest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    candidates
        .into_iter()
        .map(|c| (strsim::jaro_winkler(name, c), c))
        .filter(|(s, _)| *s > 0.7)
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, c)| c)
}

/// `what` is e.g. "key in the `gears` block": the name is put after its noun.
pub fn unknown_name(what: &str, name: &Name, allowed: &[&str]) -> Diagnostic {
    let reason = match what.split_once(' ') {
        Some((noun, place)) => format!("unknown {noun} `{}` {place}", name.text),
        None => format!("unknown {what} `{}`", name.text),
    };
    let mut d = Diagnostic::new(DiagnosticKind::UnknownName, name.span, reason);
    if let Some(n) = nearest(&name.text, allowed.iter().copied()) {
        d = d.hint(format!("did you mean `{n}`?"));
    }
    if allowed.is_empty() {
        d.hint("nothing may be written here")
    } else {
        d.hint(format!("allowed here: {}", allowed.join(", ")))
    }
}

/// The entries of one block, sorted by kind, with every name checked against what is allowed.
pub struct Fields<'a> {
    pub what: String,
    pub span: Span,
    pub values: BTreeMap<&'a str, (&'a Name, &'a Value)>,
    pub blocks: Vec<&'a Block>,
    pub calls: Vec<&'a Call>,
}

impl<'a> Fields<'a> {
    /// Sorts `items`; unknown keys, blocks and calls and duplicate keys become diagnostics.
    pub fn read(
        what: impl Into<String>,
        span: Span,
        items: &'a [Item],
        keys: &[&str],
        blocks: &[&str],
        calls: &[&str],
        errors: &mut Vec<Diagnostic>,
    ) -> Fields<'a> {
        let mut f = Fields { what: what.into(), span, values: BTreeMap::new(), blocks: Vec::new(), calls: Vec::new() };
        let all: Vec<&str> = keys.iter().chain(blocks).chain(calls).copied().collect();
        for item in items {
            match item {
                Item::Assignment { key, value } if keys.contains(&key.text.as_str()) => {
                    if let Some((first, _)) = f.values.get(key.text.as_str()) {
                        errors.push(
                            Diagnostic::new(
                                DiagnosticKind::DuplicateKey,
                                key.span,
                                format!("`{}` is given twice in {}", key.text, f.what),
                            )
                            .hint(format!(
                                "`{}` was already given earlier in this block; keep one of them",
                                first.text
                            )),
                        );
                    } else {
                        f.values.insert(key.text.as_str(), (key, value));
                    }
                }
                Item::Block(b) if blocks.contains(&b.kind.text.as_str()) => f.blocks.push(b),
                Item::Call(c) if calls.contains(&c.name.text.as_str()) => f.calls.push(c),
                other => {
                    let what = match other {
                        Item::Assignment { .. } => format!("key in {}", f.what),
                        Item::Block(_) => format!("block in {}", f.what),
                        Item::Call(_) => format!("entry in {}", f.what),
                    };
                    errors.push(unknown_name(&what, other.head(), &all));
                }
            }
        }
        f
    }

    pub fn has(&self, key: &str) -> bool {
        self.values.contains_key(key)
    }

    pub fn missing(&self, key: &str, example: &str) -> Diagnostic {
        Diagnostic::new(DiagnosticKind::MissingKey, self.span, format!("{} has no `{key}`", self.what))
            .hint(format!("add `{key} = {example}`"))
    }

    /// A required quantity.
    pub fn required<Q: SiQuantity>(&self, key: &str, example: &str, errors: &mut Vec<Diagnostic>) -> Option<Given<Q>> {
        if !self.has(key) {
            errors.push(self.missing(key, example));
            return None;
        }
        self.optional(key, errors)
    }

    /// An optional quantity.
    pub fn optional<Q: SiQuantity>(&self, key: &str, errors: &mut Vec<Diagnostic>) -> Option<Given<Q>> {
        let (_, value) = self.values.get(key)?;
        let (si, written) = scalar(key, value, Q::DIMENSION, errors)?;
        Some(Given { value: Q::from_si(si), written, span: value.span })
    }

    /// An optional dimensionless number within `[lo, hi]`.
    pub fn number(&self, key: &str, lo: f64, hi: f64, errors: &mut Vec<Diagnostic>) -> Option<Given<f64>> {
        let (_, value) = self.values.get(key)?;
        let (x, written) = scalar(key, value, Dimension::NONE, errors)?;
        if !(lo..=hi).contains(&x) {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    value.span,
                    format!("`{key}` = {x} is outside [{lo}, {hi}]"),
                )
                .hint(format!("`{key}` must lie between {lo} and {hi}")),
            );
            return None;
        }
        Some(Given { value: x, written, span: value.span })
    }

    /// An optional name value (`load_sharing = equal`), checked against `allowed`.
    pub fn name(&self, key: &str, allowed: &[&str], errors: &mut Vec<Diagnostic>) -> Option<&'a Name> {
        let (_, value) = self.values.get(key)?;
        match &value.kind {
            ValueKind::Call(c) if c.arguments.is_empty() => {
                if allowed.is_empty() || allowed.contains(&c.name.text.as_str()) {
                    Some(&c.name)
                } else {
                    errors.push(unknown_name(&format!("value for `{key}`"), &c.name, allowed));
                    None
                }
            }
            _ => {
                errors.push(
                    Diagnostic::new(DiagnosticKind::WrongDimension, value.span, format!("`{key}` expects a name"))
                        .hint(if allowed.is_empty() {
                            format!("write `{key} = name`")
                        } else {
                            format!("one of: {}", allowed.join(", "))
                        }),
                );
                None
            }
        }
    }

    /// A quantity that may be swept: a single value, a list or a range.
    pub fn sweep<Q: SiQuantity>(&self, key: &str, example: &str, errors: &mut Vec<Diagnostic>) -> Option<Sweep<Q>> {
        if !self.has(key) {
            errors.push(self.missing(key, example));
            return None;
        }
        let (_, value) = self.values.get(key)?;
        sweep_values(key, value, Q::DIMENSION, errors).map(|(si, unit, written, factor)| Sweep {
            values: si.into_iter().map(Q::from_si).collect(),
            unit,
            factor,
            written_values: written,
            span: value.span,
        })
    }
}

/// Evaluates a unit (None: dimensionless) and checks it against the expected dimension.
pub fn checked_scale(
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
                };
                let kind = match e {
                    UnitError::Unknown { .. } => DiagnosticKind::UnknownUnit,
                    UnitError::OffsetInCompound { .. } => DiagnosticKind::WrongDimension,
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
    Some(scale)
}

fn finite(key: &str, x: f64, span: Span, errors: &mut Vec<Diagnostic>) -> Option<f64> {
    if x.is_finite() {
        Some(x)
    } else {
        errors.push(
            Diagnostic::new(DiagnosticKind::OutOfRange, span, format!("`{key}` is not a finite number"))
                .hint("numbers must lie within ±1.7e308"),
        );
        None
    }
}

/// A single value in SI, and the text as written.
pub fn scalar(key: &str, value: &Value, expected: Dimension, errors: &mut Vec<Diagnostic>) -> Option<(f64, String)> {
    match &value.kind {
        ValueKind::Quantity { number, unit } => {
            let n = finite(key, *number, value.span, errors)?;
            let scale = checked_scale(key, unit.as_ref(), expected, value.span, errors)?;
            let si = finite(key, scale.to_si(n), value.span, errors)?;
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
    let scale = checked_scale(key, unit.as_ref(), expected, value.span, errors)?;
    let mut si = Vec::with_capacity(numbers.len());
    let mut written = Vec::with_capacity(numbers.len());
    for (x, span) in numbers {
        let x = finite(key, x, span, errors)?;
        si.push(finite(key, scale.to_si(x), span, errors)?);
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

/// "a length", "an angle".
pub fn a(noun: &str) -> String {
    match noun.chars().next() {
        Some('a' | 'e' | 'i' | 'o' | 'u') => format!("an {noun}"),
        _ => format!("a {noun}"),
    }
}

/// A number as a user would write it back: shortest round-trip form.
pub fn format_number(x: f64) -> String {
    if x != 0.0 && (x.abs() < 1e-3 || x.abs() >= 1e7) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}
