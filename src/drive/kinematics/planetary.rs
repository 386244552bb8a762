//! A planetary stage: a sun, n planets on a carrier, a ring. Two of its members sit on the stage's
//! two places (shafts), the third is held by the housing.
//!
//! **Willis** (Müller, *Die Umlaufgetriebe*, 2nd ed., Springer 1998, eq 2.2; VDI 2157): with the
//! stationary ratio i₀ = −z_ring/z_sun (the carrier held, sun to ring),
//! n_sun − i₀ n_ring − (1 − i₀) n_carrier = 0.
//!
//! **Torques and losses** (Müller §3, whose one-member-fixed efficiencies are Krüger's): the external
//! torques on the members balance, T_sun + T_ring + T_carrier = 0. Only the rolling power
//! P_w = T_sun (ω_sun − ω_carrier) passes the meshes, in the carrier's frame; the meshes lose the
//! share 1 − η₀ of it, η₀ = η_sun–planet · η_planet–ring (the stationary efficiency). Where P_w > 0 the
//! sun drives the meshes (w = +1), else the ring does (w = −1), and T_ring = −i₀ η₀^w T_sun. The
//! stage's loss is then Σ T ω = (1 − η₀^w) P_w ≥ 0: (1 − η₀) times the rolling power of the side
//! that drives the meshes.
//!
//! The stage's layout as the drive's physics reads it ([`PlanetaryLayout`]: teeth, planets, the
//! members on the places, both meshes' working sizes, the planets' mass and bearings) lives here
//! with its kinematics.
//!
//! ```
//! use gearloss::drive::kinematics::planetary::{one_fixed_efficiency, PlanetaryMember::*};
//! // Krüger's check, i₀ = −3, η₀ = 0.98505: sun in, carrier out, ring held: η = (1 + 3 η₀)/4.
//! let eta = one_fixed_efficiency(-3.0, 0.98505, Sun, Carrier);
//! assert!((eta - (1.0 + 3.0 * 0.98505) / 4.0).abs() < 1e-15 && (eta - 0.98879).abs() < 5e-6);
//! // Ring in, carrier out, sun held: η = (3 + η₀)/4 = 0.99626.
//! assert!((one_fixed_efficiency(-3.0, 0.98505, Ring, Carrier) - 0.99626).abs() < 5e-6);
//! ```

use super::stage_kinematics::StageKinematics;
use crate::losses::gear_no_load::GearsRunning;
use crate::losses::Bearing;

/// A member of a planetary stage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PlanetaryMember {
    Sun,
    Ring,
    Carrier,
}

impl PlanetaryMember {
    /// Every member, in the order [sun, ring, carrier] of the speed and torque arrays.
    pub const ALL: [PlanetaryMember; 3] = [PlanetaryMember::Sun, PlanetaryMember::Ring, PlanetaryMember::Carrier];

    pub fn index(self) -> usize {
        self as usize
    }

    pub fn name(self) -> &'static str {
        match self {
            PlanetaryMember::Sun => "sun",
            PlanetaryMember::Ring => "ring",
            PlanetaryMember::Carrier => "carrier",
        }
    }
}

/// The kinematics of a planetary stage: the sun's and the ring's teeth, and the members on the
/// stage's two places (the third is held).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Planetary {
    pub sun_teeth: u32,
    pub ring_teeth: u32,
    /// [place 0, place 1].
    pub members: [PlanetaryMember; 2],
}

impl Planetary {
    /// i₀ = −z_ring/z_sun.
    pub fn stationary_ratio(&self) -> f64 {
        stationary_ratio(self.sun_teeth, self.ring_teeth)
    }

    /// The member the housing holds.
    pub fn held(&self) -> PlanetaryMember {
        held(self.members)
    }

    /// [ω_sun, ω_ring, ω_carrier] with the held member at rest and member `known` at `omega`.
    pub fn member_speeds(&self, known: PlanetaryMember, omega: f64) -> [f64; 3] {
        willis(self.stationary_ratio(), (known, omega), (self.held(), 0.0))
    }
}

/// i₀ = −z_ring/z_sun, the ratio sun to ring with the carrier held.
pub fn stationary_ratio(sun_teeth: u32, ring_teeth: u32) -> f64 {
    -f64::from(ring_teeth) / f64::from(sun_teeth)
}

/// The member that is neither of `members`.
pub fn held(members: [PlanetaryMember; 2]) -> PlanetaryMember {
    PlanetaryMember::ALL.into_iter().find(|m| !members.contains(m)).expect("two members leave a third")
}

