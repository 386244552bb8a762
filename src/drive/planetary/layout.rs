//! What the drive's physics reads of a planetary stage (SI): the teeth, the planets, which members
//! sit on the stage's places, the carrier's centre distance, the working pitch radii and pressure
//! angles of both meshes, the planets' mass and bearings.

use crate::drive::kinematics::planetary::{held, Planetary, PlanetaryMember};
use crate::losses::gear_no_load::GearsRunning;
use crate::losses::Bearing;

/// A planetary stage's layout.
#[derive(Debug, Clone, PartialEq)]
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
