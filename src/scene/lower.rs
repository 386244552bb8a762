//! Stage 2, lower: [`SceneAst`] → [`Scene`]: names resolved (use before definition is fine), every
//! quantity unit-checked into a uom value, ranges checked, and the gear pair's geometry checked.
//! Every problem is collected; lowering fails with all of them.

use std::collections::BTreeMap;

use uom::si::length::meter;

use super::ast::*;
use super::diagnostics::{Diagnostic, DiagnosticKind};
use super::fields::{checked_scale, format_number, unknown_name, Fields};
use super::units::Dimension;
use crate::friction::catalog;
use crate::geometry::{GeometryProblem, PairPart, SpurGeometry, SpurPairInput};
use crate::model::*;

const SCENE_BLOCKS: &[&str] = &["gears", "material", "lubricant", "operating", "friction", "dynamics", "analyses"];
const GEARS_KEYS: &[&str] =
    &["module", "diametral_pitch", "pressure_angle", "center_distance", "face_width", "load_sharing"];
const GEAR_KEYS: &[&str] =
    &["teeth", "profile_shift", "tip_diameter", "inertia", "material", "roughness_ra", "roughness_rq", "roughness_rz"];
const MATERIAL_KEYS: &[&str] = &["youngs_modulus", "poisson_ratio"];
const LUBRICANT_KEYS: &[&str] =
    &["dynamic_viscosity", "density", "kinematic_viscosity", "pressure_viscosity", "type", "temperature"];
const OPERATING_KEYS: &[&str] = &["pinion_torque", "pinion_speed"];
const ANALYSES: &[&str] =
    &["efficiency", "friction_along_loa", "film", "contact", "dynamics", "stability_map", "numerics"];
const FORMULATIONS: &[&str] = &["external", "internal"];

/// Lowers a parsed scene. On failure, every diagnostic found.
pub fn lower_scene(ast: &SceneAst) -> Result<Scene, Vec<Diagnostic>> {
    lower_scene_in(ast, None)
}

