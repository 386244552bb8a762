//! Lowering of the `gears` and `material` blocks: the gear pair with its checked quantities, and
//! the pair's geometry checks mapped back to the spans the user wrote.

use std::collections::BTreeMap;

use uom::si::length::meter;

use super::ast::*;
use super::fields::{positive, Fields};
use super::lower_tooth_system::ToothSystem;
use super::units::Dimension;
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::geometry::{GeometryProblem, PairGeometry, PairInput, PairPart};
use crate::model::*;

const GEARS_KEYS: &[&str] = &[
    "module",
    "diametral_pitch",
    "transverse_module",
    "transverse_diametral_pitch",
    "pressure_angle",
    "transverse_pressure_angle",
    "helix_angle",
    "hand",
    "center_distance",
    "face_width",
    "load_sharing",
    "mesh",
];
const GEAR_KEYS: &[&str] = &[
    "teeth",
    "profile_shift",
    "tip_diameter",
    "inertia",
    "mass",
    "material",
    "roughness_ra",
    "roughness_rq",
    "roughness_rz",
    "root_diameter",
    "bore_diameter",
];
const MATERIAL_KEYS: &[&str] = &["youngs_modulus", "poisson_ratio"];

pub(super) fn block_label(block: &Block) -> &str {
    block.label.as_ref().map_or("", |l| l.text.as_str())
}

pub(super) fn lower_material(block: &Block, errors: &mut Vec<Diagnostic>) -> Option<Material> {
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

pub(super) fn lower_gears(
    block: &Block,
    materials: &BTreeMap<&str, Material>,
    errors: &mut Vec<Diagnostic>,
) -> Option<GearPair> {
    lower_gears_named(block, ["pinion", "wheel"], materials, errors)
}

/// [`lower_gears`] of a pair whose pinion and wheel blocks are named `names` (a planetary stage's
/// `sun` and `planet`, or `planet` and `ring`), so that messages name them as written.
pub(super) fn lower_gears_named(
    block: &Block,
    names: [&str; 2],
    materials: &BTreeMap<&str, Material>,
    errors: &mut Vec<Diagnostic>,
) -> Option<GearPair> {
    let f = Fields::read("the `gears` block", block.span, &block.items, GEARS_KEYS, &names, &[], errors);
    let ToothSystem { helix_angle, hand, module, module_source, pressure_angle, transverse_pressure_angle } =
        super::lower_tooth_system::lower_tooth_system(&f, errors);
    let center_distance = positive(f.optional("center_distance", errors), "center_distance", errors);
    let face_width = positive(f.required("face_width", "14 mm", errors), "face_width", errors);
    let load_sharing = match f.name("load_sharing", &["equal", "none", "stiffness"], errors).map(|n| n.text.as_str()) {
        Some("none") => LoadSharing::None,
        Some("stiffness") => LoadSharing::Stiffness,
        _ => LoadSharing::Equal,
    };
    let internal = f.name("mesh", &["external", "internal"], errors).is_some_and(|n| n.text == "internal");
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
    let pinion = gear(names[0]);
    let wheel = gear(names[1]);
    let pair = GearPair {
        module: module?,
        module_source,
        pressure_angle: pressure_angle?,
        transverse_pressure_angle,
        helix_angle,
        hand,
        center_distance,
        face_width: face_width?,
        load_sharing,
        pinion: pinion?,
        wheel: wheel?,
        internal,
        span: block.kind.span,
    };
    if let (Some(b), LoadSharing::None) = (&pair.helix_angle, pair.load_sharing) {
        if b.value.value != 0.0 {
            let (key, _) = f.values["load_sharing"];
            errors.push(
                Diagnostic::new(DiagnosticKind::OutOfRange, key.span, "`load_sharing = none` is a spur-pair reading")
                    .hint("a helical pair shares its load by constant stiffness density along the contact lines (He & Singh): leave `load_sharing` out"),
            );
            return None;
        }
    }
    check_geometry(&pair, errors)?;
    Some(pair)
}

/// The scene's material named `name`; else an error at the name with the nearest defined one and
/// how to define it (a gear's and a shaft's `material = …`).
pub(super) fn named_material<'m>(
    name: &Name,
    materials: &'m BTreeMap<&str, Material>,
    errors: &mut Vec<Diagnostic>,
) -> Option<&'m Material> {
    if let Some(m) = materials.get(name.text.as_str()) {
        return Some(m);
    }
    let mut d =
        Diagnostic::new(DiagnosticKind::Undefined, name.span, format!("material `{}` is not defined", name.text));
    if let Some(n) = super::fields::nearest(&name.text, materials.keys().copied()) {
        d = d.hint(format!("did you mean `{n}`?"));
    }
    errors.push(d.hint(format!(
        "define it in the scene: `material {} {{ youngs_modulus = 206 GPa  poisson_ratio = 0.3 }}`",
        name.text
    )));
    None
}

