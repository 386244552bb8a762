//! The thermal inputs: `gearbox { housing { ... } }` and `duty_cycle "name" { step(...) ... }`.
//!
//! ```text
//! gearbox {
//!     housing {
//!         surface_area           = 0.42 m^2
//!         ambient_temperature    = 25 degC
//!         air_speed              = 0 m/s        # optional, default 0 (still air)
//!         emissivity             = 0.9          # optional, default 0.9 (painted)
//!         heat_capacity          = 18 kJ/K      # optional; a duty cycle's transient needs it
//!         foundation_conductance = 2 W/K        # optional, default 0
//!         oil_cooler(conductance = 40 W/K, above = 70 degC)   # optional
//!         max_oil_temperature    = 120 degC     # optional, default 120 degC
//!     }
//! }
//! duty_cycle "EV-like cycle" {
//!     step(duration = 2 min, pinion_torque = 0 N*m, pinion_speed = 0 rpm)
//!     step(duration = 10 min, pinion_torque = 120 N*m, pinion_speed = 2500 rpm)
//! }
//! ```

use super::ast::*;
use super::fields::{call_fields, positive, Fields};
use crate::diagnostics::{Diagnostic, DiagnosticKind, Span};
use crate::model::{
    AngularVelocity, Area, Given, HeatCapacity, ThermalConductance, ThermodynamicTemperature, Time, Torque, Velocity,
};
use crate::thermal::{Cooler, DutyCycle, DutyStep, Housing};

const HOUSING: &[&str] = &[
    "surface_area",
    "ambient_temperature",
    "air_speed",
    "emissivity",
    "heat_capacity",
    "foundation_conductance",
    "max_oil_temperature",
];
const COOLER: &[&str] = &["conductance", "above"];
/// A step's keys: one pair's, or a drive's at the ends its `operating` block names.
pub(super) struct StepKeys {
    pub torque: &'static str,
    pub speed: &'static str,
    /// A drive's torque may be negative (coast); a pair's pinion drives.
    pub signed: bool,
}

/// One pair's step: `step(duration = 10 min, pinion_torque = 120 N*m, pinion_speed = 2500 rpm)`.
pub(super) const PAIR_STEP: StepKeys = StepKeys { torque: "pinion_torque", speed: "pinion_speed", signed: false };
/// Most steps a duty cycle may have.
pub(crate) const MAX_DUTY_STEPS: usize = 10_000;
/// The ambient temperatures a housing may stand in (K): −60 °C to 80 °C.
const AMBIENT: (f64, f64) = (213.15, 353.15);

fn out_of_range(span: Span, reason: String, hint: &str) -> Diagnostic {
    Diagnostic::new(DiagnosticKind::OutOfRange, span, reason).hint(hint.to_string())
}

