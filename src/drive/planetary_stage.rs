//! A planetary stage as the drive's walk reads it (its `StageModel`): Willis's kinematics, the
//! churning body, η from its two meshes' efficiencies ([`super::planetary::flow`]), the forces on
//! its members that sit on shafts and on its planets' bearings ([`super::planetary::loads`]), and
//! its part of the report's point ([`super::planetary::point`]).
//!
//! The planet bearings' losses are Palmgren's (or SKF's) moments at the planet's speed relative to
//! the carrier under each bearing's load of [`super::planetary::loads`] (|B|/count, or with a helical
//! stage's tilting moment |(B_t/2, B_r/2 ± M/L)|), times that speed, summed over the bearings and
//! the planets; they join the fixed point of the walk with the shafts' bearings.

use super::forces::{GearLoad, MeshForceSizes};
use super::kind_state::{KindInputs, KindPoint, KindState};
use super::kinematics::planetary::{PlanetaryLayout, PlanetaryMember};
use super::kinematics::StageKinematics;
use super::layout::{Member, Stage};
use super::mesh_efficiency::MeshEfficiency;
use super::planetary::flow::PlanetMesh;
use super::planetary::flow::PlanetaryState;
use super::planetary::loads::{lossless_torques, planet_forces};
use super::planetary::point::{PlanetaryPoint, MESH_GEARS};
use super::point::{BearingPoint, StagePoint};
use super::stage_model::StageModel;
use crate::geometry::PairGeometry;
use crate::losses::gear_no_load::GearsRunning;
use crate::losses::Oil;

impl StagePoint {
    /// A planetary stage's part of the point; None for a stage of another kind.
    pub fn planetary(&self) -> Option<&PlanetaryPoint> {
        match self.kind.as_deref() {
            Some(KindPoint::Planetary(p)) => Some(p),
            _ => None,
        }
    }
}

impl StageModel for PlanetaryLayout {
    fn inputs(&self, layout: &super::layout::Drive, stage: &Stage, further: &[&PairGeometry]) -> Option<KindInputs> {
        super::planetary::inputs::planetary_inputs(layout, stage, self, further.first().copied())
            .map(KindInputs::Planetary)
    }

    fn kinematics(&self, _: &Stage) -> Box<dyn StageKinematics> {
        Box::new(PlanetaryLayout::kinematics(self))
    }

