//! Stage 2, lower: [`SceneAst`] → [`Scene`]: names resolved (use before definition is fine), every
//! quantity unit-checked into a uom value, ranges checked, and the gear pair's geometry checked.
//! Every problem is collected; lowering fails with all of them.

use std::collections::BTreeMap;

use super::ast::*;
use super::fields::{checked_scale, unknown_name, Fields};
use super::lower_friction::{check_friction_needs, lower_friction};
use super::lower_gears::{block_label, lower_gears, lower_material};
use super::lower_lubricant::{lower_lubricant, lower_lubricant_value};
use super::lower_operating::{check_oil_sweep, check_record_rows, lower_operating};
pub use super::lower_operating::{MAX_DETAIL_POINTS, MAX_RECORD_ROWS};
use super::units::Dimension;
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::model::*;

const SCENE_BLOCKS: &[&str] = &[
    "gears",
    "stage",
    "material",
    "lubricant",
    "operating",
    "friction",
    "dynamics",
    "gearbox",
    "duty_cycle",
    "analyses",
];
const ANALYSES: &[&str] = &[
    "efficiency",
    "efficiency_map",
    "friction_along_loa",
    "film",
    "contact",
    "dynamics",
    "stability_map",
    "numerics",
    "thermal_balance",
    "duty_cycle",
    "transmission_error",
];
const FORMULATIONS: &[&str] = &["external", "internal"];

/// Lowers a parsed scene. On failure, every diagnostic found.
pub fn lower_scene(ast: &SceneAst) -> Result<Scene, Vec<Diagnostic>> {
    lower_scene_in(ast, None)
}

/// As [`lower_scene`], with the folder of the scene file, where files it names (a stiffness CSV) are read.
pub fn lower_scene_in(ast: &SceneAst, base_dir: Option<&std::path::Path>) -> Result<Scene, Vec<Diagnostic>> {
    let mut errors = Vec::new();
    let top = Fields::read("the scene", ast.title_span, &ast.items, &["lubricant"], SCENE_BLOCKS, &[], &mut errors);

    let (materials, singles, stages) = scene_blocks(ast, &top, &mut errors);
    if !stages.is_empty() {
        return super::lower_drive_scene::lower_drive_scene(ast, &top, &materials, &singles, &stages, errors);
    }

    let gears = singles.get("gears").and_then(|b| lower_gears(b, &materials, &mut errors));
    let operating = singles.get("operating").and_then(|b| lower_operating(b, &mut errors));
    let housing = singles.get("gearbox").and_then(|g| {
        g.items.iter().find_map(|i| match i {
            Item::Block(b) if b.kind.text == "housing" => Some(b),
            _ => None,
        })
    });
    let housing = housing.and_then(|b| super::lower_thermal::lower_housing(b, &mut errors));
    let duty_cycle = singles.get("duty_cycle").and_then(|b| super::lower_thermal::lower_duty_cycle(b, &mut errors));
    let lubricant = scene_lubricant(&singles, &top, operating.as_ref(), housing.as_ref(), &mut errors);
    if let Some(op) = &operating {
        check_oil_sweep(op, lubricant.as_ref(), &mut errors);
    }
    let friction = singles.get("friction").map_or_else(Vec::new, |b| lower_friction(b, &mut errors));
    let analyses = singles.get("analyses").map_or_else(Analyses::default, |b| lower_analyses(b, false, &mut errors));
    let gearbox = singles.get("gearbox").and_then(|b| super::lower_gearbox::lower_gearbox(b, &mut errors));
    let dynamics =
        singles.get("dynamics").and_then(|b| super::lower_dynamics::lower_dynamics(b, base_dir, &mut errors));
    if let Some(span) = analyses.dynamics_span {
        check_dynamics_needs(span, singles.contains_key("dynamics"), gears.as_ref(), dynamics.as_ref(), &mut errors);
    }

    // (A law that failed to lower has its own error; this one is for a scene that lists none.)
    let lists_laws = singles.get("friction").is_some_and(|b| !b.items.is_empty());
    if let (Some(span), false) = (analyses.friction_span, lists_laws) {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::MissingKey,
                span,
                "`efficiency` and `friction_along_loa` need friction laws, and the scene lists none",
            )
            .hint("add a block such as `friction { coulomb(mu = 0.05) }` (README lists the laws)"),
        );
    }
    // A lubricant that failed to lower has its own error; the laws' needs are checked against a
    // lowered one or a missing one.
    let lubricant_failed =
        lubricant.is_none() && (singles.contains_key("lubricant") || top.values.contains_key("lubricant"));
    if let (Some(g), false) = (&gears, lubricant_failed) {
        check_friction_needs(&friction, g, lubricant.as_ref(), &mut errors);
    }
    if let (Some(gb), Some(block), Some(g)) = (&gearbox, singles.get("gearbox"), &gears) {
        super::lower_gearbox::check_immersion(gb.lubrication.as_ref(), g, lubrication_span(block), &mut errors);
    }
    if let (Some(gb), Some(block), false) = (&gearbox, singles.get("gearbox"), lubricant_failed) {
        super::lower_gearbox::check_gearbox_needs(gb, block, lubricant.as_ref(), &analyses, &mut errors);
    }
    if !lubricant_failed {
        check_film_needs(&analyses, lubricant.as_ref(), &mut errors);
    }
    if let Some(g) = gears.as_ref().filter(|g| g.wants_teeth(&analyses, dynamics.as_ref())) {
        super::lower_teeth::check_teeth(g, &mut errors);
    }
    let equilibrium = operating.as_ref().and_then(|o| o.equilibrium);
    super::lower_thermal::check_thermal_needs(
        &super::lower_thermal::ThermalInputs {
            housing: housing.as_ref(),
            housing_failed: singles.get("gearbox").is_some_and(|g| g.items.iter().any(|i| i.head().text == "housing")),
            duty_block: singles.get("duty_cycle").map(|b| b.kind.span),
            equilibrium,
            moves_with_temperature: lubricant.as_ref().is_none_or(|l| l.oil.is_some()),
            lubricant_failed,
        },
        &analyses,
        &mut errors,
    );
    match (gears, operating) {
        (Some(gears), Some(operating)) if errors.is_empty() => {
            let scene = Scene {
                title: ast.title.clone(),
                gears,
                lubricant,
                operating,
                friction,
                dynamics,
                gearbox,
                housing,
                duty_cycle,
                analyses,
                drive: None,
            };
            super::lower_dynamics::check_frequency_ratio(&scene, &mut errors);
            check_record_rows(&scene, &mut errors);
            if errors.is_empty() {
                Ok(scene)
            } else {
                Err(errors)
            }
        }
        _ => Err(errors),
    }
}

