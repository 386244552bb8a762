//! report.md: the report for a reader, in engineering units (mm, m/s, MPa, µm), fixed decimals.

use std::fmt::Write;

use super::table::{fixed, header, row, scaled, sig};
use crate::report::{Report, Severity};

pub fn render_markdown(r: &Report) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "# {}\n", r.title);
    let _ = writeln!(out, "Report written by gearloss from the scene `{}`.\n", r.title);
    out.push_str(&super::markdown_losses::headline(r));

    let _ = writeln!(out, "## Scene\n");
    header(&mut out, &["input", "as written", "SI"]);
    for i in &r.inputs {
        row(
            &mut out,
            &[
                format!("`{}`", i.key),
                i.written.clone(),
                format!("{} {}", sig(i.si.si()), i.si.unit()).trim_end().to_string(),
            ],
        );
    }

    out.push_str(&super::markdown_losses::lubricant_section(r));

    let g = &r.geometry;
    let _ = writeln!(out, "\n## Geometry\n");
    header(&mut out, &["quantity", "symbol", "value"]);
    let deg = 180.0 / std::f64::consts::PI;
    let mm = |q: &crate::report::number::Q| format!("{} mm", scaled(q, 1e3, 4));
    let pts = &g.points_from_t1;
    let mut contact_rows: Vec<(f64, String, String, String)> =
        vec![(pts.A.si(), "start of contact".into(), "T1A".into(), mm(&pts.A))];
    if let Some(b) = &pts.B {
        contact_rows.push((b.si(), "lowest point of single contact".into(), "T1B".into(), mm(b)));
    }
    contact_rows.push((pts.P.si(), "pitch point".into(), "T1P".into(), mm(&pts.P)));
    if let Some(d) = &pts.D {
        contact_rows.push((d.si(), "highest point of single contact".into(), "T1D".into(), mm(d)));
    }
    for c in &pts.pair_changes {
        let u = &c.distance_from_t1;
        contact_rows.push((u.si(), "number of pairs changes (3 ↔ 2)".into(), format!("T1({})", c.name), mm(u)));
    }
    contact_rows.push((pts.E.si(), "end of contact".into(), "T1E".into(), mm(&pts.E)));
    contact_rows.sort_by(|x, y| x.0.total_cmp(&y.0));
    let rows: Vec<(&str, &str, String)> = vec![
        ("module", "m", format!("{} mm", scaled(&g.module, 1e3, 4))),
        ("pressure angle", "α", format!("{}°", scaled(&g.pressure_angle, deg, 4))),
        ("gear ratio", "u = z2/z1", fixed(g.gear_ratio.0, 4)),
        (
            "centre distance",
            "a",
            format!("{} mm ({})", scaled(&g.center_distance, 1e3, 4), g.center_distance_source.replace('_', " ")),
        ),
        ("zero-backlash centre distance", "a_0", format!("{} mm", scaled(&g.zero_backlash_center_distance, 1e3, 4))),
        ("operating pressure angle", "α_w", format!("{}°", scaled(&g.operating_pressure_angle, deg, 4))),
        ("zero-backlash pressure angle", "α_w0", format!("{}°", scaled(&g.zero_backlash_pressure_angle, deg, 4))),
        ("face width", "b", format!("{} mm", scaled(&g.face_width, 1e3, 3))),
        ("base pitch", "p_b", format!("{} mm", scaled(&g.base_pitch, 1e3, 4))),
        ("line of action", "T1T2", format!("{} mm", scaled(&g.line_of_action_length, 1e3, 4))),
        ("transverse contact ratio", "ε_α", fixed(g.contact_ratio.0, 4)),
        ("Ohlendorf gear loss factor", "H_V", fixed(g.ohlendorf_loss_factor.0, 5)),
        ("reduced modulus", "E'", format!("{} GPa", scaled(&g.reduced_modulus, 1e-9, 3))),
        ("load sharing", "", format!("{:?}", g.load_sharing).to_lowercase()),
    ];
    let mut rows = rows;
    if let Some(h) = &g.helical {
        let at = rows.iter().position(|r| r.1 == "α").map_or(0, |i| i + 1);
        let helical_rows: Vec<(&str, &str, String)> = vec![
            ("helix angle (reference circle)", "β", format!("{}°", scaled(&g.helix_angle, deg, 4))),
            ("base helix angle", "β_b", format!("{}°", scaled(&h.base_helix_angle, deg, 4))),
            ("transverse module", "m_t", format!("{} mm", scaled(&h.transverse_module, 1e3, 4))),
            ("transverse pressure angle", "α_t", format!("{}°", scaled(&h.transverse_pressure_angle, deg, 4))),
        ];
        rows.splice(at..at, helical_rows);
        rows[0].0 = "normal module";
        rows[0].1 = "m_n";
        rows[at - 1].0 = "normal pressure angle";
        rows[at - 1].1 = "α_n";
        let at = rows.iter().position(|r| r.1 == "ε_α").map_or(rows.len(), |i| i + 1);
        let more: Vec<(&str, &str, String)> = vec![
            ("overlap ratio", "ε_β", fixed(g.overlap_ratio.0, 4)),
            ("total contact ratio", "ε_γ", fixed(g.total_contact_ratio.0, 4)),
        ];
        rows.splice(at..at, more);
    }
    let (before, after) = rows.split_at(rows.iter().position(|r| r.1 == "T1T2").map_or(rows.len(), |i| i + 1));
    for (q, s, v) in before {
        row(&mut out, &[q.to_string(), s.to_string(), v.clone()]);
    }
    for (_, q, s, v) in contact_rows {
        row(&mut out, &[q, s, v]);
    }
    for (q, s, v) in after {
        row(&mut out, &[q.to_string(), s.to_string(), v.clone()]);
    }
    let _ = writeln!(out);
    header(&mut out, &["gear", "z", "x", "d mm", "d_b mm", "d_a mm", "d_a from", "d_w mm", "ε_i", "s_a mm", "x_min"]);
    for (name, gr) in [("pinion", &g.pinion), ("wheel", &g.wheel)] {
        row(
            &mut out,
            &[
                name.into(),
                gr.teeth.to_string(),
                fixed(gr.profile_shift.0, 4),
                scaled(&gr.pitch_diameter, 1e3, 4),
                scaled(&gr.base_diameter, 1e3, 4),
                scaled(&gr.tip_diameter, 1e3, 4),
                format!("{:?}", gr.tip_diameter_source)
                    .replace("AddendumRule", "addendum rule")
                    .replace("Given", "given"),
                scaled(&gr.working_pitch_diameter, 1e3, 4),
                fixed(gr.addendum_contact_ratio.0, 4),
                scaled(&gr.tip_thickness, 1e3, 4),
                fixed(gr.undercut_limit.0, 4),
            ],
        );
    }
    if let Some(h) = &g.helical {
        super::markdown_helical::plane_of_action(&mut out, h, &r.plots);
    }

    let _ = writeln!(out, "\n## Contact along the line of action\n");
    for p in r.plots.iter().filter(|p| p.kind == crate::report::PlotKind::ContactState) {
        let _ = writeln!(out, "![{}]({})\n", p.title, p.file);
    }
    let _ = writeln!(
        out,
        "Positions are distances from T1 on the pinion base circle; s < 0 in approach, s > 0 in recess; w is the load per unit face width of the contact.\n"
    );
    for op in &r.operating_points {
        let _ = writeln!(
            out,
            "### Operating point {}: {}\n\nT_p = {} N·m, n_p = {} {}, F_bn = {} N, T_mesh = {} ms, v_t = {} m/s\n",
            op.index + 1,
            op.label,
            fixed(op.pinion_torque.si(), 2),
            fixed(r.speed_unit.value(&op.pinion_speed), 1),
            r.speed_unit.name,
            fixed(op.normal_load.si(), 1),
            fixed(op.mesh_period.si() * 1e3, 5),
            fixed(op.pitch_line_velocity.si(), 3)
        );
        header(
            &mut out,
            &[
                "point", "T1C mm", "s mm", "ρ1 mm", "ρ2 mm", "R mm", "v1 m/s", "v2 m/s", "v_s m/s", "v_Σ m/s", "SR",
                "pairs", "share", "w N/mm", "p_H MPa", "b_H µm",
            ],
        );
        for c in &op.contact {
            row(
                &mut out,
                &[
                    c.point.clone().unwrap_or_default(),
                    scaled(&c.distance_from_t1, 1e3, 3),
                    scaled(&c.s, 1e3, 3),
                    scaled(&c.radius_of_curvature_pinion, 1e3, 3),
                    scaled(&c.radius_of_curvature_wheel, 1e3, 3),
                    scaled(&c.reduced_radius, 1e3, 3),
                    scaled(&c.velocity_pinion, 1.0, 3),
                    scaled(&c.velocity_wheel, 1.0, 3),
                    scaled(&c.sliding_velocity, 1.0, 3),
                    scaled(&c.sum_velocity, 1.0, 3),
                    fixed(c.slide_to_roll.0, 3),
                    c.pairs_in_contact.to_string(),
                    fixed(c.load_share.0, 3),
                    scaled(&c.load_per_width, 1e-3, 1),
                    scaled(&c.hertz_pressure, 1e-6, 1),
                    scaled(&c.hertz_half_width, 1e6, 1),
                ],
            );
        }
        let _ = writeln!(out);
        super::markdown_friction::point(&mut out, op, g.helical.is_some());
    }
    super::markdown_friction::sweep(&mut out, r);
    out.push_str(&super::markdown_losses::budget_section(r));
    out.push_str(&super::markdown_bearings::bearings_section(r));
    out.push_str(&super::markdown_losses::map_section(r));
    out.push_str(&super::markdown_thermal::thermal_section(r));
    out.push_str(&super::markdown_teeth::teeth_section(r));
    super::markdown_dynamics::dynamics(&mut out, r);
    super::markdown_sweep::sweep_summary(&mut out, r);

    let _ = writeln!(out, "## Findings\n");
    for f in &r.findings {
        let tag = match f.severity {
            Severity::Note => "note",
            Severity::Warning => "**warning**",
        };
        let _ = writeln!(out, "- {tag}: {}", f.message);
    }
    out
}