/// The `housing` block inside `gearbox`.
pub(super) fn lower_housing(block: &Block, errors: &mut Vec<Diagnostic>) -> Option<Housing> {
    let f = Fields::read("the `housing` block", block.span, &block.items, HOUSING, &[], &["oil_cooler"], errors);
    let before = errors.len();
    let area: Option<Given<Area>> = positive(f.required("surface_area", "0.42 m^2", errors), "surface_area", errors);
    let ambient: Option<Given<ThermodynamicTemperature>> = f.required("ambient_temperature", "25 degC", errors);
    let ambient = ambient.filter(|a| {
        let ok = (AMBIENT.0..=AMBIENT.1).contains(&a.value.value);
        if !ok {
            errors.push(out_of_range(
                a.span,
                format!("`ambient_temperature` = {} is outside −60 °C to 80 °C", a.written),
                "give the temperature of the air around the housing, e.g. `ambient_temperature = 25 degC`",
            ));
        }
        ok
    });
    let air: Option<Given<Velocity>> = f.optional("air_speed", errors);
    let air = air.filter(|v| {
        let ok = v.value.value >= 0.0;
        if !ok {
            errors.push(out_of_range(
                v.span,
                format!("`air_speed` = {} is negative", v.written),
                "give the speed of the air along the housing: 0 m/s for still air",
            ));
        }
        ok
    });
    let emissivity = f.number("emissivity", f64::NEG_INFINITY, f64::INFINITY, errors).filter(|e| {
        let ok = e.value > 0.0 && e.value <= 1.0;
        if !ok {
            errors.push(out_of_range(
                e.span,
                format!("`emissivity` = {} is outside (0, 1]", e.written),
                "a painted or cast housing has about 0.9, bare aluminium 0.1 to 0.2",
            ));
        }
        ok
    });
    let emissivity = emissivity.map(|e| e.value);
    let c: Option<Given<HeatCapacity>> = positive(f.optional("heat_capacity", errors), "heat_capacity", errors);
    let g: Option<Given<ThermalConductance>> = f.optional("foundation_conductance", errors);
    let limit: Option<Given<ThermodynamicTemperature>> = f.optional("max_oil_temperature", errors);
    let cooler = match f.calls.as_slice() {
        [] => None,
        [call, rest @ ..] => {
            if let Some(second) = rest.first() {
                errors.push(
                    Diagnostic::new(DiagnosticKind::DuplicateKey, second.span, "the housing has two oil coolers")
                        .hint("give one `oil_cooler(conductance = 40 W/K, above = 70 degC)` with their sum"),
                );
            }
            lower_cooler(call, errors)
        }
    };
    let (area, ambient) = (area?, ambient?);
    let limit = limit.map_or(393.15, |l| l.value.value);
    if limit <= ambient.value.value {
        errors.push(out_of_range(
            f.values.get("max_oil_temperature").map_or(block.span, |(_, v)| v.span),
            format!("the oil's limit ({:.2} °C) is at or below the ambient temperature", limit - 273.15),
            "give a `max_oil_temperature` above `ambient_temperature`, e.g. `max_oil_temperature = 120 degC`",
        ));
    }
    if let Some(g) = &g {
        if g.value.value < 0.0 {
            errors.push(out_of_range(g.span, "`foundation_conductance` is negative".into(), "give 0 W/K or more"));
        }
    }
    (errors.len() == before).then(|| Housing {
        area: area.value.value,
        ambient: ambient.value.value,
        air_speed: air.map_or(0.0, |v| v.value.value),
        emissivity: emissivity.unwrap_or(0.9),
        heat_capacity: c.map(|c| c.value.value),
        foundation_conductance: g.map_or(0.0, |g| g.value.value),
        cooler,
        max_oil_temperature: limit,
    })
}

fn lower_cooler(call: &Call, errors: &mut Vec<Diagnostic>) -> Option<Cooler> {
    let mut items = Vec::new();
    let f = call_fields(call, "`oil_cooler(...)`", COOLER, &mut items, errors);
    let g: Option<Given<ThermalConductance>> =
        positive(f.required("conductance", "40 W/K", errors), "conductance", errors);
    let above: Option<Given<ThermodynamicTemperature>> = f.required("above", "70 degC", errors);
    Some(Cooler { conductance: g?.value.value, above: above?.value.value })
}

/// A top-level `duty_cycle "name" { step(...) ... }` block.
pub(super) fn lower_duty_cycle(block: &Block, keys: &StepKeys, errors: &mut Vec<Diagnostic>) -> Option<DutyCycle> {
    let f = Fields::read("the `duty_cycle` block", block.span, &block.items, &[], &[], &["step"], errors);
    let before = errors.len();
    if f.calls.is_empty() {
        errors.push(
            Diagnostic::new(DiagnosticKind::MissingKey, block.span, "the duty cycle has no steps")
                .hint(format!("add `step(duration = 10 min, {} = 120 N*m, {} = 2500 rpm)`", keys.torque, keys.speed)),
        );
        return None;
    }
    if f.calls.len() > MAX_DUTY_STEPS {
        errors.push(out_of_range(
            f.calls[MAX_DUTY_STEPS].span,
            format!("the duty cycle has {} steps, above the limit of {MAX_DUTY_STEPS}", f.calls.len()),
            "merge steps of equal torque and speed, or resample the cycle",
        ));
        return None;
    }
    let steps: Vec<Option<DutyStep>> = f.calls.iter().map(|c| lower_step(c, keys, errors)).collect();
    let name = block.label.as_ref().map_or_else(|| "duty cycle".to_string(), |l| l.text.clone());
    let steps: Option<Vec<DutyStep>> = steps.into_iter().collect();
    steps.filter(|_| errors.len() == before).map(|steps| DutyCycle { name, steps })
}

