//! The plane-of-action section of a helical pair's report: contact lines, L(t), the regions of the
//! mesh cycle and the axial force.

use super::markup::md;

use super::table::{fixed, header, row};
use crate::geometry::regions::{LineEnd, PitchSide};
use crate::report::helical::HelicalReport;
use crate::report::PlotRef;

fn end(e: LineEnd) -> &'static str {
    match e {
        LineEnd::StartOfContact => "A",
        LineEnd::FaceEdge => "face",
        LineEnd::EndOfContact => "E",
    }
}

fn side(s: PitchSide) -> &'static str {
    match s {
        PitchSide::Approach => "approach",
        PitchSide::Both => "across P",
        PitchSide::Recess => "recess",
    }
}

/// The section under `heading` (`### Plane of action (helical pair)`), its figure from `plots`.
pub(crate) fn plane_of_action<'a>(
    out: &mut String,
    heading: &str,
    h: &HelicalReport,
    plots: impl IntoIterator<Item = &'a PlotRef>,
    u: crate::report::units::Units,
) {
    md!(out, "\n{heading}\n");
    for p in plots.into_iter().filter(|p| p.kind == crate::report::PlotKind::PlaneOfAction) {
        md!(out, "![{}]({})\n", p.title, p.file);
    }
    md!(
        out,
        "Contact lines are straight, inclined by β_b, one transverse base pitch apart; line k has its z = +b/2 end at T1A + (τ + k) p_bt (He & Singh eq 11). Constant stiffness density: every line carries the load w = F_bn / L(t) per unit length.\n"
    );
    header(out, &["quantity", "value"]);
    let mm = |q: &crate::report::number::Q| u.length().with(q.si(), 4);
    for (q, v) in [
        ("line lead b tan β_b", mm(&h.line_lead)),
        ("mean contact length L̄ = ε_α b / cos β_b", mm(&h.mean_contact_length)),
        (
            "shortest total contact length",
            format!("{} at τ = {}", mm(&h.contact_length_min.value), fixed(h.contact_length_min.tau.0, 6)),
        ),
        (
            "longest total contact length",
            format!("{} at τ = {}", mm(&h.contact_length_max.value), fixed(h.contact_length_max.tau.0, 6)),
        ),
        ("lines in contact", format!("{} to {}", h.lines_in_contact[0], h.lines_in_contact[1])),
    ] {
        row(out, &[q.into(), v]);
    }
    for a in &h.axial_force {
        row(out, &[format!("axial force F_a at {}", a.operating_point), u.force().with(a.value.si(), 2)]);
    }
    md!(
        out,
        "\nRegions of one mesh cycle (τ in mesh periods), found from the geometry: in each, every line in contact with the boundaries holding its two ends (A: the start-of-contact line u = T1A, E: the end-of-contact line u = T1E, face: a face edge z = ±b/2) and its side of the pitch line.\n"
    );
    header(out, &["region", "τ from", "τ to", "lines (k: ends, side)"]);
    for (i, r) in h.regions.iter().enumerate() {
        let lines: Vec<String> = r
            .lines
            .iter()
            .map(|l| format!("{}: {}–{}, {}", l.index, end(l.ends[0]), end(l.ends[1]), side(l.side)))
            .collect();
        row(out, &[(i + 1).to_string(), fixed(r.from, 6), fixed(r.to, 6), lines.join("; ")]);
    }
}
