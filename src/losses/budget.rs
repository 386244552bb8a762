//! The loss budget of one operating point beside the mesh: gear churning or jet impulse, bearings
//! (no-load and load-dependent) and seals, with the bearing loads it took them from.
//!
//! Each part is a row of the catalogue [`super::parts`]; this file adds them up.

use serde::Serialize;

pub use super::bearing_loss::{BearingLoads, BearingLoss};
use super::gearbox::Gearbox;
use super::oil::Oil;
use super::parts::{LossColumn, PartLosses, PartState, PARTS};
use crate::geometry::PairGeometry;

/// Everything but the mesh at one operating point (W); parts the scene does not describe are `None`.
/// (Where a model leaves its tested range the report says so once for the run:
/// [`super::gear_no_load::Lubrication::note`].)
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct LossBudget {
    /// The power of each column the gearbox fills (W), in column order.
    pub parts: Vec<(LossColumn, f64)>,
    pub bearings: Vec<BearingLoss>,
}

impl LossBudget {
    /// The sum of the parts present (W).
    pub fn beside_mesh(&self) -> f64 {
        self.parts.iter().map(|(_, p)| p).sum()
    }

    /// One column's power (W), when the gearbox fills it.
    pub fn part(&self, column: LossColumn) -> Option<f64> {
        self.parts.iter().find(|(c, _)| *c == column).map(|(_, p)| *p)
    }
}

/// The budget of one (operating point, law, formulation): the mesh loss it was given plus the parts
/// beside the mesh, the total and the total efficiency 1 − P_total/P_in, and every bearing place's
/// loads and losses in the scene's order (pinion shaft, then wheel shaft), as the record files carry
/// it ([`super::columns`] names the columns).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BudgetParts {
    /// The power of each column the gearbox fills (W), in column order.
    pub parts: Vec<(LossColumn, f64)>,
    pub total_loss: f64,
    pub total_efficiency: f64,
    pub bearings: Vec<BearingLoads>,
}

impl LossBudget {
    /// The parts with a mesh loss `mesh` (W) at input power `input` (W).
    pub fn with_mesh(&self, mesh: f64, input: f64) -> BudgetParts {
        let total = mesh + self.beside_mesh();
        BudgetParts {
            parts: self.parts.clone(),
            total_loss: total,
            total_efficiency: 1.0 - total / input,
            bearings: self.bearings.iter().map(|b| b.loads).collect(),
        }
    }
}

impl BudgetParts {
    /// One column's power (W), when the gearbox fills it.
    pub fn part(&self, column: LossColumn) -> Option<f64> {
        self.parts.iter().find(|(c, _)| *c == column).map(|(_, p)| *p)
    }
}

/// The budget at pinion torque T_1 (N·m) and speed ω_1 (rad/s) in `oil`: every part of the
/// catalogue ([`super::parts::PARTS`]) the gearbox describes.
pub fn loss_budget(gearbox: &Gearbox, g: &PairGeometry, torque: f64, omega_1: f64, oil: &Oil) -> LossBudget {
    let at = PartState {
        pinion_torque: torque,
        omega: [omega_1, omega_1 / g.gear_ratio],
        pitch_radius: g.working_pitch_radius,
        face_width: g.face_width,
        transverse_force: torque / g.base_radius[0],
        pressure_angle: g.operating_pressure_angle,
        axial_force: g.axial_force(torque),
    };
    let mut out = PartLosses::default();
    for part in PARTS.iter().filter_map(|p| (p.of)(gearbox)) {
        part.losses(&at, oil, &mut out);
    }
    out.powers.sort_by_key(|(c, _)| *c);
    LossBudget { parts: out.powers, bearings: out.bearings }
}
