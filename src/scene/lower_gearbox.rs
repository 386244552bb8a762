//! The `gearbox` block: lubrication method, and the bearings and seals on each shaft.
//!
//! ```text
//! gearbox {
//!     lubrication = dip(pinion_immersion = 0 mm, wheel_immersion = 30 mm, axis_height = 80 mm, housing_width = 200 mm)
//!     pinion_shaft {
//!         bearing(type = cylindrical_roller, bore = 30 mm, outside = 72 mm, at = -40 mm)
//!         bearing(type = cylindrical_roller, bore = 30 mm, outside = 72 mm, at = 40 mm)
//!         seal(diameter = 30 mm)
//!     }
//!     wheel_shaft {
//!         bearing(type = deep_groove_ball, bore = 30 mm, outside = 55 mm, static_load_rating = 11.2 kN,
//!                 model = skf(r1 = 4.1e-7, r2 = 1.7, s1 = 3.73e-3, s2 = 14.6), count = 2)
//!     }
//! }
//! ```

use super::ast::*;
use super::fields::{call_fields, positive, unknown_name, Fields};
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::losses::skf_bearing::{self, SkfConstants};
use crate::losses::{Bearing, BearingType, Gearbox, Lubrication, Seal};
use crate::model::{Force, Length, Velocity, VolumeRate};

const SHAFTS: [&str; 2] = ["pinion_shaft", "wheel_shaft"];
const DIP: &[&str] = &["pinion_immersion", "wheel_immersion", "axis_height", "housing_width"];
const INJECTION: &[&str] = &["flow", "jet_speed"];
pub(crate) const BEARING: &[&str] =
    &["type", "bore", "outside", "mean_diameter", "count", "at", "static_load_rating", "f0", "f1", "y", "model"];
pub(crate) const SKF: &[&str] = &["r1", "r2", "s1", "s2", "y", "mu_bl", "mu_ehl"];
pub(crate) const SEAL: &[&str] = &["diameter", "count"];

fn metres(g: Option<crate::model::Given<Length>>) -> Option<f64> {
    g.map(|g| g.value.value)
}

pub(super) fn lower_gearbox(block: &Block, errors: &mut Vec<Diagnostic>) -> Option<Gearbox> {
    let blocks = [SHAFTS[0], SHAFTS[1], "housing"];
    let f = Fields::read("the `gearbox` block", block.span, &block.items, &["lubrication"], &blocks, &[], errors);
    let before = errors.len();
    let lubrication = f.values.get("lubrication").and_then(|(_, v)| lower_lubrication(v, errors));
    let mut bearings: [Vec<Bearing>; 2] = [Vec::new(), Vec::new()];
    let mut seals: [Vec<Seal>; 2] = [Vec::new(), Vec::new()];
    // (The housing is the thermal balance's: `super::lower_thermal`.)
    for shaft in f.blocks.iter().filter(|b| b.kind.text != "housing") {
        let s = SHAFTS.iter().position(|n| *n == shaft.kind.text).unwrap_or(0);
        let what = format!("the `{}` block", SHAFTS[s]);
        let sf = Fields::read(&what, shaft.span, &shaft.items, &[], &[], &["bearing", "seal"], errors);
        for call in &sf.calls {
            match call.name.text.as_str() {
                "bearing" => bearings[s].extend(lower_bearing(call, errors)),
                _ => seals[s].extend(lower_seal(call, errors)),
            }
        }
        check_positions(&bearings[s], shaft, errors);
    }
    (errors.len() == before).then_some(Gearbox { lubrication, bearings, seals })
}

