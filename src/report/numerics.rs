//! The error-against-run-time study in the report: one row per method and tolerance (deterministic),
//! and the run times apart (written to timing files only, never into snapshotted text).

use serde::{Deserialize, Serialize};

use super::number::Num;
use crate::dynamics::propagator::Method;
use crate::dynamics::DynamicFormulation;

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct NumericsRow {
    pub method: String,
    pub rtol: Num,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<Num>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub final_state_error: Option<Num>,
    pub steps: usize,
    pub rejected: usize,
    pub evaluations: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub failure: Option<String>,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct NumericsReport {
    pub formulation: DynamicFormulation,
    pub reference: Method,
    pub periods: usize,
    pub runs: Vec<NumericsRow>,
}

/// Run times, for the timing files only.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct Timings {
    pub reference_seconds: f64,
    /// (method, rtol, error (none for a failed run), seconds)
    pub runs: Vec<(String, f64, Option<f64>, f64)>,
}