/// As [`lower_scene`], with the folder of the scene file, where files it names (a stiffness CSV) are read.
pub fn lower_scene_in(ast: &SceneAst, base_dir: Option<&std::path::Path>) -> Result<Scene, Vec<Diagnostic>> {
    let mut errors = Vec::new();
    let top = Fields::read("the scene", ast.title_span, &ast.items, &[], SCENE_BLOCKS, &[], &mut errors);

    let mut materials: BTreeMap<&str, Material> = BTreeMap::new();
    let mut singles: BTreeMap<&str, &Block> = BTreeMap::new();
    for block in &top.blocks {
        let kind = block.kind.text.as_str();
        if kind == "material" {
            if let Some(m) = lower_material(block, &mut errors) {
                if materials.contains_key(m.name.as_str()) {
                    errors.push(
                        Diagnostic::new(
                            DiagnosticKind::DuplicateKey,
                            block.label.as_ref().map_or(block.kind.span, |l| l.span),
                            format!("material `{}` is defined twice", m.name),
                        )
                        .hint("give each material a name of its own"),
                    );
                } else {
                    materials.insert(block_label(block), m);
                }
            }
        } else if singles.insert(kind, block).is_some() {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::DuplicateKey,
                    block.kind.span,
                    format!("the scene has two `{kind}` blocks"),
                )
                .hint(format!("merge them into one `{kind}` block")),
            );
        }
    }
    for (name, example) in [
        ("gears", "gears { module = 4.5 mm ... }"),
        ("operating", "operating { pinion_torque = 100 N*m  pinion_speed = 1000 rpm }"),
    ] {
        if !singles.contains_key(name) {
            errors.push(
                Diagnostic::new(DiagnosticKind::MissingKey, ast.title_span, format!("the scene has no `{name}` block"))
                    .hint(format!("add `{example}`")),
            );
        }
    }

    let gears = singles.get("gears").and_then(|b| lower_gears(b, &materials, &mut errors));
    let lubricant = singles.get("lubricant").and_then(|b| lower_lubricant(b, &mut errors));
    let operating = singles.get("operating").and_then(|b| lower_operating(b, &mut errors));
    let friction = singles.get("friction").map_or_else(Vec::new, |b| lower_friction(b, &mut errors));
    let analyses = singles.get("analyses").map_or_else(Analyses::default, |b| lower_analyses(b, &mut errors));
    let dynamics =
        singles.get("dynamics").and_then(|b| super::lower_dynamics::lower_dynamics(b, base_dir, &mut errors));
    if let Some(span) = analyses.dynamics_span {
        if !singles.contains_key("dynamics") {
            errors.push(
                Diagnostic::new(DiagnosticKind::MissingKey, span, "the dynamics analyses need a `dynamics` block")
                    .hint("add `dynamics { mesh_stiffness { single = 1.96e8 N/m  double = 3.92e8 N/m }  damping_ratio = 0.05  friction = coulomb(mu = 0.08) }`"),
            );
        }
        if let Some(g) = &gears {
            for (name, gear) in [("pinion", &g.pinion), ("wheel", &g.wheel)] {
                if gear.inertia.is_none() {
                    errors.push(
                        Diagnostic::new(
                            DiagnosticKind::MissingKey,
                            gear.span,
                            format!("the dynamics need the {name}'s `inertia`"),
                        )
                        .hint(format!("add `inertia = 3.45e-4 kg*m^2` to `{name}`")),
                    );
                }
            }
        }
    }

    if let Some(g) = &gears {
        check_friction_needs(&friction, g, lubricant.as_ref(), &mut errors);
    }
    if let Some(span) = analyses.film_span {
        if lubricant.as_ref().is_none_or(|l| l.pressure_viscosity.is_none()) {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::MissingKey,
                    span,
                    "`film` needs the lubricant's `pressure_viscosity`, which the scene lacks",
                )
                .hint("add `pressure_viscosity = 2.0e-8 1/Pa` to the `lubricant` block"),
            );
        }
    }
    match (gears, operating) {
        (Some(gears), Some(operating)) if errors.is_empty() => {
            Ok(Scene { title: ast.title.clone(), gears, lubricant, operating, friction, dynamics, analyses })
        }
        _ => Err(errors),
    }
}

fn block_label(block: &Block) -> &str {
    block.label.as_ref().map_or("", |l| l.text.as_str())
}

fn lower_material(block: &Block, errors: &mut Vec<Diagnostic>) -> Option<Material> {
    let Some(label) = &block.label else {
        errors.push(
            Diagnostic::new(DiagnosticKind::MissingKey, block.kind.span, "a material needs a name")
                .hint("write `material steel { ... }`"),
        );
        return None;
    };
    let f =
        Fields::read(format!("material `{}`", label.text), block.span, &block.items, MATERIAL_KEYS, &[], &[], errors);
    let e: Option<Given<Pressure>> = f.required("youngs_modulus", "206 GPa", errors);
    if !f.has("poisson_ratio") {
        errors.push(f.missing("poisson_ratio", "0.3"));
    }
    let nu = f.number("poisson_ratio", 0.0, 0.499, errors);
    let e = positive(e, "youngs_modulus", errors);
    Some(Material { name: label.text.clone(), youngs_modulus: e?, poisson_ratio: nu? })
}

fn positive<T: super::units::SiQuantity>(
    g: Option<Given<T>>,
    key: &str,
    errors: &mut Vec<Diagnostic>,
) -> Option<Given<T>> {
    let g = g?;
    if g.value.si() > 0.0 {
        Some(g)
    } else {
        errors.push(
            Diagnostic::new(DiagnosticKind::OutOfRange, g.span, format!("`{key}` = {} must be positive", g.written))
                .hint(format!("give `{key}` a value above zero")),
        );
        None
    }
}

