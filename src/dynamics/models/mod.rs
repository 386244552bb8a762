//! The catalogue of dynamic models: each model is one file implementing [`GearDynamics`] and one
//! row of [`catalog::MODELS`]; the evaluation holds a `Box<dyn GearDynamics>` and never names a
//! model.
//!
//! Today: the SDOF torsional model along the line of action ([`sdof`]) and the 6-DOF model of
//! both gears on their bearings (`six_dof`). Each wraps the mesh (an [`crate::dynamics::SdofSystem`]
//! at one operating point and formulation) in its own system, analyses it with the shared engine
//! (Floquet, trajectories, integrators) and gives back generic data
//! (`crate::dynamics::analysis`).

pub(crate) mod catalog;
pub(crate) mod gear_dynamics;
pub(crate) mod model_id;
pub mod sdof;
pub(crate) mod six_dof;

pub use catalog::{DynamicModelEntry, MODELS};
pub use gear_dynamics::{GearDynamics, ModelFacts, ModelInputs, Wants};
pub use model_id::DynamicModelId;