    /// Sun, ring or carrier.
    fn member_name(&self, m: Member) -> &'static str {
        self.members[m.index()].name()
    }

    /// The carrier with its planets where it turns, else the sun ([`PlanetaryLayout::churning`]).
    fn gears_running(&self, _: &Stage, _: &MeshForceSizes, places: [f64; 2]) -> (usize, GearsRunning) {
        self.churning(self.member_speeds(places))
    }

    /// The stage's η from its meshes' (the sun–planet mesh is the stage's own pair, mesh 0, the sun
    /// its pinion; the planet–ring mesh is mesh 1, the planet its pinion), kept for the point (at
    /// no torque or speed no mesh is evaluated and η = 1).
    fn efficiency(
        &self,
        (k, _): (usize, &Stage),
        meshes: &dyn MeshEfficiency,
        (driving, torque, _): (Member, f64, f64),
        places: [f64; 2],
    ) -> (f64, Option<KindState>) {
        let mesh = |mesh: PlanetMesh, t: f64, w: f64| match mesh {
            PlanetMesh::SunPlanet { sun_drives } => {
                meshes.efficiency(k, 0, if sun_drives { Member::Pinion } else { Member::Wheel }, t, w)
            }
            PlanetMesh::PlanetRing => meshes.efficiency(k, 1, Member::Pinion, t, w),
        };
        let state = super::planetary::flow::planetary_state(self, driving.index(), torque.abs(), places, &mesh);
        (state.efficiency, Some(KindState::Planetary(state)))
    }

    fn member_loads(
        &self,
        (k, stage): (usize, &Stage),
        _: &MeshForceSizes,
        (driving, torque): (Member, f64),
        places: [f64; 2],
    ) -> Vec<GearLoad> {
        super::planetary::loads::member_loads((k, stage), self, driving.index(), torque.abs(), places)
    }

    fn member_bearings(
        &self,
        stage: &Stage,
        (driving, torque): (Member, f64),
        places: [f64; 2],
        oil: &Oil,
    ) -> Option<(usize, BearingPoint)> {
        planet_bearings((stage, self), driving, torque.abs(), places, oil)
    }

    /// The sun–planet mesh's forces and the stage's [`PlanetaryPoint`].
    fn point(
        &self,
        _: &Stage,
        _: &MeshForceSizes,
        (driving, torque): (Member, f64),
        state: Option<&KindState>,
        parts: ([f64; 2], f64),
    ) -> ([f64; 3], Option<Box<KindPoint>>) {
        let Some(KindState::Planetary(state)) = state else {
            unreachable!("the walk keeps a planetary stage's state at every pass")
        };
        let point = point(state, self, driving, torque.abs(), parts);
        let forces = [point.forces.tangential[0], point.forces.radial[0], point.forces.axial];
        (forces, Some(Box::new(KindPoint::Planetary(point))))
    }

    /// The sun–planet and planet–ring meshes as the point holds them (per planet, each at its
    /// driving gear's torque and speed in the carrier's frame).
    fn mesh_states(&self, _: &Stage, point: &StagePoint) -> Vec<super::mesh_state::MeshState> {
        match point.kind.as_deref() {
            Some(KindPoint::Planetary(p)) => p.mesh_states().to_vec(),
            None => Vec::new(),
        }
    }

    /// A sun among two planets or more: a floating sun.
    fn centred_member(&self, m: Member) -> bool {
        self.planets >= 2 && self.members[m.index()] == PlanetaryMember::Sun
    }

    fn one_pair_on_two_shafts(&self) -> bool {
        false
    }

    /// The sun–planet mesh (the sun the pinion) and the planet–ring mesh (the planet the pinion).
    fn mesh_gears(&self) -> &'static [[&'static str; 2]] {
        &MESH_GEARS
    }

    /// Its members, its meshes, its planets.
    fn record_columns(&self) -> &'static [&'static str] {
        &[
            "sun_speed_rpm",
            "sun_torque_N_m",
            "ring_speed_rpm",
            "ring_torque_N_m",
            "carrier_speed_rpm",
            "carrier_torque_N_m",
            "rolling_power_W",
            "basic_efficiency",
            "sun_planet_efficiency",
            "planet_ring_efficiency",
            "sun_planet_loss_W",
            "planet_ring_loss_W",
            "planet_bearing_load_N",
            "planet_bearings_W",
            "churning_W",
        ]
    }

    /// A sun on a shaft of one bearing place: a floating sun.
    fn shaft_notes(&self, stage: &Stage, bearing_places: &dyn Fn(usize) -> usize) -> Vec<(usize, String, String)> {
        let sun = self.place_of(PlanetaryMember::Sun).map(|m| stage.places[m].shaft);
        sun.filter(|j| bearing_places(*j) == 1)
            .map(|j| {
                (
                    j,
                    "a floating sun on one bearing place".to_string(),
                    "its planets centre the sun, their forces cancel on it, so the place takes only what they leave (a helical sun's axial force)".to_string(),
                )
            })
            .into_iter()
            .collect()
    }
}

impl PlanetaryPoint {
    /// The values of [`StageModel::record_columns`] (speeds in rpm).
    pub(crate) fn record_values(&self) -> Vec<f64> {
        const RPM: f64 = 30.0 / std::f64::consts::PI;
        let mut v = Vec::with_capacity(15);
        for i in 0..3 {
            v.extend([self.speeds[i] * RPM, self.torques[i]]);
        }
        v.extend([self.rolling_power, self.basic_efficiency, self.mesh_efficiency[0], self.mesh_efficiency[1]]);
        v.extend([
            self.mesh_loss[0],
            self.mesh_loss[1],
            self.forces.bearing,
            self.planet_bearings[0] + self.planet_bearings[1],
        ]);
        v.push(self.churning);
        v
    }
}

