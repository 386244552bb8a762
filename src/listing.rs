//! What the language accepts, as text for the terminal (`gearloss laws`, `gearloss oils`,
//! `gearloss bearings`) and the commented scene `gearloss new` writes. Each list is read from the
//! catalogue the lowering checks names against, so it cannot drift from what a scene may write.

use crate::friction::catalog::{ArgumentDefault, LAWS};
use crate::losses::BearingType;
use crate::scene::lower_gearbox::{BEARING, SEAL, SKF};
use crate::tribology::lubricant::{base_oil, iso_lubricant_factor, lowest_grade, BaseOil, ISO_VG_GRADES};

/// The commented template scene of `gearloss new` (a spur pair, an ISO VG oil, two laws, a
/// gearbox, the efficiency analysis; the dynamics block commented out).
pub const TEMPLATE: &str = include_str!("templates/new_scene.gear");

/// `gearloss laws`: every friction law with its arguments (SI unit, default), what it needs from
/// the scene and its source.
pub fn laws() -> String {
    let mut out =
        String::from("Friction laws (write them in `friction { ... }`, or `friction = ...` in `dynamics`):\n");
    for l in LAWS {
        let args: Vec<String> = l
            .arguments
            .iter()
            .map(|a| {
                let unit = a.dimension.si_unit();
                let unit = if unit.is_empty() || unit == "1" { String::new() } else { format!(" {unit}") };
                match a.default {
                    ArgumentDefault::Required => format!("{} = …{unit} ({}, required)", a.name, a.what),
                    ArgumentDefault::Derived => format!("{} ({}, optional)", a.name, a.what),
                    ArgumentDefault::Value(d) => format!("{} = {d}{unit} ({}, default)", a.name, a.what),
                }
            })
            .collect();
        let needs: Vec<&str> = l.needs.iter().map(|n| n.key()).collect();
        out.push_str(&format!("\n{}  —  {}\n", l.id.name(), l.title));
        if !args.is_empty() {
            out.push_str(&format!("    arguments: {}\n", args.join("; ")));
        }
        if !needs.is_empty() {
            out.push_str(&format!("    needs:     {}\n", needs.join(", ")));
        }
        out.push_str(&format!("    source:    {}\n", l.source));
    }
    out.push_str(
        "\nFor an engineering answer: iso_14179_2 (the standard's mean μ, load- and speed-dependent) for a gearbox\nbudget; benedict_kelley or xu for μ along the path of contact in mixed or full-film lubrication; composite\nwhen the film parameter Λ spans regimes; coulomb to compare with a measured constant μ.\n",
    );
    out
}

/// `gearloss oils`: the ISO VG catalogue (grades and base oils with their data and sources).
pub fn oils() -> String {
    let grades: Vec<String> = ISO_VG_GRADES.iter().map(|g| format!("{g}")).collect();
    let mut out = format!(
        "Oils: `lubricant = iso_vg(GRADE, BASE)`, read at `oil_temperature` (ASTM D341 through ν40 and ν100).\n\nISO VG grades (ISO 3448): {}\n\n",
        grades.join(", ")
    );
    out.push_str(&format!(
        "{:<16} {:>5} {:>10} {:>5} {:>9}  {}\n",
        "base", "VI", "ρ15 kg/m³", "X_L", "lowest", "pressure-viscosity α, source"
    ));
    for name in BaseOil::NAMES {
        let Some(base) = BaseOil::from_name(name) else { continue };
        let xl = iso_lubricant_factor(base).map_or("—".into(), |x| format!("{x}"));
        match base_oil(base) {
            Some(d) => out.push_str(&format!(
                "{:<16} {:>5} {:>10} {:>5} {:>9}  {}\n",
                name,
                d.viscosity_index,
                d.density_15,
                xl,
                lowest_grade(base).map_or("—".into(), |g| format!("VG {g}")),
                d.source
            )),
            None => out.push_str(&format!(
                "{:<16} {:>5} {:>10} {:>5} {:>9}  not in the catalogue: give `nu_40`, `nu_100`, `density_15` and `base = {name}` in a lubricant block (X_L from ISO/TR 14179-2)\n",
                name, "—", "—", xl, "—"
            )),
        }
    }
    out.push_str("\nA measured oil: `lubricant \"name\" { nu_40 = 220 mm^2/s  nu_100 = 19 mm^2/s  density_15 = 880 kg/m^3  base = mineral }`.\n");
    out
}

/// `gearloss bearings`: the bearing types with Palmgren's factors, the keys of a `bearing(...)`,
/// the SKF model's constants and the seals.
pub fn bearings() -> String {
    let mut out = String::from(
        "Bearings: `bearing(type = ..., bore = ..., outside = ...)` in `pinion_shaft { }` or `wheel_shaft { }` of `gearbox`.\nPalmgren (ISO/TR 14179-2; SKF General Catalogue 4000 E, 1989): M_0 = 1e-7 f_0 (ν n)^(2/3) d_m³ (ν n ≥ 2000), 160e-7 f_0 d_m³ below; M_1 = f_1 P_1 d_m.\n\n",
    );
    out.push_str(&format!("{:<22} {:>4}  {:<26} {:<24} {}\n", "type", "f_0", "f_1", "P_1", "needs"));
    for name in BearingType::NAMES {
        let Some(t) = BearingType::from_name(name) else { continue };
        let (f1, p1) = match t {
            BearingType::DeepGrooveBall => ("0.0007 (P_0/C_0)^0.5", "max(3F_a − 0.1F_r, F_r)"),
            BearingType::AngularContactBall => ("0.001 (P_0/C_0)^0.33", "max(F_a − 0.1F_r, F_r)"),
            BearingType::CylindricalRoller => ("0.0003", "F_r"),
            BearingType::TaperedRoller => ("0.0004", "max(2 Y F_a, F_r)"),
            BearingType::SphericalRoller => ("0.0005 (P_0/C_0)^0.33", "max(F_r + 2.5 F_a, F_r)"),
        };
        let needs = if t.needs_static_rating() { "static_load_rating (or f1)" } else { "" };
        let line = format!("{:<22} {:>4}  {:<26} {:<24} {}", name, t.f0(), f1, p1, needs);
        out.push_str(line.trim_end());
        out.push('\n');
    }
    out.push_str(&format!(
        "\nKeys of `bearing(...)`: {}.\nThe SKF model (SKF catalogue 17000, 2018): `model = skf({})` replaces M_0 and M_1 by M_rr and M_sl.\nSeals (ISO/TR 14179-2 after Linke): `seal({})`, P = 7.69e-6 d² n (d in mm, n in rpm).\n",
        BEARING.join(", "),
        SKF.join(", "),
        SEAL.join(", ")
    ));
    out
}
