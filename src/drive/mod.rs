//! A drive: shafts carrying gears, bearings and seals, joined by stages, power entering at the input
//! shaft and leaving at the output (README, "Several stages").
//!
//! ```text
//!  Drive (layout) ─kinematics─▶ shaft speeds ─walk─▶ torques along the power flow ◀─┐
//!   shafts, stages,  (catalogue:   by ratio       (source → sink, or back      │ fixed point:
//!   input, output     one file a                   from a given sink)           │ bearing losses
//!                     stage kind)                       │                      │ from the loads
//!                                                       ▼                      │
//!                                        mesh forces (forces) ─statics─▶ bearing loads ─┘
//! ```
//!
//! A stage kind is one `StageModel` (`stage_model.rs`) (`parallel_stage.rs`, `planetary_stage.rs`; one
//! row of `Stage::model` in `stage_kinds.rs`): the walk reads every stage through it and never asks
//! its kind.
//!
//! The mesh efficiency comes in from outside ([`mesh_efficiency::MeshEfficiency`]): the evaluation builds one per
//! stage from the stage's own pair (a checked mesh, never the scene), with the driving member in
//! the pinion's role.

pub(crate) mod forces;
pub(crate) mod internal_stage;
pub(crate) mod kind_state;
pub mod kinematics;
pub(crate) mod layout;
mod loss_parts_serde;
pub(crate) mod mesh_efficiency;
pub(crate) mod mesh_state;
pub(crate) mod parallel_stage;
pub(crate) mod pass;
pub(crate) mod planetary;
pub(crate) mod planetary_stage;
pub(crate) mod point;
pub(crate) mod seeded_losses;
pub mod shaft_beam;
pub mod shaft_bending;
pub(crate) mod speeds;
pub(crate) mod stage_kinds;
pub(crate) mod stage_model;
pub mod statics;
pub mod walk;
mod walk_parts;
mod walk_point;

pub use forces::{mesh_forces, GearLoad, MeshForceSizes};
pub use kind_state::{KindInputs, KindPoint};
pub use layout::{Drive, DriveOperating, GearPlace, Hand, Member, Shaft, ShaftEnd, Stage};
pub use mesh_efficiency::MeshEfficiency;
pub use mesh_state::MeshState;
pub use point::{BearingPoint, DrivePoint, LossParts, PowerFlow, ShaftPoint, StagePoint};
pub use walk::{solve, EndValue, TOLERANCE};
