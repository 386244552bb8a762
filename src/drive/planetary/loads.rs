//! The forces of a planetary stage: each planet's two mesh forces, its bearing's load, and the
//! forces on the members that sit on shafts (for the shafts' statics).
//!
//! As a parallel stage's, the forces follow the driving torque without the meshes' losses (the
//! lossless torques of [`member_torques`] at η₀ = 1), shared equally by the n planets. Planet j sits
//! at the angle θ_j = φ + 2πj/n (φ the stage's `direction`) at the carrier's centre distance a_w; with
//! r̂ = (cos θ_j, sin θ_j) and t̂ = (−sin θ_j, cos θ_j) (Niemann & Winter, *Maschinenelemente* III,
//! "Umlaufgetriebe"; ISO 6336-1 for F_r = F_t tan α_w):
//!
//! - on the sun, at r_w,sun r̂: F = −T_sun/(n r_w,sun) t̂ − |F_t,sun| tan α_w,sp r̂ (towards its centre);
//! - on the ring, at r_w,ring r̂: F = −T_ring/(n r_w,ring) t̂ + |F_t,ring| tan α_w,pr r̂ (outwards);
//! - on the carrier, at a_w r̂: the reverse of both (the planet passes them on through its bearing).
//!
//! The planet's bearing carries the two mesh forces and the planet's centrifugal force m ω_c² a_w:
//! B = −m ω_c² a_w r̂ − F_sun→planet − F_ring→planet, |B| shared by the planet's `count` bearings.
//! With n ≥ 2 the forces on each member cancel (only the torque remains); one planet loads the
//! sun's and the carrier's shafts.
//!
//! A helical stage adds each mesh's axial force F_a = F_t tan β_w = |T_sun| tan β/(n r_sun) (the
//! same in both meshes: F_t,sp r_w,p = F_t,pr r_w,p' and tan β_w = tan β r_w/r). Its sense follows
//! the parallel stage's rule ([`crate::drive::forces`]): a gear of hand h (+1 right) whose mesh
//! torque about +z is T_m receives −h sign(T_m) F_a along z. On the sun, T_m = −T_sun: F_z,sun =
//! h_sun sign(T_sun) F_a per planet, n F_a in all; the planet receives the reverse at the sun mesh
//! and, its two mesh torques opposite, the same F_z,sun at the ring mesh, so the ring receives
//! −F_z,sun per planet and the planet's axial forces cancel into the tilting moment
//! M = F_a (r_w,p + r_w,p') about its tangent, which its bearings pass to the carrier: there the two
//! axial forces act at the contact points, r_w,sun r̂ and r_w,ring r̂ (their sum over n ≥ 2 equally
//! spaced planets vanishes). A planet on two bearings a spacing L apart, its mesh plane midway,
//! gives each half the in-plane load and ±M/L along r̂: |(B_t/2, B_r/2 ± M/L)| (Niemann & Winter,
//! *Maschinenelemente* III, "Umlaufgetriebe"; the planet bearing's tilting load as in VDI 2157).

use crate::drive::forces::GearLoad;
use crate::drive::kinematics::planetary::{member_torques, stationary_ratio, PlanetaryLayout, PlanetaryMember};
use crate::drive::layout::{Member, Stage};

/// One planet's forces (N).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PlanetForces {
    /// F_t of the sun–planet and of the planet–ring mesh.
    pub tangential: [f64; 2],
    /// F_r of the sun–planet and of the planet–ring mesh.
    pub radial: [f64; 2],
    /// m ω_c² a_w.
    pub centrifugal: f64,
    /// |B|, the whole planet's bearing load in the transverse plane.
    pub bearing: f64,
    /// F_a of each mesh (N; 0 for a spur stage).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub axial: f64,
    /// The planet's tilting moment F_a (r_w,p + r_w,p') (N·m; 0 for a spur stage).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub tilting: f64,
    /// B's tangential and radial parts (N), for the bearings' split.
    #[serde(skip)]
    pub bearing_parts: [f64; 2],
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

impl PlanetForces {
    /// The load of each of a planet's `count` bearings (N): |B|/count each, or, where two bearings
    /// `spacing` apart carry a tilting moment, |(B_t/2, B_r/2 ± M/L)|.
    pub fn bearing_loads(&self, count: usize, spacing: Option<f64>) -> Vec<f64> {
        match (count, spacing) {
            (2, Some(l)) if self.tilting != 0.0 => {
                let [t, r] = self.bearing_parts;
                let m = self.tilting / l;
                vec![(0.5 * t).hypot(0.5 * r + m), (0.5 * t).hypot(0.5 * r - m)]
            }
            _ => vec![self.bearing / count as f64; count],
        }
    }
}

