//! The mesh force of a stage on each of its two gears, as a force vector at a point in the frame of
//! the gear's own shaft: x, y transverse (the drive's fixed frame, seen from +z), z the shaft's own
//! axial coordinate.
//!
//! From the driving member's torque T (N·m) and the working pitch radii (ISO 21771:2007; Niemann &
//! Winter, Maschinenelemente II, 2.5 "Zahnkräfte"): F_t = T/r_w,driving, F_r = F_t tan α_wt,
//! F_a = F_t tan β_w with tan β_w = tan β · r_w/r, so F_a = T tan β / r_driving. The force acts at the
//! contact point on the line of centres, at r_w from each axis: the pinion's at angle φ from its
//! centre, the wheel's at φ + π from its own. On the driving gear the tangential part opposes its
//! rotation and the radial part points to its centre; the driven gear receives the opposite force.
//! Axial sense: on the driving gear with a right-hand helix turning counter-clockwise about +z the
//! axial force points along +z; it flips with the hand and with the sense of rotation, and the
//! driven gear (of the other hand) receives the opposite. An internal stage's forces
//! ([`internal_mesh_forces`]): the contact beyond the pinion's axis, the ring pushed outward.

use super::layout::{Hand, Member, Stage};

/// The sizes of a stage's pair the forces read (m, rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshForceSizes {
    /// [pinion, wheel] working pitch radii r_w.
    pub working_pitch_radius: [f64; 2],
    /// [pinion, wheel] reference radii r.
    pub pitch_radius: [f64; 2],
    /// The working transverse pressure angle α_wt.
    pub working_pressure_angle: f64,
    /// The reference helix angle β (0 for spur).
    pub helix_angle: f64,
    /// The face width b, for the no-load parts.
    pub face_width: f64,
}

impl MeshForceSizes {
    /// The sizes of the pair `g`.
    pub(crate) fn of(g: &crate::geometry::PairGeometry) -> MeshForceSizes {
        MeshForceSizes {
            working_pitch_radius: g.working_pitch_radius,
            pitch_radius: g.pitch_radius,
            working_pressure_angle: g.operating_pressure_angle,
            helix_angle: g.helix_angle,
            face_width: g.face_width,
        }
    }

    /// [F_t, F_r, F_a] (N) when member `driving` puts `torque` (N·m) into the mesh.
    pub fn magnitudes(&self, driving: Member, torque: f64) -> [f64; 3] {
        let d = driving.index();
        let f_t = torque / self.working_pitch_radius[d];
        [f_t, f_t * self.working_pressure_angle.tan(), torque * self.helix_angle.tan() / self.pitch_radius[d]]
    }
}

/// A force `force` (N) on a gear of shaft `shaft`, acting at `point` (m: x, y from the shaft's
/// axis, z on the shaft's own axial coordinate).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct GearLoad {
    /// The stage's index (in the drive's stage order) and which of its gears this is.
    pub stage: usize,
    pub member: Member,
    pub shaft: usize,
    pub point: [f64; 3],
    pub force: [f64; 3],
}

impl GearLoad {
    /// The moment of the force about the shaft's axis (N·m, about +z).
    pub fn torque(&self) -> f64 {
        self.point[0] * self.force[1] - self.point[1] * self.force[0]
    }
}

/// The mesh forces of `stage` on [pinion, wheel] when member `driving` passes torque `torque`
/// (N·m, ≥ 0) into the mesh turning at `omega` (rad/s, signed about +z).
///
/// ```
/// use gearloss::drive::{mesh_forces, MeshForceSizes, Member};
/// # use gearloss::drive::{GearPlace, Hand, Stage};
/// # use gearloss::drive::kinematics::StageKind;
/// let stage = Stage { name: "first".into(), kind: StageKind::Parallel,
///     places: [GearPlace { shaft: 0, at: 0.05 }, GearPlace { shaft: 1, at: 0.05 }],
///     teeth: [23, 68], hand: Some(Hand::Right), direction: 0.0, lubrication: None };
/// let sizes = MeshForceSizes { working_pitch_radius: [0.019, 0.056], pitch_radius: [0.019, 0.056],
///     working_pressure_angle: 0.37, helix_angle: 0.4, face_width: 0.035 };
/// let [p, w] = mesh_forces((0, &stage), &sizes, Member::Pinion, 100.0, 300.0);
/// // The pinion is braked by the mesh (moment −T about +z), the wheel driven clockwise, the sense
/// // it turns (−T r_w2/r_w1 about +z).
/// assert!((p.torque() + 100.0).abs() < 1e-12);
/// assert!((w.torque() + 100.0 * 0.056 / 0.019).abs() < 1e-9);
/// // Right-hand pinion driving counter-clockwise: its axial force along +z.
/// assert!((p.force[2] - 100.0 * 0.4f64.tan() / 0.019).abs() < 1e-9 && w.force[2] == -p.force[2]);
/// ```
pub fn mesh_forces(
    (index, stage): (usize, &Stage),
    sizes: &MeshForceSizes,
    driving: Member,
    torque: f64,
    omega: f64,
) -> [GearLoad; 2] {
    let d = driving.index();
    let [f_t, f_r, f_a] = sizes.magnitudes(driving, torque);
    let (s, c) = stage.direction.sin_cos();
    // Unit vectors from each gear's centre to the contact point: the pinion's along φ, the wheel's
    // along φ + π.
    let unit = [[c, s], [-c, -s]];
    let point = |m: usize| {
        let r = sizes.working_pitch_radius[m];
        [r * unit[m][0], r * unit[m][1], stage.places[m].at]
    };
    let sense = if omega < 0.0 { -1.0 } else { 1.0 };
    let hand = match (stage.hand, driving) {
        (None, _) => 0.0,
        (Some(h), Member::Pinion) => h.sign(),
        (Some(Hand::Right), Member::Wheel) => -1.0,
        (Some(Hand::Left), Member::Wheel) => 1.0,
    };
    // On the driving gear: tangential −sense F_t (ẑ × û), radial −F_r û, axial hand · sense · F_a.
    let u = unit[d];
    let on_driving = [
        -sense * f_t * -u[1] - f_r * u[0],
        -sense * f_t * u[0] - f_r * u[1],
        if f_a == 0.0 { 0.0 } else { hand * sense * f_a },
    ];
    let load = |m: usize, sign: f64| {
        let member = if m == 0 { Member::Pinion } else { Member::Wheel };
        gear_load((index, stage), member, point(m), on_driving.map(|x| sign * x))
    };
    let mut out = [load(0, 1.0), load(1, 1.0)];
    out[1 - d] = load(1 - d, -1.0);
    out
}

/// The mesh forces of an internal stage on [pinion, ring] (`internal_stage.rs` states the model)
/// when member `driving` passes `torque` (N·m, ≥ 0) into the mesh turning at `omega` (rad/s,
/// signed about +z; both gears turn that way).
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
        let r = sizes.working_pitch_radius[m.index()];
        gear_load((index, stage), m, [r * c, r * s, stage.places[m.index()].at], on_pinion.map(|x| sign * x))
    };
    [load(Member::Pinion, 1.0), load(Member::Wheel, -1.0)]
}

/// The load `force` (N) at `point` (m, the shaft's frame) on `member` of stage `index`, on that
/// member's shaft.
fn gear_load((index, stage): (usize, &Stage), member: Member, point: [f64; 3], force: [f64; 3]) -> GearLoad {
    GearLoad { stage: index, member, shaft: stage.places[member.index()].shaft, point, force }
}