/// The scene's blocks: its materials by name (each defined once), its stages in order, and every
/// other block by kind (at most one of each); the `operating` block must be there, and either a
/// `gears` block (one pair) or `stage` blocks (a drive).
type SceneBlocks<'a> = (BTreeMap<&'a str, Material>, BTreeMap<&'a str, &'a Block>, Vec<&'a Block>);

fn scene_blocks<'a>(ast: &'a SceneAst, top: &Fields<'a>, errors: &mut Vec<Diagnostic>) -> SceneBlocks<'a> {
    let mut materials: BTreeMap<&str, Material> = BTreeMap::new();
    let mut singles: BTreeMap<&str, &Block> = BTreeMap::new();
    let mut stages: Vec<&Block> = Vec::new();
    for block in &top.blocks {
        let kind = block.kind.text.as_str();
        if kind == "stage" {
            stages.push(block);
        } else if kind == "material" {
            if let Some(m) = lower_material(block, errors) {
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
    if let (Some(gears), Some(stage)) = (singles.get("gears"), stages.first()) {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::DuplicateKey,
                gears.kind.span,
                "the scene has a `gears` block and `stage` blocks",
            )
            .hint(format!(
                "a scene is one pair (`gears`) or a drive of stages: move this pair into a `stage` block like `{}`",
                stage.label.as_ref().map_or("stage", |l| l.text.as_str())
            )),
        );
    }
    let example = if stages.is_empty() {
        "operating { pinion_torque = 100 N*m  pinion_speed = 1000 rpm }"
    } else {
        "operating { output_torque = 1000 N*m  output_speed = 500 rpm }"
    };
    for (name, example) in [("gears", "gears { module = 4.5 mm ... }"), ("operating", example)] {
        if name == "gears" && !stages.is_empty() {
            continue;
        }
        if !singles.contains_key(name) {
            errors.push(
                Diagnostic::new(DiagnosticKind::MissingKey, ast.title_span, format!("the scene has no `{name}` block"))
                    .hint(format!("add `{example}`")),
            );
        }
    }
    (materials, singles, stages)
}

/// What the dynamics analyses need: a `dynamics` block, both gears' inertias, and their masses for a
/// model on bearings.
fn check_dynamics_needs(
    span: Span,
    has_block: bool,
    gears: Option<&GearPair>,
    dynamics: Option<&DynamicsSpec>,
    errors: &mut Vec<Diagnostic>,
) {
    if !has_block {
        errors.push(
            Diagnostic::new(DiagnosticKind::MissingKey, span, "the dynamics analyses need a `dynamics` block")
                .hint("add `dynamics { mesh_stiffness { single = 1.96e8 N/m  double = 3.92e8 N/m }  damping_ratio = 0.05  friction = coulomb(mu = 0.08) }`"),
        );
    }
    if let Some(g) = gears {
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
            let on_bearings = dynamics.map(|d| d.model.id.entry()).filter(|m| m.on_bearings);
            if let Some(model) = on_bearings.filter(|_| gear.mass.is_none()) {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::MissingKey,
                        gear.span,
                        format!("the {} model needs the {name}'s `mass`", model.name),
                    )
                    .hint(format!("add `mass = 1.5 kg` to `{name}` (the gear with its share of the shaft)")),
                );
            }
        }
    }
}

