//! Involute gear geometry and the contact state along the line of action (plain SI `f64`).
//!
//! Knows nothing of scenes, friction or reports: it takes a [`pair::PairInput`] and gives numbers.

pub mod contact;
pub mod contact_lines;
pub mod elastic;
pub mod involute;
pub mod mesh;
pub mod pair;
pub mod pair_checks;
pub mod pair_input;
pub mod path;
pub mod regions;
pub mod sharing;
pub mod stiffness;
pub mod teeth;

pub use contact::{ContactPoint, OperatingState};
pub use involute::involute;
pub use mesh::{Contacts, Mesh};
pub use pair::{GeometryProblem, PairGeometry, PairInput, PairPart, TipSource};