pub(super) fn lower_lubrication(value: &Value, errors: &mut Vec<Diagnostic>) -> Option<Lubrication> {
    let ValueKind::Call(call) = &value.kind else {
        errors.push(
            Diagnostic::new(DiagnosticKind::WrongDimension, value.span, "`lubrication` expects `dip(...)` or `injection(...)`")
                .hint("write `lubrication = dip(pinion_immersion = 0 mm, wheel_immersion = 30 mm, axis_height = 80 mm, housing_width = 200 mm)`"),
        );
        return None;
    };
    let mut items = Vec::new();
    match call.name.text.as_str() {
        "dip" => {
            let f = call_fields(call, "`dip(...)`", DIP, &mut items, errors);
            let e1 = metres(f.required("pinion_immersion", "0 mm", errors));
            let e2 = metres(f.required("wheel_immersion", "30 mm", errors));
            let h = metres(positive(f.required("axis_height", "80 mm", errors), "axis_height", errors));
            let l = metres(positive(f.required("housing_width", "200 mm", errors), "housing_width", errors));
            let (e1, e2, h, l) = (e1?, e2?, h?, l?);
            if e1 < 0.0 || e2 < 0.0 {
                errors.push(
                    Diagnostic::new(DiagnosticKind::OutOfRange, call.span, "an immersion depth is negative")
                        .hint("give the depth of the tip circle below the oil level; 0 for a gear above the oil"),
                );
                return None;
            }
            Some(Lubrication::Dip { immersion: [e1, e2], axis_height: h, housing_width: l })
        }
        "injection" => {
            let f = call_fields(call, "`injection(...)`", INJECTION, &mut items, errors);
            let q: Option<crate::model::Given<VolumeRate>> =
                positive(f.required("flow", "2 l/min", errors), "flow", errors);
            let v: Option<crate::model::Given<Velocity>> = f.required("jet_speed", "10 m/s", errors);
            Some(Lubrication::Injection { flow: q?.value.value, jet_speed: v?.value.value.max(0.0) })
        }
        _ => {
            errors.push(unknown_name("lubrication method", &call.name, &["dip", "injection"]));
            None
        }
    }
}

pub(super) fn lower_bearing(call: &Call, errors: &mut Vec<Diagnostic>) -> Option<Bearing> {
    let mut items = Vec::new();
    let f = call_fields(call, "`bearing(...)`", BEARING, &mut items, errors);
    let kind = match f.name("type", BearingType::NAMES, errors) {
        Some(n) => BearingType::from_name(&n.text),
        None => {
            if !f.has("type") {
                errors.push(f.missing("type", "cylindrical_roller"));
            }
            None
        }
    };
    let bore = metres(positive(f.optional("bore", errors), "bore", errors));
    let outside = metres(positive(f.optional("outside", errors), "outside", errors));
    let mean = metres(positive(f.optional("mean_diameter", errors), "mean_diameter", errors));
    let mean_diameter = match (bore, outside, mean) {
        (Some(d), Some(big_d), None) if big_d > d => Some(0.5 * (d + big_d)),
        (None, None, Some(dm)) => Some(dm),
        _ => {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::MissingKey,
                    call.span,
                    "a bearing needs `bore` and `outside` (D > d), or `mean_diameter`",
                )
                .hint("write `bearing(type = cylindrical_roller, bore = 30 mm, outside = 72 mm)`"),
            );
            None
        }
    };
    let count = f.number("count", 1.0, 64.0, errors).map_or(1, |c| c.value.round() as usize);
    let c0: Option<crate::model::Given<Force>> =
        positive(f.optional("static_load_rating", errors), "static_load_rating", errors);
    let kind = kind?;
    let skf = lower_bearing_model(&f, kind, bore.zip(outside), errors).ok()?;
    // Palmgren's f_1 of the ball and spherical types, and SKF's contact angle α_F of a deep groove
    // ball bearing under axial load, need C_0.
    let needs_c0 =
        if skf.is_some() { kind == BearingType::DeepGrooveBall } else { kind.needs_static_rating() && !f.has("f1") };
    if needs_c0 && c0.is_none() {
        let hint = if skf.is_some() { "" } else { ", or give `f1`" };
        errors.push(
            Diagnostic::new(
                DiagnosticKind::MissingKey,
                call.span,
                format!("a {} bearing's load-dependent moment needs its static load rating C_0", kind.name()),
            )
            .hint(format!("add `static_load_rating = 20 kN` (from the bearing's catalogue){hint}")),
        );
        return None;
    }
    Some(Bearing {
        kind,
        mean_diameter: mean_diameter?,
        count,
        static_load_rating: c0.map(|c| c.value.value),
        f0: f.number("f0", 0.1, 100.0, errors).map(|g| g.value),
        f1: f.number("f1", 1e-6, 0.1, errors).map(|g| g.value),
        y: tapered_y(&f, kind, errors).ok()?,
        position: metres(f.optional("at", errors)),
        skf,
    })
}

