//! Lowering of the `dynamics` block and the dynamics analyses.

use std::path::Path;

use super::ast::*;
use super::fields::{scalar, sweep_values, unknown_name, Fields};
use super::lower_dynamics_blocks::{bearings, free_response, transmission_error};
use super::units::Dimension;
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::dynamics::models::catalog::{entry, MODELS};
use crate::dynamics::DynamicFormulation;
use crate::geometry::stiffness::catalog::named_models;
use crate::geometry::stiffness::StiffnessId;
use crate::model::{DynamicModel, DynamicsSpec, Gear, Solver, StiffnessSpec};

const KEYS: &[&str] =
    &["model", "formulations", "mesh_stiffness", "damping_ratio", "friction", "solver", "transmission_error"];
const STIFFNESS_KEYS: &[&str] = &["single", "double", "triple", "table", "file", "per_length"];
const SOLVERS: &[&str] = &["auto", "magnus"];
const FORMULATIONS: &[&str] = &["base", "external", "internal", "internal_chord"];

pub(crate) fn lower_dynamics(
    block: &Block,
    base_dir: Option<&Path>,
    errors: &mut Vec<Diagnostic>,
) -> Option<DynamicsSpec> {
    let f = Fields::read(
        "the `dynamics` block",
        block.span,
        &block.items,
        KEYS,
        &["mesh_stiffness", "transmission_error", "free_response", "bearings"],
        &[],
        errors,
    );
    let names: Vec<&str> = MODELS.iter().map(|m| m.name).collect();
    let entry = f.name("model", &names, errors).and_then(|n| entry(&n.text)).unwrap_or(&MODELS[0]);
    let formulations = match f.values.get("formulations") {
        None => vec![DynamicFormulation::Base, DynamicFormulation::External, DynamicFormulation::Internal],
        Some((_, v)) => formulations(v, errors)?,
    };
    let damping_ratio = f.number("damping_ratio", 0.0, 1.0, errors).map_or(0.05, |g| g.value);
    let solver = match f.name("solver", SOLVERS, errors).map(|n| n.text.as_str()) {
        Some("magnus") => Solver::Magnus,
        _ => Solver::Auto,
    };
    let friction = dynamics_friction(&f, errors)?;
    if friction.is_none() && formulations.iter().any(|f| *f != DynamicFormulation::Base) {
        errors.push(
            f.missing("friction", "coulomb(mu = 0.08)")
                .hint("the external and internal formulations need a friction law"),
        );
        return None;
    }
    let transmission_error = transmission_error(&f, errors)?;
    let free_response = free_response(&f, errors)?;
    if let Some(bad) = formulations.iter().find(|x| !entry.formulations.contains(x)) {
        let allowed: Vec<String> = entry.formulations.iter().map(|x| format!("`{}`", x.name())).collect();
        let names: Vec<&str> = entry.formulations.iter().map(|x| x.name()).collect();
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                f.values.get("formulations").map_or(block.kind.span, |(_, v)| v.span),
                format!("the {} model takes the {} formulations, not `{}`", entry.name, and_list(&allowed), bad.name()),
            )
            .hint(format!(
                "{} in the {} model: write `formulations = [{}]`",
                entry.formulations_reason,
                entry.label,
                names.join(", ")
            )),
        );
        return None;
    }
    let bearings = if entry.on_bearings {
        Some(bearings(&f, block, entry.name, errors)?)
    } else {
        if let Some(b) = f.blocks.iter().find(|b| b.kind.text == "bearings") {
            let owners: Vec<&str> = MODELS.iter().filter(|m| m.on_bearings).map(|m| m.name).collect();
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    b.kind.span,
                    format!("`bearings` belong to the {} model", owners.join(" and ")),
                )
                .hint(format!(
                    "write `model = {}` to use them, or leave them out for the {} model",
                    owners.join("` or `model = "),
                    entry.label
                )),
            );
            return None;
        }
        None
    };
    let model = DynamicModel { id: entry.id, bearings };
    let stiffness = stiffness(&f, base_dir, errors)?;
    Some(DynamicsSpec {
        model,
        formulations,
        stiffness,
        damping_ratio,
        friction,
        solver,
        transmission_error,
        free_response,
        span: block.kind.span,
    })
}

/// The one friction law of the dynamics (`friction = coulomb(mu = 0.08)`), if given; None when it
/// fails to lower.
fn dynamics_friction(f: &Fields, errors: &mut Vec<Diagnostic>) -> Option<Option<crate::model::FrictionLawSpec>> {
    Some(match f.values.get("friction") {
        None => None,
        Some((_, v)) => match &v.kind {
            ValueKind::Call(c) => match crate::friction::catalog::entry(&c.name.text) {
                Some(_) => {
                    let mut laws = super::lower_friction::lower_law(c, errors);
                    if laws.len() > 1 {
                        errors.push(
                            Diagnostic::new(
                                DiagnosticKind::OutOfRange,
                                v.span,
                                "the dynamics take one friction law, not a sweep",
                            )
                            .hint("give one value, e.g. `friction = coulomb(mu = 0.08)`"),
                        );
                        return None;
                    }
                    laws.pop()
                }
                None => {
                    let ids: Vec<&str> = crate::friction::catalog::LAWS.iter().map(|l| l.id.name()).collect();
                    errors.push(unknown_name("law for `friction`", &c.name, &ids));
                    return None;
                }
            },
            _ => {
                errors.push(
                    Diagnostic::new(DiagnosticKind::WrongDimension, v.span, "`friction` expects a law")
                        .hint("write `friction = coulomb(mu = 0.08)`"),
                );
                return None;
            }
        },
    })
}

