//! A parallel stage as the drive's walk reads it: one external pair on two shafts (spur or
//! helical), its pinion and wheel on the stage's two places. The same model, with its own
//! kinematics and forces, is the internal stage's (`internal_stage.rs`).

use super::forces::{internal_mesh_forces, mesh_forces, GearLoad, MeshForceSizes};
use super::kind_state::{KindPoint, KindState};
use super::kinematics::{internal::Internal, parallel::Parallel, StageKinematics};
use super::layout::{Member, Stage};
use super::mesh_efficiency::MeshEfficiency;
use super::mesh_state::MeshState;
use super::point::{BearingPoint, StagePoint};
use super::stage_model::StageModel;
use crate::losses::gear_no_load::GearsRunning;
use crate::losses::Oil;

/// A stage of one pair on two parallel shafts: external (the parallel kind) or internal (a pinion
/// inside a ring gear, [`super::internal_stage::INTERNAL_STAGE`]).
pub(crate) struct ParallelStage {
    pub internal: bool,
}

/// The parallel stage kind.
pub(crate) const PARALLEL_STAGE: ParallelStage = ParallelStage { internal: false };

impl StageModel for ParallelStage {
    fn kinematics(&self, stage: &Stage) -> Box<dyn StageKinematics> {
        match self.internal {
            true => Box::new(Internal { teeth: stage.teeth }),
            false => Box::new(Parallel { teeth: stage.teeth }),
        }
    }

    fn member_name(&self, m: Member) -> &'static str {
        m.name()
    }

    /// Both gears at their places' speeds: the mesh's parts on the pinion's shaft.
    fn gears_running(&self, _: &Stage, sizes: &MeshForceSizes, places: [f64; 2]) -> (usize, GearsRunning) {
        let running = GearsRunning {
            omega: places.map(f64::abs),
            pitch_radius: sizes.working_pitch_radius,
            face_width: sizes.face_width,
        };
        (0, running)
    }

    /// The one mesh's η at the driving gear's torque and speed (1 at no torque or no speed, where
    /// no mesh is evaluated), the pair as [`Self::mesh_states`] gives it.
    fn efficiency(
        &self,
        (k, stage): (usize, &Stage),
        meshes: &dyn MeshEfficiency,
        (driving, torque, speed): (Member, f64, f64),
        _: [f64; 2],
    ) -> (f64, Option<KindState>) {
        if torque == 0.0 || speed == 0.0 {
            return (1.0, None);
        }
        let (driving, torque, speed) = self.in_pinion_place(stage, (driving, torque.abs(), speed.abs()));
        (meshes.efficiency(k, 0, driving, torque, speed), None)
    }

    fn member_loads(
        &self,
        (k, stage): (usize, &Stage),
        sizes: &MeshForceSizes,
        (driving, torque): (Member, f64),
        places: [f64; 2],
    ) -> Vec<GearLoad> {
        let forces = if self.internal { internal_mesh_forces } else { mesh_forces };
        forces((k, stage), sizes, driving, torque, places[driving.index()]).to_vec()
    }

    fn member_bearings(&self, _: &Stage, _: (Member, f64), _: [f64; 2], _: &Oil) -> Option<(usize, BearingPoint)> {
        None
    }

    fn point(
        &self,
        _: &Stage,
        sizes: &MeshForceSizes,
        (driving, torque): (Member, f64),
        _: Option<&KindState>,
        _: ([f64; 2], f64),
    ) -> ([f64; 3], Option<Box<KindPoint>>) {
        (sizes.magnitudes(driving, torque), None)
    }

    fn centred_member(&self, _: Member) -> bool {
        false
    }

    fn one_pair_on_two_shafts(&self) -> bool {
        true
    }

    fn mesh_gears(&self) -> &'static [[&'static str; 2]] {
        &[["pinion", "wheel"]]
    }

    fn record_columns(&self) -> &'static [&'static str] {
        &[]
    }

    fn shaft_notes(&self, _: &Stage, _: &dyn Fn(usize) -> usize) -> Vec<(usize, String, String)> {
        Vec::new()
    }

    /// The pair with the gear [`Self::in_pinion_place`] puts there in the pinion's place.
    fn mesh_states(&self, stage: &Stage, point: &StagePoint) -> Vec<MeshState> {
        let driving = (point.driving, point.driving_torque.abs(), point.driving_speed.abs());
        super::stage_model::one_mesh(point, self.in_pinion_place(stage, driving))
    }
}

impl ParallelStage {
    /// The gear evaluated in the pinion's place and its |T| and |ω| when `driving` drives at |T|
    /// and |ω|: the driving gear (the wheel driving is the pair with its roles swapped), except that
    /// a ring is no pinion: an internal pair driven by its ring is evaluated as the pinion's pair at
    /// the same power, T/u and ω·u with u = z_ring/z_pinion (README, "An internal stage").
    fn in_pinion_place(&self, stage: &Stage, (driving, torque, speed): (Member, f64, f64)) -> (Member, f64, f64) {
        match (self.internal, driving) {
            (true, Member::Wheel) => {
                let u = f64::from(stage.teeth[1]) / f64::from(stage.teeth[0]);
                (Member::Pinion, torque / u, speed * u)
            }
            _ => (driving, torque, speed),
        }
    }
}
