//! The thermal sections of a drive's report (a scene of one pair's too: its one-stage drive's): the
//! housing, one balance per kept row, the heat balance's curve and the duty cycle, flattened into
//! the report (report.json keeps its four top-level keys).

use serde::{Deserialize, Serialize};

use super::thermal::{DutyCycleReport, HeatBalanceReport, HousingReport, ThermalRecord};

/// The housing, the balances, the heat-balance curve and the duty cycle of one report.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct ThermalSections {
    /// The housing as a thermal node, when the scene gives one and asks for its balance.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub housing: Option<HousingReport>,
    /// One thermal balance per kept row (the torque and speed its given ends', the row in words),
    /// when the scene asks for it.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub thermal: Vec<ThermalRecord>,
    /// P_V(θ) and P_Q(θ) at the first row.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub heat_balance: Option<HeatBalanceReport>,
    /// The duty cycle under the first law and formulation.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub duty_cycle: Option<DutyCycleReport>,
}
