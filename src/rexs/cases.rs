//! The lubricant (referenced by the casing or a stage) and the load spectrum: per load case the
//! input's speed, the torque its external load defines, the oil temperature and the case's share
//! of the operating time (each case's attributes add to or override the model's).

use super::error::describe;
use super::error::RexsError;
use super::model::{Attribute, Component, RexsModel};
use super::shafts::ShaftData;
use super::units::{flag, quantity, required, text, Kind};

#[derive(Debug, Clone, PartialEq)]
pub(crate) struct LubricantData {
    pub id: u64,
    pub name: String,
    pub nu_40: f64,
    pub nu_100: f64,
    /// kg/m³.
    pub density_15: f64,
    /// gearloss's base oil.
    pub base: &'static str,
    pub base_given: bool,
}

/// One load case at the input.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct CaseData {
    pub id: u64,
    /// rpm, signed about the shaft's u axis.
    pub speed: f64,
    /// N·m into the box (positive: the input drives), from the load's torque about u and the speed's sign.
    pub torque: f64,
    /// °C.
    pub oil_temperature: Option<f64>,
    /// Share of the operating time (0–1).
    pub fraction: Option<f64>,
}

const BASES: &[(&str, &str)] = &[
    ("mineral_oil", "mineral"),
    ("polyalfaolefin", "pao"),
    ("polyalphaolefin", "pao"),
    ("non_water_soluble_polyglycol", "pag_insoluble"),
    ("water_soluble_polyglycol", "pag_soluble"),
    ("phosphate_ester", "phosphate_ester"),
    ("traction_fluid", "traction"),
];

pub(crate) fn read_lubricant(
    model: &RexsModel,
    warnings: &mut Vec<String>,
) -> Result<Option<LubricantData>, RexsError> {
    let Some(l) = model.of_kind("lubricant").next() else {
        warnings.push(
            "the model has no lubricant: an ISO VG 220 mineral gear oil is chosen (replace it with the unit's oil)"
                .into(),
        );
        return Ok(None);
    };
    let kind = text(l, &["lubricant_type_iso_6336_2006"]);
    let base = kind.and_then(|k| BASES.iter().find(|(r, _)| *r == k).map(|(_, g)| *g));
    if base.is_none() {
        warnings.push(format!("{}: no ISO 6336 lubricant type; a mineral base oil is assumed (chosen)", describe(l)));
    }
    Ok(Some(LubricantData {
        id: l.id,
        name: l.name.clone(),
        nu_40: required(l, &["viscosity_at_40_degree_celsius"], Kind::Viscosity)?,
        nu_100: required(l, &["viscosity_at_100_degree_celsius"], Kind::Viscosity)?,
        density_15: required(l, &["density_at_15_degree_celsius"], Kind::Density)?,
        base: base.unwrap_or("mineral"),
        base_given: base.is_some(),
    }))
}

/// Component `c` with a load case's attributes over its own.
fn in_case(c: &Component, case: Option<&[Attribute]>) -> Component {
    let mut out = c.clone();
    for a in case.unwrap_or(&[]) {
        out.attributes.retain(|x| x.id != a.id);
        out.attributes.insert(0, a.clone());
    }
    out
}

/// A case's share of the operating time (0–1): `operating_time_fraction` in % (REXS ≥ 1.3), or
/// `load_duration_fraction` as a fraction (≤ 1.2; Bearinx writes it in 1.4 too, in %), or a
/// tool's `custom_load_duration_fraction` (the same reading).
fn share(unit: &Component) -> Option<f64> {
    let a = unit.attribute(&["operating_time_fraction", "load_duration_fraction", "custom_load_duration_fraction"])?;
    let super::model::AttributeValue::Number(x) = a.value else { return None };
    Some(if a.unit.as_deref() == Some("%") { x / 100.0 } else { x })
}

/// The load cases (or the model's own values as one case) and the unit's operating time (h).
pub(crate) fn read_cases(
    model: &RexsModel,
    shafts: &[ShaftData],
    warnings: &mut Vec<String>,
) -> Result<(Vec<CaseData>, Option<f64>), RexsError> {
    let input = shafts.iter().find(|s| s.input).expect("read_shafts found the input");
    let shaft = &model.components[&input.id];
    let torque_load = model
        .components
        .values()
        .find(|c| c.kind == "external_load" && flag(c, &["defines_torque"]) == Some(true))
        .ok_or_else(|| {
            RexsError::new(
                "no external load defines the torque (`defines_torque`)",
                "export the input's load with its torque",
            )
        })?;
    let unit = model.of_kind("gear_unit").next();
    let casing = model.of_kind("gear_casing").next();
    let cases: Vec<Option<&super::model::LoadCase>> =
        if model.load_cases.is_empty() { vec![None] } else { model.load_cases.iter().map(Some).collect() };
    let mut out = Vec::new();
    let mut forces = false;
    let mut powered = false;
    for case in cases {
        let of = |c: &Component| in_case(c, case.and_then(|k| k.components.get(&c.id)).map(Vec::as_slice));
        let speed = required(&of(shaft), &["rotational_speed"], Kind::Speed)?;
        let load = of(torque_load);
        let torque = match (
            quantity(&load, &["torque_around_u_axis"], Kind::Torque)?,
            quantity(&load, &["power"], Kind::Power)?,
        ) {
            (Some(t), _) => t,
            // A load given as power at the input's speed: T = P/ω (P in kW, n in rpm).
            (None, Some(p)) if speed != 0.0 => {
                powered = true;
                p * 1e3 / (speed.abs() * std::f64::consts::PI / 30.0)
            }
            _ => required(&load, &["torque_around_u_axis"], Kind::Torque)?,
        };
        let fraction = unit.map(&of).and_then(|u| share(&u));
        let oil = match casing.map(&of) {
            Some(c) => quantity(&c, &["temperature_lubricant"], Kind::Temperature)?,
            None => None,
        };
        for l in model.of_kind("external_load").filter(|l| l.id != torque_load.id) {
            let l = of(l);
            forces |= ["force_u_direction", "force_v_direction", "force_w_direction", "torque_around_v_axis", "torque_around_w_axis"]
                .iter()
                .any(|id| matches!(l.attribute(&[id]).map(|a| &a.value), Some(super::model::AttributeValue::Number(x)) if *x != 0.0));
        }
        let sign = if speed < 0.0 { -1.0 } else { 1.0 };
        out.push(CaseData {
            id: case.map_or(0, |k| k.id),
            speed,
            torque: torque * sign,
            oil_temperature: oil,
            fraction,
        });
    }
    if powered {
        warnings.push(format!(
            "{}: its load is given as power: the torque is P/ω at the input's speed in each case",
            describe(torque_load)
        ));
    }
    if out.len() > 1 && out.iter().any(|c| c.fraction.is_none()) {
        let missing: Vec<String> = out.iter().filter(|c| c.fraction.is_none()).map(|c| c.id.to_string()).collect();
        warnings.push(format!(
            "load case(s) {} give no share of the operating time: those without one share what the others leave equally (chosen)",
            missing.join(", ")
        ));
    }
    if forces {
        warnings.push("not imported: the external loads' forces and bending moments on the shaft ends (gearloss loads its shafts by the meshes only)".into());
    }
    let hours = match unit {
        Some(u) => quantity(u, &["operating_time", "load_duration"], Kind::Hours)?,
        None => None,
    };
    Ok((out, hours))
}