/// Willis: [ω_sun, ω_ring, ω_carrier] from the speeds of two different members,
/// ω_s − i₀ ω_r − (1 − i₀) ω_c = 0.
pub fn willis(i0: f64, a: (PlanetaryMember, f64), b: (PlanetaryMember, f64)) -> [f64; 3] {
    use PlanetaryMember::*;
    let mut w = [f64::NAN; 3];
    w[a.0.index()] = a.1;
    w[b.0.index()] = b.1;
    match held([a.0, b.0]) {
        Sun => w[0] = i0 * w[1] + (1.0 - i0) * w[2],
        Ring => w[1] = (w[0] - (1.0 - i0) * w[2]) / i0,
        Carrier => w[2] = (w[0] - i0 * w[1]) / (1.0 - i0),
    }
    w
}

/// The members' external torques with the meshes' losses, from one member's torque.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MemberTorques {
    /// [T_sun, T_ring, T_carrier] (N·m, about +z, the torques the outside puts on the members).
    pub torques: [f64; 3],
    /// P_w = T_sun (ω_sun − ω_carrier) (W).
    pub rolling_power: f64,
    /// The sun drives the meshes (P_w ≥ 0): w = +1; else the ring does.
    pub sun_drives_meshes: bool,
}

impl MemberTorques {
    /// Σ T ω (W): the power the stage turns into heat.
    pub fn loss(&self, speeds: [f64; 3]) -> f64 {
        (0..3).map(|i| self.torques[i] * speeds[i]).sum()
    }

    /// η = Σ P_out / Σ P_in over the members (P = T ω; in: P > 0): the one-member-fixed η, and the
    /// two-DOF stage's (a differential summing or splitting power) where all three turn; 1 where
    /// no power flows.
    pub fn efficiency(&self, speeds: [f64; 3]) -> f64 {
        let p: Vec<f64> = (0..3).map(|i| self.torques[i] * speeds[i]).collect();
        let input: f64 = p.iter().filter(|x| **x > 0.0).sum();
        let output: f64 = -p.iter().filter(|x| **x < 0.0).sum::<f64>();
        if input > 0.0 {
            output / input
        } else {
            1.0
        }
    }
}

/// The torques on all three members when `given` = (member, external torque) at `speeds`
/// ([ω_sun, ω_ring, ω_carrier]) with stationary ratio i₀ and stationary efficiency η₀:
/// T_ring = −i₀ η₀^w T_sun, T_carrier = −T_sun − T_ring, w = sign(P_w).
pub fn member_torques(i0: f64, eta0: f64, given: (PlanetaryMember, f64), speeds: [f64; 3]) -> MemberTorques {
    let relative = speeds[0] - speeds[2];
    // The sign of T_sun follows from the given torque alone (−1/i₀ > 0 and 1 − i₀ η₀^w > 0).
    let sun_sign = match given.0 {
        PlanetaryMember::Sun | PlanetaryMember::Ring => given.1.signum(),
        PlanetaryMember::Carrier => -given.1.signum(),
    };
    let sun_drives_meshes = sun_sign * relative >= 0.0;
    let k = if sun_drives_meshes { eta0 } else { 1.0 / eta0 };
    let t_sun = match given.0 {
        PlanetaryMember::Sun => given.1,
        PlanetaryMember::Ring => -given.1 / (i0 * k),
        PlanetaryMember::Carrier => -given.1 / (1.0 - i0 * k),
    };
    let t_ring = -i0 * k * t_sun;
    MemberTorques { torques: [t_sun, t_ring, -t_sun - t_ring], rolling_power: t_sun * relative, sun_drives_meshes }
}

/// η = P_out/P_in of a stage with one member held, `input` driving and `output` driven
/// (Krüger's one-member-fixed efficiencies, from i₀ and η₀).
pub fn one_fixed_efficiency(i0: f64, eta0: f64, input: PlanetaryMember, output: PlanetaryMember) -> f64 {
    let speeds = willis(i0, (input, 1.0), (held([input, output]), 0.0));
    member_torques(i0, eta0, (input, 1.0), speeds).efficiency(speeds)
}

impl StageKinematics for Planetary {
    fn speeds(&self, known: usize, omega: f64) -> Vec<f64> {
        let w = self.member_speeds(self.members[known], omega);
        self.members.iter().map(|m| w[m.index()]).collect()
    }

    fn torque_ratio(&self, driving: usize) -> f64 {
        let w = self.member_speeds(self.members[driving], 1.0);
        (w[self.members[driving].index()] / w[self.members[1 - driving].index()]).abs()
    }
}

