//! The lubricant, in one of three forms, resolved to its values at the oil temperature:
//!
//! - `lubricant = iso_vg(100, mineral)` or a block with `grade` and `base`: the ISO VG catalogue;
//! - a block with `nu_40`, `nu_100`, `density_15` (and `base`): a measured oil;
//! - a block with `dynamic_viscosity` (and `density` or `kinematic_viscosity`): values already at
//!   the oil temperature.
//!
//! The first two need `oil_temperature` in `operating`; ν, ρ, η and α at that temperature then
//! follow ([`crate::tribology::lubricant`]) and every law, film and loss reads them.

use std::collections::BTreeMap;

use super::ast::*;
use super::fields::{call_fields, positive, unknown_name, Fields};
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::model::*;
use crate::tribology::lubricant::{
    self, base_oil, catalogue, lowest_grade, BaseOil, NoNu100, NotInCatalogue, OilData, ISO_VG_GRADES,
};

pub(super) const LUBRICANT_KEYS: &[&str] = &[
    "dynamic_viscosity",
    "density",
    "kinematic_viscosity",
    "pressure_viscosity",
    "type",
    "base",
    "temperature",
    "grade",
    "nu_40",
    "nu_100",
    "density_15",
];
const AT_TEMPERATURE: &[&str] = &["dynamic_viscosity", "density", "kinematic_viscosity", "temperature"];
const MEASURED: &[&str] = &["nu_40", "nu_100", "density_15"];

/// `lubricant = iso_vg(grade, base)` at the scene's top.
pub(super) fn lower_lubricant_value(
    value: &Value,
    oil_temperature: Option<&Given<ThermodynamicTemperature>>,
    errors: &mut Vec<Diagnostic>,
) -> Option<Lubricant> {
    let ValueKind::Call(call) = &value.kind else {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::WrongDimension,
                value.span,
                "`lubricant = ...` expects `iso_vg(grade, base)`",
            )
            .hint("write `lubricant = iso_vg(100, mineral)`, or a `lubricant { ... }` block with measured values"),
        );
        return None;
    };
    if call.name.text != "iso_vg" {
        errors.push(unknown_name("lubricant function", &call.name, &["iso_vg"]));
        return None;
    }
    let mut items = Vec::new();
    let f = call_fields(call, "`iso_vg(...)`", &["grade", "base"], &mut items, errors);
    if !f.has("grade") || !f.has("base") {
        errors.push(
            Diagnostic::new(DiagnosticKind::MissingKey, call.span, "`iso_vg` needs a grade and a base oil").hint(
                "write `iso_vg(100, mineral)`: an ISO VG grade from 2 to 1500, base mineral, pao, pag_insoluble, pag_soluble or ester",
            ),
        );
        return None;
    }
    let oil = catalogue_oil(&f, errors)?;
    let name = format!("ISO VG {} {}", fmt_grade(oil.nu_40 * 1e6), oil.base.words());
    resolve(name, oil, None, call.span, oil_temperature, errors)
}