fn lower_gears(block: &Block, materials: &BTreeMap<&str, Material>, errors: &mut Vec<Diagnostic>) -> Option<GearPair> {
    let f = Fields::read("the `gears` block", block.span, &block.items, GEARS_KEYS, &["pinion", "wheel"], &[], errors);
    let (module, module_source) = match (f.has("module"), f.has("diametral_pitch")) {
        (true, true) => {
            let (key, _) = f.values["diametral_pitch"];
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::DuplicateKey,
                    key.span,
                    "both `module` and `diametral_pitch` are given",
                )
                .hint("give one of them: m = 1/P_d"),
            );
            (None, ModuleSource::Module)
        }
        (false, true) => {
            let p: Option<Given<ReciprocalLength>> =
                positive(f.optional("diametral_pitch", errors), "diametral_pitch", errors);
            match p {
                Some(p) => {
                    let m = Given {
                        value: Length::new::<meter>(1.0 / p.value.value),
                        written: format!("1/({})", p.written),
                        span: p.span,
                    };
                    (Some(m), ModuleSource::DiametralPitch(p))
                }
                None => (None, ModuleSource::Module),
            }
        }
        _ => (positive(f.required("module", "4.5 mm", errors), "module", errors), ModuleSource::Module),
    };
    let pressure_angle: Option<Given<Angle>> = f.required("pressure_angle", "20 deg", errors);
    let pressure_angle = pressure_angle.and_then(|a| {
        let deg = a.value.value.to_degrees();
        if (10.0..=35.0).contains(&deg) {
            Some(a)
        } else {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    a.span,
                    format!("pressure angle {deg:.4}° is outside 10° to 35°"),
                )
                .hint("standard pressure angles are 14.5°, 20° and 25°"),
            );
            None
        }
    });
    let center_distance = positive(f.optional("center_distance", errors), "center_distance", errors);
    let face_width = positive(f.required("face_width", "14 mm", errors), "face_width", errors);
    let load_sharing = match f.name("load_sharing", &["equal", "none"], errors).map(|n| n.text.as_str()) {
        Some("none") => LoadSharing::None,
        _ => LoadSharing::Equal,
    };
    let mut gear = |name: &str| -> Option<Gear> {
        let found: Vec<&&Block> = f.blocks.iter().filter(|b| b.kind.text == name).collect();
        match found.as_slice() {
            [] => {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::MissingKey,
                        block.kind.span,
                        format!("the `gears` block has no `{name}`"),
                    )
                    .hint(format!("add `{name} {{ teeth = 20  material = steel }}`")),
                );
                None
            }
            [one, rest @ ..] => {
                for r in rest {
                    errors.push(
                        Diagnostic::new(DiagnosticKind::DuplicateKey, r.kind.span, format!("`{name}` is given twice"))
                            .hint(format!("keep one `{name}` block")),
                    );
                }
                lower_gear(one, materials, errors)
            }
        }
    };
    let pinion = gear("pinion");
    let wheel = gear("wheel");
    let pair = GearPair {
        module: module?,
        module_source,
        pressure_angle: pressure_angle?,
        center_distance,
        face_width: face_width?,
        load_sharing,
        pinion: pinion?,
        wheel: wheel?,
        span: block.kind.span,
    };
    check_geometry(&pair, errors)?;
    Some(pair)
}