/// `model = palmgren` (the default) or `model = skf(r1 = …, r2 = …, s1 = …, s2 = …)`: the SKF model's
/// constants with the bearing's [d, D]; `Err` after an error.
fn lower_bearing_model(
    f: &Fields,
    kind: BearingType,
    diameters: Option<(f64, f64)>,
    errors: &mut Vec<Diagnostic>,
) -> Result<Option<(SkfConstants, [f64; 2])>, ()> {
    let Some((_, value)) = f.values.get("model") else { return Ok(None) };
    let model = match &value.kind {
        ValueKind::Call(c) if c.name.text == "palmgren" && c.arguments.is_empty() => return Ok(None),
        ValueKind::Call(c) if c.name.text == "skf" => c,
        ValueKind::Call(c) => {
            errors.push(unknown_name("model for a bearing", &c.name, &["palmgren", "skf"]));
            return Err(());
        }
        _ => {
            errors.push(
                Diagnostic::new(DiagnosticKind::WrongDimension, value.span, "`model` expects `palmgren` or `skf(...)`")
                    .hint("write `model = skf(r1 = 1.09e-6, s1 = 0.16, s2 = 0.0015)` with the series' constants from SKF's tables"),
            );
            return Err(());
        }
    };
    let fail = |errors: &mut Vec<Diagnostic>, reason: String, hint: &str| {
        errors.push(Diagnostic::new(DiagnosticKind::OutOfRange, model.span, reason).hint(hint.to_string()));
        Err(())
    };
    if !skf_bearing::supports(kind) {
        return fail(
            errors,
            format!("the SKF model is not available here for a {} bearing", kind.name()),
            "the SKF model covers deep_groove_ball, cylindrical_roller and tapered_roller; use `model = palmgren` (with `f0`, `f1`)",
        );
    }
    if f.has("f0") || f.has("f1") {
        return fail(
            errors,
            "`f0` and `f1` are Palmgren's factors, not the SKF model's".into(),
            "leave out `f0` and `f1`, or `model`",
        );
    }
    let Some((d, big_d)) = diameters else {
        return fail(
            errors,
            "the SKF model needs the bearing's `bore` and `outside` diameters".into(),
            "write `bore = 30 mm, outside = 72 mm` instead of `mean_diameter`",
        );
    };
    let mut items = Vec::new();
    let k = call_fields(model, "`skf(...)`", SKF, &mut items, errors);
    let needs_r2 = kind != BearingType::CylindricalRoller;
    let constant = |key: &str, required: bool, errors: &mut Vec<Diagnostic>| -> Option<f64> {
        if required && !k.has(key) {
            errors.push(
                Diagnostic::new(DiagnosticKind::MissingKey, k.span, format!("`skf(...)` has no `{key}`")).hint(
                    format!(
                "add `{key}`, the value for the bearing's series in SKF's table of geometry constants (R1, R2, S1, S2)"
            ),
                ),
            );
        }
        k.number(key, 0.0, 1e4, errors).map(|g| g.value)
    };
    let before = errors.len();
    let r1 = constant("r1", true, errors);
    let r2 = constant("r2", needs_r2, errors);
    let s1 = constant("s1", true, errors);
    let s2 = constant("s2", true, errors);
    let y = k.number("y", 0.3, 5.0, errors).map_or(1.6, |g| g.value);
    let mu_bl = k.number("mu_bl", 0.0, 1.0, errors).map_or(skf_bearing::MU_BOUNDARY, |g| g.value);
    let mu_ehl = k.number("mu_ehl", 0.0, 1.0, errors).map(|g| g.value);
    if errors.len() > before {
        return Err(());
    }
    let (Some(r1), Some(s1), Some(s2)) = (r1, s1, s2) else { return Err(()) };
    let constants = SkfConstants { r1, r2: r2.unwrap_or(0.0), s1, s2, y, mu_bl, mu_ehl };
    Ok(Some((constants, [d, big_d])))
}

pub(super) fn lower_seal(call: &Call, errors: &mut Vec<Diagnostic>) -> Option<Seal> {
    let mut items = Vec::new();
    let f = call_fields(call, "`seal(...)`", SEAL, &mut items, errors);
    let d = metres(positive(f.required("diameter", "30 mm", errors), "diameter", errors));
    let count = f.number("count", 1.0, 64.0, errors).map_or(1, |c| c.value.round() as usize);
    Some(Seal { diameter: d?, count })
}

/// `y`, the axial load factor of a tapered roller bearing's Palmgren P_1 (refused on other types,
/// and beside an SKF model, which takes its own `y`); `Err` after an error.
fn tapered_y(f: &Fields, kind: BearingType, errors: &mut Vec<Diagnostic>) -> Result<Option<f64>, ()> {
    let Some(y) = f.number("y", 0.3, 5.0, errors) else { return Ok(None) };
    if kind != BearingType::TaperedRoller || f.has("model") {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                y.span,
                format!(
                    "`y` is the axial load factor of a tapered roller bearing's P_1; this is a {} bearing{}",
                    kind.name(),
                    if f.has("model") { " with a model of its own" } else { "" }
                ),
            )
            .hint("leave `y` out, or give it inside `model = skf(...)` for the SKF model"),
        );
        return Err(());
    }
    Ok(Some(y.value))
}

