//! A seeded walk's losses without its point: what a one-pair drive's P_V(θ) reads (a thermal
//! balance, a rating, a duty cycle evaluate it hundreds of times), the first pass of
//! [`super::walk::solve_from`] from its seed and no more.

use super::mesh_efficiency::MeshEfficiency;
use super::walk::{shaft_speeds, DriveModel, EndValue, Seed, Walk};

/// The losses of a walk's first pass from a seed (W): each stage's driving torque (N·m) and mesh
/// loss, and every shaft's own losses added up — its bearings at the seed's loads, its gears'
/// no-load parts, its seals. A one-pair drive at a given pinion torque seeded by
/// [`super::walk::shaft_losses_at`] at that torque settles in this pass
/// ([`super::walk::solve_from`]); its point's losses are these but for rounding.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SeededLosses {
    pub(crate) driving_torque: Vec<f64>,
    pub(crate) mesh_loss: Vec<f64>,
    pub(crate) beside_meshes: f64,
    /// Whether every power of the pass is a finite number.
    pub(crate) finite: bool,
}

/// The first pass of the walk with `torque` and `speed` at the ends they name, started from `seed`.
pub(crate) fn seeded_losses(
    model: &DriveModel,
    meshes: &dyn MeshEfficiency,
    (torque, speed): (EndValue, EndValue),
    seed: &Seed,
) -> SeededLosses {
    let omega = shaft_speeds(model.drive, speed);
    let (walk, from_source, given_power) = Walk::given(model, &omega, torque);
    let pass = walk.pass(meshes, from_source, given_power, &seed.fixed, &seed.bearings, None);
    let finite = pass.is_finite();
    SeededLosses {
        driving_torque: pass.driving_torque,
        mesh_loss: pass.mesh_loss,
        beside_meshes: (0..omega.len()).map(|j| seed.own(j)).sum(),
        finite,
    }
}