fn lower_gear(block: &Block, materials: &BTreeMap<&str, Material>, errors: &mut Vec<Diagnostic>) -> Option<Gear> {
    let name = block.kind.text.as_str();
    let f = Fields::read(format!("the `{name}` block"), block.span, &block.items, GEAR_KEYS, &[], &[], errors);
    let teeth = match f.values.get("teeth") {
        None => {
            errors.push(f.missing("teeth", "20"));
            None
        }
        Some((_, v)) => super::fields::scalar("teeth", v, Dimension::NONE, errors).and_then(|(z, written)| {
            if z.fract() != 0.0 || !(5.0..=1000.0).contains(&z) {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::OutOfRange,
                        v.span,
                        format!("{name} teeth = {z} is not a whole number from 5 to 1000"),
                    )
                    .hint("an involute gear needs at least 5 teeth"),
                );
                None
            } else {
                Some(Given { value: z as u32, written, span: v.span })
            }
        }),
    };
    let profile_shift = f.number("profile_shift", -1.5, 2.5, errors).unwrap_or(Given {
        value: 0.0,
        written: "0 (default)".into(),
        span: block.kind.span,
    });
    let tip_diameter = positive(f.optional("tip_diameter", errors), "tip_diameter", errors);
    let inertia = positive(f.optional("inertia", errors), "inertia", errors);
    let mut rough = |key: &str| -> Option<Given<Length>> {
        let r: Option<Given<Length>> = f.optional(key, errors);
        r.and_then(|g| {
            if g.value.value >= 0.0 && g.value.value < 1e-3 {
                Some(g)
            } else {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::OutOfRange,
                        g.span,
                        format!("`{key}` = {} is not a roughness", g.written),
                    )
                    .hint("roughness lies between 0 and 1 mm; typical gear flanks have Ra 0.1 to 1 µm"),
                );
                None
            }
        })
    };
    let (ra, rq, rz) = (rough("roughness_ra"), rough("roughness_rq"), rough("roughness_rz"));
    let material = match f.name("material", &[], errors) {
        None if !f.has("material") => {
            errors.push(f.missing("material", "steel"));
            None
        }
        None => None,
        Some(m) => match materials.get(m.text.as_str()) {
            Some(mat) => Some(mat.clone()),
            None => {
                let mut d =
                    Diagnostic::new(DiagnosticKind::Undefined, m.span, format!("material `{}` is not defined", m.text));
                if let Some(n) = super::fields::nearest(&m.text, materials.keys().copied()) {
                    d = d.hint(format!("did you mean `{n}`?"));
                }
                errors.push(d.hint(format!(
                    "define it in the scene: `material {} {{ youngs_modulus = 206 GPa  poisson_ratio = 0.3 }}`",
                    m.text
                )));
                None
            }
        },
    };
    Some(Gear {
        teeth: teeth?,
        profile_shift,
        tip_diameter,
        inertia,
        material: material?,
        roughness_ra: ra,
        roughness_rq: rq,
        roughness_rz: rz,
        span: block.kind.span,
    })
}

impl GearPair {
    /// The geometry input in SI.
    pub fn spur_input(&self) -> SpurPairInput {
        let g = |x: &Option<Given<Length>>| x.as_ref().map(|d| d.value.get::<meter>());
        SpurPairInput {
            module: self.module.value.get::<meter>(),
            pressure_angle: self.pressure_angle.value.value,
            teeth: [self.pinion.teeth.value, self.wheel.teeth.value],
            profile_shift: [self.pinion.profile_shift.value, self.wheel.profile_shift.value],
            tip_diameter: [g(&self.pinion.tip_diameter), g(&self.wheel.tip_diameter)],
            center_distance: g(&self.center_distance),
            face_width: self.face_width.value.get::<meter>(),
        }
    }

    pub fn geometry(&self) -> Result<SpurGeometry, Vec<GeometryProblem>> {
        SpurGeometry::compute(&self.spur_input())
    }
}

fn check_geometry(pair: &GearPair, errors: &mut Vec<Diagnostic>) -> Option<()> {
    match pair.geometry() {
        Ok(_) => Some(()),
        Err(problems) => {
            for p in problems {
                let gear = |i: usize| if i == 0 { &pair.pinion } else { &pair.wheel };
                let span = match p.part {
                    PairPart::Teeth(i) => gear(i).teeth.span,
                    PairPart::ProfileShift(i) => gear(i).profile_shift.span,
                    PairPart::TipDiameter(i) => gear(i).tip_diameter.as_ref().map_or(gear(i).span, |d| d.span),
                    PairPart::CenterDistance => pair.center_distance.as_ref().map_or(pair.span, |d| d.span),
                    PairPart::Pair => pair.span,
                };
                errors.push(Diagnostic::new(DiagnosticKind::Geometry, span, p.reason).hint(p.hint));
            }
            None
        }
    }
}

