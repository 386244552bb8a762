//! A scene written with `stage` blocks lowered into a [`Scene`] with its [`SceneDrive`]: the
//! stages (each pair checked as one pair is), the shafts, the drive put together and checked, the
//! operating points at the drive's ends, the lubricant, friction laws and analyses as for one pair.
//! A drive's report is its efficiency (with its map, thermal balance and duty cycle); the analyses
//! of one pair's contact, film and dynamics run on its stages' meshes
//! ([`super::lower_stage_analyses`]).

use std::collections::BTreeMap;

use super::ast::*;
use super::fields::Fields;
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::model::*;

pub(super) fn lower_drive_scene(
    ast: &SceneAst,
    (top, materials, singles): (&Fields, &BTreeMap<&str, Material>, &BTreeMap<&str, &Block>),
    stage_blocks: &[&Block],
    (base_dir, one_pair): (Option<&std::path::Path>, bool),
    mut errors: Vec<Diagnostic>,
) -> Result<Scene, Vec<Diagnostic>> {
    let errors = &mut errors;
    let stages: Vec<_> =
        stage_blocks.iter().filter_map(|b| super::lower_stage::lower_stage(b, materials, errors)).collect();
    for (i, s) in stages.iter().enumerate() {
        if stages[..i].iter().any(|t| t.name.text == s.name.text) {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::DuplicateKey,
                    s.name.span,
                    format!("two stages are named `{}`", s.name.text),
                )
                .hint("give each stage a name of its own"),
            );
        }
    }
    let cycle_blocks = (singles.get("vehicle"), singles.get("drive_cycle"));
    let operating = singles
        .get("operating")
        .and_then(|b| super::lower_drive_operating::lower_drive_operating(b, cycle_blocks.1.is_some(), errors));
    let gearbox_block = singles.get("gearbox");
    let shafts = gearbox_block.and_then(|b| super::lower_shafts::lower_shafts(b, materials, errors));
    if gearbox_block.is_none() {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::MissingKey,
                ast.title_span,
                "a drive of stages needs a `gearbox` block with its shafts",
            )
            .hint("add `gearbox { shaft motor { input ... } shaft output { output ... } }`"),
        );
    }
    let housing = gearbox_block
        .and_then(|g| {
            g.items.iter().find_map(|i| match i {
                Item::Block(b) if b.kind.text == "housing" => Some(b),
                _ => None,
            })
        })
        .and_then(|b| super::lower_thermal::lower_housing(b, errors));
    let lubricant = super::lower_lubricant::scene_lubricant(
        singles,
        top,
        operating.as_ref().map(|o| &o.0),
        housing.as_ref(),
        errors,
    );
    if let Some((op, _)) = &operating {
        super::lower_operating::check_oil_sweep(op, lubricant.as_ref(), errors);
    }
    let duty_cycle = match (singles.get("duty_cycle"), &operating) {
        (Some(b), Some((_, ends))) => super::lower_thermal::lower_duty_cycle(b, &step_keys(*ends), errors),
        _ => None,
    };
    let friction = singles.get("friction").map_or_else(Vec::new, |b| super::lower_friction::lower_friction(b, errors));
    let analyses = singles
        .get("analyses")
        .map_or_else(Analyses::default, |b| super::lower_analyses::lower_analyses(b, true, errors));
    check_analyses(singles.get("analyses").copied(), &analyses, ast.title_span, friction.is_empty(), errors);
    let dynamics = singles.get("dynamics").and_then(|b| super::lower_dynamics::lower_dynamics(b, base_dir, errors));
    let cycle = super::lower_vehicle::cycle_of_scene(cycle_blocks, analyses.drive_cycle, base_dir, errors);
    if let (Some(c), Some((op, _)), Some(_)) = (&cycle, &operating, analyses.drive_cycle) {
        let transient = housing.as_ref().is_some_and(|h| h.heat_capacity.is_some());
        // (An `oil_temperature` written but refused has its own error.)
        let written =
            singles.get("operating").is_some_and(|b| b.items.iter().any(|i| i.head().text == "oil_temperature"));
        if !transient && !written && op.oil_temperature.is_none() && op.oil_temperatures.is_none() {
            errors.push(
                Diagnostic::new(DiagnosticKind::MissingKey, c.span, "the drive cycle needs the oil's temperature")
                    .hint("give `oil_temperature = 80 degC` in `operating` (held over the cycle), or the housing's `heat_capacity` (the sump then follows the cycle)"),
            );
        }
    }
    let lubricant_failed =
        lubricant.is_none() && (singles.contains_key("lubricant") || top.values.contains_key("lubricant"));
    super::lower_thermal::check_thermal_needs(
        &super::lower_thermal::ThermalInputs {
            housing: housing.as_ref(),
            housing_failed: gearbox_block.is_some_and(|g| g.items.iter().any(|i| i.head().text == "housing")),
            duty_block: singles.get("duty_cycle").map(|b| b.kind.span),
            equilibrium: operating.as_ref().and_then(|o| o.0.equilibrium),
            moves_with_temperature: lubricant.as_ref().is_none_or(|l| l.oil.is_some()),
            lubricant_failed,
        },
        &analyses,
        errors,
    );
    if !lubricant_failed {
        for s in &stages {
            super::lower_friction::check_friction_needs(&friction, &s.pair, lubricant.as_ref(), errors);
            for pair in s.kind.further_pairs() {
                super::lower_friction::check_friction_needs(&friction, pair, lubricant.as_ref(), errors);
            }
        }
    }
    super::lower_stage_analyses::check_stage_analyses(
        &super::lower_stage_analyses::StageAnalysesInputs {
            stages: &stages,
            analyses: &analyses,
            dynamics: dynamics.as_ref(),
            dynamics_block: singles.get("dynamics").copied(),
            lubricant: lubricant.as_ref(),
            lubricant_failed,
            operating: operating.as_ref().map(|o| &o.0),
            detail_points: singles
                .get("operating")
                .and_then(|b| b.items.iter().map(Item::head).find(|k| k.text == "detail_points"))
                .map(|k| k.span),
        },
        errors,
    );
    let (Some((operating, ends)), Some(shafts), Some(gearbox)) = (operating, shafts, gearbox_block) else {
        return Err(std::mem::take(errors));
    };
    check_oil_needs(&shafts, &stages, lubricant.as_ref(), lubricant_failed, gearbox.kind.span, errors);
    check_gear_faces(&stages, errors);
    let equilibrium = operating.equilibrium.is_some();
    let layout = super::lower_drive::build_drive(
        &stages,
        stages.len() == stage_blocks.len(),
        shafts,
        ends,
        (gearbox.kind.span, one_pair),
        errors,
    );
    let balance_rows = analyses.thermal_balance.is_some() && housing.is_some() && !equilibrium;
    match layout {
        Some(layout) if errors.is_empty() => Ok(Scene {
            title: ast.title.clone(),
            gears: stages[0].pair.clone(),
            lubricant,
            operating,
            friction,
            dynamics,
            gearbox: None,
            housing,
            duty_cycle,
            analyses,
            drive: Some(SceneDrive {
                layout,
                further_pairs: stages.iter().map(|s| s.kind.further_pairs().into_iter().cloned().collect()).collect(),
                pairs: stages.into_iter().map(|s| s.pair).collect(),
                cycle,
                one_pair,
                oil_at_balance: equilibrium,
                balance_rows,
            }),
        }),
        _ => Err(std::mem::take(errors)),
    }
}

