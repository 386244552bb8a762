//! An internal stage as the drive's walk reads it: a pinion inside a ring gear (the stage's wheel)
//! on two parallel shafts, both turning the same way.
//!
//! The mesh force (ISO 21771:2007's internal pair; Niemann & Winter, Maschinenelemente II, 2.5):
//! F_t = T/r_w, F_r = F_t tan α_wt, F_a = T tan β/r of the driving gear, as for an external pair.
//! The contact lies on the line of centres beyond the pinion's axis, seen from the ring's: at r_w1
//! from the pinion's centre and r_w2 from the ring's, both along the stage's direction φ. On the
//! pinion the radial part points to its centre whichever gear drives (the teeth push apart), the
//! tangential part opposes its rotation when it drives and drives it when it is driven, and the
//! axial part is an external pair's on its own flank (a right-hand pinion driving counter-clockwise:
//! +z); the ring receives the opposite force.
//!
//! Where the ring drives (coast), the mesh is evaluated with the pinion in the pinion's place at the
//! same power (a ring is no pinion): the pinion's torque T z_p/z_r and speed ω z_r/z_p
//! (`evaluate/drive_setup.rs`), as a planetary stage's planet–ring mesh is.

use super::forces::{GearLoad, MeshForceSizes};
use super::kind_state::{KindPoint, KindState};
use super::kinematics::{internal::Internal, StageKinematics};
use super::layout::{Member, Stage};
use super::mesh_efficiency::MeshEfficiency;
use super::point::BearingPoint;
use super::stage_model::StageModel;
use crate::losses::gear_no_load::GearsRunning;
use crate::losses::Oil;

/// The internal stage kind.
pub(crate) struct InternalStage;

impl StageModel for InternalStage {
    fn kinematics(&self, stage: &Stage) -> Box<dyn StageKinematics> {
        Box::new(Internal { teeth: stage.teeth })
    }

    fn member_name(&self, m: Member) -> &'static str {
        m.name()
    }

    /// Both gears at their places' speeds (lowering refuses a lubrication method on an internal
    /// stage: no churning is charged).
    fn gears_running(&self, _: &Stage, sizes: &MeshForceSizes, places: [f64; 2]) -> (usize, GearsRunning) {
        let running = GearsRunning {
            omega: places.map(f64::abs),
            pitch_radius: sizes.working_pitch_radius,
            face_width: sizes.face_width,
        };
        (0, running)
    }

    /// The one mesh's η at the driving gear's torque and speed (1 at no torque or no speed).
    fn efficiency(
        &self,
        (k, _): (usize, &Stage),
        meshes: &dyn MeshEfficiency,
        (driving, torque, speed): (Member, f64, f64),
        _: [f64; 2],
    ) -> (f64, Option<KindState>) {
        if torque == 0.0 || speed == 0.0 {
            (1.0, None)
        } else {
            (meshes.efficiency(k, 0, driving, torque.abs(), speed), None)
        }
    }

    fn member_loads(
        &self,
        (k, stage): (usize, &Stage),
        sizes: &MeshForceSizes,
        (driving, torque): (Member, f64),
        places: [f64; 2],
    ) -> Vec<GearLoad> {
        internal_mesh_forces((k, stage), sizes, driving, torque, places[driving.index()]).to_vec()
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
}

/// The mesh forces of an internal stage on [pinion, ring] when member `driving` passes `torque`
/// (N·m, ≥ 0) into the mesh turning at `omega` (rad/s, signed about +z; both gears turn that way).
pub(crate) fn internal_mesh_forces(
    (index, stage): (usize, &Stage),
    sizes: &MeshForceSizes,
    driving: Member,
    torque: f64,
    omega: f64,
) -> [GearLoad; 2] {
    let [f_t, f_r, f_a] = sizes.magnitudes(driving, torque);
    let (s, c) = stage.direction.sin_cos();
    let sense = if omega < 0.0 { -1.0 } else { 1.0 };
    // +1 where the pinion drives (its rotation opposed), −1 where it is driven.
    let role = if driving == Member::Pinion { 1.0 } else { -1.0 };
    let hand = stage.hand.map_or(0.0, |h| h.sign());
    let on_pinion = [
        -role * sense * f_t * -s - f_r * c,
        -role * sense * f_t * c - f_r * s,
        if f_a == 0.0 { 0.0 } else { role * hand * sense * f_a },
    ];
    let load = |m: Member, sign: f64| {
        let place = stage.places[m.index()];
        let r = sizes.working_pitch_radius[m.index()];
        GearLoad {
            stage: index,
            member: m,
            shaft: place.shaft,
            point: [r * c, r * s, place.at],
            force: on_pinion.map(|x| sign * x),
        }
    };
    [load(Member::Pinion, 1.0), load(Member::Wheel, -1.0)]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drive::kinematics::StageKind;
    use crate::drive::layout::GearPlace;

    fn stage(direction: f64) -> Stage {
        Stage {
            name: "ring".into(),
            kind: StageKind::Internal,
            places: [GearPlace { shaft: 0, at: 0.0 }, GearPlace { shaft: 1, at: 0.0 }],
            teeth: [25, 75],
            hand: None,
            direction,
            lubrication: None,
        }
    }

    const SIZES: MeshForceSizes = MeshForceSizes {
        working_pitch_radius: [0.025, 0.075],
        pitch_radius: [0.025, 0.075],
        working_pressure_angle: 0.35,
        helix_angle: 0.0,
        face_width: 0.025,
    };

    /// Pinion driving counter-clockwise at 60 N·m: the mesh brakes it (moment −60 N·m) and drives
    /// the ring the same way (+60 · 75/25 = +180 N·m); the radial force pushes the pinion to its
    /// centre (−x at φ = 0) and the ring outward; 1e-12. With the ring driving at 180 N·m the
    /// ring is braked and the pinion driven, the radial forces as before.
    #[test]
    fn the_ring_turns_with_the_pinion_and_the_teeth_push_apart() {
        for direction in [0.0, 1.1] {
            let [p, r] = internal_mesh_forces((0, &stage(direction)), &SIZES, Member::Pinion, 60.0, 100.0);
            assert!((p.torque() + 60.0).abs() < 1e-12 && (r.torque() - 180.0).abs() < 1e-12);
            let radial = |l: &GearLoad| (l.force[0] * direction.cos() + l.force[1] * direction.sin()) / (60.0 / 0.025);
            assert!((radial(&p) + 0.35f64.tan()).abs() < 1e-12 && (radial(&r) - 0.35f64.tan()).abs() < 1e-12);
            let [p, r] = internal_mesh_forces((0, &stage(direction)), &SIZES, Member::Wheel, 180.0, 100.0 / 3.0);
            assert!((p.torque() - 60.0).abs() < 1e-12 && (r.torque() + 180.0).abs() < 1e-12);
            assert!((radial(&p) + 0.35f64.tan()).abs() < 1e-12);
        }
    }
}