/// The lossless external torques [T_sun, T_ring, T_carrier] when place `driving` puts `torque`
/// (N·m, > 0) in at `speeds` ([ω_sun, ω_ring, ω_carrier]).
pub(crate) fn lossless_torques(layout: &PlanetaryLayout, driving: usize, torque: f64, speeds: [f64; 3]) -> [f64; 3] {
    let member = layout.members[driving];
    let i0 = stationary_ratio(layout.teeth[0], layout.teeth[2]);
    member_torques(i0, 1.0, (member, torque * speeds[member.index()].signum()), speeds).torques
}

/// The forces of a planet that carries 1/`divisor` of the sun's torque (1/n with equal sharing),
/// at the torques `torques` and speeds `speeds`.
pub(crate) fn planet_forces(
    layout: &PlanetaryLayout,
    torques: [f64; 3],
    speeds: [f64; 3],
    divisor: f64,
) -> PlanetForces {
    let r = layout.working_pitch_radius;
    let f_sun = torques[0].abs() / (divisor * r[0]);
    let f_ring = torques[1].abs() / (divisor * r[3]);
    let radial = [f_sun * layout.working_pressure_angle[0].tan(), f_ring * layout.working_pressure_angle[1].tan()];
    let centrifugal = layout.planet_mass * speeds[2] * speeds[2] * layout.center_distance;
    // In the planet's own frame (r̂ outwards from the central axis): the tangential forces of both
    // meshes add, the sun's radial push outwards and the ring's inwards meet the centrifugal force.
    let b_t = f_sun + f_ring;
    let b_r = centrifugal + radial[0] - radial[1];
    let axial =
        layout.helix.map_or(0.0, |h| torques[0].abs() * h.helix_angle.tan() / (divisor * h.sun_reference_radius));
    PlanetForces {
        tangential: [f_sun, f_ring],
        radial,
        centrifugal,
        bearing: b_t.hypot(b_r),
        axial,
        tilting: axial * (r[1] + r[2]),
        bearing_parts: [b_t, b_r],
    }
}

/// The forces on the stage's members that sit on shafts, one per planet and member, when place
/// `driving` puts `torque` in at the places' speeds `places`.
pub(crate) fn member_loads(
    (k, stage): (usize, &Stage),
    layout: &PlanetaryLayout,
    driving: usize,
    torque: f64,
    places: [f64; 2],
) -> Vec<GearLoad> {
    let speeds = layout.member_speeds(places);
    let t = lossless_torques(layout, driving, torque, speeds);
    let n = layout.planets;
    // Every planet's mesh forces (equal sharing), signed here by the torques they carry.
    let f = planet_forces(layout, t, speeds, f64::from(n));
    let r = layout.working_pitch_radius;
    let mut out = Vec::new();
    for j in 0..n {
        let theta = stage.direction + std::f64::consts::TAU * f64::from(j) / f64::from(n);
        let (radial_dir, tangent) = ([theta.cos(), theta.sin()], [-theta.sin(), theta.cos()]);
        let along =
            |f_t: f64, f_r: f64| [f_t * tangent[0] + f_r * radial_dir[0], f_t * tangent[1] + f_r * radial_dir[1]];
        let on_sun = along(-t[0].signum() * f.tangential[0], -f.radial[0]);
        let on_ring = along(-t[1].signum() * f.tangential[1], f.radial[1]);
        let on_carrier = [-(on_sun[0] + on_ring[0]), -(on_sun[1] + on_ring[1])];
        let axial_on_sun = layout.helix.map_or(0.0, |h| h.sun_hand * t[0].signum() * f.axial);
        let mut loads = vec![
            (PlanetaryMember::Sun, r[0], [on_sun[0], on_sun[1], axial_on_sun]),
            (PlanetaryMember::Ring, r[3], [on_ring[0], on_ring[1], -axial_on_sun]),
            (PlanetaryMember::Carrier, layout.center_distance, [on_carrier[0], on_carrier[1], 0.0]),
        ];
        if axial_on_sun != 0.0 {
            // The planet's axial forces reach the carrier where they act: its tilting moment.
            loads.push((PlanetaryMember::Carrier, r[0], [0.0, 0.0, -axial_on_sun]));
            loads.push((PlanetaryMember::Carrier, r[3], [0.0, 0.0, axial_on_sun]));
        }
        for (member, radius, force) in loads {
            let Some(place) = layout.place_of(member) else { continue };
            let at = stage.places[place];
            out.push(GearLoad {
                stage: k,
                member: if place == 0 { Member::Pinion } else { Member::Wheel },
                shaft: at.shaft,
                point: [radius * radial_dir[0], radius * radial_dir[1], at.at],
                force,
            });
        }
    }
    out
}
