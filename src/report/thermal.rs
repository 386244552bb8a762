//! The thermal balance in the report: the housing as given, one record per kept efficiency record
//! (θ*, status, what the housing gives off by path, the ratings), the heat-balance curve of the
//! first point and the duty cycle. Temperatures in K, like every quantity of report.json.

use serde::{Deserialize, Serialize};

use super::finding::{Finding, Severity};
use super::number::{Num, Q};
use crate::evaluate::thermal::{DutyCycleResult, HeatBalanceCurve};
use crate::model::{Formulation, Scene};
use crate::thermal::{BalanceStatus, Housing};

/// The heat balance's and the duty cycle's plots' titles.
pub(crate) const HEAT_BALANCE_TITLE: &str =
    "Heat balance: the losses P_V and what the housing gives off P_Q against the oil temperature";
pub(crate) const DUTY_TEMPERATURE_TITLE: &str = "Sump temperature over the duty cycle";
pub(crate) const DUTY_ENERGY_TITLE: &str = "Energy lost in each step of the duty cycle";

/// The housing as the scene gives it (defaults filled in), in SI.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct HousingReport {
    pub surface_area: Q,
    pub ambient_temperature: Q,
    pub air_speed: Q,
    pub emissivity: Num,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub heat_capacity: Option<Q>,
    pub foundation_conductance: Q,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub oil_cooler: Option<CoolerReport>,
    pub max_oil_temperature: Q,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct CoolerReport {
    pub conductance: Q,
    pub above: Q,
}

/// What the housing gives off at θ*, by path (W).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct DissipationReport {
    pub convection: Q,
    pub radiation: Q,
    pub foundation: Q,
    pub cooler: Q,
    pub total: Q,
}

/// A torque the box carries at a temperature, and its power T ω.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Rating {
    pub torque: Q,
    pub power: Q,
}

/// The balance of one (operating point, law, formulation).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ThermalRecord {
    pub case: usize,
    /// A drive's operating point in words (`T_out = 150 N·m, n_out = 500 rpm`): its torque and
    /// speed below are the given ends', not a pinion's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub point: Option<String>,
    pub law: crate::friction::catalog::LawId,
    pub label: String,
    pub formulation: Formulation,
    pub pinion_torque: Q,
    pub pinion_speed: Q,
    /// θ*, absent without a balance up to 200 °C.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub oil_temperature: Option<Q>,
    pub status: BalanceStatus,
    /// P_V at θ*.
    pub power_loss: Q,
    pub dissipation: DissipationReport,
    pub heat_transfer_coefficient: Q,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub thermal_rating: Option<Rating>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub thermal_rating_95: Option<Rating>,
}

/// P_V(θ) and P_Q(θ) of one point for the heat-balance plot.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct HeatBalanceReport {
    /// The operating point, law and formulation, in words.
    pub label: String,
    #[serde(deserialize_with = "super::floats::nan_from_null")]
    pub temperature: Vec<f64>,
    #[serde(deserialize_with = "super::floats::nan_from_null")]
    pub power_loss: Vec<f64>,
    #[serde(deserialize_with = "super::floats::nan_from_null")]
    pub dissipation: Vec<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub oil_temperature: Option<Q>,
    pub max_oil_temperature: Q,
    pub ambient_temperature: Q,
}

/// One step of a duty cycle.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct DutyStepReport {
    pub label: String,
    pub duration: Q,
    pub pinion_torque: Q,
    pub pinion_speed: Q,
    /// The transient's θ at the step's end and the energy lost in the step.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub oil_temperature_end: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub energy_lost: Option<Q>,
    /// The energy lost in the step at the scene's fixed oil temperature.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub energy_lost_fixed: Option<Q>,
    /// The loss P_V at the scene's fixed oil temperature (the step's energy there over its duration).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub power_loss_fixed: Option<Q>,
    /// What the housing gives off in the step along the transient.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub energy_dissipated: Option<Q>,
}

/// A cycle's energy at the fixed oil temperature.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct FixedTemperatureReport {
    pub oil_temperature: Q,
    pub energy_lost: Q,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub efficiency: Option<Num>,
}

/// The transient's time series.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Samples {
    pub time: Vec<f64>,
    pub oil_temperature: Vec<f64>,
}

