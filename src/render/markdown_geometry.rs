//! report.md's geometry section: the pair's quantities (normal and transverse for a helical pair),
//! the characteristic points on the line of action in order, each gear's diameters and tooth checks.

use super::markup::md;

use super::table::{fixed, header, row, scaled};
use crate::report::units::Units;
use crate::report::{GeometryReport, Report};

/// The geometry section.
pub(super) fn geometry_section(out: &mut String, r: &Report) {
    md!(out, "\n## Geometry\n");
    geometry_tables(out, &r.geometry, r.units(), ["pinion", "wheel"]);
    if let Some(h) = &r.geometry.helical {
        super::markdown_helical::plane_of_action(out, "### Plane of action (helical pair)", h, &r.plots, r.units());
    }
}

/// The pair's table and its gears' (named `names`), in units `u`: a pair's Geometry section and
/// each stage mesh's of a drive.
pub(crate) fn geometry_tables(out: &mut String, g: &GeometryReport, u: Units, names: [&str; 2]) {
    pair_table(out, g, u);
    md!(out);
    gears_table(out, g, u, names);
}

/// A row of the pair's table: quantity, symbol, value.
type PairRow = (&'static str, &'static str, String);

/// The pair's quantities, with the points of the path of contact in their order from T1 after the
/// line of action.
fn pair_table(out: &mut String, g: &GeometryReport, u: Units) {
    header(out, &["quantity", "symbol", "value"]);
    let rows = pair_rows(g, u);
    let (before, after) = rows.split_at(rows.iter().position(|r| r.1 == "T1T2").map_or(rows.len(), |i| i + 1));
    for (q, s, v) in before {
        row(out, &[q.to_string(), s.to_string(), v.clone()]);
    }
    for (_, q, s, v) in contact_points(g, u) {
        row(out, &[q, s, v]);
    }
    for (q, s, v) in after {
        row(out, &[q.to_string(), s.to_string(), v.clone()]);
    }
}

/// The points of the path of contact (A, B, P, D, E and where 3 ↔ 2 pairs change), sorted from T1:
/// (distance, quantity, symbol, value).
fn contact_points(g: &GeometryReport, u: Units) -> Vec<(f64, String, String, String)> {
    let len = u.length();
    let mm = |q: &crate::report::number::Q| len.with(q.si(), 4);
    let pts = &g.points_from_t1;
    let mut rows: Vec<(f64, String, String, String)> =
        vec![(pts.A.si(), "start of contact".into(), "T1A".into(), mm(&pts.A))];
    if let Some(b) = &pts.B {
        rows.push((b.si(), "lowest point of single contact".into(), "T1B".into(), mm(b)));
    }
    rows.push((pts.P.si(), "pitch point".into(), "T1P".into(), mm(&pts.P)));
    if let Some(d) = &pts.D {
        rows.push((d.si(), "highest point of single contact".into(), "T1D".into(), mm(d)));
    }
    for c in &pts.pair_changes {
        let u = &c.distance_from_t1;
        rows.push((u.si(), "number of pairs changes (3 ↔ 2)".into(), format!("T1({})", c.name), mm(u)));
    }
    rows.push((pts.E.si(), "end of contact".into(), "T1E".into(), mm(&pts.E)));
    rows.sort_by(|x, y| x.0.total_cmp(&y.0));
    rows
}

