//! Stage 2, lower: [`SceneAst`] → [`Scene`]: names resolved (use before definition is fine), every
//! quantity unit-checked into a uom value, ranges checked, and the gear pair's geometry checked.
//! Every problem is collected; lowering fails with all of them.

use std::collections::BTreeMap;

use super::ast::*;
use super::fields::{checked_scale, Fields};
use super::lower_friction::{check_friction_needs, lower_friction};
use super::lower_gears::{block_label, lower_gears, lower_material};
use super::lower_operating::{check_oil_sweep, lower_operating};
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
    "vehicle",
    "drive_cycle",
    "analyses",
];
/// Lowers a parsed scene. On failure, every diagnostic found.
pub fn lower_scene(ast: &SceneAst) -> Result<Scene, Vec<Diagnostic>> {
    lower_scene_in(ast, None)
}

/// As [`lower_scene`], with the folder of the scene file, where files it names (a stiffness CSV) are read.
///
/// Every scene lowers to one form: a scene of stages to its drive, a scene of one pair to its
/// blocks as written (read by the pair's analyses) with its one-stage drive beside them
/// (`Scene::drive`, `one_pair`; the rewrite of `scene/pair_stage.rs`, lowered after the pair's own
/// lowering has passed, so a pair's errors are worded for a pair), and a pair on a drive cycle to
/// its one-stage drive alone.
pub fn lower_scene_in(ast: &SceneAst, base_dir: Option<&std::path::Path>) -> Result<Scene, Vec<Diagnostic>> {
    if super::pair_stage::is_pair_on_a_cycle(ast) {
        return lower_any(&super::pair_stage::as_one_stage(ast), base_dir, true);
    }
    let mut scene = lower_any(ast, base_dir, false)?;
    if scene.drive.is_none() {
        // Only the drive and its map's ends differ from the pair's own lowering: the pair's blocks
        // (its gearbox as the budget reads it among them) stay as the pair lowered them.
        let one_stage = lower_any(&super::pair_stage::as_one_stage(ast), base_dir, true)?;
        scene.drive = one_stage.drive;
        scene.analyses.map_ends = one_stage.analyses.map_ends;
    }
    Ok(scene)
}

/// A scene of one pair lowered as the one-stage drive it is, whatever it asks for (the rewrite of
/// `scene/pair_stage.rs`: stage `pair` on shafts `pinion_shaft` in and `wheel_shaft` out); a scene
/// of stages as [`lower_scene_in`] lowers it. What the pipeline of one path reads for every scene;
/// tests/it/one_stage.rs holds each pair's numbers against its one-stage drive's.
pub fn lower_as_one_stage_drive(ast: &SceneAst, base_dir: Option<&std::path::Path>) -> Result<Scene, Vec<Diagnostic>> {
    let one_pair = ast.items.iter().any(|i| matches!(i, Item::Block(b) if b.kind.text == "gears"))
        && !ast.items.iter().any(|i| matches!(i, Item::Block(b) if b.kind.text == "stage"));
    match one_pair {
        true => lower_any(&super::pair_stage::as_one_stage(ast), base_dir, true),
        false => lower_scene_in(ast, base_dir),
    }
}