/// "`a`", "`a` and `b`", "`a`, `b` and `c`".
fn and_list(items: &[String]) -> String {
    match items.split_last() {
        None => String::new(),
        Some((last, [])) => last.clone(),
        Some((last, rest)) => format!("{} and {last}", rest.join(", ")),
    }
}

fn formulations(v: &Value, errors: &mut Vec<Diagnostic>) -> Option<Vec<DynamicFormulation>> {
    let ValueKind::List { items, unit: None } = &v.kind else {
        errors.push(
            Diagnostic::new(DiagnosticKind::WrongDimension, v.span, "`formulations` expects a list of names")
                .hint("write `formulations = [base, external, internal]`"),
        );
        return None;
    };
    let mut out = Vec::new();
    for item in items {
        match item {
            ListItem::Name(n) => match n.text.as_str() {
                "base" => out.push(DynamicFormulation::Base),
                "external" => out.push(DynamicFormulation::External),
                "internal" => out.push(DynamicFormulation::Internal),
                "internal_chord" => out.push(DynamicFormulation::InternalChord),
                _ => {
                    errors.push(unknown_name("formulation", n, FORMULATIONS));
                    return None;
                }
            },
            ListItem::Number(_, s) => {
                errors.push(
                    Diagnostic::new(DiagnosticKind::WrongDimension, *s, "a formulation is a name")
                        .hint("write `formulations = [base, external, internal]`"),
                );
                return None;
            }
        }
    }
    out.dedup();
    Some(out)
}

/// A stiffness CSV next to the scene: one value per line in N/m (or `tau, k` pairs, then the second
/// column is used); blank lines and lines starting with `#` are skipped.
fn read_stiffness_csv(value: &Value, base_dir: Option<&Path>, errors: &mut Vec<Diagnostic>) -> Option<Vec<f64>> {
    let ValueKind::Text(name) = &value.kind else {
        errors.push(
            Diagnostic::new(DiagnosticKind::WrongDimension, value.span, "`file` expects a \"file name\"")
                .hint("write `file = \"stiffness.csv\"`, a file next to the scene"),
        );
        return None;
    };
    let path = base_dir.map_or_else(|| Path::new(name).to_path_buf(), |d| d.join(name));
    let text = match super::source::read_text(&path, super::source::MAX_TABLE_BYTES) {
        Ok(t) => t,
        Err(e) => {
            errors.push(
                Diagnostic::new(DiagnosticKind::Undefined, value.span, format!("cannot read `{name}`: {e}"))
                    .hint("a text file of at most 4 MiB; the path is relative to the folder of the scene file"),
            );
            return None;
        }
    };
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let field = line.split([',', ';', '\t']).map(str::trim).rfind(|x| !x.is_empty()).unwrap_or("");
        match field.parse::<f64>() {
            Ok(k) if k.is_finite() && k > 0.0 => out.push(k),
            _ => {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::OutOfRange,
                        value.span,
                        format!("`{name}` line {}: `{line}` is not a positive stiffness", i + 1),
                    )
                    .hint("one stiffness in N/m per line (or `tau, k`); `#` starts a comment"),
                );
                return None;
            }
        }
    }
    if out.len() < 4 {
        errors.push(
            Diagnostic::new(DiagnosticKind::OutOfRange, value.span, format!("`{name}` holds {} values", out.len()))
                .hint("give at least 4 values over one mesh cycle"),
        );
        return None;
    }
    Some(out)
}