/// The pair's quantities: a spur pair's, a helical pair's normal and transverse values in their
/// place, the diametral pitch of an inch pair.
fn pair_rows(g: &GeometryReport, u: Units) -> Vec<PairRow> {
    let deg = 180.0 / std::f64::consts::PI;
    let len = u.length();
    let mut rows: Vec<PairRow> = vec![
        ("module", "m", len.with(g.module.si(), 4)),
        ("pressure angle", "α", format!("{}°", scaled(&g.pressure_angle, deg, 4))),
        ("gear ratio", "u = z2/z1", fixed(g.gear_ratio.0, 4)),
        (
            "centre distance",
            "a",
            format!("{} ({})", len.with(g.center_distance.si(), 4), g.center_distance_source.replace('_', " ")),
        ),
        ("zero-backlash centre distance", "a_0", len.with(g.zero_backlash_center_distance.si(), 4)),
        ("operating pressure angle", "α_w", format!("{}°", scaled(&g.operating_pressure_angle, deg, 4))),
        ("zero-backlash pressure angle", "α_w0", format!("{}°", scaled(&g.zero_backlash_pressure_angle, deg, 4))),
        ("face width", "b", len.with(g.face_width.si(), 3)),
        ("base pitch", "p_b", len.with(g.base_pitch.si(), 4)),
        ("line of action", "T1T2", len.with(g.line_of_action_length.si(), 4)),
        ("transverse contact ratio", "ε_α", fixed(g.contact_ratio.0, 4)),
        ("Ohlendorf gear loss factor", "H_V", fixed(g.ohlendorf_loss_factor.0, 5)),
        ("reduced modulus", "E'", u.modulus().with(g.reduced_modulus.si(), 3)),
        ("load sharing", "", format!("{:?}", g.load_sharing).to_lowercase()),
    ];
    if let Some(h) = &g.helical {
        let at = rows.iter().position(|r| r.1 == "α").map_or(0, |i| i + 1);
        let helical_rows: Vec<PairRow> = vec![
            ("helix angle (reference circle)", "β", format!("{}°", scaled(&g.helix_angle, deg, 4))),
            ("base helix angle", "β_b", format!("{}°", scaled(&h.base_helix_angle, deg, 4))),
            ("transverse module", "m_t", len.with(h.transverse_module.si(), 4)),
            ("transverse pressure angle", "α_t", format!("{}°", scaled(&h.transverse_pressure_angle, deg, 4))),
        ];
        rows.splice(at..at, helical_rows);
        rows[0].0 = "normal module";
        rows[0].1 = "m_n";
        rows[at - 1].0 = "normal pressure angle";
        rows[at - 1].1 = "α_n";
        let at = rows.iter().position(|r| r.1 == "ε_α").map_or(rows.len(), |i| i + 1);
        let more: Vec<PairRow> = vec![
            ("overlap ratio", "ε_β", fixed(g.overlap_ratio.0, 4)),
            ("total contact ratio", "ε_γ", fixed(g.total_contact_ratio.0, 4)),
        ];
        rows.splice(at..at, more);
    }
    if !u.is_si() {
        // An inch pair is known by its diametral pitch P = 1/m (normal, for a helical pair).
        let name = if g.helical.is_some() { "normal diametral pitch" } else { "diametral pitch" };
        let pitch = format!("{} 1/in", fixed(crate::report::units::INCH / g.module.si(), 4));
        rows.insert(1, (name, "P = 1/m", pitch));
    }
    rows
}

/// Each gear's numbers, diameters and tip.
fn gears_table(out: &mut String, g: &GeometryReport, u: Units, names: [&str; 2]) {
    let len = u.length();
    let cols = [
        "gear".to_string(),
        "z".into(),
        "x".into(),
        len.heading("d"),
        len.heading("d_b"),
        len.heading("d_a"),
        "d_a from".into(),
        len.heading("d_w"),
        "ε_i".into(),
        len.heading("s_a"),
        "x_min".into(),
    ];
    header(out, &cols);
    for (k, (name, gr)) in names.into_iter().zip([&g.pinion, &g.wheel]).enumerate() {
        // A ring is cut by a pinion-type cutter: a rack's undercut limit says nothing of it.
        let ring = g.internal && k == 1;
        let name = if ring && name == "wheel" { "wheel (ring)".to_string() } else { name.to_string() };
        row(
            out,
            &[
                name,
                gr.teeth.to_string(),
                fixed(gr.profile_shift.0, 4),
                len.q(&gr.pitch_diameter, 4),
                len.q(&gr.base_diameter, 4),
                len.q(&gr.tip_diameter, 4),
                format!("{:?}", gr.tip_diameter_source)
                    .replace("AddendumRule", "addendum rule")
                    .replace("Given", "given"),
                len.q(&gr.working_pitch_diameter, 4),
                fixed(gr.addendum_contact_ratio.0, 4),
                len.q(&gr.tip_thickness, 4),
                if ring { "—".into() } else { fixed(gr.undercut_limit.0, 4) },
            ],
        );
    }
}