/// A `lubricant` block in any of its forms.
pub(super) fn lower_lubricant(
    block: &Block,
    oil_temperature: Option<&Given<ThermodynamicTemperature>>,
    errors: &mut Vec<Diagnostic>,
) -> Option<Lubricant> {
    let f = Fields::read("the `lubricant` block", block.span, &block.items, LUBRICANT_KEYS, &[], &[], errors);
    let alpha = positive(f.optional("pressure_viscosity", errors), "pressure_viscosity", errors);
    let base = base_key(&f, errors);
    let by_grade = f.has("grade");
    let measured = MEASURED.iter().any(|k| f.has(k));
    if by_grade || measured {
        let mut clash: Vec<&str> = AT_TEMPERATURE.iter().copied().filter(|k| f.has(k)).collect();
        if by_grade {
            clash.extend(MEASURED.iter().copied().filter(|k| f.has(k)));
        }
        if let Some(k) = clash.first() {
            let (key, _) = f.values[k];
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::DuplicateKey,
                    key.span,
                    format!("`{k}` cannot stand beside {}", if by_grade { "`grade`" } else { "`nu_40`/`nu_100`" }),
                )
                .hint("give the oil one way: `grade` and `base`; or `nu_40`, `nu_100`, `density_15`; or the values at temperature (`dynamic_viscosity` ...)"),
            );
            return None;
        }
        let oil = if by_grade { catalogue_oil(&f, errors)? } else { measured_oil(&f, base, errors)? };
        let name = block
            .label
            .as_ref()
            .map_or_else(|| format!("ISO VG {} {}", fmt_grade(oil.nu_40 * 1e6), oil.base.words()), |l| l.text.clone());
        return resolve(name, oil, alpha, block.span, oil_temperature, errors);
    }
    let name = block.label.as_ref().map_or("lubricant".to_string(), |l| l.text.clone());
    let eta = positive(f.required("dynamic_viscosity", "95 mPa*s", errors), "dynamic_viscosity", errors);
    let density: Option<Given<MassDensity>> = positive(f.optional("density", errors), "density", errors);
    let nu: Option<Given<KinematicViscosity>> =
        positive(f.optional("kinematic_viscosity", errors), "kinematic_viscosity", errors);
    let temperature: Option<Given<ThermodynamicTemperature>> =
        positive(f.optional("temperature", errors), "temperature", errors);
    if f.has("density") && f.has("kinematic_viscosity") {
        let (key, _) = f.values["kinematic_viscosity"];
        errors.push(
            Diagnostic::new(
                DiagnosticKind::DuplicateKey,
                key.span,
                "both `density` and `kinematic_viscosity` are given",
            )
            .hint("give one of them: ν = η/ρ"),
        );
    }
    if let (Some(t), Some(theta)) = (&temperature, oil_temperature) {
        if (t.value.value - theta.value.value).abs() > 1e-9 {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    t.span,
                    format!("the lubricant's values hold at {}, but `oil_temperature` is {}", t.written, theta.written),
                )
                .hint("values at one temperature cannot be moved to another: give `nu_40`, `nu_100` and `density_15` (or `grade` and `base`) instead"),
            );
        }
    }
    Some(Lubricant {
        name,
        dynamic_viscosity: eta?,
        density,
        kinematic_viscosity: nu,
        pressure_viscosity: alpha,
        kind: base,
        temperature: temperature.or_else(|| oil_temperature.cloned()),
        oil: None,
        alpha_from_oil: false,
    })
}

/// `base` (or its older name `type`).
fn base_key(f: &Fields, errors: &mut Vec<Diagnostic>) -> Option<BaseOil> {
    if f.has("base") && f.has("type") {
        let (key, _) = f.values["type"];
        errors.push(
            Diagnostic::new(DiagnosticKind::DuplicateKey, key.span, "both `base` and `type` are given")
                .hint("`type` is the older name of `base`: keep one"),
        );
        return None;
    }
    let key = if f.has("type") { "type" } else { "base" };
    f.name(key, BaseOil::NAMES, errors).and_then(|n| BaseOil::from_name(&n.text))
}

fn fmt_grade(g: f64) -> String {
    format!("{}", g.round())
}