/// A drive's duty steps name the ends its `operating` block does (`output_torque`, ...).
fn step_keys(ends: crate::drive::DriveOperating) -> super::lower_thermal::StepKeys {
    use crate::drive::ShaftEnd::{Input, Output};
    super::lower_thermal::StepKeys {
        torque: if ends.torque_at == Input { "input_torque" } else { "output_torque" },
        speed: if ends.speed_at == Output { "output_speed" } else { "input_speed" },
        signed: true,
    }
}

/// A drive's analyses: `efficiency` (and its map, the thermal balance, the duty cycle), which need
/// friction laws; a drive that asks for nothing, or only for analyses of one pair, runs its stages'
/// meshes as pairs alone ([`super::lower_stage_analyses`]).
fn check_analyses(block: Option<&Block>, a: &Analyses, title: Span, no_laws: bool, errors: &mut Vec<Diagnostic>) {
    match (a.efficiency.is_some(), a.friction_span) {
        (false, _) if a.drive_cycle.is_some() && no_laws => errors.push(
            Diagnostic::new(
                DiagnosticKind::MissingKey,
                a.drive_cycle.unwrap_or(title),
                "a drive cycle's losses need friction laws, and the scene lists none",
            )
            .hint("add a block such as `friction { iso_14179_2(x_l = 0.75) }` (README lists the laws)"),
        ),
        (false, _) if a.drive_cycle.is_some() || a.wants_pair_analyses() || a.asks_nothing() => {}
        (false, _) => errors.push(
            Diagnostic::new(
                DiagnosticKind::MissingKey,
                block.map_or(title, |b| b.kind.span),
                "the thermal balance, the duty cycle and the efficiency map charge the drive's efficiency, and the scene asks for none",
            )
            .hint("add `efficiency(formulations = [external])` to `analyses`"),
        ),
        (true, Some(span)) if no_laws => errors.push(
            Diagnostic::new(
                DiagnosticKind::MissingKey,
                span,
                "`efficiency` needs friction laws, and the scene lists none",
            )
            .hint("add a block such as `friction { iso_14179_2(x_l = 0.75) }` (README lists the laws)"),
        ),
        _ => {}
    }
}

