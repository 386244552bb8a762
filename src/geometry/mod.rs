//! Involute gear geometry and the contact state along the line of action (plain SI `f64`).
//!
//! Knows nothing of scenes, friction or reports: it takes a [`pair::PairInput`] and gives numbers.

pub mod contact;
pub(crate) mod contact_lines;
pub(crate) mod elastic;
pub(crate) mod involute;
pub mod loss_factor;
pub mod mesh;
pub(crate) mod pair;
pub(crate) mod pair_checks;
pub(crate) mod pair_input;
pub(crate) mod path;
pub mod regions;
pub(crate) mod sharing;
pub mod stiffness;
pub mod teeth;
pub(crate) mod undercut;

pub use contact::{ContactPoint, OperatingState};
pub use involute::involute;
pub use mesh::{Contacts, Mesh};
pub use pair::{GeometryProblem, PairGeometry, PairInput, PairPart, TipSource};
pub use pair_checks::trochoid_margin;
pub use undercut::undercut_radius;
