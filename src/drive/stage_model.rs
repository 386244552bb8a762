//! What the drive's walk reads of a stage kind: one [`StageModel`] a kind (`parallel_stage.rs`,
//! `planetary/model.rs`), one row of `Stage::model` (`stage_kinds.rs`) each. The walk never asks which kind a
//! stage is: the kind gives its kinematics, the gears its no-load parts charge, its efficiency
//! from its meshes', the forces on its members, the bearings its own members carry and its part
//! of the report's point.

use super::forces::{GearLoad, MeshForceSizes};
use super::kind_state::{KindInputs, KindPoint, KindState};
use super::kinematics::StageKinematics;
use super::layout::{Member, Stage};
use super::mesh_efficiency::MeshEfficiency;
use super::mesh_state::MeshState;
use super::point::{BearingPoint, StagePoint};
use crate::geometry::PairGeometry;
use crate::losses::gear_no_load::GearsRunning;
use crate::losses::Oil;

/// A stage kind as the drive's walk reads it. `places` are the speeds of the stage's two places
/// (rad/s, signed about +z), `driving` the place whose member puts the power in, `torque` its
/// torque into the stage (N·m; > 0 unless said).
pub(crate) trait StageModel {
    /// The speeds of the stage's members and its ideal torque ratio.
    fn kinematics(&self, stage: &Stage) -> Box<dyn StageKinematics>;

    /// The name of the member on place `m`.
    fn member_name(&self, m: Member) -> &'static str;

    /// The gears the stage's lubrication sets running (churning, jet impulse and windage at their
    /// speeds), and the place the mesh's parts are charged on (the other place takes the second
    /// gear's windage).
    fn gears_running(&self, stage: &Stage, sizes: &MeshForceSizes, places: [f64; 2]) -> (usize, GearsRunning);

    /// η of stage `k` (P_out/P_in of its meshes) at `speed` (|ω| of the driving place, rad/s,
    /// > 0) from its meshes' efficiencies `meshes`, and what the kind keeps of it for its point.
    fn efficiency(
        &self,
        stage: (usize, &Stage),
        meshes: &dyn MeshEfficiency,
        driving_torque_speed: (Member, f64, f64),
        places: [f64; 2],
    ) -> (f64, Option<KindState>);

    /// The forces of stage `k` on its members that sit on shafts, `torque` signed as the walk
    /// carries it.
    fn member_loads(
        &self,
        stage: (usize, &Stage),
        sizes: &MeshForceSizes,
        driving_torque: (Member, f64),
        places: [f64; 2],
    ) -> Vec<GearLoad>;

    /// The bearings the stage's own members carry (none on a shaft's places), charged to a shaft:
    /// its index and the place as the report lists it; None when the kind has none.
    fn member_bearings(
        &self,
        stage: &Stage,
        driving_torque: (Member, f64),
        places: [f64; 2],
        oil: &Oil,
    ) -> Option<(usize, BearingPoint)>;

    /// The stage's mesh forces [F_t, F_r, F_a] (N) for its point, and the kind's part of the point
    /// from the settled pass's `state`; `parts` are the [no-load, load] losses of the bearings its
    /// members carry and its no-load parts (W).
    fn point(
        &self,
        stage: &Stage,
        sizes: &MeshForceSizes,
        driving_torque: (Member, f64),
        state: Option<&KindState>,
        parts: ([f64; 2], f64),
    ) -> ([f64; 3], Option<Box<KindPoint>>);

    /// Whether the member on place `m` is centred by the kind's own bodies (a sun among two planets
    /// or more: a floating sun), so that one bearing place may carry its shaft when it is alone there.
    fn centred_member(&self, m: Member) -> bool;

    /// Whether the stage is one pair on two shafts, whose mesh misalignment their bending gives.
    fn one_pair_on_two_shafts(&self) -> bool;

    /// The gears [in the pinion's place, in the wheel's] of each of its meshes, in mesh order (mesh
    /// 0 the stage's own pair).
    fn mesh_gears(&self) -> &'static [[&'static str; 2]];

    /// The kind's own columns of drive_records.csv, after every stage's (the values are its
    /// [`KindPoint::record_values`]).
    fn record_columns(&self) -> &'static [&'static str];

    /// What the report notes of the shafts the stage sits on: (shaft, what it carries, why that is
    /// sound), e.g. a gear the kind centres on a shaft of one bearing place.
    fn shaft_notes(&self, stage: &Stage, bearing_places: &dyn Fn(usize) -> usize) -> Vec<(usize, String, String)>;

    /// The kind's own inputs for the report's table of stages (`layout` the drive the stage sits
    /// in, `further` the geometries of its meshes beyond its own pair, mesh 1 first): none by
    /// default, every stage's inputs being in the stage's row.
    fn inputs(&self, _layout: &super::layout::Drive, _stage: &Stage, _further: &[&PairGeometry]) -> Option<KindInputs> {
        None
    }

    /// The stage's meshes at `point` as the walk evaluated them, each with the gear it evaluated
    /// in the pinion's place at that gear's |T| and |ω|: by default the one pair, its driving gear
    /// in the pinion's place.
    fn mesh_states(&self, _stage: &Stage, point: &StagePoint) -> Vec<MeshState> {
        one_mesh(point, (point.driving, point.driving_torque.abs(), point.driving_speed.abs()))
    }
}

/// The state of a stage of one mesh at `point`: its pair with the gear on place `driving` in the
/// pinion's place at |T| `torque` and |ω| `speed`.
pub(crate) fn one_mesh(point: &StagePoint, (driving, torque, speed): (Member, f64, f64)) -> Vec<MeshState> {
    vec![MeshState {
        mesh: 0,
        name: None,
        driving,
        members: [driving.name(), driving.other().name()],
        torque,
        speed,
        efficiency: point.mesh_efficiency,
    }]
}
