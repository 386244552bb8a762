//! Markdown table cells: fixed-decimal numbers, scaled quantities, significant digits, and the rows
//! and header of a pipe table. Shared by every Markdown section.

use super::markup::md;

use crate::report::number::Q;

pub(crate) fn scaled(q: &Q, factor: f64, d: usize) -> String {
    fixed(q.si() * factor, d)
}

pub(crate) fn row(out: &mut String, cells: &[String]) {
    md!(out, "| {} |", cells.join(" | "));
}

/// A pipe table's header row and rule; the cells are `&str` or `String` headings.
pub(crate) fn header<S: AsRef<str>>(out: &mut String, cells: &[S]) {
    let cells: Vec<&str> = cells.iter().map(AsRef::as_ref).collect();
    md!(out, "| {} |", cells.join(" | "));
    md!(out, "|{}|", cells.iter().map(|_| "---").collect::<Vec<_>>().join("|"));
}

pub(crate) use crate::numerics::rounding::{fixed, sig};

pub(crate) use crate::report::law_words::law_words;
