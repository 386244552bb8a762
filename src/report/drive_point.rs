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
    /// At `oil_temperature = equilibrium`: the point's own balance, where it was evaluated.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub balance: Option<PointBalance>,
}

impl DrivePointReport {
    /// A scene of one pair's total efficiency as its own report has always defined it: the whole
    /// loss over the power at the pinion gear, η = 1 − P_V/(T_1 ω_1), where the drive's η is
    /// P_out/P_in at the box's ends (P_in is T_1 ω_1 plus the pinion shaft's own losses). The same
    /// P_V; None unless the one stage's pinion drives (a point in coast, a drive of several stages).
    pub fn pinion_efficiency(&self) -> Option<f64> {
        let d = &self.point;
        let [s] = d.stages.as_slice() else { return None };
        let power = s.driving_torque * s.driving_speed;
        (s.driving == crate::drive::Member::Pinion && !d.both_ends_deliver && power > 0.0)
            .then(|| crate::losses::total_efficiency(self.total_loss, power))
    }
}

/// A point's own balance at `oil_temperature = equilibrium`: θ* and the oil read there, which every
/// loss of the point rests on.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PointBalance {
    /// θ* (K); None when the point finds no balance (then read at the scene's oil).
    pub temperature: Option<f64>,
    /// The sump's status in words.
    pub status: String,
    /// The oil at θ*: dynamic viscosity η (Pa·s) and kinematic viscosity ν (m²/s, where the oil
    /// has a density).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dynamic_viscosity: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kinematic_viscosity: Option<f64>,
}

impl PointBalance {
    /// A point's balance with the oil read at its θ* (the lubricant moved there as the walk moved it).
    pub(crate) fn of(scene: &crate::model::Scene, b: crate::thermal::Balance) -> PointBalance {
        let oil = b.temperature.and_then(|t| scene.lubricant.as_ref().map(|l| l.at_kelvin(t)));
        PointBalance {
            temperature: b.temperature,
            status: b.status.words().to_string(),
            dynamic_viscosity: oil.as_ref().map(|l| l.dynamic_viscosity.value.value),
            kinematic_viscosity: oil.as_ref().and_then(|l| l.kinematic_viscosity_si()),
        }
    }
}
