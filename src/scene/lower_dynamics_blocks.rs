//! Lowering of the sub-blocks of `dynamics`: the bearings of the 6-DOF model, the free response
//! and the static transmission error.

use super::ast::*;
use super::fields::{scalar, sweep_values, unknown_name, Fields};
use super::units::Dimension;
use crate::diagnostics::{Diagnostic, DiagnosticKind, Span};
use crate::dynamics::six_dof::Bearing;
use crate::model::{AngularVelocity, DynamicsSpec, FreeResponseSpec, GearPair, Sweep};
use crate::scene::units::SiQuantity;

const STE_KEYS: &[&str] = &["amplitudes", "phases"];
const BEARING_KEYS: &[&str] = &["loa", "oloa", "damping_ratio"];

/// `bearings { pinion { loa = 5e8 N/m  oloa = 5e8 N/m  damping_ratio = 0.02 }  wheel { ... } }`.
pub(super) fn bearings(f: &Fields, block: &Block, model: &str, errors: &mut Vec<Diagnostic>) -> Option<[Bearing; 2]> {
    let Some(b) = f.blocks.iter().find(|b| b.kind.text == "bearings") else {
        errors.push(
            Diagnostic::new(DiagnosticKind::MissingKey, block.kind.span, format!("the {model} model needs `bearings`"))
                .hint("add `bearings { pinion { loa = 5e8 N/m  oloa = 5e8 N/m  damping_ratio = 0.02 }  wheel { loa = 5e8 N/m  oloa = 5e8 N/m  damping_ratio = 0.02 } }`"),
        );
        return None;
    };
    let t = Fields::read("`bearings`", b.span, &b.items, &[], &["pinion", "wheel"], &[], errors);
    let mut out = [None, None];
    for (i, name) in ["pinion", "wheel"].iter().enumerate() {
        let Some(g) = t.blocks.iter().find(|x| x.kind.text == *name) else {
            errors.push(
                Diagnostic::new(DiagnosticKind::MissingKey, b.kind.span, format!("`bearings` has no `{name}`"))
                    .hint(format!("add `{name} {{ loa = 5e8 N/m  oloa = 5e8 N/m  damping_ratio = 0.02 }}`")),
            );
            continue;
        };
        let k = Fields::read(format!("the `{name}` bearing"), g.span, &g.items, BEARING_KEYS, &[], &[], errors);
        let stiff = |key: &str, errors: &mut Vec<Diagnostic>| -> Option<f64> {
            let Some((_, v)) = k.values.get(key) else {
                errors.push(k.missing(key, "5e8 N/m"));
                return None;
            };
            let (x, _) = scalar(key, v, Dimension::STIFFNESS, errors)?;
            if x > 0.0 {
                Some(x)
            } else {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::OutOfRange,
                        v.span,
                        format!("`{key}` bearing stiffness must be positive"),
                    )
                    .hint("rolling-element bearings with their housing: about 1e8 to 1e10 N/m"),
                );
                None
            }
        };
        let (loa, oloa) = (stiff("loa", errors), stiff("oloa", errors));
        let zeta = k.number("damping_ratio", 0.0, 1.0, errors).map_or(0.02, |g| g.value);
        if let (Some(loa), Some(oloa)) = (loa, oloa) {
            out[i] = Some(Bearing { loa, oloa, damping_ratio: zeta });
        }
    }
    Some([out[0]?, out[1]?])
}

/// Most mesh periods of a free response.
pub(crate) const MAX_FREE_PERIODS: usize = 2000;

