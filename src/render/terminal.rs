//! What `gearloss run` prints when it is done: the answer (the report's headline), how many
//! warnings and notes the report has with the first warnings, and where the report is.

use super::markup::counted;
use crate::report::{Report, Severity};

/// Warnings printed in full; the rest are counted.
pub const FIRST_WARNINGS: usize = 3;

/// The terminal summary of one report (`label`: its oil temperature folder, or empty).
pub fn run_summary(report: &Report, label: &str) -> String {
    let mut out = String::new();
    let at = if label.is_empty() { String::new() } else { format!(" ({label})") };
    out.push_str(&format!("{}{at}\n\n", report.title));
    out.push_str(&super::markdown_losses::headline_body(report));
    warnings_tail(&mut out, &report.findings);
    out
}

/// "N warnings, M notes" and the first warnings, with how many more report.md holds.
fn warnings_tail(out: &mut String, findings: &[crate::report::Finding]) {
    let warnings: Vec<&str> =
        findings.iter().filter(|f| f.severity == Severity::Warning).map(|f| f.message.as_str()).collect();
    let notes = findings.len() - warnings.len();
    out.push_str(&format!("{}, {}", counted(warnings.len(), "warning", "warnings"), counted(notes, "note", "notes")));
    if warnings.is_empty() {
        out.push_str(".\n");
        return;
    }
    out.push_str(":\n");
    for w in warnings.iter().take(FIRST_WARNINGS) {
        out.push_str(&format!("  - {w}\n"));
    }
    if warnings.len() > FIRST_WARNINGS {
        out.push_str(&format!("  … and {} more in report.md, \"Findings\".\n", warnings.len() - FIRST_WARNINGS));
    }
}

/// The terminal summary of a drive's run: each operating point's ends, total loss and η (where the
/// scene asks for none, that its stage meshes' analyses follow), then the number of warnings and
/// the first of them.
pub fn drive_summary(report: &crate::report::drive::DriveReport, label: &str) -> String {
    let at = if label.is_empty() { String::new() } else { format!(" ({label})") };
    let mut out = format!("{}{at}\n\n", report.title);
    if report.points.is_empty() && report.cycle.is_none() && !report.stage_pairs.is_empty() {
        out.push_str("  The scene asks for no efficiency: its stages' meshes are analysed as pairs alone, below.\n");
    }
    for p in &report.points {
        let d = &p.point;
        out.push_str(&format!(
            "  {} ({} {}): {} in {:.1} W, out {:.1} W, lost {:.2} W, η = {}{}{}\n",
            p.label,
            p.law,
            p.formulation,
            d.flow.name(),
            d.input_power,
            d.output_power,
            d.power_lost(),
            if d.both_ends_deliver {
                "0 (both ends deliver)".to_string()
            } else {
                format!("{:.4} %", 100.0 * d.efficiency)
            },
            match p.pinion_efficiency().filter(|_| report.one_pair) {
                Some(e) => format!(" (at the pinion {:.4} %)", 100.0 * e),
                None => String::new(),
            },
            if d.settled() { "" } else { " — NOT SETTLED (see the warnings)" }
        ));
    }
    if report.rows > report.points.len() {
        out.push_str(&format!(
            "  … {} more in drive_records.csv (η {} over all {}: report.md, \"Headline\")\n",
            counted(report.rows - report.points.len(), "row", "rows"),
            match (&report.least_efficiency, &report.greatest_efficiency) {
                (Some((lo, _)), Some((hi, _))) => format!("from {:.4} % to {:.4} %", 100.0 * lo, 100.0 * hi),
                _ => "ranges".to_string(),
            },
            report.rows
        ));
    }
    if let Some(c) = &report.cycle {
        let w = &c.whole;
        out.push_str(&format!(
            "  drive cycle \"{}\" ({} s, {:.4} km, {}): the box loses {:.3} ± {:.2e} Wh in drive and {:.3} ± {:.2e} Wh in recuperation, {:.3} Wh/km; cycle efficiency {:.3} % in drive, {:.3} % in recuperation\n",
            c.name,
            w.to_s - w.from_s,
            w.distance_km,
            c.vehicle,
            w.loss_drive_wh,
            w.loss_drive_error_wh,
            w.loss_recuperation_wh,
            w.loss_recuperation_error_wh,
            w.loss_wh_per_km,
            100.0 * w.efficiency_drive,
            100.0 * w.efficiency_recuperation
        ));
        if let Some(t) = &c.temperature {
            out.push_str(&format!(
                "  the sump: {:.2} °C → {:.2} °C, highest {:.3} °C\n",
                t.start_c, t.end_c, t.max.value
            ));
        }
    }
    out.push('\n');
    warnings_tail(&mut out, &report.findings);
    out
}