/// Two gears of parallel stages on one shaft may not share any of its length: their faces (each
/// `at` ± b/2) must not overlap.
fn check_gear_faces(stages: &[super::lower_stage::StageDecl], errors: &mut Vec<Diagnostic>) {
    let faces: Vec<(&str, f64, f64, &str, crate::diagnostics::Span)> = stages
        .iter()
        .filter(|s| s.kind.coaxial().is_none())
        .flat_map(|s| {
            let b = s.pair.face_width.value.value;
            s.places.iter().map(move |(shaft, at)| (shaft.text.as_str(), *at, b, s.name.text.as_str(), shaft.span))
        })
        .collect();
    for (k, (shaft, at, b, stage, span)) in faces.iter().enumerate() {
        let Some(other) = faces[..k].iter().find(|f| f.0 == *shaft && (f.1 - at).abs() < 0.5 * (f.2 + b)) else {
            continue;
        };
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                *span,
                format!(
                    "stage `{stage}`'s gear on shaft `{shaft}` at {} mm (face {} mm) overlaps stage `{}`'s gear at {} mm (face {} mm)",
                    mm(*at),
                    mm(*b),
                    other.3,
                    mm(other.1),
                    mm(other.2)
                ),
            )
            .hint("two gears cannot share a stretch of one shaft: give each its own `at` (the face mid-plane), at least half the sum of their face widths apart"),
        );
    }
}

/// A length (m) in mm as a message shows it: to the µm, trailing zeros left out.
fn mm(x: f64) -> String {
    let text = format!("{:.3}", x * 1e3);
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// Bearings and injection need the oil's kinematic viscosity and density.
fn check_oil_needs(
    shafts: &[super::lower_shafts::ShaftDecl],
    stages: &[super::lower_stage::StageDecl],
    lubricant: Option<&Lubricant>,
    lubricant_failed: bool,
    gearbox: Span,
    errors: &mut Vec<Diagnostic>,
) {
    let needs = shafts.iter().any(|s| !s.bearings.is_empty())
        || stages.iter().any(|s| matches!(s.lubrication, Some(crate::losses::Lubrication::Injection { .. })));
    if needs && !lubricant_failed && lubricant.and_then(|l| l.kinematic_viscosity_si()).is_none() {
        errors.push(
            Diagnostic::new(DiagnosticKind::MissingKey, gearbox, "bearing and injection losses need the oil's kinematic viscosity and density")
                .hint("give the lubricant by grade or by `nu_40`, `nu_100` and `density_15`, with `oil_temperature` in `operating`"),
        );
    }
}
