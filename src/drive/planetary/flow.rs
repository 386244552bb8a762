//! A planetary stage at one operating point: the members' speeds and torques, the two meshes'
//! efficiencies at the rolling speeds (the carrier's frame) and loads, η₀ and the stage's η.
//!
//! Each mesh is evaluated as a pair at the load one planet carries (the n planets share equally;
//! with a load-sharing factor K_γ > 1 the most loaded planet's meshes at K_γ/n of the sun's torque
//! and the others' at the rest, η₀ then the load-weighted Σ w η_sp η_pr):
//! the sun–planet mesh with the sun's torque T_sun/n at |ω_sun − ω_carrier| (the planet in the
//! pinion's place, the pair's roles swapped, where the ring drives the meshes), the planet–ring mesh
//! (internal) with the planet's torque T_sun z_planet/(n z_sun) at the planet's speed relative to
//! the carrier, the planet in the pinion's place whichever drives. η₀ = η_sp η_pr, and the torques
//! follow from [`member_torques`]; where the given torque is the ring's or the carrier's, T_sun
//! depends on η₀ and η₀ on T_sun: the two are iterated until the meshes' loads move by less than
//! 1e-15 relative (where the sun's torque is given, one evaluation of each mesh).
//!
//! The meshes' losses add up to the stage's: with the sun driving the meshes the sun–planet mesh
//! loses (1 − η_sp) P_d and the planet–ring mesh (1 − η_pr) η_sp P_d, P_d the driving side's rolling
//! power (the reverse order where the ring drives), together (1 − η₀) P_d = Σ T ω.

use crate::drive::kinematics::planetary::{member_torques, stationary_ratio, MemberTorques, PlanetaryLayout};

/// A planetary stage's two meshes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum PlanetMesh {
    /// The sun and a planet (external); `sun_drives` says which is in the pinion's place.
    SunPlanet { sun_drives: bool },
    /// A planet and the ring (internal), the planet in the pinion's place.
    PlanetRing,
}

/// The stage at one operating point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PlanetaryState {
    /// [ω_sun, ω_ring, ω_carrier] (rad/s, signed about +z).
    pub speeds: [f64; 3],
    pub torques: MemberTorques,
    /// [η_sun–planet, η_planet–ring] and η₀ = their product.
    pub mesh_efficiency: [f64; 2],
    pub basic_efficiency: f64,
    /// [sun–planet, planet–ring] losses of all planets (W).
    pub mesh_loss: [f64; 2],
    /// The pinion's torque per planet (N·m) and speed in the carrier's frame (rad/s) of each mesh.
    pub mesh_torque: [f64; 2],
    pub mesh_speed: [f64; 2],
    /// η = P_out/P_in of the stage.
    pub efficiency: f64,
}

/// The stage when the member on place `driving` puts `torque` (N·m, > 0) into it, the places
/// turning at `places` (rad/s, signed); `mesh` gives a mesh's efficiency at the pinion's torque
/// and speed.
pub(crate) fn planetary_state(
    layout: &PlanetaryLayout,
    driving: usize,
    torque: f64,
    places: [f64; 2],
    mesh: &dyn Fn(PlanetMesh, f64, f64) -> f64,
) -> PlanetaryState {
    let speeds = layout.member_speeds(places);
    let i0 = stationary_ratio(layout.teeth[0], layout.teeth[2]);
    let member = layout.members[driving];
    let given = (member, torque * speeds[member.index()].signum());
    let n = f64::from(layout.planets);
    let (z_sun, z_planet) = (f64::from(layout.teeth[0]), f64::from(layout.teeth[1]));
    let relative = (speeds[0] - speeds[2]).abs();
    // The planet's speed relative to the carrier.
    let planet = layout.planet_speed(speeds);
    let mut eta = [1.0, 1.0];
    let (mut mesh_torque, mut mesh_speed) = ([0.0; 2], [relative, planet]);
    // The loads η was last evaluated at: the fixed point stops when the next loads are the same.
    let mut evaluated: Option<([f64; 2], bool)> = None;
    for _ in 0..50 {
        let torques = member_torques(i0, eta[0] * eta[1], given, speeds);
        let per_planet = torques.torques[0].abs() / n;
        let sun_drives = torques.sun_drives_meshes;
        let loads =
            [if sun_drives { per_planet } else { per_planet * z_planet / z_sun }, per_planet * z_planet / z_sun];
        let settled = evaluated.is_some_and(|(last, drives): ([f64; 2], bool)| {
            drives == sun_drives && (0..2).all(|i| (loads[i] - last[i]).abs() <= 1e-15 * loads[i])
        });
        if settled {
            break;
        }
        mesh_torque = loads;
        mesh_speed[0] = if sun_drives { relative } else { planet };
        eta = if per_planet == 0.0 || relative == 0.0 {
            [1.0, 1.0]
        } else {
            let at = |divisor: f64| {
                let t = torques.torques[0].abs() / divisor;
                let sp = if sun_drives { t } else { t * z_planet / z_sun };
                [
                    mesh(PlanetMesh::SunPlanet { sun_drives }, sp, mesh_speed[0]),
                    mesh(PlanetMesh::PlanetRing, t * z_planet / z_sun, mesh_speed[1]),
                ]
            };
            match layout.carrying_shares().as_slice() {
                [(_, divisor)] => at(*divisor),
                classes => unequal(classes.iter().map(|(count, d)| (count / d, at(*d))), sun_drives),
            }
        };
        evaluated = Some((loads, sun_drives));
    }
    let torques = member_torques(i0, eta[0] * eta[1], given, speeds);
    let eta0 = eta[0] * eta[1];
    let p_w = torques.rolling_power.abs();
    let mesh_loss = if torques.sun_drives_meshes {
        [(1.0 - eta[0]) * p_w, (1.0 - eta[1]) * eta[0] * p_w]
    } else {
        // The ring's rolling power P_w/η₀ drives the meshes.
        let p_d = p_w / eta0;
        [(1.0 - eta[0]) * eta[1] * p_d, (1.0 - eta[1]) * p_d]
    };
    let p_in = (given.1 * speeds[member.index()]).abs();
    let efficiency = if p_in > 0.0 { 1.0 - (mesh_loss[0] + mesh_loss[1]) / p_in } else { 1.0 };
    PlanetaryState {
        speeds,
        torques,
        mesh_efficiency: eta,
        basic_efficiency: eta0,
        mesh_loss,
        mesh_torque,
        mesh_speed,
        efficiency,
    }
}

/// [η_sp, η_pr] of planets sharing the load unequally, from each class's (share of the rolling
/// power, [η_sp, η_pr]): η₀ = Σ w η_sp η_pr (the meshes' losses add up over the planets), the mesh the
/// power enters first at its weighted mean Σ w η and the other at η₀ over it.
fn unequal(classes: impl Iterator<Item = (f64, [f64; 2])>, sun_drives: bool) -> [f64; 2] {
    let (mut first, mut both) = (0.0, 0.0);
    for (w, [sp, pr]) in classes {
        first += w * if sun_drives { sp } else { pr };
        both += w * sp * pr;
    }
    if sun_drives {
        [first, both / first]
    } else {
        [both / first, first]
    }
}
