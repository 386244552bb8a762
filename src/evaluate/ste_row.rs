//! The static transmission error at one torque as the record files carry it (the `ste_*` columns
//! of a `transmission_error` row).

use serde::{Deserialize, Serialize};

use crate::geometry::teeth::transmission_error::TransmissionError;

/// The static transmission error at one torque as the record files carry it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SteRow {
    /// Peak-to-peak of δ over a mesh cycle (m), from the located extremes.
    #[serde(rename = "ste_peak_to_peak_m")]
    pub peak_to_peak: f64,
    /// Mean of δ over a mesh cycle (m), integrated, and its error estimate.
    #[serde(rename = "ste_mean_m")]
    pub mean: f64,
    #[serde(rename = "ste_mean_error_m")]
    pub mean_error: f64,
}

impl SteRow {
    /// The record files' column names, in order.
    pub const COLUMNS: [&'static str; 3] = ["ste_peak_to_peak_m", "ste_mean_m", "ste_mean_error_m"];

    pub fn of(te: &TransmissionError) -> SteRow {
        SteRow { peak_to_peak: te.peak_to_peak(), mean: te.mean, mean_error: te.mean_error }
    }

    /// The numbers in [`Self::COLUMNS`] order.
    pub fn numbers(&self) -> [f64; 3] {
        [self.peak_to_peak, self.mean, self.mean_error]
    }
}
