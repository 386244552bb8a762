//! What the drive's physics found at one operating point, law and formulation: every shaft's
//! speed, torques and bearing loads, every stage's driving member and mesh loss, the ends' torques
//! and powers, the parts of the loss and the efficiency.

use serde::{Deserialize, Serialize};

use crate::losses::parts::{LossColumn, COLUMN_COUNT};

use super::kind_state::KindPoint;
use super::layout::Member;

/// Which end delivers the power.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PowerFlow {
    /// The input shaft delivers (the motor drives).
    Drive,
    /// The output shaft delivers (coast, recuperation).
    Coast,
}

impl PowerFlow {
    pub fn name(self) -> &'static str {
        match self {
            PowerFlow::Drive => "drive",
            PowerFlow::Coast => "coast",
        }
    }
}

/// One bearing place at an operating point.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BearingPoint {
    pub kind: String,
    pub count: usize,
    /// On the shaft's own axial coordinate (m); None for a place of a one-pair scene written
    /// without `at` (it carries its share of the gear force, `shaft_bending::shared_reactions`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub position: Option<f64>,
    pub locating: bool,
    /// The whole place's reaction on the shaft [R_x, R_y, R_z] (N); zero for a planetary stage's
    /// planet bearings (listed with their carrier's shaft, they load the planets' pins).
    pub reaction: [f64; 3],
    /// Per bearing: |(R_x, R_y)|/count and, at the locating place, |R_z|/count (N).
    pub radial_load: f64,
    pub axial_load: f64,
    /// The place's powers (W): M_0 (or M_rr) and M_1 (or M_sl) × |ω| × count.
    pub no_load: f64,
    pub load: f64,
    /// Bearings a stage's own members carry (`StageModel::member_bearings`: a planetary stage's
    /// planet bearings on the planets' pins), charged to this shaft, not one of the shaft's bearing
    /// places. report.json keeps the key it has always had, `on_planets`.
    #[serde(default, rename = "on_planets", skip_serializing_if = "std::ops::Not::not")]
    pub of_stage_members: bool,
}

impl BearingPoint {
    /// One of the shaft's own bearing places (not bearings a stage's members carry).
    pub fn is_shaft_place(&self) -> bool {
        !self.of_stage_members
    }
}

/// One shaft at an operating point. Powers and torques along the power flow: `received` comes in
/// through its gear (or at the end where the source is), `passed` leaves it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ShaftPoint {
    pub name: String,
    /// Signed, about +z (rad/s).
    pub speed: f64,
    pub received_torque: f64,
    pub passed_torque: f64,
    pub received_power: f64,
    pub passed_power: f64,
    pub bearings: Vec<BearingPoint>,
    /// The mesh forces on the shaft's gears, in the frame the statics reads.
    pub gear_loads: Vec<super::forces::GearLoad>,
    pub seals: f64,
    /// The gears' no-load parts charged on this shaft (W): the churning and jet impulse of the stages whose pinion it carries, the windage of each gear it carries.
    pub gear_no_load: f64,
    /// A shaft with sections: its bending (elastic beam).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bending: Option<super::shaft_bending::ShaftBending>,
}

impl ShaftPoint {
    /// All the shaft's own losses (W).
    pub fn losses(&self) -> f64 {
        self.bearings.iter().map(|b| b.no_load + b.load).sum::<f64>() + self.seals + self.gear_no_load
    }
}

/// One stage at an operating point.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StagePoint {
    pub name: String,
    pub driving: Member,
    /// The driving gear's torque into the mesh and the driven gear's out of it (N·m).
    pub driving_torque: f64,
    pub driven_torque: f64,
    /// |ω| of the driving gear (rad/s).
    pub driving_speed: f64,
    pub mesh_efficiency: f64,
    /// (1 − η_mesh) × the power through the mesh (W).
    pub mesh_loss: f64,
    /// The stage's no-load parts (W): churning and jet impulse charged on its pinion's shaft, each gear's windage on its own.
    pub no_load: f64,
    /// F_t, F_r, F_a (N).
    pub tangential_force: f64,
    pub radial_force: f64,
    pub axial_force: f64,
    /// The mesh misalignment its bent shafts imply (m), when both have sections (reported, not fed
    /// back into the mesh).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mesh_misalignment: Option<f64>,
    /// The stage kind's own part of the point (its members, meshes and what they carry), for a
    /// kind that has one.
    #[serde(flatten, default)]
    pub kind: Option<Box<KindPoint>>,
}

impl StagePoint {
    /// The name of the member on place `m`: pinion or wheel, or the kind's own name of it.
    pub fn member_name(&self, m: Member) -> &'static str {
        match &self.kind {
            Some(k) => k.member_name(m, self.driving),
            None => m.name(),
        }
    }
}

/// The parts of the total loss (W): the meshes' and each column of the loss-part catalogue's
/// (`crate::losses::parts::COLUMNS`), in report.json under `meshes` and each column's key.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LossParts {
    pub meshes: f64,
    /// Each column's power, in column order.
    pub parts: [f64; COLUMN_COUNT],
}

