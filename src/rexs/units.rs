//! REXS unit strings as the files write them, and the quantities gearloss reads: each attribute's
//! value converted by its unit string (never by assumption), a unit that contradicts the quantity
//! refused.

use super::error::RexsError;
use super::model::{AttributeValue, Component};

/// What an attribute measures, and the unit the written scene gives it in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kind {
    /// mm
    Length,
    /// deg
    Angle,
    /// rpm
    Speed,
    /// N·m
    Torque,
    /// kN
    Force,
    /// mm²/s
    Viscosity,
    /// kg/m³
    Density,
    /// °C
    Temperature,
    /// h
    Hours,
    /// kW
    Power,
    /// a plain number
    Number,
}

impl Kind {
    fn words(self) -> &'static str {
        match self {
            Kind::Length => "a length",
            Kind::Angle => "an angle",
            Kind::Speed => "a rotational speed",
            Kind::Torque => "a torque",
            Kind::Force => "a force",
            Kind::Viscosity => "a kinematic viscosity",
            Kind::Density => "a density",
            Kind::Temperature => "a temperature",
            Kind::Hours => "a time",
            Kind::Power => "a power",
            Kind::Number => "a plain number",
        }
    }
}

/// The factor from `unit` to `kind`'s scene unit, None when the unit is not one of `kind`'s.
fn factor(unit: &str, kind: Kind) -> Option<f64> {
    let u = unit.trim();
    let plain = matches!(u, "" | "none" | "-");
    match kind {
        Kind::Length => match u {
            "mm" => Some(1.0),
            "m" => Some(1e3),
            "mum" | "µm" | "um" => Some(1e-3),
            _ => None,
        },
        Kind::Angle => matches!(u, "deg" | "°").then_some(1.0).or((u == "rad").then_some(180.0 / std::f64::consts::PI)),
        Kind::Speed => matches!(u, "1 / min" | "1/min" | "rpm").then_some(1.0),
        Kind::Torque => matches!(u, "N m" | "N*m" | "Nm").then_some(1.0),
        Kind::Force => match u {
            "kN" => Some(1.0),
            "N" => Some(1e-3),
            _ => None,
        },
        Kind::Viscosity => matches!(u, "mm^2 / s" | "mm^2/s" | "mm²/s").then_some(1.0),
        Kind::Density => match u {
            "kg / dm^3" | "kg/dm^3" | "g / cm^3" => Some(1e3),
            "kg / m^3" | "kg/m^3" => Some(1.0),
            _ => None,
        },
        Kind::Temperature => matches!(u, "C" | "°C" | "degC").then_some(1.0),
        Kind::Hours => matches!(u, "h").then_some(1.0),
        Kind::Power => match u {
            "kW" => Some(1.0),
            "W" => Some(1e-3),
            _ => None,
        },
        Kind::Number => plain.then_some(1.0),
    }
}

/// Component `c`'s attribute (any of `ids`, a renamed attribute's names) as `kind` in the scene's
/// unit: None when absent; an error when its unit contradicts `kind` or it is not a number.
pub(crate) fn quantity(c: &Component, ids: &[&str], kind: Kind) -> Result<Option<f64>, RexsError> {
    let Some(a) = c.attribute(ids) else { return Ok(None) };
    let unit = a.unit.as_deref().unwrap_or("");
    let Some(f) = factor(unit, kind) else {
        return Err(RexsError::at(
            c,
            format!("`{}` is given in `{unit}`, which is not the unit of {}", a.id, kind.words()),
            "the attribute's unit must be the one the REXS schema gives it",
        ));
    };
    match &a.value {
        AttributeValue::Number(x) => Ok(Some(x * f)),
        _ => Err(RexsError::at(c, format!("`{}` is not a number", a.id), "give the attribute a numeric value")),
    }
}

/// As [`quantity`], required: an error naming the component and attribute when it is missing.
pub(crate) fn required(c: &Component, ids: &[&str], kind: Kind) -> Result<f64, RexsError> {
    quantity(c, ids, kind)?.ok_or_else(|| {
        RexsError::at(c, format!("`{}` is missing", ids[0]), "the model needs it; export it from the design tool")
    })
}

/// A text or enum attribute.
pub(crate) fn text<'a>(c: &'a Component, ids: &[&str]) -> Option<&'a str> {
    match &c.attribute(ids)?.value {
        AttributeValue::Text(t) => Some(t.as_str()),
        _ => None,
    }
}

/// A boolean attribute.
pub(crate) fn flag(c: &Component, ids: &[&str]) -> Option<bool> {
    match &c.attribute(ids)?.value {
        AttributeValue::Bool(b) => Some(*b),
        _ => None,
    }
}

/// A three-vector attribute in mm (`support_vector`, `u_axis_vector`).
pub(crate) fn vector(c: &Component, id: &str) -> Option<[f64; 3]> {
    let a = c.attribute(&[id])?;
    let f = factor(a.unit.as_deref().unwrap_or("mm"), Kind::Length).unwrap_or(1.0);
    match &a.value {
        AttributeValue::Numbers(v) if v.len() == 3 => Some([v[0] * f, v[1] * f, v[2] * f]),
        _ => None,
    }
}