/// The lubricant, from a `lubricant` block or `lubricant = ...`, read at the oil temperature (at
/// ambient when the scene asks for the equilibrium, until the run has found it).
pub(super) fn scene_lubricant(
    singles: &BTreeMap<&str, &Block>,
    top: &Fields,
    operating: Option<&Operating>,
    housing: Option<&crate::thermal::Housing>,
    errors: &mut Vec<Diagnostic>,
) -> Option<Lubricant> {
    // At `oil_temperature = equilibrium` the lubricant is read at ambient until the run has found the
    // balance (the report says the temperature it used).
    let ambient = match (operating.and_then(|o| o.equilibrium), housing) {
        (Some(span), Some(h)) => Some(Given {
            value: ThermodynamicTemperature::new::<uom::si::thermodynamic_temperature::kelvin>(h.ambient),
            written: "equilibrium".to_string(),
            span,
        }),
        _ => None,
    };
    let oil_temperature = operating.and_then(|o| o.oil_temperature.as_ref()).or(ambient.as_ref());
    // An `oil_temperature` that failed to lower has its own error: the lubricant is not read at none.
    let temperature_failed = oil_temperature.is_none()
        && singles.get("operating").is_some_and(|b| b.items.iter().any(|i| i.head().text == "oil_temperature"));
    match (singles.get("lubricant"), top.values.get("lubricant")) {
        _ if temperature_failed => None,
        (Some(_), Some((key, _))) => {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::DuplicateKey,
                    key.span,
                    "the scene has a `lubricant` block and `lubricant = ...`",
                )
                .hint("keep one of them"),
            );
            None
        }
        (Some(b), None) => lower_lubricant(b, oil_temperature, errors),
        (None, Some((_, v))) => lower_lubricant_value(v, oil_temperature, errors),
        (None, None) => None,
    }
}

/// Where a block's `lubrication = ...` value stands (the block's name when it has none).
pub(super) fn lubrication_span(block: &Block) -> Span {
    block
        .items
        .iter()
        .find_map(|i| match i {
            Item::Assignment { key, value } if key.text == "lubrication" => Some(value.span),
            _ => None,
        })
        .unwrap_or(block.kind.span)
}

/// `film` needs the lubricant's pressure-viscosity coefficient.
fn check_film_needs(analyses: &Analyses, lubricant: Option<&Lubricant>, errors: &mut Vec<Diagnostic>) {
    if let Some(span) = analyses.film_span {
        if lubricant.is_none_or(|l| l.pressure_viscosity.is_none()) {
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
}

/// The `analyses` block; a drive's (`drive`) map is given at its ends.
pub(super) fn lower_analyses(block: &Block, drive: bool, errors: &mut Vec<Diagnostic>) -> Analyses {
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
                            if items.is_empty() {
                                errors.push(
                                    Diagnostic::new(
                                        DiagnosticKind::OutOfRange,
                                        value.span,
                                        "`formulations` is an empty list: there is nothing to compute",
                                    )
                                    .hint("name at least one: `formulations = [external, internal]`, or leave the argument out for both"),
                                );
                            }
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
                a.friction_span = Some(call.span);
            }
            "efficiency_map" if drive => {
                if let Some((t, s, ends)) = super::lower_drive_operating::lower_drive_map(call, errors) {
                    a.efficiency_map = Some((t, s));
                    a.map_ends = Some(ends);
                }
                a.efficiency.get_or_insert_with(|| vec![Formulation::External, Formulation::Internal]);
                a.friction_span = a.friction_span.or(Some(call.span));
            }
            "efficiency_map" => {
                a.efficiency_map = super::lower_gearbox::lower_efficiency_map(call, errors);
                // The map's formulations are those of `efficiency`: both unless the scene names them.
                a.efficiency.get_or_insert_with(|| vec![Formulation::External, Formulation::Internal]);
                a.friction_span = a.friction_span.or(Some(call.span));
            }
            "transmission_error" => a.transmission_error = super::lower_teeth::lower_transmission_error(call, errors),
            "stability_map" => {
                a.stability_map = super::lower_dynamics_blocks::lower_stability_map(call, errors);
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
                    "friction_along_loa" => {
                        a.friction_along_loa = true;
                        a.friction_span = Some(call.span);
                    }
                    "film" => {
                        a.film = true;
                        a.film_span = Some(call.span);
                    }
                    "thermal_balance" => a.thermal_balance = Some(call.span),
                    "duty_cycle" => a.duty_cycle = Some(call.span),
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
