//! A thermal balance as the record files carry it: flat columns, one row a record.

use crate::thermal;

/// The balance of an efficiency record as the record files carry it (flat columns).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ThermalRow {
    /// θ* (K), absent without a balance up to 200 °C.
    #[serde(rename = "oil_temperature_K")]
    pub oil_temperature: Option<f64>,
    pub thermal_status: thermal::BalanceStatus,
    /// P_V at θ* (W).
    #[serde(rename = "loss_at_balance_W")]
    pub loss_at_balance: f64,
    #[serde(rename = "dissipation_convection_W")]
    pub convection: f64,
    #[serde(rename = "dissipation_radiation_W")]
    pub radiation: f64,
    #[serde(rename = "dissipation_foundation_W")]
    pub foundation: f64,
    #[serde(rename = "dissipation_cooler_W")]
    pub cooler: f64,
    #[serde(rename = "dissipation_W")]
    pub dissipation: f64,
    #[serde(rename = "heat_transfer_coefficient_W_m2_K")]
    pub heat_transfer_coefficient: f64,
    #[serde(rename = "thermal_rating_N_m")]
    pub rating: Option<f64>,
    #[serde(rename = "thermal_rating_95_N_m")]
    pub rating_95: Option<f64>,
}

impl ThermalRow {
    /// The record files' column names, in order.
    pub const COLUMNS: [&'static str; 11] = [
        "oil_temperature_K",
        "thermal_status",
        "loss_at_balance_W",
        "dissipation_convection_W",
        "dissipation_radiation_W",
        "dissipation_foundation_W",
        "dissipation_cooler_W",
        "dissipation_W",
        "heat_transfer_coefficient_W_m2_K",
        "thermal_rating_N_m",
        "thermal_rating_95_N_m",
    ];

    /// The numbers after the status, in [`Self::COLUMNS`] order.
    pub fn numbers(&self) -> [Option<f64>; 9] {
        [
            Some(self.loss_at_balance),
            Some(self.convection),
            Some(self.radiation),
            Some(self.foundation),
            Some(self.cooler),
            Some(self.dissipation),
            Some(self.heat_transfer_coefficient),
            self.rating,
            self.rating_95,
        ]
    }
}
