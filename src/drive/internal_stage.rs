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

use super::parallel_stage::ParallelStage;

/// The internal stage kind: a parallel stage's model (its gears' no-load parts, its one mesh's η,
/// its point) with the internal pair's kinematics and forces ([`super::forces::internal_mesh_forces`]).
/// Lowering refuses a lubrication method on it (no ring churning is charged).
pub(crate) const INTERNAL_STAGE: ParallelStage = ParallelStage { internal: true };

#[cfg(test)]
mod tests {
    use crate::drive::forces::{internal_mesh_forces, GearLoad, MeshForceSizes};
    use crate::drive::kinematics::StageKind;
    use crate::drive::layout::{GearPlace, Member, Stage};

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
