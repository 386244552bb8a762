//! Stage kinematics as a catalogue: each stage kind one file implementing [`StageKinematics`] and
//! one row of [`catalog::STAGE_KINDS`]: parallel axes (an external spur or helical pair) and a
//! planetary stage (sun, planets, ring, carrier; one member held).

pub(crate) mod catalog;
pub mod internal;
pub mod parallel;
pub mod planetary;
pub(crate) mod stage_kinematics;

pub use catalog::{StageKind, StageKindEntry, StageKindId, STAGE_KINDS};
pub use stage_kinematics::StageKinematics;
