//! The loss budget of one operating point beside the mesh: gear churning or jet impulse, bearings
//! (no-load and load-dependent) and seals, with the bearing loads it took them from.
//!
//! Each part is a row of the catalogue [`super::parts`]; this file adds them up.

use serde::Serialize;

pub use super::bearing_loss::{BearingLoads, BearingLoss};
use super::gear_no_load::GearsRunning;
use super::gearbox::Gearbox;
use super::oil::Oil;
use super::pair_statics::{place_loads, GearForce};
use super::parts::catalog::{add_parts, columns_of};
use super::parts::{LossColumn, PartLosses, PartState};
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

/// The total efficiency of a pair with its gearbox, ISO/TR 14179-2's: η = 1 − P_V/P_in, the whole
/// loss `loss` (W) over the power `input` (W) at the pinion gear, T_1 ω_1 — a scene of one pair's
/// η total in its budget, its map and, run as its one-stage drive, "η at the pinion" (the drive's
/// own η, P_out/P_in, takes the input's power, the pinion's plus its shaft's losses).
pub fn total_efficiency(loss: f64, input: f64) -> f64 {
    1.0 - loss / input
}

impl LossBudget {
    /// The parts with a mesh loss `mesh` (W) at input power `input` (W).
    pub fn with_mesh(&self, mesh: f64, input: f64) -> BudgetParts {
        let total = mesh + self.beside_mesh();
        BudgetParts {
            parts: self.parts.clone(),
            total_loss: total,
            total_efficiency: total_efficiency(total, input),
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
/// catalogue ([`super::parts::PARTS`]) the gearbox describes, on the pinion's and the wheel's shaft
/// at ω_1 and ω_1/u, their bearing places loaded by the mesh force ([`super::pair_statics`]). A run
/// charges a pair's budget on its one-stage drive (the same parts on the drive's shafts and
/// statics); this is the gearbox on its own, for a library user without a scene and the independent
/// calculation the run's budget is tested against (1e-14).
pub fn loss_budget(gearbox: &Gearbox, g: &PairGeometry, torque: f64, omega_1: f64, oil: &Oil) -> LossBudget {
    let omega = [omega_1, omega_1 / g.gear_ratio];
    let f_bt = torque / g.base_radius[0];
    let axial = g.axial_force(torque);
    let force = |s: usize| GearForce {
        tangential: f_bt * g.operating_pressure_angle.cos(),
        radial: f_bt * g.operating_pressure_angle.sin(),
        axial: if s == 0 { axial } else { -axial },
        radius: g.working_pitch_radius[s],
    };
    let loads: [Vec<[f64; 2]>; 2] = [0, 1].map(|s| place_loads(&gearbox.bearings[s], force(s), f_bt));
    let running = GearsRunning { omega, pitch_radius: g.working_pitch_radius, face_width: g.face_width };
    let (shafts, stages) = gearbox.parts_on(running, &[&loads[0], &loads[1]]);
    let on = PartState { shafts: &shafts, stages: &stages };
    let mut out = PartLosses::new(2, 1, true);
    add_parts(&on, oil, false, &mut out);
    add_parts(&on, oil, true, &mut out);
    let parts = columns_of(&on).into_iter().map(|c| (c, out.column(c))).collect();
    let places = out.places.unwrap_or_default();
    let bearings = (0..2)
        .flat_map(|s| gearbox.bearings[s].iter().zip(&places[s]).map(move |(b, loads)| (s, b, *loads)))
        .map(|(s, b, loads)| BearingLoss {
            shaft: ["pinion", "wheel"][s],
            kind: b.kind.name(),
            model: b.model_name(),
            count: b.count,
            position: b.position,
            loads,
        })
        .collect();
    LossBudget { parts, bearings }
}
