//! The mesh efficiency a drive's walk reads from outside: the evaluation builds it from each stage's
//! own pairs (a friction law on a checked mesh, never the scene).

use super::layout::Member;

/// The mesh efficiency of a stage's meshes, from outside (a friction law on each mesh's own pair).
pub trait MeshEfficiency {
    /// η of mesh `mesh` of stage `stage` when the gear in place `driving` puts `torque` (N·m, > 0)
    /// into it at `speed` (rad/s, > 0, in the frame the mesh turns in). Mesh 0 is the stage's own
    /// pair (its pinion and wheel in the places [`Member`] names); a kind of several meshes numbers
    /// its others on (a planetary stage's planet–ring mesh is 1, the planet in the pinion's place).
    fn efficiency(&self, stage: usize, mesh: usize, driving: Member, torque: f64, speed: f64) -> f64;
}