/// A duty cycle: its steps, the transient's totals and the fixed-temperature energy.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct DutyCycleReport {
    pub name: String,
    /// The law and formulation the losses are read with.
    pub label: String,
    pub formulation: Formulation,
    pub steps: Vec<DutyStepReport>,
    /// E_in = Σ T ω Δt at the input: a drive's whose torque and speed are both given
    /// at its input and no step coasts; absent otherwise (no cycle efficiency then).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub energy_in: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub oil_temperature_max: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub energy_lost: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub energy_dissipated: Option<Q>,
    /// (E_in − E_lost)/E_in of the transient; absent when nothing goes in.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub efficiency: Option<Num>,
    /// The largest difference of a step-end θ between the integrator's two tolerances.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error_estimate: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fixed_temperature: Option<FixedTemperatureReport>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub samples: Option<Samples>,
    pub max_oil_temperature: Q,
    pub ambient_temperature: Q,
}

pub(crate) fn housing_report(h: &Housing) -> HousingReport {
    HousingReport {
        surface_area: Q::new(h.area, "m^2"),
        ambient_temperature: Q::new(h.ambient, "K"),
        air_speed: Q::new(h.air_speed, "m/s"),
        emissivity: Num(h.emissivity),
        heat_capacity: h.heat_capacity.map(|c| Q::new(c, "J/K")),
        foundation_conductance: Q::new(h.foundation_conductance, "W/K"),
        oil_cooler: h
            .cooler
            .map(|c| CoolerReport { conductance: Q::new(c.conductance, "W/K"), above: Q::new(c.above, "K") }),
        max_oil_temperature: Q::new(h.max_oil_temperature, "K"),
    }
}

fn law_words(scene: &Scene, law_index: usize, f: Formulation) -> String {
    format!("{}, {}", scene.friction[law_index].label(), f.name())
}

/// The heat balance of curve `c`, at the row, law and formulation `label` names.
pub(crate) fn heat_balance_at(label: String, c: &HeatBalanceCurve, h: &Housing) -> HeatBalanceReport {
    HeatBalanceReport {
        label,
        temperature: c.temperatures.clone(),
        power_loss: c.losses.clone(),
        dissipation: c.dissipation.clone(),
        oil_temperature: c.balance.temperature.map(|t| Q::new(t, "K")),
        max_oil_temperature: Q::new(h.max_oil_temperature, "K"),
        ambient_temperature: Q::new(h.ambient, "K"),
    }
}

/// The duty cycle's report; `at_input`: its steps' torque and speed are the input's (a drive's
/// whose operating block gives both at the input: a scene of one pair's), which gives the energy in
/// and the cycle's efficiency.
pub(crate) fn duty_cycle_report(
    scene: &Scene,
    d: &DutyCycleResult,
    h: &Housing,
    at_input: bool,
) -> Option<DutyCycleReport> {
    let cycle = scene.duty_cycle.as_ref()?;
    let e_in = (at_input && cycle.steps.iter().all(|s| s.pinion_torque >= 0.0)).then(|| cycle.energy_in());
    let efficiency = |lost: f64| e_in.filter(|e| *e > 0.0).map(|e| Num((e - lost) / e));
    let transient = d.transient.as_ref().and_then(|t| t.as_ref().ok());
    let steps = cycle
        .steps
        .iter()
        .enumerate()
        .map(|(k, s)| DutyStepReport {
            label: s.label.clone(),
            duration: Q::new(s.duration, "s"),
            pinion_torque: Q::new(s.pinion_torque, "N*m"),
            pinion_speed: Q::new(s.pinion_speed, "rad/s"),
            oil_temperature_end: transient.map(|t| Q::new(t.steps[k].temperature, "K")),
            energy_lost: transient.map(|t| Q::new(t.steps[k].energy_lost, "J")),
            energy_lost_fixed: d.fixed.as_ref().map(|p| Q::new(p[k] * s.duration, "J")),
            power_loss_fixed: d.fixed.as_ref().map(|p| Q::new(p[k], "W")),
            energy_dissipated: transient.map(|t| Q::new(t.steps[k].energy_dissipated, "J")),
        })
        .collect();
    let lost = transient.map(|t| t.steps.iter().map(|s| s.energy_lost).sum::<f64>());
    let fixed_lost = d.fixed.as_ref().map(|p| p.iter().zip(&cycle.steps).map(|(p, s)| p * s.duration).sum::<f64>());
    Some(DutyCycleReport {
        name: cycle.name.clone(),
        label: law_words(scene, d.law_index, d.formulation),
        formulation: d.formulation,
        steps,
        energy_in: e_in.map(|e| Q::new(e, "J")),
        oil_temperature_max: transient.map(|t| Q::new(t.max_temperature(h.ambient), "K")),
        energy_lost: lost.map(|e| Q::new(e, "J")),
        energy_dissipated: transient.map(|t| Q::new(t.steps.iter().map(|s| s.energy_dissipated).sum(), "J")),
        efficiency: lost.and_then(efficiency),
        error_estimate: transient.map(|t| Q::new(t.error, "K")),
        fixed_temperature: fixed_lost.zip(scene.operating.oil_temperature.as_ref()).map(|(e, t)| {
            FixedTemperatureReport {
                oil_temperature: Q::new(t.value.value, "K"),
                energy_lost: Q::new(e, "J"),
                efficiency: efficiency(e),
            }
        }),
        samples: transient.map(|t| Samples {
            time: t.samples.iter().map(|s| s.0).collect(),
            oil_temperature: t.samples.iter().map(|s| s.1).collect(),
        }),
        max_oil_temperature: Q::new(h.max_oil_temperature, "K"),
        ambient_temperature: Q::new(h.ambient, "K"),
    })
}

