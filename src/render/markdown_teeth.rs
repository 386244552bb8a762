//! report.md's section on the teeth: the bodies the potential-energy method read, its stiffness
//! figures beside ISO 6336-1 Method B, and the static transmission error per torque.

use super::markup::md;

use super::table::{fixed, header, row};
use crate::report::teeth::IsoReport;
use crate::report::units::Units;
use crate::report::{PlotKind, Report};

/// The section, empty when the scene does not ask for the teeth.
pub(crate) fn teeth_section(r: &Report) -> String {
    let mut out = String::new();
    let Some(s) = &r.stiffness else { return out };
    md!(out, "\n## Mesh stiffness from the teeth\n");
    md!(
        out,
        "Potential-energy method: per unit face width 1/k_w(s) = 1/k_h + Σ over both teeth (1/k_b + 1/k_s + 1/k_a + 1/k_f), bending, shear and axial compression of each tooth over its involute and the trochoid fillet its generating rack cuts (dedendum h_fP, tip radius ρ_fP below: the rounding tangent to the flank at h_aP, or the full round tip where the rack is too narrow for it{}), Sainsot's fillet foundation and linearised Hertz k_h = π E′/4; the mesh stiffness K(s) sums the pairs in contact{}. Positions s from A along the line of action{}. Relative error estimate of k(s): {:.1e} (Chebyshev degree {}).\n",
        if s.helical_lines.is_some() { "; a helical pair's teeth are those the rack of its transverse section cuts" } else { "" },
        if s.helical_lines.is_some() { ", each helical contact line integrated exactly over its transverse sections" } else { "" },
        if s.helical_lines.is_some() { " (of the mid-face section)" } else { "" },
        s.relative_error.0,
        s.series_degree
    );
    let u = r.units();
    let len = u.length();
    bodies_table(&mut out, s, u);
    md!(out);
    header(&mut out, &["per unit face width", "potential energy", "ISO 6336-1 Method B"]);
    let kw = u.stiffness_per_width();
    let per = |x: f64| kw.cell(x, 3);
    row(
        &mut out,
        &[
            kw.heading("single pair"),
            format!(
                "{} (largest, at s = {})",
                per(s.max_single_per_width.value.si()),
                len.with(s.max_single_per_width.position.si(), 4)
            ),
            format!("c' = {}", per(s.iso_6336.c_single.si())),
        ],
    );
    row(
        &mut out,
        &[
            kw.heading("mesh"),
            format!("{} (mean K̄/b)", per(s.mean_per_width.si())),
            format!("c_γα = {}", per(s.iso_6336.c_gamma_alpha.si())),
        ],
    );
    let iso = &s.iso_6336;
    md!(
        out,
        "\nISO's figures include its factor C_M = {:.1} (theory to measured teeth); the method's are theoretical. Mean mesh stiffness K̄ = {}.",
        iso.c_m.0,
        u.stiffness().with(s.mean.si(), 2)
    );
    md!(out, "\n{}", iso_readings(iso, u));
    for p in r.plots.iter().filter(|p| p.kind == PlotKind::MeshStiffness) {
        md!(out, "\n![{}]({})", p.title, p.file);
    }
    transmission_error_lines(&mut out, r);
    out.push('\n');
    out
}

