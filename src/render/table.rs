//! Markdown table cells: fixed-decimal numbers, scaled quantities, significant digits, and the rows
//! and header of a pipe table. Shared by every Markdown section.

use std::fmt::Write;

use crate::report::number::Q;

/// Writes `x` with `d` decimals; non-finite values are written as `—` (and listed in the findings).
pub fn fixed(x: f64, d: usize) -> String {
    if x.is_finite() {
        let s = format!("{x:.d$}");
        if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
            s[1..].to_string()
        } else {
            s
        }
    } else {
        "—".into()
    }
}

pub fn scaled(q: &Q, factor: f64, d: usize) -> String {
    fixed(q.si() * factor, d)
}

pub fn row(out: &mut String, cells: &[String]) {
    let _ = writeln!(out, "| {} |", cells.join(" | "));
}

pub fn header(out: &mut String, cells: &[&str]) {
    let _ = writeln!(out, "| {} |", cells.join(" | "));
    let _ = writeln!(out, "|{}|", cells.iter().map(|_| "---").collect::<Vec<_>>().join("|"));
}

pub use crate::numerics::rounding::sig;

pub use crate::report::law_words::law_words;
