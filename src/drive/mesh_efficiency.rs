//! The mesh efficiency a drive's walk reads from outside: the evaluation builds it from each stage's
//! own pairs (a friction law on a checked mesh, never the scene).

use super::layout::Member;
use super::planetary::PlanetMesh;

/// The mesh efficiency of a stage, from outside (a friction law on the stage's own pair).
pub trait MeshEfficiency {
    /// η of stage `stage` when member `driving` puts `torque` (N·m, > 0) into the mesh at `speed`
    /// (rad/s, > 0).
    fn efficiency(&self, stage: usize, driving: Member, torque: f64, speed: f64) -> f64;
    /// η of one mesh of planetary stage `stage` when its pinion carries `torque` (N·m per planet,
    /// > 0) at `speed` (rad/s in the carrier's frame, > 0).
    fn planet_mesh(&self, stage: usize, mesh: PlanetMesh, torque: f64, speed: f64) -> f64;
}
