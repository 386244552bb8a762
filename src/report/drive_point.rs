//! One operating point of a drive's report: the point, law and formulation, and the law's
//! validity on each stage (what report.md's point tables and the findings read).

use serde::{Deserialize, Serialize};

use crate::drive::DrivePoint;

/// One operating point, law and formulation.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct DrivePointReport {
    /// `T_out = 150 N*m, n_out = 500 rpm`: the values as given.
    pub label: String,
    pub law: String,
    pub formulation: String,
    /// The power the box loses, P_in − P_out (W), report.md's "total": what the loss parts (the
    /// records' `total_W`) add up to where the point's books balance.
    #[serde(default)]
    pub total_loss: f64,
    pub point: DrivePoint,
    /// By stage: the law's contacts outside its validity range of those read along A–E, and the
    /// first reason met (empty when inside).
    pub validity: Vec<(usize, usize, String)>,
    /// At `oil_temperature = equilibrium`: the point's own balance θ* (K), where it was evaluated
    /// (None when it finds none: then at the scene's oil), and the sump's status in words.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub balance: Option<(Option<f64>, String)>,
}