/// `free_response { x0 = 2e-6 in  v0 = 20 in/s  periods = 20 }` (He & Singh Figs 8–9).
pub(super) fn free_response(f: &Fields, errors: &mut Vec<Diagnostic>) -> Option<Option<FreeResponseSpec>> {
    let Some(b) = f.blocks.iter().find(|b| b.kind.text == "free_response") else { return Some(None) };
    let t = Fields::read("`free_response`", b.span, &b.items, &["x0", "v0", "periods"], &[], &[], errors);
    let get = |key: &str, dim: Dimension, errors: &mut Vec<Diagnostic>| -> Option<f64> {
        match t.values.get(key) {
            None => Some(0.0),
            Some((_, v)) => scalar(key, v, dim, errors).map(|(x, _)| x),
        }
    };
    let x0 = get("x0", Dimension::LENGTH, errors);
    let v0 = get("v0", Dimension::VELOCITY, errors);
    let periods = t.number("periods", 1.0, MAX_FREE_PERIODS as f64, errors).map_or(20.0, |g| g.value);
    let (x0, v0) = (x0?, v0?);
    if x0 == 0.0 && v0 == 0.0 {
        errors.push(
            Diagnostic::new(DiagnosticKind::MissingKey, b.kind.span, "a free response needs an initial state")
                .hint("give `x0` (a DTE) or `v0` (its rate), e.g. `x0 = 2e-6 in  v0 = 20 in/s`"),
        );
        return None;
    }
    Some(Some(FreeResponseSpec { x0, v0, periods: periods.round() as usize }))
}

/// `transmission_error { amplitudes = [1.5, 0.4] um  phases = [0, 90] deg }`: ε(t) = Σ a_n cos(2π n t/T + φ_n).
pub(super) fn transmission_error(f: &Fields, errors: &mut Vec<Diagnostic>) -> Option<Vec<(f64, f64)>> {
    let Some(b) = f.blocks.iter().find(|b| b.kind.text == "transmission_error") else { return Some(Vec::new()) };
    let t = Fields::read("`transmission_error`", b.span, &b.items, STE_KEYS, &[], &[], errors);
    let Some((_, a)) = t.values.get("amplitudes") else {
        errors.push(t.missing("amplitudes", "[1.5, 0.4] um"));
        return None;
    };
    let (amps, _, _, _) = sweep_values("amplitudes", a, Dimension::LENGTH, errors)?;
    let phases = match t.values.get("phases") {
        None => vec![0.0; amps.len()],
        Some((_, p)) => {
            let (ph, _, _, _) = sweep_values("phases", p, Dimension::ANGLE, errors)?;
            if ph.len() != amps.len() {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::OutOfRange,
                        p.span,
                        format!("{} phases for {} amplitudes", ph.len(), amps.len()),
                    )
                    .hint("give one phase per harmonic, or none (all zero)"),
                );
                return None;
            }
            ph
        }
    };
    Some(amps.into_iter().zip(phases).collect())
}

/// `stability_map(pinion_speed = 1000..60000 rpm step 100)`.
pub(crate) fn lower_stability_map(call: &Call, errors: &mut Vec<Diagnostic>) -> Option<Sweep<AngularVelocity>> {
    let mut out = None;
    for (name, value) in &call.arguments {
        if name.text != "pinion_speed" {
            errors.push(unknown_name("argument of `stability_map`", name, &["pinion_speed"]));
            continue;
        }
        let (si, unit, written, factor) = sweep_values("pinion_speed", value, Dimension::ANGULAR_VELOCITY, errors)?;
        if si.iter().any(|x| *x <= 0.0) {
            errors.push(
                Diagnostic::new(DiagnosticKind::OutOfRange, value.span, "stability map speeds must be positive")
                    .hint("write e.g. `1000..60000 rpm step 100`"),
            );
            return None;
        }
        out = Some(Sweep {
            values: si.into_iter().map(AngularVelocity::from_si).collect(),
            unit,
            factor,
            written_values: written,
            span: value.span,
        });
    }
    if out.is_none() {
        errors.push(
            Diagnostic::new(DiagnosticKind::MissingKey, call.span, "`stability_map` needs `pinion_speed`")
                .hint("write `stability_map(pinion_speed = 1000..60000 rpm step 100)`"),
        );
    }
    out
}

/// What the dynamics analyses need: a `dynamics` block, both gears' inertias, and their masses for a
/// model on bearings.
pub(super) fn check_dynamics_needs(
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