fn lower_lubricant(block: &Block, errors: &mut Vec<Diagnostic>) -> Option<Lubricant> {
    let name = block.label.as_ref().map_or("lubricant".to_string(), |l| l.text.clone());
    let f = Fields::read("the `lubricant` block", block.span, &block.items, LUBRICANT_KEYS, &[], &[], errors);
    let eta = positive(f.required("dynamic_viscosity", "95 mPa*s", errors), "dynamic_viscosity", errors);
    let density: Option<Given<MassDensity>> = positive(f.optional("density", errors), "density", errors);
    let nu: Option<Given<KinematicViscosity>> =
        positive(f.optional("kinematic_viscosity", errors), "kinematic_viscosity", errors);
    let alpha = positive(f.optional("pressure_viscosity", errors), "pressure_viscosity", errors);
    let temperature = positive(f.optional("temperature", errors), "temperature", errors);
    let kind = f.name("type", LubricantType::NAMES, errors).and_then(|n| LubricantType::from_name(&n.text));
    if f.has("density") && f.has("kinematic_viscosity") {
        let (key, _) = f.values["kinematic_viscosity"];
        errors.push(
            Diagnostic::new(
                DiagnosticKind::DuplicateKey,
                key.span,
                "both `density` and `kinematic_viscosity` are given",
            )
            .hint("give one of them: ν = η/ρ"),
        );
    }
    Some(Lubricant {
        name,
        dynamic_viscosity: eta?,
        density,
        kinematic_viscosity: nu,
        pressure_viscosity: alpha,
        kind,
        temperature,
    })
}

fn lower_operating(block: &Block, errors: &mut Vec<Diagnostic>) -> Option<Operating> {
    let f = Fields::read("the `operating` block", block.span, &block.items, OPERATING_KEYS, &[], &[], errors);
    let torque: Option<Sweep<Torque>> = f.sweep("pinion_torque", "[100, 200] N*m", errors);
    let speed: Option<Sweep<AngularVelocity>> = f.sweep("pinion_speed", "1000 rpm", errors);
    let check = |key: &str, values: &[f64], span: Span, errors: &mut Vec<Diagnostic>| -> bool {
        match values.iter().find(|v| **v <= 0.0) {
            Some(_) => {
                errors.push(
                    Diagnostic::new(DiagnosticKind::OutOfRange, span, format!("`{key}` must be positive"))
                        .hint("the pinion drives: give a positive torque and speed"),
                );
                false
            }
            None => true,
        }
    };
    let torque = torque
        .filter(|t| check("pinion_torque", &t.values.iter().map(|v| v.value).collect::<Vec<_>>(), t.span, errors));
    let speed =
        speed.filter(|s| check("pinion_speed", &s.values.iter().map(|v| v.value).collect::<Vec<_>>(), s.span, errors));
    Some(Operating { pinion_torque: torque?, pinion_speed: speed? })
}

fn lower_friction(block: &Block, errors: &mut Vec<Diagnostic>) -> Vec<FrictionLawSpec> {
    let ids: Vec<&str> = catalog::LAWS.iter().map(|l| l.id).collect();
    let f = Fields::read("the `friction` block", block.span, &block.items, &[], &[], &ids, errors);
    f.calls.iter().flat_map(|c| lower_law(c, errors)).collect()
}

