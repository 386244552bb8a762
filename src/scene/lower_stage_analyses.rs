//! A drive's analyses of one pair (`friction_along_loa`, `film`, `dynamics`, `stability_map`,
//! `numerics`, `transmission_error`) run on the meshes of its stages: what they need of each stage
//! they run on, checked here as a scene of one pair has it checked.
//!
//! ```text
//! analyses {
//!     efficiency(formulations = [external])
//!     friction_along_loa
//!     film
//!     stages = [second]        # the stages whose meshes are analysed; every stage without it
//! }
//! ```
//!
//! The analyses run at the drive's first operating point, or at those `detail_points` names in its
//! `operating` block ([`crate::evaluate::stage_pairs`]).

use super::ast::Block;
use super::lower_stage::StageDecl;
use crate::diagnostics::{Diagnostic, DiagnosticKind, Span};
use crate::model::{Analyses, DynamicsSpec, GearPair, Lubricant, Operating};

/// What a drive's analyses of one pair are checked against.
pub(super) struct StageAnalysesInputs<'a> {
    pub stages: &'a [StageDecl],
    pub analyses: &'a Analyses,
    pub dynamics: Option<&'a DynamicsSpec>,
    pub dynamics_block: Option<&'a Block>,
    pub lubricant: Option<&'a Lubricant>,
    pub lubricant_failed: bool,
    pub operating: Option<&'a Operating>,
    /// Where the operating block writes `detail_points`, if it does.
    pub detail_points: Option<Span>,
}

/// The stage names `stages = [...]` lists exist; the analyses have operating points to run at;
/// each analysed stage's pairs (a planetary stage's sun–planet and planet–ring pairs) give what the
/// analyses need (inertias for the dynamics, outlines for the teeth, an external pair for the
/// dynamic models), and the lubricant its pressure–viscosity coefficient for the film.
pub(super) fn check_stage_analyses(i: &StageAnalysesInputs, errors: &mut Vec<Diagnostic>) {
    let a = i.analyses;
    let listed = a.stages.as_deref().unwrap_or_default();
    for (k, (name, span)) in listed.iter().enumerate() {
        if listed[..k].iter().any(|(n, _)| n == name) {
            errors.push(
                Diagnostic::new(DiagnosticKind::DuplicateKey, *span, format!("`stages` names stage `{name}` twice"))
                    .hint("name each stage once"),
            );
        } else if !i.stages.iter().any(|s| &s.name.text == name) {
            let names: Vec<String> = i.stages.iter().map(|s| format!("`{}`", s.name.text)).collect();
            errors.push(
                Diagnostic::new(DiagnosticKind::UnknownName, *span, format!("no stage is named `{name}`"))
                    .hint(format!("the drive's stages are {}", names.join(", "))),
            );
        }
    }
    let Some(asked) = first_asked(a, i.detail_points) else {
        if let Some(span) = i.detail_points {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::MissingKey,
                    span,
                    "a drive's `detail_points` are the points its stages' meshes are reported in full at, and the scene asks for neither `efficiency` nor an analysis of one pair",
                )
                .hint("add `efficiency(formulations = [external])`, `friction_along_loa`, `film` or `dynamics` to `analyses`, or leave `detail_points` out"),
            );
        }
        if let Some((_, span)) = a.stages.as_ref().and_then(|s| s.first()) {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::MissingKey,
                    *span,
                    "`stages` names the stages the analyses of one pair run on, and the scene asks for none",
                )
                .hint("add `friction_along_loa`, `film` or `dynamics` to `analyses`, or leave `stages` out"),
            );
        }
        return;
    };
    if i.operating.is_some_and(|o| o.count() == 0) {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::MissingKey,
                asked,
                "the analyses of one pair run on each stage at the drive's operating points, and this scene gives none",
            )
            .hint("add `output_torque = [150] N*m` and `output_speed = [1000] rpm` to `operating` (one pair on a drive cycle: `pinion_torque` and `pinion_speed`); the drive cycle keeps its own"),
        );
    }
    if !i.lubricant_failed {
        super::lower_lubricant::check_film_needs(a, i.lubricant, errors);
    }
    if let Some(span) = a.dynamics_span {
        super::lower_dynamics_blocks::check_dynamics_needs(span, i.dynamics_block.is_some(), None, i.dynamics, errors);
    }
    for stage in i.stages.iter().filter(|s| a.analyses_stage(&s.name.text)) {
        if let (Some((what, why)), Some(span)) = (stage.kind.off_fixed_axes(), a.dynamics_span) {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    span,
                    format!("the dynamic models are of one pair on fixed axes; {what} `{}` {why}", stage.name.text),
                )
                .hint("name the stages the dynamics run on without it: `stages = [...]` in `analyses`"),
            );
            continue;
        }
        check_pair(&stage.pair, i, errors);
        for pair in stage.kind.further_pairs() {
            check_pair(pair, i, errors);
        }
    }
}

/// Where the first analysis of one pair is asked for (the `detail_points` when those and
/// `efficiency` ask for the meshes in full); None when the drive runs no stage's mesh as a pair.
fn first_asked(a: &Analyses, detail_points: Option<Span>) -> Option<Span> {
    if !a.runs_stage_pairs(detail_points.is_some()) {
        return None;
    }
    a.friction_span
        .or(a.film_span)
        .or(a.dynamics_span)
        .or(a.transmission_error.as_ref().map(|t| t.span))
        .or(detail_points)
}

/// One analysed pair: what the dynamics and the teeth need of it.
fn check_pair(pair: &GearPair, i: &StageAnalysesInputs, errors: &mut Vec<Diagnostic>) {
    let a = i.analyses;
    if pair.internal {
        let wants = super::lower_gears::InternalPairWants {
            teeth: pair.wants_teeth(a, i.dynamics),
            dynamics: a.dynamics_span,
            gearbox: None,
        };
        let before = errors.len();
        super::lower_gears::check_internal_pair(pair, &wants, errors);
        for e in &mut errors[before..] {
            *e = e.clone().hint("a planetary stage's planet–ring mesh is internal: leave that stage out with `stages = [...]` in `analyses`");
        }
        return;
    }
    if let Some(span) = a.dynamics_span {
        super::lower_dynamics_blocks::check_dynamics_needs(span, true, Some(pair), i.dynamics, errors);
    }
    if pair.wants_teeth(a, i.dynamics) {
        super::lower_teeth::check_teeth(pair, errors);
    }
}

/// The checks of one mesh's problem that read its operating speeds and counts (a scene of one
/// pair's, a drive's stage mesh at its operating state): every problem found.
pub(crate) fn check_pair_at_state(problem: &crate::mesh::MeshProblem) -> Vec<Diagnostic> {
    let mut errors = Vec::new();
    super::lower_dynamics::check_frequency_ratio(problem, &mut errors);
    super::lower_operating::check_record_rows(problem, &mut errors);
    errors
}
