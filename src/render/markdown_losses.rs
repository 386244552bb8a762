//! report.md's headline (the answer first), the lubricant at temperature, the loss budget and the
//! efficiency map.

use super::markup::{counted, md};

use super::table::{fixed, header, row};
use crate::report::{Report, Severity};

/// The headline block: the scene in one line, per law and operating point η̄ and the loss (and the
/// budget's total where given), the map's range, and the count of warnings and notes.
pub(crate) fn headline(r: &Report) -> String {
    let mut out = String::from("## Headline\n\n");
    out.push_str(&headline_body(r));
    let warnings = r.findings.iter().filter(|f| f.severity == Severity::Warning).count();
    let notes = r.findings.len() - warnings;
    md!(
        out,
        "Findings: {}, {} (listed at the end).\n",
        counted(warnings, "warning", "warnings"),
        counted(notes, "note", "notes")
    );
    out
}

/// The headline without its heading and findings count (the terminal prints it after `run`).
pub(crate) fn headline_body(r: &Report) -> String {
    let mut out = String::new();
    let g = &r.geometry;
    let kind = if g.helix_angle.si() > 0.0 {
        format!("helical pair β = {:.2}°", g.helix_angle.si().to_degrees())
    } else {
        "spur pair".to_string()
    };
    let kind = if g.internal { format!("internal {kind} (the wheel a ring)") } else { kind };
    let u = r.units();
    let oil = r.lubricant.as_ref().map_or(String::new(), |l| match &l.temperature {
        Some(t) => format!(", {} at {:.0} {}", l.name, u.temperature().value(t.si()), u.temperature().unit),
        None => format!(", {}", l.name),
    });
    // A pair sized in other units than millimetres is named as written too (8 1/in, 1.25 in).
    let size_keys = ["gears.diametral_pitch", "gears.transverse_diametral_pitch", "gears.module", "gears.face_width"];
    let written: Vec<&crate::report::input_row::InputRow> =
        r.inputs.iter().filter(|i| size_keys.contains(&i.key.as_str())).collect();
    let pitch = written.iter().any(|i| i.key.contains("diametral_pitch"));
    let as_written = if written.iter().all(|i| i.written.ends_with(" mm")) {
        String::new()
    } else {
        let shown: Vec<String> = written
            .iter()
            .filter(|i| !(pitch && i.key == "gears.module"))
            .map(|i| format!("{} = {}", i.key.trim_start_matches("gears."), i.written))
            .collect();
        format!(" (as written: {})", shown.join(", "))
    };
    md!(
        out,
        "{kind}, z = {}/{}, {}, b = {}{as_written}{oil}; {}.\n",
        r.geometry.pinion.teeth,
        r.geometry.wheel.teeth,
        if u.is_si() {
            format!("m = {} mm", fixed(g.module.si() * 1e3, 3))
        } else {
            let p = if g.helix_angle.si() > 0.0 { "P_n" } else { "P" };
            format!("{p} = {} 1/in", fixed(crate::report::units::INCH / g.module.si(), 3))
        },
        u.length().with(g.face_width.si(), 2),
        counted(
            r.operating_points.len().max(r.records.as_ref().map_or(0, |x| x.operating_points)),
            "operating point",
            "operating points"
        ),
    );
    super::headline::efficiency(&mut out, r);
    if !r.efficiency.is_empty() {
        md!(out, "Mesh losses only: the losses around the mesh (gears without load, bearings, seals) are the drive's, in the report whose `stages/` folder holds this one.\n");
    }
    if let Some(d) = &r.dynamics {
        super::headline::dynamics(&mut out, d, r.units());
    }
    out
}

/// The lubricant at the oil temperature and where its values come from.
pub(crate) fn lubricant_section(r: &Report) -> String {
    let mut out = String::new();
    let Some(l) = &r.lubricant else { return out };
    md!(out, "\n## Lubricant\n");
    lubricant_table(&mut out, l, r.units());
    out
}

/// The lubricant's table (quantity, value) and its source, in units `u`: a pair's Lubricant section
/// and a drive's Oil section.
pub(crate) fn lubricant_table(
    out: &mut String,
    l: &crate::report::losses::LubricantReport,
    u: crate::report::units::Units,
) {
    header(out, &["quantity", "value"]);
    row(out, &["name".into(), l.name.clone()]);
    if let Some(b) = &l.base {
        row(out, &["base oil".into(), b.clone()]);
    }
    if let Some(t) = &l.temperature {
        row(out, &["oil temperature".into(), u.temperature().with(t.si(), 1)]);
    }
    let nu = u.kinematic_viscosity();
    if let Some(n) = &l.kinematic_viscosity {
        row(out, &["kinematic viscosity ν".into(), nu.with(n.si(), 3)]);
    }
    row(out, &["dynamic viscosity η".into(), u.dynamic_viscosity().with(l.dynamic_viscosity.si(), 3)]);
    if let Some(d) = &l.density {
        row(out, &["density ρ".into(), u.density().with(d.si(), 1)]);
    }
    if let Some(a) = &l.pressure_viscosity {
        row(out, &["pressure–viscosity coefficient α".into(), u.pressure_viscosity().with(a.si(), 3)]);
    }
    row(out, &["lubricant factor X_L (ISO/TR 14179-2)".into(), fixed(l.lubricant_factor.0, 3)]);
    if let (Some(a), Some(b), Some(d)) = (&l.nu_40, &l.nu_100, &l.density_15) {
        row(out, &["ν40 / ν100".into(), format!("{} / {}", nu.cell(a.si(), 2), nu.with(b.si(), 3))]);
        row(out, &["density at 15 °C".into(), u.density().with(d.si(), 1)]);
    }
    if let Some(vi) = &l.viscosity_index {
        row(out, &["viscosity index (ASTM D2270)".into(), fixed(vi.0, 1)]);
    }
    md!(out, "\nSource: {}.", l.source);
}
