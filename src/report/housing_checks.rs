//! The housing's inputs where the thermal model stops meaning anything: an air speed beyond the
//! convection correlation's data, an oil limit no gear oil survives, a cooler set below the air.
//! Warnings in the report (the values are physically possible, the model's answer is not to be
//! trusted there), each naming the input, its value and the bound.

use super::finding::{Finding, Severity};
use crate::model::{LubricantType, Scene};

/// The largest air speed the forced-convection part h_f = 3.26 v^0.89 is read at (m/s). MoWiTT's
/// correlation (Yazdanian & Klems, ASHRAE Trans. 100(1), 1994) was fitted to site winds on a
/// low-rise building; gearloss reads it up to 10 m/s (a fresh breeze, or a fan-cooled housing) and
/// warns beyond: at 400 m/s it would give h_f = 675 W/(m² K), an answer no housing gives.
pub(crate) const MAX_AIR_SPEED: f64 = 10.0;

/// How far above its base oil's continuous service limit a housing's `max_oil_temperature` may be
/// set before the limit itself is implausible (K): oxidation doubles every 10 K, so 30 K above is
/// an eighth of the oil's life; no gear oil is meant to run there.
pub(crate) const LIMIT_MARGIN: f64 = 30.0;

/// The warnings about the housing's inputs.
/// `u`: the units the report shows values in.
pub(super) fn housing_findings(scene: &Scene, u: super::units::Units) -> Vec<Finding> {
    let Some(h) = scene.housing.as_ref() else { return Vec::new() };
    let deg = u.temperature();
    let warn = |message: String| Finding { severity: Severity::Warning, message };
    let mut out = Vec::new();
    if h.air_speed > MAX_AIR_SPEED {
        out.push(warn(format!(
            "the housing's air speed {} is beyond the {} the forced-convection correlation (MoWiTT, h_f = 3.26 v^0.89) is read to: its h_f = {:.0} W/(m² K) is extrapolated and the balance temperature with it",
            u.velocity().with(h.air_speed, 1),
            u.velocity().with(MAX_AIR_SPEED, 1),
            3.26 * h.air_speed.powf(0.89)
        )));
    }
    // The base oil (a lubricant of unknown base counts as mineral, as everywhere in the budget).
    let base = scene.lubricant.as_ref().and_then(|l| l.oil.as_ref().map(|o| o.base)).or_else(|| {
        match scene.lubricant.as_ref().and_then(|l| l.kind) {
            None | Some(LubricantType::Mineral) => Some(crate::tribology::lubricant::BaseOil::Mineral),
            Some(_) => None,
        }
    });
    if let Some(limit) = base.and_then(crate::tribology::lubricant::service_limit_celsius) {
        let max = h.max_oil_temperature - 273.15;
        if max > limit + LIMIT_MARGIN {
            out.push(warn(format!(
                "the housing's `max_oil_temperature` {} is more than {:.0} K above the {} a {} gear oil is run at continuously: no gear oil is meant to run there (its life halves every 10 K), so a balance found below that limit may still be one the oil does not survive",
                deg.with(h.max_oil_temperature, 0),
                LIMIT_MARGIN,
                deg.with(limit + 273.15, 0),
                base.map_or("", |b| b.words())
            )));
        }
    }
    if let Some(c) = h.cooler.filter(|c| c.above < h.ambient) {
        out.push(warn(format!(
            "the oil cooler is set to work above {}, below the ambient {}: the model lets it take heat from an oil cooler than the air around, as only a chilled coolant can, and the sump may settle below ambient; set `above` at or above the ambient temperature unless the coolant is chilled",
            deg.with(c.above, 1),
            deg.with(h.ambient, 1)
        )));
    }
    out
}