/// A law call checked against the catalogue: arguments known, with the right dimension, defaults filled in.
/// A law call checked against the catalogue: arguments known, with the right dimension, defaults
/// filled in. One argument may be a sweep (`coulomb(mu = [0.02, 0.04, 0.08])`): the law is then
/// evaluated once per value.
pub fn lower_law(call: &Call, errors: &mut Vec<Diagnostic>) -> Vec<FrictionLawSpec> {
    let Some(entry) = catalog::entry(&call.name.text) else { return Vec::new() };
    let names: Vec<&str> = entry.arguments.iter().map(|a| a.name).collect();
    let mut arguments: Vec<(String, f64, String)> = Vec::new();
    let mut swept: Option<(String, Vec<(f64, String)>)> = None;
    let mut ok = true;
    for (name, value) in &call.arguments {
        let Some(spec) = entry.arguments.iter().find(|a| a.name == name.text) else {
            errors.push(unknown_name(&format!("argument of `{}`", entry.id), name, &names));
            ok = false;
            continue;
        };
        let given_before =
            arguments.iter().any(|(n, _, _)| n == spec.name) || swept.as_ref().is_some_and(|(n, _)| n == spec.name);
        if given_before {
            errors.push(
                Diagnostic::new(DiagnosticKind::DuplicateKey, name.span, format!("`{}` is given twice", spec.name))
                    .hint("keep one"),
            );
            ok = false;
            continue;
        }
        let values: Option<Vec<(f64, String)>> = match &value.kind {
            ValueKind::List { .. } | ValueKind::Range { .. } => {
                if swept.is_some() {
                    errors.push(
                        Diagnostic::new(
                            DiagnosticKind::OutOfRange,
                            value.span,
                            format!("`{}` sweeps a second argument", entry.id),
                        )
                        .hint("a law may sweep one argument; write a second law for another sweep"),
                    );
                    ok = false;
                    continue;
                }
                super::fields::sweep_values(spec.name, value, spec.dimension, errors).map(|(si, unit, written)| {
                    si.into_iter()
                        .zip(written)
                        .map(|(x, w)| (x, format!("{} {unit}", format_number(w)).trim_end().to_string()))
                        .collect()
                })
            }
            _ => super::fields::scalar(spec.name, value, spec.dimension, errors).map(|v| vec![v]),
        };
        let Some(values) = values else {
            ok = false;
            continue;
        };
        if let Some((x, _)) = values.iter().find(|(x, _)| !(x.is_finite() && *x >= 0.0)) {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    value.span,
                    format!("`{}` = {x} must not be negative", spec.name),
                )
                .hint(format!("{} is a magnitude; the sign follows the sliding direction", spec.what)),
            );
            ok = false;
            continue;
        }
        if values.len() > 1 || matches!(value.kind, ValueKind::List { .. } | ValueKind::Range { .. }) {
            swept = Some((spec.name.to_string(), values));
        } else {
            let (x, w) = values.into_iter().next().expect("one value");
            arguments.push((spec.name.to_string(), x, w));
        }
    }
    for spec in entry.arguments {
        if arguments.iter().any(|(n, _, _)| n == spec.name) || swept.as_ref().is_some_and(|(n, _)| n == spec.name) {
            continue;
        }
        match spec.default {
            Some(d) => arguments.push((spec.name.to_string(), d, "default".into())),
            None => {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::MissingKey,
                        call.span,
                        format!("`{}` needs `{}` ({})", entry.id, spec.name, spec.what),
                    )
                    .hint(format!("write `{}({} = ...)`", entry.id, spec.name)),
                );
                ok = false;
            }
        }
    }
    if !ok {
        return Vec::new();
    }
    match swept {
        None => vec![FrictionLawSpec { id: entry.id.to_string(), arguments, span: call.span }],
        Some((name, values)) => values
            .into_iter()
            .map(|(x, w)| {
                let mut args = arguments.clone();
                args.insert(0, (name.clone(), x, w));
                FrictionLawSpec { id: entry.id.to_string(), arguments: args, span: call.span }
            })
            .collect(),
    }
}