fn lower_gear(block: &Block, materials: &BTreeMap<&str, Material>, errors: &mut Vec<Diagnostic>) -> Option<Gear> {
    let name = block.kind.text.as_str();
    let f =
        Fields::read(format!("the `{name}` block"), block.span, &block.items, GEAR_KEYS, &["tip_relief"], &[], errors);
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
    let mass = positive(f.optional("mass", errors), "mass", errors);
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
        Some(m) => named_material(m, materials, errors).cloned(),
    };
    Some(Gear {
        teeth: teeth?,
        profile_shift,
        tip_diameter,
        inertia,
        mass,
        material: material?,
        roughness_ra: ra,
        roughness_rq: rq,
        roughness_rz: rz,
        root_diameter: positive(f.optional("root_diameter", errors), "root_diameter", errors),
        bore_diameter: positive(f.optional("bore_diameter", errors), "bore_diameter", errors),
        tip_relief: super::lower_teeth::lower_tip_relief(name, &f.blocks, errors),
        span: block.kind.span,
    })
}

impl GearPair {
    /// The geometry input in SI.
    pub fn pair_input(&self) -> PairInput {
        let g = |x: &Option<Given<Length>>| x.as_ref().map(|d| d.value.get::<meter>());
        PairInput {
            module: self.module.value.get::<meter>(),
            pressure_angle: self.pressure_angle.value.value,
            helix_angle: self.helix_angle.as_ref().map_or(0.0, |b| b.value.value),
            teeth: [self.pinion.teeth.value, self.wheel.teeth.value],
            profile_shift: [self.pinion.profile_shift.value, self.wheel.profile_shift.value],
            tip_diameter: [g(&self.pinion.tip_diameter), g(&self.wheel.tip_diameter)],
            center_distance: g(&self.center_distance),
            face_width: self.face_width.value.get::<meter>(),
            internal: self.internal,
        }
    }

    pub fn geometry(&self) -> Result<PairGeometry, Vec<GeometryProblem>> {
        PairGeometry::compute(&self.pair_input())
    }

    /// The pair with pinion and wheel exchanged: the wheel driving, in the pinion's place.
    pub fn swapped(&self) -> GearPair {
        GearPair { pinion: self.wheel.clone(), wheel: self.pinion.clone(), ..self.clone() }
    }
}

pub(super) fn check_geometry(pair: &GearPair, errors: &mut Vec<Diagnostic>) -> Option<()> {
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

/// What a scene asks of its internal pair that the tool does not model for one.
pub(super) struct InternalPairWants {
    /// The teeth's stiffness (load sharing by stiffness, tip relief, bodies, transmission error).
    pub teeth: bool,
    pub dynamics: Option<crate::diagnostics::Span>,
    pub gearbox: Option<crate::diagnostics::Span>,
}

/// An internal pair (`mesh = internal`) is evaluated along its path of contact (every law, both
/// formulations, the film): its teeth's stiffness, its dynamics and a loss budget on shafts are
/// external-pair models, refused here with the way on.
pub(super) fn check_internal_pair(pair: &GearPair, wants: &InternalPairWants, errors: &mut Vec<Diagnostic>) {
    if wants.teeth {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                pair.span,
                "the teeth's stiffness (load sharing by stiffness, tip relief, gear bodies, transmission error) is modelled for external pairs only",
            )
            .hint("an internal pair shares its load equally: leave out `load_sharing = stiffness`, `tip_relief`, `root_diameter`, `bore_diameter` and `transmission_error`"),
        );
    }
    if let Some(span) = wants.dynamics {
        errors.push(
            Diagnostic::new(DiagnosticKind::OutOfRange, span, "the dynamic models are written for external pairs")
                .hint("leave out `dynamics`, `stability_map` and `numerics` for an internal pair"),
        );
    }
    if let Some(span) = wants.gearbox {
        errors.push(
            Diagnostic::new(DiagnosticKind::OutOfRange, span, "a ring's loss budget on shafts is the planetary stage's")
                .hint("describe the ring in a drive's `planetary` stage, where its bearings, the planets' and the carrier's churning are charged"),
        );
    }
}
