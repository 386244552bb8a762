//! Involute gear geometry and the contact state along the line of action (plain SI `f64`).
//!
//! Knows nothing of scenes, friction or reports: it takes a [`pair::PairInput`] and gives numbers.

pub(crate) mod contact;
pub(crate) mod contact_lines;
pub(crate) mod elastic;
pub(crate) mod involute;
pub(crate) mod loss_factor;
pub(crate) mod mesh;
pub(crate) mod pair;
pub(crate) mod pair_checks;
pub(crate) mod pair_input;
pub(crate) mod path;
pub(crate) mod regions;
pub(crate) mod sharing;
pub mod stiffness;
pub mod teeth;
pub(crate) mod undercut;

pub use contact::{reduced_modulus, Sharing};
pub use contact::{ContactPoint, OperatingState};
pub use involute::involute;
pub use loss_factor::{closed_form_holds, ohlendorf_closed_form, shared_sliding_integral};
pub use mesh::LINE_NODES;
pub use mesh::{Contacts, Mesh};
pub use pair::{GeometryProblem, PairGeometry, PairInput, PairPart, TipSource};
pub use pair_checks::trochoid_margin;
pub use regions::{LineEnd, PitchSide};
pub use undercut::undercut_radius;