fn check_friction_needs(
    laws: &[FrictionLawSpec],
    gears: &GearPair,
    lubricant: Option<&Lubricant>,
    errors: &mut Vec<Diagnostic>,
) {
    for law in laws {
        let Some(entry) = catalog::entry(&law.id) else {
            continue;
        };
        for need in entry.needs {
            let both = |get: fn(&Gear) -> bool| get(&gears.pinion) && get(&gears.wheel);
            let present = match need {
                catalog::Needs::Lubricant => lubricant.is_some(),
                catalog::Needs::RoughnessRa => both(|g| g.roughness_ra.is_some()),
                catalog::Needs::RoughnessRq => both(|g| g.roughness_rq.is_some()),
                catalog::Needs::RoughnessRz => both(|g| g.roughness_rz.is_some()),
                catalog::Needs::KinematicViscosity => lubricant.is_some_and(|l| l.kinematic_viscosity_si().is_some()),
                catalog::Needs::PressureViscosity => lubricant.is_some_and(|l| l.pressure_viscosity.is_some()),
            };
            if !present && (lubricant.is_some() || *need == catalog::Needs::Lubricant) {
                let hint = match need {
                    catalog::Needs::Lubricant => {
                        "add `lubricant \"name\" { dynamic_viscosity = 95 mPa*s  density = 880 kg/m^3 }`".to_string()
                    }
                    catalog::Needs::KinematicViscosity => {
                        "add `density` or `kinematic_viscosity` to the lubricant".to_string()
                    }
                    catalog::Needs::PressureViscosity => {
                        "add `pressure_viscosity = 2.0e-8 1/Pa` to the lubricant".to_string()
                    }
                    other => format!("add `{} = 0.4 um` to both `pinion` and `wheel`", other.key()),
                };
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::MissingKey,
                        law.span,
                        format!("`{}` needs `{}`, which the scene lacks", law.id, need.key()),
                    )
                    .hint(hint),
                );
            }
        }
    }
}

fn lower_analyses(block: &Block, errors: &mut Vec<Diagnostic>) -> Analyses {
    let f = Fields::read("the `analyses` block", block.span, &block.items, &[], &[], ANALYSES, errors);
    let mut a = Analyses::default();
    for call in &f.calls {
        match call.name.text.as_str() {
            "efficiency" => {
                let mut formulations = vec![Formulation::External, Formulation::Internal];
                for (name, value) in &call.arguments {
                    if name.text != "formulations" {
                        errors.push(unknown_name("argument of `efficiency`", name, &["formulations"]));
                        continue;
                    }
                    match &value.kind {
                        ValueKind::List { items, unit: None } => {
                            formulations.clear();
                            for item in items {
                                match item {
                                    ListItem::Name(n) if n.text == "external" => {
                                        formulations.push(Formulation::External)
                                    }
                                    ListItem::Name(n) if n.text == "internal" => {
                                        formulations.push(Formulation::Internal)
                                    }
                                    ListItem::Name(n) => errors.push(unknown_name("formulation", n, FORMULATIONS)),
                                    ListItem::Number(_, s) => errors.push(
                                        Diagnostic::new(DiagnosticKind::WrongDimension, *s, "a formulation is a name")
                                            .hint("write `formulations = [external, internal]`"),
                                    ),
                                }
                            }
                            formulations.dedup();
                        }
                        _ => errors.push(
                            Diagnostic::new(
                                DiagnosticKind::WrongDimension,
                                value.span,
                                "`formulations` expects a list of names",
                            )
                            .hint("write `formulations = [external, internal]`"),
                        ),
                    }
                }
                a.efficiency = Some(formulations);
            }
            "stability_map" => {
                a.stability_map = super::lower_dynamics::lower_stability_map(call, errors);
                a.dynamics_span = Some(call.span);
            }
            other => {
                if let Some((name, _)) = call.arguments.first() {
                    errors.push(unknown_name(&format!("argument of `{other}`"), name, &[]));
                }
                match other {
                    "dynamics" => {
                        a.dynamics = true;
                        a.dynamics_span = Some(call.span);
                    }
                    "numerics" => {
                        a.numerics = true;
                        a.dynamics_span = Some(call.span);
                    }
                    "friction_along_loa" => a.friction_along_loa = true,
                    "film" => {
                        a.film = true;
                        a.film_span = Some(call.span);
                    }
                    _ => {}
                }
            }
        }
    }
    a
}

/// Checks a lone unit expression against a dimension (for `gearloss units` and tests).
pub fn unit_scale(text: &str, expected: Dimension) -> Result<f64, Vec<Diagnostic>> {
    let u = super::parse::parse_unit_text(text)?;
    let mut errors = Vec::new();
    match checked_scale("unit", Some(&u), expected, u.span, &mut errors) {
        Some(s) => Ok(s.factor),
        None => Err(errors),
    }
}
