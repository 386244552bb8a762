//! The `.gear` language: grammar, syntax tree, units, diagnostics and lowering.

pub(crate) mod ast;
pub(crate) mod check;
pub(crate) mod fields;
pub(crate) mod grammar;
pub(crate) mod limits;
pub mod lower;
pub(crate) mod lower_dynamics;
pub(crate) mod lower_dynamics_blocks;
pub(crate) mod lower_friction;
pub(crate) mod lower_gearbox;
pub(crate) mod lower_gears;
pub(crate) mod lower_lubricant;
pub(crate) mod lower_operating;
pub(crate) mod lower_teeth;
pub(crate) mod lower_thermal;
pub(crate) mod lower_tooth_system;
pub mod parse;
pub(crate) mod screen;
pub mod source;
pub mod summary;
pub(crate) mod sweeps;
pub(crate) mod syntax_errors;
pub mod units;
pub(crate) mod values;
