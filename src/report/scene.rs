//! The scene's inputs as the user wrote them and in SI, for the report's first table.

pub use super::input_row::{InputRow, SiValue};
use super::number::{Num, Q};
use crate::model::{Given, ModuleSource, Scene};
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
pub(super) fn unit_system(scene: &Scene) -> super::number::UnitSystem {
    pair_unit_system(&scene.gears)
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

/// The units findings and tables show this scene's results in.
pub(super) fn units(scene: &Scene) -> super::units::Units {
    super::units::Units::of_system(unit_system(scene))
}

pub(super) fn inputs(scene: &Scene) -> Vec<InputRow> {
    let mut rows = Vec::new();
    let g = &scene.gears;
    match &g.module_source {
        ModuleSource::DiametralPitch(p) => input(&mut rows, "gears.diametral_pitch", p, "1/m"),
        ModuleSource::TransverseDiametralPitch(p) => input(&mut rows, "gears.transverse_diametral_pitch", p, "1/m"),
        ModuleSource::TransverseModule(m) => input(&mut rows, "gears.transverse_module", m, "m"),
        ModuleSource::Module => {}
    }
    if let Some(b) = &g.helix_angle {
        input(&mut rows, "gears.helix_angle", b, "rad");
    }
    input(&mut rows, "gears.module", &g.module, "m");
    if let Some(a) = &g.transverse_pressure_angle {
        input(&mut rows, "gears.transverse_pressure_angle", a, "rad");
    }
    input(&mut rows, "gears.pressure_angle", &g.pressure_angle, "rad");
    if let Some(a) = &g.center_distance {
        input(&mut rows, "gears.center_distance", a, "m");
    }
    input(&mut rows, "gears.face_width", &g.face_width, "m");
    for (name, gear) in [("pinion", &g.pinion), ("wheel", &g.wheel)] {
        gear_inputs(&mut rows, name, gear);
    }
    if let Some(l) = &scene.lubricant {
        lubricant_inputs(&mut rows, l);
    }
    if let Some(g) = &scene.gearbox {
        super::gearbox_inputs::gearbox_inputs(&mut rows, g, !unit_system(scene).is_si());
    }
    if let Some(h) = &scene.housing {
        super::gearbox_inputs::housing_inputs(&mut rows, h);
    }
    rows
}

/// One gear's inputs: teeth, shift, tip, inertia, roughness, root and bore, relief, material.
fn gear_inputs(rows: &mut Vec<InputRow>, name: &str, gear: &crate::model::Gear) {
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
fn lubricant_inputs(rows: &mut Vec<InputRow>, l: &crate::model::Lubricant) {
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
