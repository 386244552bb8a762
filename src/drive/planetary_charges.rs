//! What the drive's walk charges for a planetary stage: its efficiency between its two places, its
//! planets' bearings (on the carrier's shaft, or the driving member's where the carrier is held)
//! and the point the report reads.
//!
//! The planet bearings' losses are Palmgren's (or SKF's) moments at the planet's speed relative to
//! the carrier under the bearing load |B|/count of [`super::planetary::loads`], times that speed, the count
//! and n; they join the fixed point of the walk with the shafts' bearings.

use super::kinematics::planetary::PlanetaryLayout;
use super::layout::{Member, Stage};
use super::mesh_efficiency::MeshEfficiency;
use super::planetary::flow::{planetary_state, PlanetaryState};
use super::planetary::loads::{lossless_torques, planet_forces};
use super::planetary::point::PlanetaryPoint;
use super::point::BearingPoint;
use crate::losses::Oil;

/// The stage at place `driving` putting `torque` (N·m, > 0) in, the places at `places` (rad/s).
pub(crate) fn state(
    meshes: &dyn MeshEfficiency,
    k: usize,
    layout: &PlanetaryLayout,
    driving: Member,
    torque: f64,
    places: [f64; 2],
) -> PlanetaryState {
    planetary_state(layout, driving.index(), torque, places, &|mesh, t, w| meshes.planet_mesh(k, mesh, t, w))
}

/// The planets' bearings at the driving torque: the shaft they are charged on, the place as the
/// report lists it, and their power (W); None without planet bearings or without an oil viscosity.
pub(crate) fn planet_bearings(
    stage: &Stage,
    driving: Member,
    torque: f64,
    places: [f64; 2],
    oil: &Oil,
) -> Option<(usize, BearingPoint)> {
    let layout = stage.planetary.as_ref()?;
    let bearing = layout.planet_bearing?;
    let speeds = layout.member_speeds(places);
    let torques = lossless_torques(layout, driving.index(), torque, speeds);
    let omega = layout.planet_speed(speeds);
    let n = bearing.count as f64;
    // Each class of planets by its load; the place lists the most loaded planet's bearing.
    let (mut no_load, mut load, mut radial) = (0.0, 0.0, 0.0f64);
    for (count, divisor) in layout.planet_shares() {
        let per_bearing = planet_forces(layout, torques, speeds, divisor).bearing / n;
        radial = radial.max(per_bearing);
        let (m0, m1) = match oil.nu {
            Some(nu) => bearing.moments(per_bearing, 0.0, nu, omega, oil.mineral),
            None => (0.0, None),
        };
        let per_planet = n * omega;
        no_load += m0 * per_planet * count;
        load += m1.unwrap_or(0.0) * per_planet * count;
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
            on_planets: true,
        },
    ))
}

/// The report's point of the stage from its state `s` in the settled pass (driving torque `torque`).
pub(crate) fn point(
    s: &PlanetaryState,
    stage: &Stage,
    driving: Member,
    torque: f64,
    (planet_bearings, churning): ([f64; 2], f64),
) -> PlanetaryPoint {
    let layout = stage.planetary.as_ref().expect("a planetary stage has its layout");
    let torques = lossless_torques(layout, driving.index(), torque, s.speeds);
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
        forces: planet_forces(layout, torques, s.speeds, most_loaded(layout)),
        planet_bearings,
        churning,
    }
}

/// 1/d of the sun's torque the most loaded planet carries: d = n/K_γ.
fn most_loaded(layout: &PlanetaryLayout) -> f64 {
    layout.planet_shares()[0].1
}
