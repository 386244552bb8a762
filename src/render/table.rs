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

/// Six significant digits, for the SI column of the inputs.
pub fn sig(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let s = format!("{x:.5e}");
    let v: f64 = s.parse().unwrap_or(x);
    if (1e-3..1e6).contains(&v.abs()) {
        let decimals = (5 - v.abs().log10().floor() as i32).max(0) as usize;
        let t = format!("{v:.decimals$}");
        if t.contains('.') {
            t.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            t
        }
    } else {
        match s.split_once('e') {
            Some((mantissa, exp)) if mantissa.contains('.') => {
                format!("{}e{exp}", mantissa.trim_end_matches('0').trim_end_matches('.'))
            }
            _ => s,
        }
    }
}

pub use crate::report::law_words::law_words;
