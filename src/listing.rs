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

/// A template of `gearloss new --kind K`: its kind, what it is (the `--kind` help), the scene's
/// text and a file written beside it, if any (name, bytes).
pub struct Template {
    pub kind: &'static str,
    pub what: &'static str,
    pub text: &'static str,
    pub beside: Option<(&'static str, &'static [u8])>,
}

/// The drive-cycle template's trace, written beside the scene: (file name, bytes) — the WLTC
/// class 3b of UN GTR No. 15 as NREL FASTSim ships it (Apache-2.0, `specs/cycles/NOTICE`).
pub const CYCLE_TRACE: (&str, &[u8]) = ("wltc_3b.csv", include_bytes!("../specs/cycles/wltc_3b.csv"));

/// The templates of `gearloss new --kind K`, the first the default.
pub const TEMPLATES: &[Template] = &[
    Template {
        kind: "pair",
        what: "a spur pair, an ISO VG oil, two laws, a gearbox, efficiency",
        text: TEMPLATE,
        beside: None,
    },
    Template {
        kind: "drive",
        what: "a two-stage helical box on three shafts with bearings, seals, jets, a loss map and the sump's balance",
        text: include_str!("templates/new_drive.gear"),
        beside: None,
    },
    Template {
        kind: "planetary",
        what: "a planetary stage: sun in, carrier out, ring held, three planets",
        text: include_str!("templates/new_planetary.gear"),
        beside: None,
    },
    Template {
        kind: "cycle",
        what: "a one-stage reducer in its car over WLTC class 3b (its trace written beside it)",
        text: include_str!("templates/new_cycle.gear"),
        beside: Some(CYCLE_TRACE),
    },
];

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
        if let Some((_, ms)) = LAW_COST_MS.iter().find(|(name, _)| *name == l.id.name()) {
            out.push_str(&format!("    cost:      ~{ms} ms a point of a two-stage drive\n"));
        }
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

/// What a law costs: the wall time of one operating point of a two-stage drive (the EV reducer of
/// `specs/ev_two_stage_reducer.gear`: 2 000 points, one law, the external formulation, `gearloss
/// run` in release on 2 cores, 2026-11-28), in ms. ISO/TR 14179-2 charges its closed-form loss;
/// every other law integrates η over the mesh cycle to 1e-10 at each pass of each stage's fixed
/// point, and the composite law solves its film at every node. A map's or a cycle's cost is about
/// this times its points.
pub(crate) const LAW_COST_MS: &[(&str, f64)] = &[
    ("coulomb", 2.7),
    ("benedict_kelley", 4.2),
    ("benedict_kelley_bernard", 5.3),
    ("xu", 6.3),
    ("smoothed_coulomb", 2.9),
    ("composite", 183.0),
    ("misharin", 15.0),
    ("odonoghue_cameron", 13.0),
    ("drozdov_gavrikov", 31.0),
    ("iso_14179_2", 0.035),
    ("matsumoto", 16.0),
];

/// `gearloss bearings`: the bearing types with Palmgren's factors, the keys of a `bearing(...)`,
/// the SKF model's constants and the seals.
pub fn bearings() -> String {
    let mut out = String::from(
        "Bearings: `bearing(type = ..., bore = ..., outside = ...)` in a shaft block of `gearbox`: `pinion_shaft { }` or `wheel_shaft { }` for one pair, `shaft <name> { }` in a drive of stages (and `planet { bearing(...) }` in a planetary stage).\nIn a drive, `at = ...` places the bearing along its shaft and the bare flag `locating` (`bearing(..., at = 20 mm, locating)`) names the one place of the shaft that takes the axial force (without it, the shaft's first place does, with a warning).\nPalmgren (ISO/TR 14179-2; SKF General Catalogue 4000 E, 1989): M_0 = 1e-7 f_0 (ν n)^(2/3) d_m³ (ν n ≥ 2000), 160e-7 f_0 d_m³ below; M_1 = f_1 P_1 d_m.\n\n",
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
        "\nKeys of `bearing(...)`: {}, and in a drive the flag `locating` and `radial_stiffness = 4e8 N/m` (a sprung place; the shaft then needs its `section`s).\nValidity: the load-dependent factors f_1 of ball and spherical roller bearings grow as (P_0/C_0)^x, read by SKF for static loads up to the static rating: a bearing loaded beyond P_0/C_0 = 1 is flagged in the report (its loss is extrapolated, and the bearing is overloaded).\nThe SKF model (SKF catalogue 17000, 2018): `model = skf({})` replaces M_0 and M_1 by M_rr and M_sl.\nSeals (ISO/TR 14179-2 after Linke): `seal({})`, P = 7.69e-6 d² n (d in mm, n in rpm).\n",
        BEARING.join(", "),
        SKF.join(", "),
        SEAL.join(", ")
    ));
    out
}

#[cfg(test)]
mod tests {
    /// Every law of the catalogue has its cost, and every cost a law.
    #[test]
    fn every_law_has_its_cost() {
        let names: Vec<&str> = crate::friction::catalog::LAWS.iter().map(|l| l.id.name()).collect();
        for n in &names {
            assert!(super::LAW_COST_MS.iter().any(|(c, _)| c == n), "no cost for {n}");
        }
        for (c, _) in super::LAW_COST_MS {
            assert!(names.contains(c), "a cost for {c}, which is no law");
        }
    }
}
