//! What a planetary stage's physics found at one operating point: the members' speeds and torques,
//! the rolling power, both meshes, η₀ and η, the planets' forces and bearings, the churning.

use serde::{Deserialize, Serialize};

use super::loads::PlanetForces;
use crate::drive::kinematics::planetary::PlanetaryMember;
use crate::drive::layout::Member;
use crate::drive::mesh_state::MeshState;

/// A planetary stage at one operating point.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlanetaryPoint {
    pub planets: u32,
    pub held: PlanetaryMember,
    /// The member that puts the power in and the one that takes it out.
    pub driving_member: PlanetaryMember,
    pub driven_member: PlanetaryMember,
    /// [sun, ring, carrier]: speeds (rad/s, signed about +z) and the torques the outside puts on
    /// them (N·m, T_sun + T_ring + T_carrier = 0).
    pub speeds: [f64; 3],
    pub torques: [f64; 3],
    /// P_w = T_sun (ω_sun − ω_carrier) (W).
    pub rolling_power: f64,
    pub sun_drives_meshes: bool,
    /// [sun–planet, planet–ring]: η, the losses of all planets (W), the pinion's torque per planet
    /// (N·m) and its speed in the carrier's frame (rad/s).
    pub mesh_efficiency: [f64; 2],
    pub mesh_loss: [f64; 2],
    pub mesh_torque: [f64; 2],
    pub mesh_speed: [f64; 2],
    /// η₀ = η_sp η_pr.
    pub basic_efficiency: f64,
    /// η of the stage (meshes only; its bearings and churning are charged on the shafts).
    pub efficiency: f64,
    /// The planet's speed relative to the carrier (rad/s).
    pub planet_speed: f64,
    /// The most loaded planet's forces (every planet's with equal sharing).
    pub forces: PlanetForces,
    /// All planets' bearings (W): no-load and load parts.
    pub planet_bearings: [f64; 2],
    /// The churning body's loss (W): the carrier with its planets, or the sun where the carrier is held.
    pub churning: f64,
    /// A helical stage's planet bearings under its tilting moment, in words (empty for a spur stage).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub tilting_support: String,
}

/// The gears [in the pinion's place, in the wheel's] of a planetary stage's meshes as the stage's
/// pairs are written: the sun–planet mesh (mesh 0) and the planet–ring mesh (mesh 1).
pub(crate) const MESH_GEARS: [[&str; 2]; 2] = [["sun", "planet"], ["planet", "ring"]];

impl PlanetaryPoint {
    /// Its two meshes as the walk evaluates them: the sun–planet mesh (the stage's own pair, the sun
    /// its pinion) driven by the sun or the planet, whichever drives the meshes, and the
    /// planet–ring mesh (mesh 1) with the planet in the pinion's place whichever drives; each at
    /// the pinion's torque per planet and its speed in the carrier's frame.
    pub(crate) fn mesh_states(&self) -> [MeshState; 2] {
        let sun = self.sun_drives_meshes;
        let at = |i: usize| (self.mesh_torque[i].abs(), self.mesh_speed[i].abs(), self.mesh_efficiency[i]);
        let ((t0, w0, e0), (t1, w1, e1)) = (at(0), at(1));
        [
            MeshState {
                mesh: 0,
                name: Some("sun–planet"),
                driving: if sun { Member::Pinion } else { Member::Wheel },
                members: if sun { MESH_GEARS[0] } else { [MESH_GEARS[0][1], MESH_GEARS[0][0]] },
                torque: t0,
                speed: w0,
                efficiency: e0,
            },
            MeshState {
                mesh: 1,
                name: Some("planet–ring"),
                driving: Member::Pinion,
                members: MESH_GEARS[1],
                torque: t1,
                speed: w1,
                efficiency: e1,
            },
        ]
    }
}
