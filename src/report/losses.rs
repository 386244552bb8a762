//! The lubricant at temperature: what the laws, films and losses read from the oil.

use serde::{Deserialize, Serialize};

use super::number::{Num, Q};

/// What the laws, films and losses read from the oil, and where it came from.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct LubricantReport {
    pub name: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub base: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub temperature: Option<Q>,
    pub dynamic_viscosity: Q,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kinematic_viscosity: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub density: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pressure_viscosity: Option<Q>,
    /// X_L of ISO/TR 14179-2 by base oil (a law's `x_l` overrides it there).
    pub lubricant_factor: Num,
    /// ν40, ν100, ρ15 and the viscosity index when the oil was given by grade or measured values.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub nu_40: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub nu_100: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub density_15: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub viscosity_index: Option<Num>,
    pub source: String,
}

/// The lubricant `l` as a mesh reads it (`t`: η, ν, ρ, α and X_L at the oil temperature, the
/// same for every mesh of a drive, which share one sump), with its data sheet values and where its
/// values come from: a pair's report and a drive's alike.
pub(crate) fn lubricant_report(l: &crate::model::Lubricant, t: &crate::tribology::Tribology) -> LubricantReport {
    let source = match &l.oil {
        Some(oil) => {
            format!("{}; ν by ASTM D341 (Walther) through ν40 and ν100, ρ by thermal expansion 7e-4 1/K", oil.source)
        }
        None => "given at the oil temperature in the scene".to_string(),
    };
    LubricantReport {
        name: l.name.clone(),
        base: l.kind.map(|b| b.words().to_string()),
        temperature: l.temperature.as_ref().map(|g| Q::new(g.value.value, "K")),
        dynamic_viscosity: Q::new(t.dynamic_viscosity, "Pa*s"),
        kinematic_viscosity: t.kinematic_viscosity.map(|v| Q::new(v, "m^2/s")),
        density: t.density().map(|rho| Q::new(rho, "kg/m^3")),
        pressure_viscosity: t.pressure_viscosity.map(|a| Q::new(a, "1/Pa")),
        lubricant_factor: Num(t.lubricant_factor),
        nu_40: l.oil.as_ref().map(|o| Q::new(o.nu_40, "m^2/s")),
        nu_100: l.oil.as_ref().map(|o| Q::new(o.nu_100, "m^2/s")),
        density_15: l.oil.as_ref().map(|o| Q::new(o.density_15, "kg/m^3")),
        viscosity_index: l.oil.as_ref().and_then(|o| o.viscosity_index()).map(Num),
        source,
    }
}
