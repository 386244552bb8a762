//! What the drive's physics found at one operating point, law and formulation: every shaft's
//! speed, torques and bearing loads, every stage's driving member and mesh loss, the ends' torques
//! and powers, the parts of the loss and the efficiency.

use serde::{Deserialize, Serialize};

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
    /// On the shaft's own axial coordinate (m).
    pub position: f64,
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
    /// A planetary stage's planet bearings (on the planets' pins, charged to this shaft), not one of
    /// the shaft's bearing places.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub on_planets: bool,
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
    /// The no-load parts of the stages whose pinion this shaft carries (W).
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
    /// The stage's no-load parts (W), charged on its pinion's shaft.
    pub no_load: f64,
    /// F_t, F_r, F_a (N).
    pub tangential_force: f64,
    pub radial_force: f64,
    pub axial_force: f64,
    /// The mesh misalignment its bent shafts imply (m), when both have sections (reported, not fed
    /// back into the mesh).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mesh_misalignment: Option<f64>,
    /// A planetary stage's members, meshes and planets.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub planetary: Option<Box<super::planetary::PlanetaryPoint>>,
}

impl StagePoint {
    /// The name of the member on place `m`: pinion or wheel, or a planetary stage's sun, ring or
    /// carrier.
    pub fn member_name(&self, m: Member) -> &'static str {
        match &self.planetary {
            Some(p) if m == self.driving => p.driving_member.name(),
            Some(p) => p.driven_member.name(),
            None => m.name(),
        }
    }
}

/// The parts of the total loss (W).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct LossParts {
    pub meshes: f64,
    pub gear_no_load: f64,
    pub bearings_no_load: f64,
    pub bearings_load: f64,
    pub seals: f64,
}

impl LossParts {
    pub fn total(&self) -> f64 {
        self.meshes + self.gear_no_load + self.bearings_no_load + self.bearings_load + self.seals
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
}

impl DrivePoint {
    /// P_source − P_sink (W): the power the box turns into heat.
    pub fn power_lost(&self) -> f64 {
        self.input_power - self.output_power
    }
}
