//! The elastic shafts of a drive in its report: report.md's sections and supports of each shaft
//! with sections, and at each point the reactions of every place, the deflection and slope at
//! each gear, the largest bending stress and where, and each stage's mesh misalignment;
//! shaft_moments.svg, the resultant bending moment along each such shaft at the report's first
//! point. Nothing here for a drive without sections.

use crate::drive::DrivePoint;
use crate::render::markup::md;
use crate::render::svg::{figure, Panel};
use crate::render::table::{fixed, header, row};
use crate::report::drive::DriveReport;
use crate::report::units::Units;

/// The bending moment plot's file.
pub(crate) const FILE: &str = "shaft_moments.svg";

/// Whether [`moments`] draws a plot: the report's first point has a bent shaft.
fn plotted(r: &DriveReport) -> bool {
    r.points.first().is_some_and(|p| p.point.shafts.iter().any(|s| s.bending.is_some()))
}

/// The sections, material, theory and supports of each shaft with sections, and the bending
/// moment plot when there is one.
pub(crate) fn inputs(out: &mut String, r: &DriveReport) {
    let shafts = &r.shafts;
    if shafts.iter().all(|s| s.beam.is_none()) {
        return;
    }
    let units = Units::of_system(r.unit_system);
    let len = units.length();
    let mm = |x: f64| len.cell(x * 1e-3, 2);
    md!(out, "\n## Shaft sections (elastic beams)\n");
    let heading = |name: &str| format!("{name} ({})", len.unit);
    header(out, &["shaft", &heading("from"), &heading("to"), &heading("D"), &heading("bore")]);
    for s in shafts {
        for x in s.beam.iter().flat_map(|b| &b.sections_mm) {
            row(out, &[s.name.clone(), mm(x[0]), mm(x[1]), mm(x[2]), mm(x[3])]);
        }
    }
    md!(out);
    for s in shafts {
        let Some(b) = &s.beam else { continue };
        let supports: Vec<String> = b
            .supports
            .iter()
            .map(|p| match p.radial_stiffness {
                Some(k) => format!("{} {} ({} N/m)", mm(p.at_mm), len.unit, crate::numerics::rounding::sig(k)),
                None => format!("{} {} (rigid)", mm(p.at_mm), len.unit),
            })
            .collect();
        let theory = if b.theory == "timoshenko" { "Timoshenko (bending and shear)" } else { "Euler–Bernoulli" };
        md!(
            out,
            "- {}: {} beam, {} (E = {}, ν = {}), on {}.",
            s.name,
            theory,
            b.material,
            units.modulus().with(b.youngs_modulus_gpa * 1e9, 1),
            fixed(b.poisson_ratio, 3),
            supports.join(", ")
        );
    }
    if plotted(r) {
        md!(out);
        md!(out, "![the bending moment along each shaft at the first point]({FILE})");
    }
}

