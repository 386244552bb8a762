//! The thermal sections of a report, a pair's and a drive's alike: the housing, one balance per
//! shown point or row, the heat balance's curve and the duty cycle. One type, flattened into both
//! reports (report.json keeps its four top-level keys).

use serde::{Deserialize, Serialize};

use super::thermal::{DutyCycleReport, HeatBalanceReport, HousingReport, ThermalRecord};

/// The housing, the balances, the heat-balance curve and the duty cycle of one report.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct ThermalSections {
    /// The housing as a thermal node, when the scene gives one and asks for its balance.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub housing: Option<HousingReport>,
    /// One thermal balance per kept efficiency record (a pair's point, a drive's row: the torque
    /// and speed its given ends', the point in words), when the scene asks for it.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub thermal: Vec<ThermalRecord>,
    /// P_V(θ) and P_Q(θ) at the first point or row.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub heat_balance: Option<HeatBalanceReport>,
    /// The duty cycle under the first law and formulation.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub duty_cycle: Option<DutyCycleReport>,
}