fn lower_step(call: &Call, keys: &StepKeys, errors: &mut Vec<Diagnostic>) -> Option<DutyStep> {
    let mut items = Vec::new();
    let f = call_fields(call, "`step(...)`", &["duration", keys.torque, keys.speed], &mut items, errors);
    let dt: Option<Given<Time>> = f.required("duration", "10 min", errors);
    let torque: Option<Given<Torque>> = f.required(keys.torque, "120 N*m", errors);
    let speed: Option<Given<AngularVelocity>> = f.required(keys.speed, "2500 rpm", errors);
    let (dt, torque, speed) = (dt?, torque?, speed?);
    if dt.value.value <= 0.0 {
        errors.push(out_of_range(
            dt.span,
            format!("a step of {} has no duration", dt.written),
            "give each step a duration above zero, e.g. `duration = 10 min`",
        ));
        return None;
    }
    if (!keys.signed && torque.value.value < 0.0) || speed.value.value < 0.0 {
        let span = if torque.value.value < 0.0 && !keys.signed { torque.span } else { speed.span };
        let (reason, hint) = if keys.signed {
            (
                "a duty step's speed may be zero but not negative",
                "a drive's speed at its ends is a magnitude; a negative torque is coast",
            )
        } else {
            (
                "a duty step's torque and speed may be zero but not negative",
                "the pinion drives: give zero (standing, or no load) or a positive value",
            )
        };
        errors.push(out_of_range(span, reason.into(), hint));
        return None;
    }
    Some(DutyStep {
        duration: dt.value.value,
        pinion_torque: torque.value.value,
        pinion_speed: speed.value.value,
        label: format!("{}, {}, {}", dt.written, torque.written, speed.written),
    })
}

/// What the thermal checks read of a lowered scene.
pub(super) struct ThermalInputs<'a> {
    pub housing: Option<&'a Housing>,
    /// The scene writes a `housing` block (that may have failed with its own errors).
    pub housing_failed: bool,
    /// Where the `duty_cycle` block is.
    pub duty_block: Option<Span>,
    pub equilibrium: Option<Span>,
    /// The lubricant can be read at any temperature (given by grade or by ν40, ν100 and ρ15), or there is none.
    pub moves_with_temperature: bool,
    pub lubricant_failed: bool,
}

/// The thermal analyses need a housing, a duty cycle needs its analysis and the analysis its
/// block, and the oil must be readable at every temperature the balance tries.
pub(super) fn check_thermal_needs(t: &ThermalInputs, analyses: &crate::model::Analyses, errors: &mut Vec<Diagnostic>) {
    let housing_hint =
        "add `housing { surface_area = 0.42 m^2  ambient_temperature = 25 degC }` to the `gearbox` block";
    let missing = |span: Span, reason: &str, hint: &str| {
        Diagnostic::new(DiagnosticKind::MissingKey, span, reason.to_string()).hint(hint.to_string())
    };
    let wants = [
        (t.equilibrium, "`oil_temperature = equilibrium` needs the gearbox's housing"),
        (analyses.thermal_balance, "`thermal_balance` needs the gearbox's housing"),
        (analyses.duty_cycle, "`duty_cycle` needs the gearbox's housing"),
    ];
    if t.housing.is_none() && !t.housing_failed {
        for (span, reason) in wants.iter().filter_map(|(s, r)| s.map(|s| (s, *r))) {
            errors.push(missing(span, reason, housing_hint));
        }
    }
    if let (Some(span), None) = (analyses.duty_cycle, t.duty_block) {
        errors.push(missing(
            span,
            "the `duty_cycle` analysis needs a `duty_cycle` block",
            "add `duty_cycle \"cycle\" { step(duration = 10 min, pinion_torque = 120 N*m, pinion_speed = 2500 rpm) }`",
        ));
    }
    if !t.moves_with_temperature && !t.lubricant_failed {
        if let Some((span, _)) = wants.iter().find_map(|(s, r)| s.map(|s| (s, r))) {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    span,
                    "the thermal balance reads the oil at every temperature it tries, and this lubricant's values hold at one temperature",
                )
                .hint("give the oil by grade (`lubricant = iso_vg(100, mineral)`) or by `nu_40`, `nu_100` and `density_15`"),
            );
        }
    }
}