impl LossParts {
    /// One column's power (W).
    pub fn part(&self, column: LossColumn) -> f64 {
        self.parts[column as usize]
    }

    /// The meshes' loss and every column's, added in that order.
    pub fn total(&self) -> f64 {
        self.parts.iter().fold(self.meshes, |total, p| total + p)
    }

    /// Every loss beside the meshes, added in column order.
    pub fn beside_meshes(&self) -> f64 {
        self.parts.iter().sum()
    }
}

/// The drive at one operating point, law and formulation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DrivePoint {
    pub flow: PowerFlow,
    /// Input: torque into the box (N·m, positive in drive) at |ω_in|; its power (W).
    pub input_torque: f64,
    pub input_speed: f64,
    pub input_power: f64,
    /// Output: torque out of the box to the load (N·m, negative in coast) at |ω_out|; its power (W).
    pub output_torque: f64,
    pub output_speed: f64,
    pub output_power: f64,
    pub shafts: Vec<ShaftPoint>,
    pub stages: Vec<StagePoint>,
    pub losses: LossParts,
    /// η = P_sink/P_source; 0 where both ends deliver.
    pub efficiency: f64,
    /// The source's power does not cover the box's losses: both ends deliver power.
    pub both_ends_deliver: bool,
    /// Passes of the fixed point until no torque moved by more than 1e-12 relative.
    pub iterations: usize,
    /// The fixed point diverged (the bearing losses grew faster than the torque that loads them):
    /// the numbers are the last pass's before it ran away.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub diverged: bool,
    /// Where the books do not balance: (P_source − P_sink) − Σ parts (W), when it is more than
    /// `BOOKS_TOLERANCE` of the larger of P_source and Σ parts, or not a finite number.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub books_gap: Option<f64>,
    /// A one-pair scene's point whose walks did not bring the mesh's driving torque to the given
    /// `pinion_torque` (to 1e-12 relative, in eight walks): by how much it is short
    /// (N·m; not a finite number where a walk failed).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pinion_torque_missed: Option<f64>,
}

/// Walks at most, beyond the first, to put a one-pair scene's torque at its pinion gear (they
/// settle in two or three).
pub(crate) const PINION_WALKS: usize = 8;

/// The books of a point balance when P_source − P_sink equals the sum of the loss parts to this
/// fraction of the larger of P_source and the parts (a settled point balances to about 1e-12).
pub(crate) const BOOKS_TOLERANCE: f64 = 1e-9;

/// Passes after which the fixed point counts as not settled.
pub(crate) const MAX_PASSES: usize = 100;

impl DrivePoint {
    /// Whether the point's numbers can be trusted: the fixed point settled and the books balance.
    pub fn settled(&self) -> bool {
        self.iterations < MAX_PASSES
            && !self.diverged
            && self.books_gap.is_none()
            && self.pinion_torque_missed.is_none()
    }

    /// What is wrong with an unsettled point, in words (empty when it settled).
    pub fn unsettled_words(&self) -> String {
        let mut out = Vec::new();
        if self.diverged {
            out.push("the fixed point of the bearing losses diverged (they grow faster than the torque that loads them: a gear far outside its bearings' span?); its numbers are the last pass's before it ran away".to_string());
        } else if self.iterations >= MAX_PASSES {
            out.push(format!("the fixed point of the bearing losses did not settle to 1e-12 in {MAX_PASSES} passes; its numbers are the last pass's"));
        }
        if let Some(gap) = self.books_gap {
            out.push(format!(
                "the books do not balance: P_source − P_sink = {:.6e} W but the loss parts add up to {:.6e} W (a gap of {gap:.3e} W)",
                self.source_power() - self.sink_power(),
                self.losses.total()
            ));
        }
        if let Some(missed) = self.pinion_torque_missed {
            out.push(format!(
                "the mesh's driving torque did not reach the given pinion_torque to 1e-12 in {PINION_WALKS} walks ({missed:.3e} N·m short); its numbers are the last walk's"
            ));
        }
        out.join("; ")
    }

    /// The power the source delivers and the sink takes (W).
    fn source_power(&self) -> f64 {
        match self.flow {
            PowerFlow::Drive => self.input_power,
            PowerFlow::Coast => -self.output_power,
        }
    }

    fn sink_power(&self) -> f64 {
        match self.flow {
            PowerFlow::Drive => self.output_power,
            PowerFlow::Coast => -self.input_power,
        }
    }

    /// The books' gap of a point as built, None where they balance ([`BOOKS_TOLERANCE`]).
    pub(crate) fn books_gap_of(&self) -> Option<f64> {
        let (source, parts) = (self.source_power(), self.losses.total());
        let gap = (source - self.sink_power()) - parts;
        let scale = source.abs().max(parts.abs());
        (!gap.is_finite() || gap.abs() > BOOKS_TOLERANCE * scale).then_some(gap)
    }

    /// P_source − P_sink (W): the power the box turns into heat.
    pub fn power_lost(&self) -> f64 {
        self.input_power - self.output_power
    }
}