/// `grade` and `base` from the catalogue.
fn catalogue_oil(f: &Fields, errors: &mut Vec<Diagnostic>) -> Option<OilData> {
    let grade = f.number("grade", 0.0, f64::MAX, errors)?;
    let base = base_key(f, errors);
    let Some(base) = base else {
        if !f.has("base") && !f.has("type") {
            errors.push(f.missing("base", "mineral"));
        }
        return None;
    };
    if !ISO_VG_GRADES.iter().any(|g| (g - grade.value).abs() < 1e-9) {
        let grades: Vec<String> = ISO_VG_GRADES.iter().map(|g| g.to_string()).collect();
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                grade.span,
                format!("{} is not an ISO 3448 viscosity grade", grade.written),
            )
            .hint(format!("ISO VG grades: {}", grades.join(", "))),
        );
        return None;
    }
    match catalogue(grade.value, base) {
        Ok(oil) => Some(oil),
        Err(why) => {
            let (key, _) = f.values.get("base").or_else(|| f.values.get("type")).copied()?;
            let (span, reason, hint) = match why {
                NotInCatalogue::NoNu100(NoNu100::BelowTable) => (
                    grade.span,
                    format!(
                        "ISO VG {} {} has no ν100 in ASTM D2270's range: at the catalogue's VI {} for {} oils, ν100 would lie below 2 mm²/s, where the standard defines no viscosity index",
                        grade.written,
                        base.name(),
                        base_oil(base).map_or(0.0, |b| b.viscosity_index),
                        base.words(),
                    ),
                    format!(
                        "the lowest {} grade the catalogue holds is ISO VG {}; for a thinner oil give `nu_40`, `nu_100` (≥ 2 mm²/s) and `density_15`",
                        base.name(),
                        lowest_grade(base).map_or("—".into(), |g| g.to_string())
                    ),
                ),
                _ => (
                    key.span,
                    format!("the catalogue has no {} oils", base.words()),
                    "the catalogue holds mineral, pao, pag_insoluble, pag_soluble and ester; for another oil give `nu_40`, `nu_100` and `density_15`".to_string(),
                ),
            };
            errors.push(Diagnostic::new(DiagnosticKind::OutOfRange, span, reason).hint(hint));
            None
        }
    }
}

/// `nu_40`, `nu_100`, `density_15` as measured.
fn measured_oil(f: &Fields, base: Option<BaseOil>, errors: &mut Vec<Diagnostic>) -> Option<OilData> {
    let nu_40: Option<Given<KinematicViscosity>> = positive(f.required("nu_40", "220 mm^2/s", errors), "nu_40", errors);
    let nu_100: Option<Given<KinematicViscosity>> =
        positive(f.required("nu_100", "19 mm^2/s", errors), "nu_100", errors);
    let rho: Option<Given<MassDensity>> =
        positive(f.required("density_15", "890 kg/m^3", errors), "density_15", errors);
    let (nu_40, nu_100, rho) = (nu_40?, nu_100?, rho?);
    if nu_100.value.value >= nu_40.value.value {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                nu_100.span,
                format!("`nu_100` = {} is not below `nu_40` = {}", nu_100.written, nu_40.written),
            )
            .hint("an oil thins as it warms: ν at 100 °C is below ν at 40 °C"),
        );
        return None;
    }
    if nu_100.value.value < lubricant::WALTHER_LOWER_LIMIT {
        errors.push(
            Diagnostic::new(DiagnosticKind::OutOfRange, nu_100.span, "`nu_100` is below 2 mm²/s")
                .hint("ASTM D341's Walther line holds from 2 mm²/s up: give the values at temperature instead"),
        );
        return None;
    }
    let base = base.unwrap_or(BaseOil::Mineral);
    Some(OilData {
        base,
        nu_40: nu_40.value.value,
        nu_100: nu_100.value.value,
        density_15: rho.value.value,
        source: format!(
            "measured: ν40 = {}, ν100 = {}, ρ15 = {} ({})",
            nu_40.written,
            nu_100.written,
            rho.written,
            if f.has("base") || f.has("type") {
                base.words()
            } else {
                "base not given: mineral assumed for X_L and α"
            }
        ),
    })
}

/// The oil at the oil temperature, as the values every later stage reads.
fn resolve(
    name: String,
    oil: OilData,
    alpha: Option<Given<ReciprocalPressure>>,
    span: Span,
    oil_temperature: Option<&Given<ThermodynamicTemperature>>,
    errors: &mut Vec<Diagnostic>,
) -> Option<Lubricant> {
    let Some(theta) = oil_temperature else {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::MissingKey,
                span,
                "an oil given by grade or by ν40/ν100 needs the oil temperature",
            )
            .hint("add `oil_temperature = 90 degC` to the `operating` block"),
        );
        return None;
    };
    Some(Lubricant::of_oil(name, oil, alpha, span, theta))
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

/// `film` needs the lubricant's pressure-viscosity coefficient.
pub(super) fn check_film_needs(analyses: &Analyses, lubricant: Option<&Lubricant>, errors: &mut Vec<Diagnostic>) {
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
