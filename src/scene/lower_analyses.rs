//! The `analyses` block: what the scene asks to compute (efficiency and its formulations, the map,
//! friction along the line of action, film, dynamics, stability map, numerics, thermal balance, duty
//! cycle, transmission error), with where each was asked for.

use super::ast::*;
use super::fields::{unknown_name, Fields};
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::model::*;

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
    "drive_cycle",
];
const FORMULATIONS: &[&str] = &["external", "internal"];

/// The `analyses` block; a drive's (`drive`) map is given at its ends.
pub(super) fn lower_analyses(block: &Block, drive: bool, errors: &mut Vec<Diagnostic>) -> Analyses {
    let keys: &[&str] = if drive { &["stages"] } else { &[] };
    let f = Fields::read("the `analyses` block", block.span, &block.items, keys, &[], ANALYSES, errors);
    let mut a =
        Analyses { stages: f.values.get("stages").and_then(|(_, v)| stage_names(v, errors)), ..Default::default() };
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
                    "drive_cycle" => a.drive_cycle = Some(call.span),
                    _ => {}
                }
            }
        }
    }
    a
}

/// `stages = [first, second]`: names of a drive's stages, each with where it is written.
fn stage_names(value: &Value, errors: &mut Vec<Diagnostic>) -> Option<Vec<(String, crate::diagnostics::Span)>> {
    let hint = "write the stages' names as a list: `stages = [first, second]`";
    let ValueKind::List { items, unit: None } = &value.kind else {
        errors.push(
            Diagnostic::new(DiagnosticKind::WrongDimension, value.span, "`stages` expects a list of stage names")
                .hint(hint),
        );
        return None;
    };
    let mut names = Vec::new();
    for item in items {
        match item {
            ListItem::Name(n) => names.push((n.text.clone(), n.span)),
            ListItem::Number(_, s) => errors
                .push(Diagnostic::new(DiagnosticKind::WrongDimension, *s, "a stage is named, not numbered").hint(hint)),
        }
    }
    if items.is_empty() {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                value.span,
                "`stages` is an empty list: no stage would be analysed",
            )
            .hint("name at least one stage, or leave `stages` out for every stage"),
        );
        return None;
    }
    Some(names)
}

/// What the lowered analyses ask, as the evaluation reads them.
impl crate::model::Analyses {
    /// Whether the analyses of one pair run on the drive's stage `name` (`stages = [...]` names it,
    /// or it names none).
    pub fn analyses_stage(&self, name: &str) -> bool {
        self.stages.as_ref().is_none_or(|s| s.iter().any(|(n, _)| n == name))
    }

    /// Whether the scene asks for an analysis of one pair's mesh (run on each stage of a drive).
    pub fn wants_pair_analyses(&self) -> bool {
        self.friction_along_loa
            || self.film
            || self.dynamics
            || self.numerics
            || self.stability_map.is_some()
            || self.transmission_error.is_some()
    }

    /// Whether a drive runs its analysed stages' meshes as pairs alone: it asks for an analysis of
    /// one pair, or names `detail_points` and asks for `efficiency` (each mesh's efficiency along
    /// its mesh cycle in full at those points, as the pair alone reports it).
    pub fn runs_stage_pairs(&self, detail_points_named: bool) -> bool {
        self.wants_pair_analyses() || (detail_points_named && self.efficiency.is_some()) || self.asks_nothing()
    }

    /// A scene with no `analyses` (or an empty one): a pair reports its geometry and its contact
    /// along the line of action, and a drive each stage's mesh as that pair alone.
    pub fn asks_nothing(&self) -> bool {
        self.efficiency.is_none()
            && !self.wants_pair_analyses()
            && self.drive_cycle.is_none()
            && self.thermal_balance.is_none()
            && self.duty_cycle.is_none()
            && self.efficiency_map.is_none()
            && self.map_ends.is_none()
    }

    /// The formulation a drive's duty cycle and drive cycle run under: `efficiency`'s first, else external.
    pub fn first_formulation(&self) -> Formulation {
        self.efficiency.as_ref().and_then(|f| f.first().copied()).unwrap_or(Formulation::External)
    }
}
