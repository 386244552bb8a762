//! Reading one block's entries: unknown and duplicate names, missing keys, and values turned into
//! unit-checked quantities through the unit table.

use std::collections::BTreeMap;

use super::ast::*;
use super::units::{Dimension, SiQuantity};
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::model::{Given, Sweep};

pub(crate) use super::sweeps::sweep_values;
pub(crate) use super::values::{checked_scale, format_number, scalar};

/// The nearest of `candidates` to `name`, for "did you mean" hints.
pub(crate) fn nearest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    candidates
        .into_iter()
        .map(|c| (strsim::jaro_winkler(name, c), c))
        .filter(|(s, _)| *s > 0.7)
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, c)| c)
}

/// `what` is e.g. "key in the `gears` block": the name is put after its noun.
pub(crate) fn unknown_name(what: &str, name: &Name, allowed: &[&str]) -> Diagnostic {
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
pub(crate) struct Fields<'a> {
    pub what: String,
    pub span: Span,
    pub values: BTreeMap<&'a str, (&'a Name, &'a Value)>,
    pub blocks: Vec<&'a Block>,
    pub calls: Vec<&'a Call>,
}

impl<'a> Fields<'a> {
    /// Sorts `items`; unknown keys, blocks and calls and duplicate keys become diagnostics.
    pub(crate) fn read(
        what: impl Into<String>,
        span: Span,
        items: &'a [Item],
        keys: &[&str],
        blocks: &[&str],
        calls: &[&str],
        errors: &mut Vec<Diagnostic>,
    ) -> Fields<'a> {
        let mut f = Fields { what: what.into(), span, values: BTreeMap::new(), blocks: Vec::new(), calls: Vec::new() };
        // A name that is both a key and a block (`lubricant`) is listed once, as a block.
        let all: Vec<&str> = keys.iter().filter(|k| !blocks.contains(k)).chain(blocks).chain(calls).copied().collect();
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

    pub(crate) fn has(&self, key: &str) -> bool {
        self.values.contains_key(key)
    }

    pub(crate) fn missing(&self, key: &str, example: &str) -> Diagnostic {
        Diagnostic::new(DiagnosticKind::MissingKey, self.span, format!("{} has no `{key}`", self.what))
            .hint(format!("add `{key} = {example}`"))
    }

    /// A required quantity.
    pub(crate) fn required<Q: SiQuantity>(
        &self,
        key: &str,
        example: &str,
        errors: &mut Vec<Diagnostic>,
    ) -> Option<Given<Q>> {
        if !self.has(key) {
            errors.push(self.missing(key, example));
            return None;
        }
        self.optional(key, errors)
    }

    /// An optional quantity.
    pub(crate) fn optional<Q: SiQuantity>(&self, key: &str, errors: &mut Vec<Diagnostic>) -> Option<Given<Q>> {
        let (_, value) = self.values.get(key)?;
        let (si, written) = scalar(key, value, Q::DIMENSION, errors)?;
        Some(Given { value: Q::from_si(si), written, span: value.span })
    }

    /// An optional dimensionless number within `[lo, hi]`.
    pub(crate) fn number(&self, key: &str, lo: f64, hi: f64, errors: &mut Vec<Diagnostic>) -> Option<Given<f64>> {
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
    pub(crate) fn name(&self, key: &str, allowed: &[&str], errors: &mut Vec<Diagnostic>) -> Option<&'a Name> {
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
    pub(crate) fn sweep<Q: SiQuantity>(
        &self,
        key: &str,
        example: &str,
        errors: &mut Vec<Diagnostic>,
    ) -> Option<Sweep<Q>> {
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

/// A call's arguments read as the entries of a block (`dip(...)`, `bearing(...)`, `iso_vg(...)`);
/// `items` holds them for as long as the fields are read.
pub(super) fn call_fields<'a>(
    call: &Call,
    what: &str,
    keys: &[&str],
    items: &'a mut Vec<Item>,
    errors: &mut Vec<Diagnostic>,
) -> Fields<'a> {
    *items = call.arguments.iter().map(|(k, v)| Item::Assignment { key: k.clone(), value: v.clone() }).collect();
    Fields::read(what, call.span, items, keys, &[], &[], errors)
}

/// `g` when its value is above zero; otherwise an error naming `key` (and None).
pub(super) fn positive<T: super::units::SiQuantity>(
    g: Option<Given<T>>,
    key: &str,
    errors: &mut Vec<Diagnostic>,
) -> Option<Given<T>> {
    let g = g?;
    if g.value.si() > 0.0 {
        Some(g)
    } else {
        errors.push(
            Diagnostic::new(DiagnosticKind::OutOfRange, g.span, format!("`{key}` = {} must be positive", g.written))
                .hint(format!("give `{key}` a value above zero")),
        );
        None
    }
}