/// A planetary stage's layout.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct PlanetaryLayout {
    /// n, the planets on the carrier (equally spaced, sharing the load equally).
    pub planets: u32,
    /// [sun, planet, ring].
    pub teeth: [u32; 3],
    /// The members on the stage's places [0, 1]; the third is held by the housing.
    pub members: [PlanetaryMember; 2],
    /// The carrier's centre distance a_w, sun axis to planet axis (m).
    pub center_distance: f64,
    /// Working pitch radii (m): [sun, planet in the sun mesh, planet in the ring mesh, ring].
    pub working_pitch_radius: [f64; 4],
    /// α_w of [sun–planet, planet–ring] (rad).
    pub working_pressure_angle: [f64; 2],
    /// The planet's tip radius (m): the carrier sweeps out to a_w + r_a,planet.
    pub planet_tip_radius: f64,
    pub face_width: f64,
    /// One planet's mass (m), for its centrifugal force on its bearing.
    pub planet_mass: f64,
    /// One planet's bearings (their `count` on each planet), if given.
    pub planet_bearing: Option<Bearing>,
    /// K_γ ≥ 1: the most loaded planet carries K_γ/n of the sun's torque, the other n − 1 share the
    /// rest equally (1: equal sharing).
    pub load_sharing_factor: f64,
    /// A helical stage's helix; None for a spur stage.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub helix: Option<PlanetaryHelix>,
    /// The distance between a planet's two bearings (m): they carry its tilting moment in a helical
    /// stage.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub planet_bearing_spacing: Option<f64>,
}

/// A helical planetary stage's helix: the sun's hand (the planets' is the other, the ring's the
/// planets'), β at the reference circle and the sun's reference radius, from which each mesh's
/// axial force F_a = F_t tan β_w = |T_sun| tan β/(n r_sun) follows (equal in both meshes: the
/// planet's torque balance).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PlanetaryHelix {
    /// β (rad, > 0).
    pub helix_angle: f64,
    /// +1 for a right-hand sun, −1 for a left-hand one.
    pub sun_hand: f64,
    /// The sun's reference radius r = m_t z/2 (m).
    pub sun_reference_radius: f64,
}

impl PlanetaryLayout {
    /// The stage's kinematics (the catalogue's entry).
    pub fn kinematics(&self) -> Planetary {
        Planetary { sun_teeth: self.teeth[0], ring_teeth: self.teeth[2], members: self.members }
    }

    /// The held member.
    pub fn held(&self) -> PlanetaryMember {
        held(self.members)
    }

    /// The place (0 or 1) of `member`, if it sits on one.
    pub fn place_of(&self, member: PlanetaryMember) -> Option<usize> {
        self.members.iter().position(|m| *m == member)
    }

    /// [ω_sun, ω_ring, ω_carrier] from the speeds of the stage's two places (the held member at rest).
    pub fn member_speeds(&self, places: [f64; 2]) -> [f64; 3] {
        let mut w = [0.0; 3];
        for (m, omega) in self.members.iter().zip(places) {
            w[m.index()] = omega;
        }
        w
    }

    /// Each class of planets by its load: (how many planets, d), each carrying 1/d of the sun's
    /// torque. Equal sharing: one class of n with d = n; with K_γ > 1, one planet with d = n/K_γ and
    /// n − 1 with d = n (n − 1)/(n − K_γ). At K_γ = n the one planet carries everything and the
    /// others nothing: their class has d = ∞ (its meshes idle; the loss of a mesh at no load is
    /// not the load-weighted η's to count, see `carrying_shares`).
    pub fn planet_shares(&self) -> Vec<(f64, f64)> {
        let n = f64::from(self.planets);
        let k = self.load_sharing_factor;
        if k == 1.0 || self.planets == 1 {
            vec![(n, n)]
        } else if k >= n {
            vec![(1.0, 1.0), (n - 1.0, f64::INFINITY)]
        } else {
            vec![(1.0, n / k), (n - 1.0, n * (n - 1.0) / (n - k))]
        }
    }

    /// The classes of [`Self::planet_shares`] that carry load (1/d > 0): the meshes' efficiencies
    /// are weighted over these (a planet that carries nothing passes no rolling power).
    pub fn carrying_shares(&self) -> Vec<(f64, f64)> {
        self.planet_shares().into_iter().filter(|(count, d)| count / d > 0.0).collect()
    }

    /// The planet's speed relative to the carrier, |ω_sun − ω_carrier| z_sun/z_planet (rad/s).
    pub fn planet_speed(&self, speeds: [f64; 3]) -> f64 {
        (speeds[0] - speeds[2]).abs() * f64::from(self.teeth[0]) / f64::from(self.teeth[1])
    }

    /// The body whose churning the stage's lubrication charges, and the place it sits on: the
    /// carrier with its planets (a disc out to a_w + r_a,planet at |ω_carrier|) where the carrier
    /// turns, else the sun (at its working pitch radius and |ω_sun|).
    pub fn churning(&self, speeds: [f64; 3]) -> (usize, GearsRunning) {
        let (member, omega, radius) = match self.place_of(PlanetaryMember::Carrier) {
            Some(_) => (PlanetaryMember::Carrier, speeds[2].abs(), self.center_distance + self.planet_tip_radius),
            None => (PlanetaryMember::Sun, speeds[0].abs(), self.working_pitch_radius[0]),
        };
        let place = self.place_of(member).expect("the sun turns where the carrier is held");
        // One body: the second entry stands still (no second windage).
        (place, GearsRunning { omega: [omega, 0.0], pitch_radius: [radius; 2], face_width: self.face_width })
    }
}