/// Warnings of the thermal balance: above the limit, no balance, a transient that crosses the
/// limit (when, in which step), a duty cycle without a heat capacity, a transient that failed.
pub(crate) fn thermal_findings(
    scene: &Scene,
    records: &[ThermalRecord],
    duty: Option<&DutyCycleReport>,
    d: Option<&DutyCycleResult>,
) -> Vec<Finding> {
    let mut out = Vec::new();
    let warn = |m: String| Finding { severity: Severity::Warning, message: m };
    let deg = super::units::Units::of_system(super::scene::pair_unit_system(&scene.gears)).temperature();
    let celsius = |q: &Q| deg.with(q.si(), 1);
    let (torque, speed) = (
        super::number::DisplayUnit::of(&scene.operating.pinion_torque),
        super::number::DisplayUnit::of(&scene.operating.pinion_speed),
    );
    for r in records {
        let point = r.point.clone().unwrap_or_else(|| {
            super::number::operating_point_words(&torque, &speed, &r.pinion_torque, &r.pinion_speed)
        });
        let at = format!("{point}, {} ({})", r.label, r.formulation.name());
        match (r.status, &r.oil_temperature) {
            (BalanceStatus::AboveLimit, Some(t)) => {
                out.push(warn(format!("the sump settles at {}, above the oil's limit, at {at}", celsius(t))))
            }
            (BalanceStatus::NoEquilibrium, _) => out.push(warn(format!(
                "no thermal balance up to {} at {at}: the housing cannot give off the losses",
                deg.with(crate::thermal::balance::SEARCH_LIMIT, 0)
            ))),
            _ => {}
        }
    }
    out.extend(duty_findings(scene, duty, d, deg));
    out
}

/// Warnings of a drive's duty cycle: a housing without heat capacity (no transient),
/// a transient that failed, a transient that crosses the oil's limit (when, in which step).
pub(crate) fn duty_findings(
    scene: &Scene,
    duty: Option<&DutyCycleReport>,
    d: Option<&DutyCycleResult>,
    deg: super::units::Shown,
) -> Vec<Finding> {
    let mut out = Vec::new();
    let warn = |m: String| Finding { severity: Severity::Warning, message: m };
    let Some(duty) = duty else { return out };
    if scene.housing.as_ref().is_some_and(|h| h.heat_capacity.is_none()) {
        out.push(warn(format!(
            "duty cycle \"{}\": the housing gives no `heat_capacity`, so the sump's transient (θ and the energies along it) is not computed; {}",
            duty.name,
            if duty.steps.iter().any(|s| s.energy_lost_fixed.is_some()) {
                "each step's energy at the scene's oil temperature is given"
            } else {
                "give `oil_temperature` in `operating` for each step's energy at a fixed temperature, or the housing's `heat_capacity`"
            }
        )));
    }
    if let Some(Some(Err(e))) = d.map(|d| &d.transient) {
        out.push(warn(format!("duty cycle \"{}\": {e}", duty.name)));
    }
    let limit = duty.max_oil_temperature.si();
    let ends = duty.steps.iter().enumerate().filter_map(|(k, s)| Some((k, s, s.oil_temperature_end.as_ref()?)));
    if let Some((k, s, end)) = ends.into_iter().find(|(_, _, end)| end.si() > limit) {
        out.push(warn(format!(
            "the sump passes the oil's limit ({}) in step {} ({}) of the duty cycle and ends that step at {}",
            deg.with(limit, 1),
            k + 1,
            s.label,
            deg.with(end.si(), 1)
        )));
    }
    out
}
