//! report.md: the sweep as a whole — where the record files are and the extremes over every
//! operating point.

use super::markup::{counted, md};

use super::table::{fixed, header, row, sig};
use crate::report::Report;

/// The "Records and extremes over the sweep" section (nothing for a run without records).
pub(crate) fn sweep_summary(out: &mut String, r: &Report) {
    let Some(rec) = &r.records else { return };
    md!(out, "## Records and extremes over the sweep\n");
    md!(
        out,
        "Every operating point × law × formulation has one row in `{}` and `{}`: {} over {}, SI units named in the column headers. {} reported in full above.\n",
        rec.csv,
        rec.jsonl,
        counted(rec.rows, "row", "rows"),
        counted(rec.operating_points, "operating point", "operating points"),
        if rec.reported_in_full >= rec.operating_points { "Every point is".to_string() } else { format!("{} of them are", rec.reported_in_full) }
    );
    let te = r.transmission_error.len();
    if te > 0 {
        md!(
            out,
            "Before them, one `transmission_error` row per torque of the static transmission error ({}: point 0, speed 0; `ste_peak_to_peak_m`, `ste_mean_m`, `ste_mean_error_m`).\n",
            counted(te, "row", "rows")
        );
    }
    let Some(s) = &r.sweep else { return };
    if !s.efficiency.is_empty() {
        md!(
            out,
            "Extremes of the mean efficiency and the power loss over all {} operating points (point numbers as in the records):\n",
            s.operating_points
        );
        let w = r.units().power();
        let p_loss = w.heading("max P_loss");
        header(out, &["law", "formulation", "min η̄ %", "at point", "max η̄ %", "at point", &p_loss, "at point"]);
        let point = |p: Option<usize>| p.map_or("—".to_string(), |p| p.to_string());
        for e in &s.efficiency {
            row(
                out,
                &[
                    format!("`{}`", e.label),
                    e.formulation.clone(),
                    e.min_efficiency.as_ref().map_or("—".into(), |v| fixed(100.0 * v.value.0, 4)),
                    point(e.min_efficiency.as_ref().map(|v| v.point)),
                    e.max_efficiency.as_ref().map_or("—".into(), |v| fixed(100.0 * v.value.0, 4)),
                    point(e.max_efficiency.as_ref().map(|v| v.point)),
                    e.max_power_loss.as_ref().map_or("—".into(), |v| w.q(&v.value, 2)),
                    point(e.max_power_loss.as_ref().map(|v| v.point)),
                ],
            );
        }
        md!(out);
    }
    if !s.dynamics.is_empty() {
        header(out, &["dynamic formulation", "unstable points (ρ > 1)", "max spectral radius ρ", "at point"]);
        for d in &s.dynamics {
            row(
                out,
                &[
                    d.formulation.clone(),
                    format!("{} of {}", d.unstable_points, s.operating_points),
                    d.max_spectral_radius.as_ref().map_or("—".into(), |v| sig(v.value.0)),
                    d.max_spectral_radius.as_ref().map_or("—".into(), |v| v.point.to_string()),
                ],
            );
        }
        md!(out);
    }
}
