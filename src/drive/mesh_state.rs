//! One mesh of a stage at an operating point as the drive's walk evaluated it: which mesh of the
//! stage, which gear drives it, and the driving gear's torque and speed. A stage's meshes are
//! what the analyses of one pair take up (each as the pair alone at that state) and what a friction
//! law's validity is read on.

use super::layout::Member;

/// One mesh of a stage at a point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshState {
    /// The mesh's index in its stage (0: the stage's own pair; a kind of several meshes numbers its
    /// others on, as [`crate::drive::MeshEfficiency`] does) and its name (None for a stage of one
    /// mesh).
    pub mesh: usize,
    pub name: Option<&'static str>,
    /// The place whose gear drives the mesh: that gear is in the pinion's place of the pair the
    /// walk evaluated (for the mesh's pair, the wheel driving means the pair with its roles swapped).
    pub driving: Member,
    /// The names of the gears in the pinion's and the wheel's places of that pair.
    pub members: [&'static str; 2],
    /// The driving gear's torque into the mesh (N·m, ≥ 0; a planetary mesh's per planet), its
    /// speed (rad/s, ≥ 0, in the frame the mesh turns in) and the mesh's efficiency.
    pub torque: f64,
    pub speed: f64,
    pub efficiency: f64,
}
