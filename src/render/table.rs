//! Markdown table cells: fixed-decimal numbers, scaled quantities, significant digits, and the rows
//! and header of a pipe table. Shared by every Markdown section.

use std::fmt::Write;

use crate::report::number::Q;

pub fn scaled(q: &Q, factor: f64, d: usize) -> String {
    fixed(q.si() * factor, d)
}

pub fn row(out: &mut String, cells: &[String]) {
    let _ = writeln!(out, "| {} |", cells.join(" | "));
}

/// A pipe table's header row and rule; the cells are `&str` or `String` headings.
pub fn header<S: AsRef<str>>(out: &mut String, cells: &[S]) {
    let cells: Vec<&str> = cells.iter().map(AsRef::as_ref).collect();
    let _ = writeln!(out, "| {} |", cells.join(" | "));
    let _ = writeln!(out, "|{}|", cells.iter().map(|_| "---").collect::<Vec<_>>().join("|"));
}

pub use crate::numerics::rounding::{fixed, sig};

pub use crate::report::law_words::law_words;
