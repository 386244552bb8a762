//! report.md: the report for a reader, in engineering units (mm, m/s, MPa, µm), fixed decimals.

use super::markup::md;

use super::table::{fixed, header, row, sig};
use crate::report::units::Units;
use crate::report::{PlotKind, Report, Severity};

/// The scene's inputs, each as written and in SI: a pair's Scene section and a drive's.
pub(crate) fn inputs_table(out: &mut String, inputs: &[crate::report::InputRow]) {
    header(out, &["input", "as written", "SI"]);
    for i in inputs {
        row(
            out,
            &[
                format!("`{}`", i.key),
                i.written.clone(),
                format!("{} {}", sig(i.si.si()), i.si.unit()).trim_end().to_string(),
            ],
        );
    }
}

pub fn render_markdown(r: &Report) -> String {
    let mut out = String::new();
    md!(out, "# {}\n", r.title);
    md!(out, "Report written by gearloss from the scene `{}`.\n", r.title);
    out.push_str(&super::markdown_losses::headline(r));

    md!(out, "## Scene\n");
    inputs_table(&mut out, &r.inputs);

    out.push_str(&super::markdown_losses::lubricant_section(r));

    super::markdown_geometry::geometry_section(&mut out, r);
    contact_section(&mut out, r);
    super::markdown_friction::sweep(&mut out, r);
    out.push_str(&super::markdown_teeth::teeth_section(r));
    super::markdown_dynamics::dynamics(&mut out, r);
    super::markdown_sweep::sweep_summary(&mut out, r);

    unlinked_plots(&mut out, r);
    md!(out, "## Findings\n");
    for f in &r.findings {
        let tag = match f.severity {
            Severity::Note => "note",
            Severity::Warning => "**warning**",
        };
        md!(out, "- {tag}: {}", f.message);
    }
    out
}

/// The contact along the line of action: its plots, then per operating point the state at the
/// characteristic points and the friction there.
fn contact_section(out: &mut String, r: &Report) {
    md!(out, "\n## Contact along the line of action\n");
    for p in r.plots.iter().filter(|p| matches!(p.kind, PlotKind::ContactState | PlotKind::Film)) {
        md!(out, "![{}]({})\n", p.title, p.file);
    }
    let helical = r.geometry.helical.is_some();
    md!(
        out,
        "Positions are distances from T1 on the pinion base circle; s < 0 in approach, s > 0 in recess; w is the load per unit face width of the contact.{}\n",
        if helical { HELICAL_CONTACT } else { "" }
    );
    let u = r.units();
    for op in &r.operating_points {
        md!(
            out,
            "### Operating point {}: {}\n\nT_p = {}, n_p = {} {}, F_bn = {}, T_mesh = {} ms, v_t = {}\n",
            op.index + 1,
            op.label,
            u.torque().with(op.pinion_torque.si(), 2),
            fixed(r.speed_unit.value(&op.pinion_speed), 1),
            r.speed_unit.name,
            u.force().with(op.normal_load.si(), 1),
            fixed(op.mesh_period.si() * 1e3, 5),
            u.velocity().with(op.pitch_line_velocity.si(), 3)
        );
        contact_table(out, op, helical, u);
        // The helical note once, under the first operating point's efficiency table.
        super::markdown_friction::point(out, op, helical, op.index == r.operating_points[0].index, u);
    }
}

/// The contact state at the table's positions of one operating point.
fn contact_table(out: &mut String, op: &crate::report::OperatingPointReport, helical: bool, u: Units) {
    let (len, vel) = (u.length(), u.velocity());
    let cols = [
        "point".to_string(),
        len.heading("T1C"),
        len.heading("s"),
        len.heading("ρ1"),
        len.heading("ρ2"),
        len.heading("R"),
        vel.heading("v1"),
        vel.heading("v2"),
        vel.heading("v_s"),
        vel.heading("v_Σ"),
        "SR".into(),
        "pairs".into(),
        "share".into(),
        u.force_per_width().heading("w"),
        u.pressure().heading("p_H"),
        u.micro().heading("b_H"),
    ];
    // A helical pair's contact is one line's point under the mean line load: no count of pairs.
    let keep = |cells: Vec<String>| -> Vec<String> {
        cells.into_iter().enumerate().filter(|(i, _)| !helical || *i != PAIRS_COLUMN).map(|(_, c)| c).collect()
    };
    header(out, &keep(cols.to_vec()));
    for c in &op.contact {
        row(
            out,
            &keep(vec![
                c.point.clone().unwrap_or_default(),
                len.q(&c.distance_from_t1, 3),
                len.q(&c.s, 3),
                len.q(&c.radius_of_curvature_pinion, 3),
                len.q(&c.radius_of_curvature_wheel, 3),
                len.q(&c.reduced_radius, 3),
                vel.q(&c.velocity_pinion, 3),
                vel.q(&c.velocity_wheel, 3),
                vel.q(&c.sliding_velocity, 3),
                vel.q(&c.sum_velocity, 3),
                fixed(c.slide_to_roll.0, 3),
                c.pairs_in_contact.to_string(),
                fixed(c.load_share.0, 3),
                u.force_per_width().q(&c.load_per_width, 1),
                u.pressure().q(&c.hertz_pressure, 1),
                u.micro().q(&c.hertz_half_width, 1),
            ]),
        );
    }
    md!(out);
}

/// The contact table's column of pairs in contact (left out for a helical pair).
const PAIRS_COLUMN: usize = 11;

/// How a helical pair's contact table reads (the state μ along the line of action is read at).
const HELICAL_CONTACT: &str = " Helical pair: each row is a point of a contact line under the mean load per unit line length w = F_bn / L̄ (L̄ = ε_α b / cos β_b, the mean total contact length), the state μ along the line of action below is read at; share = w b / F_bn = b / L̄. The efficiency integrates along the contact lines with w = F_bn / L(t) (Plane of action, above).";

/// Every plot of the report that no section above links, so that report.md links every plot the
/// folder holds.
fn unlinked_plots(out: &mut String, r: &Report) {
    let missing: Vec<_> = r.plots.iter().filter(|p| !out.contains(&format!("]({})", p.file))).collect();
    if missing.is_empty() {
        return;
    }
    md!(out, "## More plots\n");
    for p in missing {
        md!(out, "![{}]({})\n", p.title, p.file);
    }
}
