//! The scene's inputs as the user wrote them and in SI, for the report's first table.

pub use super::input_row::{InputRow, SiValue};
use super::number::{Num, Q};
use crate::mesh::MeshProblem;
use crate::model::{Given, ModuleSource};
use crate::scene::units::SiQuantity;

pub(super) fn input<T: SiQuantity>(rows: &mut Vec<InputRow>, key: &str, g: &Given<T>, unit: &'static str) {
    rows.push(InputRow {
        key: key.into(),
        written: g.written.clone(),
        si: SiValue::Dimensional(Q::new(g.value.si(), unit)),
    });
}

/// The unit system report.md shows results in: inch–pound when the pair is sized in inches (a
/// diametral pitch, or the module, transverse module or face width written in an inch length).
pub(super) fn unit_system(problem: &MeshProblem) -> super::number::UnitSystem {
    pair_unit_system(&problem.gears)
}

/// [`unit_system`] of one pair: inch–pound when it is sized in inches.
pub(super) fn pair_unit_system(g: &crate::model::GearPair) -> super::number::UnitSystem {
    use crate::scene::units::written_in_inches;
    let sized_in_inches = match &g.module_source {
        ModuleSource::DiametralPitch(_) | ModuleSource::TransverseDiametralPitch(_) => true,
        ModuleSource::TransverseModule(m) => written_in_inches(&m.written),
        ModuleSource::Module => false,
    } || written_in_inches(&g.module.written)
        || written_in_inches(&g.face_width.written);
    if sized_in_inches {
        super::number::UnitSystem::Inch
    } else {
        super::number::UnitSystem::Si
    }
}

/// The units findings and tables show this mesh's results in.
pub(super) fn units(problem: &MeshProblem) -> super::units::Units {
    super::units::Units::of_system(unit_system(problem))
}

/// The Scene table of a pair's report (the per-mesh evaluation's): its gears and its oil (a scene
/// of one pair's gearbox and housing are its one-stage drive's, `super::drive_inputs`).
pub(super) fn inputs(problem: &MeshProblem) -> Vec<InputRow> {
    let mut rows = Vec::new();
    pair_inputs(&mut rows, &problem.gears, ("", ["pinion", "wheel"]));
    if let Some(l) = &problem.lubricant {
        lubricant_inputs(&mut rows, l);
    }
    rows
}

/// A pair's inputs: its `gears` block (module or pitch, helix, pressure angle, centre distance,
/// face width) and each gear's, keyed from `prefix` (`""` for a scene of one pair, `first.` for a
/// drive's stage `first`) with the gears named `names` (`pinion`, `wheel`; `sun`, `planet`).
pub(super) fn pair_inputs(rows: &mut Vec<InputRow>, g: &crate::model::GearPair, (prefix, names): (&str, [&str; 2])) {
    let key = |k: &str| format!("{prefix}gears.{k}");
    match &g.module_source {
        ModuleSource::DiametralPitch(p) => input(rows, &key("diametral_pitch"), p, "1/m"),
        ModuleSource::TransverseDiametralPitch(p) => input(rows, &key("transverse_diametral_pitch"), p, "1/m"),
        ModuleSource::TransverseModule(m) => input(rows, &key("transverse_module"), m, "m"),
        ModuleSource::Module => {}
    }
    if let Some(b) = &g.helix_angle {
        input(rows, &key("helix_angle"), b, "rad");
    }
    input(rows, &key("module"), &g.module, "m");
    if let Some(a) = &g.transverse_pressure_angle {
        input(rows, &key("transverse_pressure_angle"), a, "rad");
    }
    input(rows, &key("pressure_angle"), &g.pressure_angle, "rad");
    if let Some(a) = &g.center_distance {
        input(rows, &key("center_distance"), a, "m");
    }
    input(rows, &key("face_width"), &g.face_width, "m");
    for (name, gear) in names.into_iter().zip([&g.pinion, &g.wheel]) {
        gear_inputs(rows, &format!("{prefix}{name}"), gear);
    }
}

/// One gear's inputs: teeth, shift, tip, inertia, roughness, root and bore, relief, material.
pub(super) fn gear_inputs(rows: &mut Vec<InputRow>, name: &str, gear: &crate::model::Gear) {
    rows.push(InputRow {
        key: format!("{name}.teeth"),
        written: gear.teeth.written.clone(),
        si: SiValue::Plain(Num(gear.teeth.value as f64)),
    });
    rows.push(InputRow {
        key: format!("{name}.profile_shift"),
        written: gear.profile_shift.written.clone(),
        si: SiValue::Plain(Num(gear.profile_shift.value)),
    });
    if let Some(d) = &gear.tip_diameter {
        input(rows, &format!("{name}.tip_diameter"), d, "m");
    }
    if let Some(j) = &gear.inertia {
        input(rows, &format!("{name}.inertia"), j, "kg*m^2");
    }
    for (key, r) in [
        ("roughness_ra", &gear.roughness_ra),
        ("roughness_rq", &gear.roughness_rq),
        ("roughness_rz", &gear.roughness_rz),
        ("root_diameter", &gear.root_diameter),
        ("bore_diameter", &gear.bore_diameter),
    ] {
        if let Some(r) = r {
            input(rows, &format!("{name}.{key}"), r, "m");
        }
    }
    if let Some(t) = &gear.tip_relief {
        input(rows, &format!("{name}.tip_relief.amount"), &t.amount, "m");
        input(rows, &format!("{name}.tip_relief.length"), &t.length, "m");
    }
    input(
        rows,
        &format!("{name}.material ({}).youngs_modulus", gear.material.name),
        &gear.material.youngs_modulus,
        "Pa",
    );
    rows.push(InputRow {
        key: format!("{name}.material ({}).poisson_ratio", gear.material.name),
        written: gear.material.poisson_ratio.written.clone(),
        si: SiValue::Plain(Num(gear.material.poisson_ratio.value)),
    });
}

/// The lubricant's inputs as the scene gave them (or as the catalogue read them at temperature).
pub(super) fn lubricant_inputs(rows: &mut Vec<InputRow>, l: &crate::model::Lubricant) {
    input(rows, "lubricant.dynamic_viscosity", &l.dynamic_viscosity, "Pa*s");
    if let Some(d) = &l.density {
        input(rows, "lubricant.density", d, "kg/m^3");
    }
    if let Some(n) = &l.kinematic_viscosity {
        input(rows, "lubricant.kinematic_viscosity", n, "m^2/s");
    }
    if let Some(a) = &l.pressure_viscosity {
        input(rows, "lubricant.pressure_viscosity", a, "1/Pa");
    }
    if let Some(t) = &l.temperature {
        input(rows, "lubricant.temperature", t, "K");
    }
}
