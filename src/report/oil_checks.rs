//! The warnings on the oil a scene runs in, the same for a scene of one pair and a drive: an oil
//! temperature above its base oil's continuous service limit, and a lubricant whose given η and ν
//! cannot be one oil's at one temperature.

use super::finding::{Finding, Severity};
use crate::model::{Lubricant, Operating};

/// Densities of oils (kg/m³): gear oils are 800–1100 (mineral ≈ 885, PAO ≈ 850, PAG ≈ 1000–1060 at
/// 15 °C); outside this band the η and ν a scene gives cannot both be one oil's at one temperature.
pub(crate) const OIL_DENSITY_RANGE: [f64; 2] = [700.0, 1200.0];

/// Both warnings, in the order a report lists them.
/// The oil is `lubricant` at the operating block's oil temperature.
pub(super) fn oil_warnings(lubricant: Option<&Lubricant>, op: &Operating, u: super::units::Units) -> Vec<Finding> {
    let warn = |message: String| Finding { severity: Severity::Warning, message };
    oil_temperature_warning(lubricant, op, u)
        .into_iter()
        .chain(implied_density_warning(lubricant, u))
        .map(warn)
        .collect()
}

/// A warning when the oil temperature is above its base oil's typical service limit
/// ([`crate::tribology::lubricant::service_limit_celsius`]).
fn oil_temperature_warning(lubricant: Option<&Lubricant>, op: &Operating, u: super::units::Units) -> Option<String> {
    let l = lubricant?;
    let base = l.oil.as_ref()?.base;
    let kelvin = op.oil_temperature.as_ref()?.value.value;
    let limit = crate::tribology::lubricant::service_limit_celsius(base)?;
    let deg = u.temperature();
    (kelvin - 273.15 > limit).then(|| {
        format!(
            "oil temperature {:.0} {} is above the {:.0} {} a {} gear oil is typically run at continuously: it ages fast there (its life roughly halves for every 10 K above); check the oil's data sheet or the cooling",
            deg.value(kelvin),
            deg.unit,
            deg.from_celsius(limit),
            deg.unit,
            base.words()
        )
    })
}

/// A warning when the density a given lubricant's η and ν imply (ρ = η/ν) is not an oil's: the
/// two viscosities are then most likely at different temperatures or one is in a mistaken unit,
/// and every film thickness and law that reads η is off by that factor. An oil given by grade or by
/// ν40, ν100 and ρ15 is one oil by construction.
fn implied_density_warning(lubricant: Option<&Lubricant>, u: super::units::Units) -> Option<String> {
    let l = lubricant?;
    if l.oil.is_some() {
        return None;
    }
    let rho = l.dynamic_viscosity.value.value / l.kinematic_viscosity_si()?;
    let [lo, hi] = OIL_DENSITY_RANGE;
    let d = u.density();
    (!(lo..=hi).contains(&rho)).then(|| {
        format!(
            "the lubricant's dynamic and kinematic viscosity imply a density ρ = η/ν = {}, outside the {}–{} of any gear oil: η and ν are not one oil's at one temperature (or one is in a mistaken unit); every film thickness and law that reads η uses the dynamic viscosity as given",
            d.with(rho, 1),
            d.cell(lo, 0),
            d.with(hi, 0)
        )
    })
}