/// Each gear as an elastic body: root, rack, bore, form circle, Sainsot's h_f and θ_f, its relief.
fn bodies_table(out: &mut String, s: &crate::report::teeth::TeethStiffnessReport, u: Units) {
    let (len, micro) = (u.length(), u.micro());
    let cols = [
        "gear".to_string(),
        len.heading("root d_f"),
        len.heading("rack h_fP"),
        len.heading("rack tip ρ_fP"),
        len.heading("bore"),
        len.heading("form circle d_Ff"),
        "h_f = r_f/r_int".into(),
        "θ_f rad".into(),
        "tip relief".into(),
    ];
    header(out, &cols);
    for b in &s.bodies {
        let relief = b.tip_relief.as_ref().map_or_else(
            || "none".to_string(),
            |t| format!("{} over {}, {}", micro.with(t.amount.si(), 2), len.with(t.length.si(), 3), t.shape),
        );
        row(
            out,
            &[
                b.gear.clone(),
                len.q(&b.root_diameter, 4),
                len.q(&b.rack_dedendum, 4),
                len.q(&b.rack_tip_radius, 4),
                len.q(&b.bore_diameter, 4),
                len.q(&b.form_diameter, 4),
                fixed(b.foundation_ratio.0, 4),
                fixed(b.root_angle.0, 5),
                relief,
            ],
        );
    }
}

/// ISO 6336-1 Method B's readings behind c′ and c_γα, in one sentence.
pub(crate) fn iso_readings(iso: &IsoReport, u: Units) -> String {
    format!(
        "ISO 6336-1 Method B's readings: z_n = z/(cos²β_b cos β) = {} / {}, c′_th = 1/q′ = {}, c′ = c′_th C_M C_R C_B cos β (E/E_st) = {} with C_M = {:.1}, C_R = 1, C_B = {}, cos β = {}, E/E_st = {}; c_γα = c′ (0.75 ε_α + 0.25) = {} with ε_α = {}.",
        fixed(iso.virtual_teeth[0].0, 3),
        fixed(iso.virtual_teeth[1].0, 3),
        u.stiffness_per_width().with(iso.c_theoretical.si(), 5),
        u.stiffness_per_width().with(iso.c_single.si(), 5),
        iso.c_m.0,
        fixed(iso.basic_rack_factor.0, 4),
        fixed(iso.cos_helix.0, 5),
        fixed(iso.modulus_ratio.0, 4),
        u.stiffness_per_width().with(iso.c_gamma_alpha.si(), 5),
        fixed(iso.contact_ratio.0, 5)
    )
}

/// The static transmission error at each torque: located extremes, peak-to-peak, integrated mean.
fn transmission_error_lines(out: &mut String, r: &Report) {
    if r.transmission_error.is_empty() {
        return;
    }
    md!(out, "\n### Static transmission error\n");
    let helical = r.stiffness.as_ref().is_some_and(|s| s.helical_lines.is_some());
    md!(
        out,
        "δ along the line of action, positive when the wheel lags; extremes located, mean integrated.{}\n",
        if helical {
            " In the transverse plane: F_bt = T_p/r_b1 is the transverse force the teeth share (the normal force F_bn = F_bt/cos β_b)."
        } else {
            ""
        }
    );
    let u = r.units();
    let (len, micro) = (u.length(), u.micro());
    let extreme = |what: &str| format!("{what} {} (at s {})", micro.unit, len.unit);
    let cols = [
        u.torque().heading("pinion torque"),
        u.force().heading(if helical { "F_bt" } else { "F_bn" }),
        extreme("min"),
        extreme("max"),
        micro.heading("peak-to-peak"),
        micro.heading("mean"),
        micro.heading("±"),
    ];
    header(out, &cols);
    for t in &r.transmission_error {
        row(
            out,
            &[
                u.torque().q(&t.pinion_torque, 2),
                u.force().q(&t.normal_force, 1),
                format!("{} ({})", micro.q(&t.min.value, 4), len.q(&t.min.position, 4)),
                format!("{} ({})", micro.q(&t.max.value, 4), len.q(&t.max.position, 4)),
                micro.q(&t.peak_to_peak, 4),
                micro.q(&t.mean, 4),
                format!("{:.1e}", micro.value(t.mean_error.si())),
            ],
        );
    }
    for p in r.plots.iter().filter(|p| matches!(p.kind, PlotKind::TransmissionError | PlotKind::LoadShare)) {
        md!(out, "\n![{}]({})", p.title, p.file);
    }
}
