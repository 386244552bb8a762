//! The `.gear` language: grammar, syntax tree, units, diagnostics and lowering.

pub mod ast;
pub mod check;
pub mod fields;
pub mod grammar;
pub mod limits;
pub mod lower;
pub mod lower_dynamics;
pub mod lower_dynamics_blocks;
pub mod lower_friction;
pub mod lower_gearbox;
pub mod lower_gears;
pub mod lower_lubricant;
pub mod lower_operating;
pub mod lower_teeth;
pub mod lower_thermal;
pub mod lower_tooth_system;
pub mod parse;
pub mod screen;
pub mod source;
pub mod summary;
pub mod sweeps;
pub mod syntax_errors;
pub mod units;
pub mod values;