fn stiffness(f: &Fields, base_dir: Option<&Path>, errors: &mut Vec<Diagnostic>) -> Option<StiffnessSpec> {
    if f.has("mesh_stiffness") {
        let names: Vec<&str> = named_models().map(|m| m.name).collect();
        return f
            .name("mesh_stiffness", &names, errors)
            .and_then(|n| named_models().find(|m| m.name == n.text))
            .map(|m| StiffnessSpec::Named(m.id));
    }
    let Some(b) = f.blocks.iter().find(|b| b.kind.text == "mesh_stiffness") else {
        return Some(StiffnessSpec::Named(StiffnessId::Iso6336));
    };
    let k = Fields::read("`mesh_stiffness`", b.span, &b.items, STIFFNESS_KEYS, &[], &[], errors);
    let get = |key: &str, errors: &mut Vec<Diagnostic>| -> Option<f64> {
        let (_, v) = k.values.get(key)?;
        let (x, _) = scalar(key, v, Dimension::STIFFNESS, errors)?;
        if x > 0.0 {
            Some(x)
        } else {
            errors.push(
                Diagnostic::new(DiagnosticKind::OutOfRange, v.span, format!("`{key}` stiffness must be positive"))
                    .hint("typical spur mesh stiffness is 1e8 to 1e9 N/m"),
            );
            None
        }
    };
    if let Some((_, v)) = k.values.get("per_length") {
        let (x, _) = scalar("per_length", v, Dimension::PRESSURE, errors)?;
        if x > 0.0 {
            return Some(StiffnessSpec::PerLength(x));
        }
        errors
            .push(Diagnostic::new(DiagnosticKind::OutOfRange, v.span, "`per_length` stiffness must be positive").hint(
                "a stiffness density along the contact lines, typically 1e10 to 2e10 N/m^2 (10 to 20 N/(mm*um))",
            ));
        return None;
    }
    if let Some((_, v)) = k.values.get("file") {
        return read_stiffness_csv(v, base_dir, errors).map(StiffnessSpec::Table);
    }
    if let Some((_, v)) = k.values.get("table") {
        let (values, _, _, _) = sweep_values("table", v, Dimension::STIFFNESS, errors)?;
        if values.len() < 4 || values.iter().any(|x| *x <= 0.0) {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    v.span,
                    "a stiffness table needs at least 4 positive values",
                )
                .hint("give k over one mesh cycle, equally spaced, from the entry of a pair at A"),
            );
            return None;
        }
        return Some(StiffnessSpec::Table(values));
    }
    let single = get("single", errors);
    let double = get("double", errors);
    let triple = get("triple", errors);
    match (single, double) {
        (Some(single), Some(double)) => Some(StiffnessSpec::Pairs { single, double, triple }),
        _ => {
            if !k.has("single") || !k.has("double") {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::MissingKey,
                        b.kind.span,
                        "`mesh_stiffness` needs `single` and `double` (or a `table`)",
                    )
                    .hint("write `mesh_stiffness { single = 1.96e8 N/m  double = 3.92e8 N/m }`"),
                );
            }
            None
        }
    }
}

/// Most natural periods per mesh period the dynamics are computed for. The work per mesh period
/// grows with f_n/f_mesh (the trajectory follows every oscillation to locate the extrema); far
/// below the resonances the response is quasi-static, and at 5 000 periods a run still takes seconds.
pub(crate) const MAX_FREQUENCY_RATIO: f64 = 5_000.0;

/// Refuses dynamics at speeds so low that f_n/f_mesh exceeds [`MAX_FREQUENCY_RATIO`] (f_n from the
/// stiffest mesh state, an upper bound), naming the lowest speed allowed.
pub(super) fn check_frequency_ratio(problem: &crate::mesh::MeshProblem, errors: &mut Vec<Diagnostic>) {
    let (Some(spec), a) = (problem.dynamics.as_ref(), &problem.analyses) else { return };
    if !(a.dynamics || a.numerics || a.stability_map.is_some()) {
        return;
    }
    let Ok(g) = problem.gears.geometry() else { return };
    let j = |gear: &Gear| gear.inertia.as_ref().map(|j| j.value.value);
    let (Some(j1), Some(j2)) = (j(&problem.gears.pinion), j(&problem.gears.wheel)) else { return };
    let k_max = spec.stiffness.build(&g, &problem.gears.bodies()).upper_bound(&g);
    let (rp, rw) = (g.base_radius[0], g.base_radius[1]);
    let m_e = j1 * j2 / (j1 * rw * rw + j2 * rp * rp);
    let f_n = (k_max / m_e).sqrt() / (2.0 * std::f64::consts::PI);
    let z1 = g.teeth[0] as f64;
    let lowest_allowed = f_n / MAX_FREQUENCY_RATIO / z1 * 2.0 * std::f64::consts::PI; // rad/s
    let mut sweeps = vec![&problem.operating.pinion_speed];
    sweeps.extend(a.stability_map.as_ref());
    for sweep in sweeps {
        let lowest = sweep.values.iter().map(|w| w.value).fold(f64::INFINITY, f64::min);
        if lowest < lowest_allowed {
            let f_mesh = lowest * z1 / (2.0 * std::f64::consts::PI);
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    sweep.span,
                    format!(
                        "the dynamics at {:.4} {} would follow {:.0} natural periods per mesh period (f_n up to {:.1} Hz, f_mesh {:.4} Hz), above the limit of {MAX_FREQUENCY_RATIO}",
                        lowest / sweep.factor,
                        sweep.unit,
                        f_n / f_mesh,
                        f_n,
                        f_mesh
                    ),
                )
                .hint(format!(
                    "that far below resonance the response is quasi-static; give the dynamics speeds of at least {:.4} {}",
                    lowest_allowed / sweep.factor,
                    sweep.unit
                )),
            );
        }
    }
}
