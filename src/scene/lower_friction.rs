//! Lowering of the `friction` block and of one law call: arguments checked against the catalogue
//! (known, right dimension, defaults filled in, one argument swept), and the inputs each law needs.

use super::ast::*;
use super::fields::{format_number, unknown_name, Fields};
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::friction::catalog;
use crate::model::*;

/// Most laws a scene may compare, a swept argument's values counted one by one (each is a column of
/// every table and a curve of every plot of an operating point).
pub(crate) const MAX_LAW_VARIANTS: usize = 256;

pub(super) fn lower_friction(block: &Block, errors: &mut Vec<Diagnostic>) -> Vec<FrictionLawSpec> {
    let ids: Vec<&str> = catalog::LAWS.iter().map(|l| l.id.name()).collect();
    let f = Fields::read("the `friction` block", block.span, &block.items, &[], &[], &ids, errors);
    let laws: Vec<FrictionLawSpec> = f.calls.iter().flat_map(|c| lower_law(c, errors)).collect();
    if laws.len() > MAX_LAW_VARIANTS {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                block.kind.span,
                format!(
                    "the `friction` block names {} laws (swept values counted), above the limit of {MAX_LAW_VARIANTS}",
                    laws.len()
                ),
            )
            .hint("sweep a law's argument over fewer values (its curve is smooth: 20 to 50 values show it)"),
        );
        return Vec::new();
    }
    laws
}

/// A law call checked against the catalogue: arguments known, with the right dimension, defaults filled in.
/// A law call checked against the catalogue: arguments known, with the right dimension, defaults
/// filled in. One argument may be a sweep (`coulomb(mu = [0.02, 0.04, 0.08])`): the law is then
/// evaluated once per value.
pub(crate) fn lower_law(call: &Call, errors: &mut Vec<Diagnostic>) -> Vec<FrictionLawSpec> {
    let Some(entry) = catalog::entry(&call.name.text) else { return Vec::new() };
    let names: Vec<&str> = entry.arguments.iter().map(|a| a.name).collect();
    let mut arguments: Vec<(String, f64, String)> = Vec::new();
    let mut swept: Option<(String, Vec<(f64, String)>)> = None;
    let mut ok = true;
    for (name, value) in &call.arguments {
        let Some(spec) = entry.arguments.iter().find(|a| a.name == name.text) else {
            errors.push(unknown_name(&format!("argument of `{}`", entry.id.name()), name, &names));
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
        let Some(values) = argument_values(entry, spec, value, swept.is_some(), errors) else {
            ok = false;
            continue;
        };
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
            catalog::ArgumentDefault::Value(d) => arguments.push((spec.name.to_string(), d, "default".into())),
            catalog::ArgumentDefault::Derived => {}
            catalog::ArgumentDefault::Required => {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::MissingKey,
                        call.span,
                        format!("`{}` needs `{}` ({})", entry.id.name(), spec.name, spec.what),
                    )
                    .hint(format!("write `{}({} = ...)`", entry.id.name(), spec.name)),
                );
                ok = false;
            }
        }
    }
    if !ok {
        return Vec::new();
    }
    match swept {
        None => vec![FrictionLawSpec { law: entry.id, arguments, span: call.span }],
        Some((name, values)) => values
            .into_iter()
            .map(|(x, w)| {
                let mut args = arguments.clone();
                args.insert(0, (name.clone(), x, w));
                FrictionLawSpec { law: entry.id, arguments: args, span: call.span }
            })
            .collect(),
    }
}

/// The value or values (a sweep) of one argument of a law, in SI with what was written; none
/// negative, at most one argument swept.
fn argument_values(
    entry: &catalog::LawEntry,
    spec: &catalog::LawArgument,
    value: &Value,
    already_swept: bool,
    errors: &mut Vec<Diagnostic>,
) -> Option<Vec<(f64, String)>> {
    let values: Option<Vec<(f64, String)>> = match &value.kind {
        ValueKind::List { .. } | ValueKind::Range { .. } => {
            if already_swept {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::OutOfRange,
                        value.span,
                        format!("`{}` sweeps a second argument", entry.id.name()),
                    )
                    .hint("a law may sweep one argument; write a second law for another sweep"),
                );
                return None;
            }
            super::fields::sweep_values(spec.name, value, spec.dimension, errors).map(|(si, unit, written, _)| {
                si.into_iter()
                    .zip(written)
                    .map(|(x, w)| (x, format!("{} {unit}", format_number(w)).trim_end().to_string()))
                    .collect()
            })
        }
        _ => super::fields::scalar(spec.name, value, spec.dimension, errors).map(|v| vec![v]),
    };
    let values = values?;
    if let Some((x, _)) = values.iter().find(|(x, _)| !(x.is_finite() && *x >= 0.0)) {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                value.span,
                format!("`{}` = {x} must not be negative", spec.name),
            )
            .hint(format!("{} is a magnitude; the sign follows the sliding direction", spec.what)),
        );
        return None;
    }
    Some(values)
}

pub(super) fn check_friction_needs(
    laws: &[FrictionLawSpec],
    gears: &GearPair,
    lubricant: Option<&Lubricant>,
    errors: &mut Vec<Diagnostic>,
) {
    for law in laws {
        let entry = law.law.entry();
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
                        "add `lubricant = iso_vg(100, mineral)` (with `oil_temperature` in `operating`) or `lubricant \"name\" { dynamic_viscosity = 95 mPa*s  density = 880 kg/m^3 }`".to_string()
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
                        format!("`{}` needs `{}`, which the scene lacks", entry.id.name(), need.key()),
                    )
                    .hint(hint),
                );
            }
        }
        if matches!(law.law, catalog::LawId::Xu | catalog::LawId::Composite) {
            check_xu_roughness(law, gears, errors);
        }
    }
}

/// Largest mean roughness S (µm) Xu et al.'s fit is evaluated at: its factor exp(b9 e^S) is 2·10⁵ at
/// 3 µm and overflows (μ not a number) near 7 µm; the fit was made on surfaces far smoother.
pub(crate) const XU_MAX_ROUGHNESS_UM: f64 = 5.0;

fn check_xu_roughness(law: &FrictionLawSpec, gears: &GearPair, errors: &mut Vec<Diagnostic>) {
    let ra = |g: &Gear| g.roughness_ra.as_ref().map(|r| r.value.value);
    let (Some(a), Some(b)) = (ra(&gears.pinion), ra(&gears.wheel)) else { return };
    let s_um = 0.5 * (a + b) * 1e6;
    if s_um > XU_MAX_ROUGHNESS_UM {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                law.span,
                format!(
                    "`{}` reads Xu et al.'s fit at the mean roughness S = {s_um:.3} µm, above {XU_MAX_ROUGHNESS_UM} µm, where its factor exp(b9·e^S) gives no meaningful (or no finite) μ",
                    law.law.name()
                ),
            )
            .hint("check `roughness_ra` of both gears (in µm, not µin?), or choose a law made for rough surfaces"),
        );
    }
}