/// Positions (`at`) on all or none of a shaft's bearing places, and then on exactly two.
fn check_positions(bearings: &[Bearing], shaft: &Block, errors: &mut Vec<Diagnostic>) {
    let with = bearings.iter().filter(|b| b.position.is_some()).count();
    let ok = with == 0 || (with == 2 && bearings.len() == 2 && bearings[0].position != bearings[1].position);
    if !ok {
        errors.push(
            Diagnostic::new(DiagnosticKind::OutOfRange, shaft.kind.span, "bearing positions (`at`) need exactly two bearing places at different positions")
                .hint("give `at` on both of the shaft's two bearings (the gear's mid-plane at 0), or on none: the load is then shared equally"),
        );
    }
}

/// The budget adds the mesh loss of `efficiency`; bearings need the oil's kinematic viscosity and
/// injection its density.
pub(super) fn check_gearbox_needs(
    gearbox: &Gearbox,
    block: &Block,
    lubricant: Option<&crate::model::Lubricant>,
    analyses: &crate::model::Analyses,
    errors: &mut Vec<Diagnostic>,
) {
    if analyses.efficiency.is_none() {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::MissingKey,
                block.kind.span,
                "the loss budget of `gearbox` needs the mesh loss of `efficiency`",
            )
            .hint("add `efficiency(formulations = [external])` to `analyses`"),
        );
    }
    let needs_oil = gearbox.bearings.iter().any(|b| !b.is_empty())
        || matches!(gearbox.lubrication, Some(Lubrication::Injection { .. }));
    if needs_oil && lubricant.and_then(|l| l.kinematic_viscosity_si()).is_none() {
        errors.push(
            Diagnostic::new(DiagnosticKind::MissingKey, block.kind.span, "bearing and injection losses need the oil's kinematic viscosity and density")
                .hint("add `lubricant = iso_vg(100, mineral)` with `oil_temperature` in `operating`, or `density` to the lubricant block"),
        );
    }
}

/// Most values along each axis of an efficiency map.
pub(crate) const MAX_MAP_VALUES: usize = 200;

/// `efficiency_map(pinion_torque = 10..400 N*m count 40, pinion_speed = 100..6000 rpm count 40)`.
pub(super) fn lower_efficiency_map(
    call: &Call,
    errors: &mut Vec<Diagnostic>,
) -> Option<(crate::model::Sweep<crate::model::Torque>, crate::model::Sweep<crate::model::AngularVelocity>)> {
    let mut items = Vec::new();
    let f = call_fields(call, "`efficiency_map(...)`", &["pinion_torque", "pinion_speed"], &mut items, errors);
    let t: Option<crate::model::Sweep<crate::model::Torque>> = f.sweep("pinion_torque", "10..400 N*m count 40", errors);
    let s: Option<crate::model::Sweep<crate::model::AngularVelocity>> =
        f.sweep("pinion_speed", "100..6000 rpm count 40", errors);
    let (t, s) = (t?, s?);
    for (key, n, values, span) in [
        ("pinion_torque", t.values.len(), t.values.iter().map(|v| v.value).collect::<Vec<_>>(), t.span),
        ("pinion_speed", s.values.len(), s.values.iter().map(|v| v.value).collect(), s.span),
    ] {
        if !(2..=MAX_MAP_VALUES).contains(&n) || values.iter().any(|v| *v <= 0.0) {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    span,
                    format!("the map's `{key}` needs 2 to {MAX_MAP_VALUES} positive values, not {n}"),
                )
                .hint(format!("write a range such as `{key} = 10..400 N*m count 40`")),
            );
            return None;
        }
    }
    Some((t, s))
}

/// A dip-lubricated gear is at most wholly under oil: its immersion depth cannot exceed its tip
/// diameter (Mauz's churning moment grows exponentially with the depth and would overflow).
pub(super) fn check_immersion(
    lubrication: Option<&Lubrication>,
    pair: &crate::model::GearPair,
    span: Span,
    errors: &mut Vec<Diagnostic>,
) {
    let (Some(Lubrication::Dip { immersion, .. }), Ok(g)) = (lubrication, pair.geometry()) else { return };
    for (i, name) in ["pinion", "wheel"].iter().enumerate() {
        let tip = 2.0 * g.tip_radius[i];
        if immersion[i] > tip {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    span,
                    format!(
                        "the {name} is immersed {:.1} mm, deeper than its tip diameter {:.1} mm",
                        immersion[i] * 1e3,
                        tip * 1e3
                    ),
                )
                .hint(format!("give `{name}_immersion` as the depth of the tip circle below the oil level: at most the tip diameter (a gear wholly under oil)")),
            );
        }
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
