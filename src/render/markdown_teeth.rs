//! report.md's section on the teeth: the bodies the potential-energy method read, its stiffness
//! figures beside ISO 6336-1 Method B, and the static transmission error per torque.

use std::fmt::Write;

use super::table::{fixed, header, row};
use crate::report::{PlotKind, Report};

/// The section, empty when the scene does not ask for the teeth.
pub fn teeth_section(r: &Report) -> String {
    let mut out = String::new();
    let Some(s) = &r.stiffness else { return out };
    let _ = writeln!(out, "\n## Mesh stiffness from the teeth\n");
    let _ = writeln!(
        out,
        "Potential-energy method: per unit face width 1/k_w(s) = 1/k_h + Σ over both teeth (1/k_b + 1/k_s + 1/k_a + 1/k_f), bending, shear and axial compression of each tooth over its involute and trochoid fillet, Sainsot's fillet foundation and linearised Hertz k_h = π E′/4; the mesh stiffness K(s) sums the pairs in contact{}. Positions s from A along the line of action{}. Relative error estimate of k(s): {:.1e} (Chebyshev degree {}).\n",
        if s.helical_lines.is_some() { ", each helical contact line integrated exactly over its transverse sections" } else { "" },
        if s.helical_lines.is_some() { " (of the mid-face section)" } else { "" },
        s.relative_error.0,
        s.series_degree
    );
    header(
        &mut out,
        &["gear", "root d_f mm", "bore mm", "form circle d_Ff mm", "h_f = r_f/r_int", "θ_f rad", "tip relief"],
    );
    for b in &s.bodies {
        let relief = b.tip_relief.as_ref().map_or_else(
            || "none".to_string(),
            |t| format!("{} µm over {} mm, {}", fixed(t.amount.si() * 1e6, 2), fixed(t.length.si() * 1e3, 3), t.shape),
        );
        row(
            &mut out,
            &[
                b.gear.clone(),
                fixed(b.root_diameter.si() * 1e3, 4),
                fixed(b.bore_diameter.si() * 1e3, 4),
                fixed(b.form_diameter.si() * 1e3, 4),
                fixed(b.foundation_ratio.0, 4),
                fixed(b.root_angle.0, 5),
                relief,
            ],
        );
    }
    let _ = writeln!(out);
    header(&mut out, &["per unit face width", "potential energy", "ISO 6336-1 Method B"]);
    let per = |x: f64| fixed(x * 1e-9, 3);
    row(
        &mut out,
        &[
            "single pair N/(mm·µm)".into(),
            format!(
                "{} (largest, at s = {} mm)",
                per(s.max_single_per_width.value.si()),
                fixed(s.max_single_per_width.position.si() * 1e3, 4)
            ),
            format!("c' = {}", per(s.iso_6336.c_single.si())),
        ],
    );
    row(
        &mut out,
        &[
            "mesh N/(mm·µm)".into(),
            format!("{} (mean K̄/b)", per(s.mean_per_width.si())),
            format!("c_γα = {}", per(s.iso_6336.c_gamma_alpha.si())),
        ],
    );
    let _ = writeln!(
        out,
        "\nISO's figures include its factor C_M = 0.8 (theory to measured teeth); the method's are theoretical. Mean mesh stiffness K̄ = {} N/µm.",
        fixed(s.mean.si() * 1e-6, 2)
    );
    for p in r.plots.iter().filter(|p| p.kind == PlotKind::MeshStiffness) {
        let _ = writeln!(out, "\n![{}]({})", p.title, p.file);
    }
    transmission_error_lines(&mut out, r);
    out.push('\n');
    out
}

/// The static transmission error at each torque: located extremes, peak-to-peak, integrated mean.
fn transmission_error_lines(out: &mut String, r: &Report) {
    if r.transmission_error.is_empty() {
        return;
    }
    let _ = writeln!(out, "\n### Static transmission error\n");
    let _ =
        writeln!(out, "δ along the line of action, positive when the wheel lags; extremes located, mean integrated.\n");
    header(
        out,
        &["pinion torque N·m", "F_bn N", "min µm (at s mm)", "max µm (at s mm)", "peak-to-peak µm", "mean µm", "± µm"],
    );
    for t in &r.transmission_error {
        row(
            out,
            &[
                fixed(t.pinion_torque.si(), 2),
                fixed(t.normal_force.si(), 1),
                format!("{} ({})", fixed(t.min.value.si() * 1e6, 4), fixed(t.min.position.si() * 1e3, 4)),
                format!("{} ({})", fixed(t.max.value.si() * 1e6, 4), fixed(t.max.position.si() * 1e3, 4)),
                fixed(t.peak_to_peak.si() * 1e6, 4),
                fixed(t.mean.si() * 1e6, 4),
                format!("{:.1e}", t.mean_error.si() * 1e6),
            ],
        );
    }
    for p in r.plots.iter().filter(|p| matches!(p.kind, PlotKind::TransmissionError | PlotKind::LoadShare)) {
        let _ = writeln!(out, "\n![{}]({})", p.title, p.file);
    }
}