/// One point's bent shafts: reactions, deflections and slopes at the gears, largest stress, and
/// the stages' mesh misalignment.
pub(crate) fn point(out: &mut String, d: &DrivePoint, units: Units) {
    if d.shafts.iter().all(|s| s.bending.is_none()) {
        return;
    }
    let (len, f, micro) = (units.length(), units.force(), units.micro());
    let (stress, torque) = (units.pressure(), units.torque());
    header(out, &["shaft (elastic)", &len.titled("place at"), &f.titled("R_x"), &f.titled("R_y"), &f.titled("R_z")]);
    for s in d.shafts.iter().filter(|s| s.bending.is_some()) {
        for b in &s.bearings {
            let r = b.reaction;
            let at = b.position.map_or_else(|| "—".into(), |x| len.cell(x, 2));
            row(out, &[s.name.clone(), at, f.cell(r[0], 2), f.cell(r[1], 2), f.cell(r[2], 2)]);
        }
    }
    md!(out);
    header(out, &["shaft (elastic)", "gear", &len.titled("at"), &micro.titled("w_x, w_y"), "θ_x, θ_y (µrad)"]);
    for s in &d.shafts {
        for g in s.bending.iter().flat_map(|b| &b.gears) {
            let stage = d.stages.get(g.stage);
            row(
                out,
                &[
                    s.name.clone(),
                    format!(
                        "{} of stage {}",
                        stage.map_or(g.member.name(), |x| x.member_name(g.member)),
                        stage.map_or(String::new(), |x| x.name.clone())
                    ),
                    len.cell(g.at, 2),
                    format!("{}, {}", micro.cell(g.deflection[0], 3), micro.cell(g.deflection[1], 3)),
                    format!("{}, {}", fixed(g.slope[0] * 1e6, 3), fixed(g.slope[1] * 1e6, 3)),
                ],
            );
        }
    }
    md!(out);
    header(
        out,
        &[
            "shaft (elastic)",
            &stress.titled("largest σ_b"),
            &len.titled("at"),
            &torque.titled("|M| there"),
            &len.titled("D there"),
            &micro.titled("largest |w|"),
            &len.titled("at"),
        ],
    );
    for s in &d.shafts {
        let Some(b) = &s.bending else { continue };
        row(
            out,
            &[
                s.name.clone(),
                stress.cell(b.max_stress, 3),
                len.cell(b.max_stress_at, 2),
                torque.cell(b.max_stress_moment, 3),
                len.cell(b.max_stress_diameter, 2),
                micro.cell(b.max_deflection, 3),
                len.cell(b.max_deflection_at, 2),
            ],
        );
    }
    md!(out);
    let misaligned: Vec<_> = d.stages.iter().filter_map(|s| s.mesh_misalignment.map(|f| (s, f))).collect();
    if !misaligned.is_empty() {
        let words: Vec<String> =
            misaligned.iter().map(|(s, f)| format!("stage {} {}", s.name, micro.with(*f, 3))).collect();
        md!(
            out,
            "Mesh misalignment from the shafts' bending (b × the gears' relative tilt on the line of action; reported, not fed back into the mesh): {}.\n",
            words.join(", ")
        );
    }
}

/// The resultant bending moment |M| along each shaft with sections at the report's first point
/// (its jumps at a helical gear drawn as steps), the bearing places and gears marked; None without one.
pub(crate) fn moments(r: &DriveReport) -> Option<Result<String, String>> {
    if !plotted(r) {
        return None;
    }
    let first = r.points.first()?;
    let units = Units::of_system(r.unit_system);
    let (len, torque, stress) = (units.length(), units.torque(), units.pressure());
    let panels: Vec<Panel> = first
        .point
        .shafts
        .iter()
        .filter_map(|s| {
            let b = s.bending.as_ref()?;
            let mut line = Vec::with_capacity(2 * b.moment.len());
            for m in &b.moment {
                line.push((len.value(m[0]), torque.value(m[1])));
                line.push((len.value(m[0]), torque.value(m[2])));
            }
            let mut marks: Vec<(String, f64)> = s
                .bearings
                .iter()
                .enumerate()
                .filter_map(|(i, p)| Some((format!("B{}", i + 1), len.value(p.position?))))
                .collect();
            marks.extend(b.gears.iter().map(|g| ("G".to_string(), len.value(g.at))));
            Some(Panel {
                y_label: format!("shaft {}: |M| ({})", s.name, torque.unit),
                x_label: format!("z on the shaft ({}); B bearing places, G gears", len.unit),
                xy: vec![(String::new(), line)],
                points: vec![(
                    format!("largest σ_b {} at {}", stress.with(b.max_stress, 2), len.with(b.max_stress_at, 2)),
                    vec![(len.value(b.max_stress_at), torque.value(b.max_stress_moment))],
                )],
                marks,
                ..Panel::default()
            })
        })
        .collect();
    let title = format!("{}: bending moment along the shafts, {} ({})", r.title, first.label, first.law);
    Some(figure(&title, &panels))
}
