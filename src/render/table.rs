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

/// A law's label in words for legends: `coulomb(mu = 0.04)` → "Coulomb μ = 0.04",
/// `iso_14179_2(x_l = 0.846)` → "ISO/TR 14179-2 X_L = 0.846".
pub fn law_words(label: &str) -> String {
    let (name, args) = match label.split_once('(') {
        Some((n, a)) => (n, a.trim_end_matches(')')),
        None => (label, ""),
    };
    let title = crate::friction::catalog::LAWS
        .iter()
        .find(|l| l.id.name() == name)
        .map_or(name.to_string(), |l| l.title.split(" (").next().unwrap_or(l.title).to_string());
    let args: Vec<String> = args
        .split(", ")
        .filter(|a| !a.is_empty())
        .map(|a| {
            let (k, v) = a.split_once(" = ").unwrap_or((a, ""));
            let k = match k {
                "mu" => "μ",
                "x_l" => "X_L",
                "mu_boundary" => "μ_bl",
                "mu_ehl" => "μ_EHL",
                other => other,
            };
            format!("{k} = {v}")
        })
        .collect();
    if args.is_empty() {
        title
    } else {
        format!("{title} {}", args.join(", "))
    }
}