/// The planets' bearings at the driving torque: the shaft they are charged on, the place as the
/// report lists it, and their power (W); None without planet bearings or without an oil viscosity.
pub(crate) fn planet_bearings(
    (stage, layout): (&Stage, &PlanetaryLayout),
    driving: Member,
    torque: f64,
    places: [f64; 2],
    oil: &Oil,
) -> Option<(usize, BearingPoint)> {
    let bearing = layout.planet_bearing?;
    let speeds = layout.member_speeds(places);
    let torques = lossless_torques(layout, driving.index(), torque, speeds);
    let omega = layout.planet_speed(speeds);
    // Each class of planets by its load; the place lists the most loaded planet's bearing.
    let (mut no_load, mut load, mut radial) = (0.0, 0.0, 0.0f64);
    for (count, divisor) in layout.planet_shares() {
        let forces = planet_forces(layout, torques, speeds, divisor);
        for per_bearing in forces.bearing_loads(bearing.count, layout.planet_bearing_spacing) {
            radial = radial.max(per_bearing);
            let (m0, m1) = match oil.nu {
                Some(nu) => bearing.moments(per_bearing, 0.0, nu, omega, oil.mineral),
                None => (0.0, None),
            };
            no_load += m0 * omega * count;
            load += m1.unwrap_or(0.0) * omega * count;
        }
    }
    let place =
        layout.place_of(crate::drive::kinematics::planetary::PlanetaryMember::Carrier).unwrap_or(driving.index());
    Some((
        stage.places[place].shaft,
        BearingPoint {
            kind: format!("{} (planets)", bearing.kind.name()),
            count: bearing.count * layout.planets as usize,
            position: Some(stage.places[place].at),
            locating: false,
            // The planets' bearings sit on pins, not on the shaft's two places: no shaft reaction.
            reaction: [0.0; 3],
            radial_load: radial,
            axial_load: 0.0,
            no_load,
            load,
            of_stage_members: true,
        },
    ))
}

/// The report's point of the stage from its state `s` in the settled pass (driving torque `torque`).
pub(crate) fn point(
    s: &PlanetaryState,
    layout: &PlanetaryLayout,
    driving: Member,
    torque: f64,
    (planet_bearings, churning): ([f64; 2], f64),
) -> PlanetaryPoint {
    let torques = lossless_torques(layout, driving.index(), torque, s.speeds);
    let forces = planet_forces(layout, torques, s.speeds, most_loaded(layout));
    PlanetaryPoint {
        planets: layout.planets,
        held: layout.held(),
        driving_member: layout.members[driving.index()],
        driven_member: layout.members[1 - driving.index()],
        speeds: s.speeds,
        torques: s.torques.torques,
        rolling_power: s.torques.rolling_power,
        sun_drives_meshes: s.torques.sun_drives_meshes,
        mesh_efficiency: s.mesh_efficiency,
        mesh_loss: s.mesh_loss,
        mesh_torque: s.mesh_torque,
        mesh_speed: s.mesh_speed,
        basic_efficiency: s.basic_efficiency,
        efficiency: s.efficiency,
        planet_speed: layout.planet_speed(s.speeds),
        forces,
        planet_bearings,
        churning,
        tilting_support: tilting_support(layout, &forces),
    }
}

/// How the most loaded planet's bearings carry its tilting moment, in words; empty for a spur stage.
fn tilting_support(layout: &PlanetaryLayout, forces: &super::planetary::loads::PlanetForces) -> String {
    if forces.tilting == 0.0 {
        return String::new();
    }
    match (layout.planet_bearing, layout.planet_bearing_spacing) {
        (None, _) => "the scene gives the planets no bearings".into(),
        (Some(b), Some(l)) if b.count == 2 => {
            let loads = forces.bearing_loads(2, Some(l));
            format!(
                "its two bearings {:.3} mm apart carry |(B_t/2, B_r/2 ± M/L)| = {:.2} N and {:.2} N",
                l * 1e3,
                loads[0],
                loads[1]
            )
        }
        (Some(_), _) => "one bearing per planet: the moment is not on its load, which is |B| (a double-row bearing's share of it is not modelled)".into(),
    }
}

/// 1/d of the sun's torque the most loaded planet carries: d = n/K_γ.
fn most_loaded(layout: &PlanetaryLayout) -> f64 {
    layout.planet_shares()[0].1
}