/// A scene of one pair or of stages; `one_pair`: the stages are the one a pair on a drive cycle is
/// ([`super::pair_stage`]).
fn lower_any(ast: &SceneAst, base_dir: Option<&std::path::Path>, one_pair: bool) -> Result<Scene, Vec<Diagnostic>> {
    let mut errors = Vec::new();
    let top = Fields::read("the scene", ast.title_span, &ast.items, &["lubricant"], SCENE_BLOCKS, &[], &mut errors);

    let (materials, singles, stages) = scene_blocks(ast, &top, &mut errors);
    if !stages.is_empty() {
        return super::lower_drive_scene::lower_drive_scene(
            ast,
            (&top, &materials, &singles),
            &stages,
            (base_dir, one_pair),
            errors,
        );
    }
    for kind in ["vehicle", "drive_cycle"] {
        if let Some(b) = singles.get(kind) {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::UnknownName,
                    b.kind.span,
                    format!("a `{kind}` block drives a gearbox of stages; this scene is one pair"),
                )
                .hint("write the box with `stage` blocks and a `gearbox` of shafts (README, \"Several stages\")"),
            );
        }
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
    let duty_cycle = singles
        .get("duty_cycle")
        .and_then(|b| super::lower_thermal::lower_duty_cycle(b, &super::lower_thermal::PAIR_STEP, &mut errors));
    let lubricant =
        super::lower_lubricant::scene_lubricant(&singles, &top, operating.as_ref(), housing.as_ref(), &mut errors);
    if let Some(op) = &operating {
        check_oil_sweep(op, lubricant.as_ref(), &mut errors);
    }
    let friction = singles.get("friction").map_or_else(Vec::new, |b| lower_friction(b, &mut errors));
    let analyses = singles
        .get("analyses")
        .map_or_else(Analyses::default, |b| super::lower_analyses::lower_analyses(b, false, &mut errors));
    if let Some(span) = analyses.drive_cycle {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::UnknownName,
                span,
                "`drive_cycle` runs a vehicle over a drive cycle, and the scene has no `vehicle` and no `drive_cycle` block",
            )
            .hint("add `vehicle \"car\" { ... }` and `drive_cycle \"WLTC\" { trace = \"wltc.csv\" }` (README, \"Vehicles and drive cycles\"), or use `duty_cycle` for a load spectrum"),
        );
    }
    let gearbox = singles.get("gearbox").and_then(|b| super::lower_gearbox::lower_gearbox(b, &mut errors));
    let dynamics =
        singles.get("dynamics").and_then(|b| super::lower_dynamics::lower_dynamics(b, base_dir, &mut errors));
    if let Some(span) = analyses.dynamics_span {
        super::lower_dynamics_blocks::check_dynamics_needs(
            span,
            singles.contains_key("dynamics"),
            gears.as_ref(),
            dynamics.as_ref(),
            &mut errors,
        );
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
        super::lower_gearbox::check_immersion(
            gb.lubrication.as_ref(),
            g,
            super::lower_gearbox::lubrication_span(block),
            &mut errors,
        );
    }
    if let (Some(gb), Some(block), false) = (&gearbox, singles.get("gearbox"), lubricant_failed) {
        super::lower_gearbox::check_gearbox_needs(gb, block, lubricant.as_ref(), &analyses, &mut errors);
    }
    if !lubricant_failed {
        super::lower_lubricant::check_film_needs(&analyses, lubricant.as_ref(), &mut errors);
    }
    if let Some(g) = gears.as_ref().filter(|g| g.internal) {
        let wants = super::lower_gears::InternalPairWants {
            teeth: g.wants_teeth(&analyses, dynamics.as_ref()),
            dynamics: analyses.dynamics_span,
            gearbox: singles.get("gearbox").map(|b| b.kind.span),
        };
        super::lower_gears::check_internal_pair(g, &wants, &mut errors);
    } else if let Some(g) = gears.as_ref().filter(|g| g.wants_teeth(&analyses, dynamics.as_ref())) {
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
            if let Some(problem) = scene.pair_alone() {
                errors.extend(super::lower_stage_analyses::check_pair_at_state(&problem));
            }
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

/// Checks a lone unit expression against a dimension (for `gearloss units` and tests).
pub fn unit_scale(text: &str, expected: Dimension) -> Result<f64, Vec<Diagnostic>> {
    let u = super::parse::parse_unit_text(text)?;
    let mut errors = Vec::new();
    match checked_scale("unit", Some(&u), expected, u.span, &mut errors) {
        Some(s) => Ok(s.factor),
        None => Err(errors),
    }
}
