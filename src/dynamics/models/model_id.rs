//! The typed identity of each dynamic model of the catalogue.

/// The typed identity of a dynamic model of the catalogue (its index in [`super::MODELS`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
pub enum DynamicModelId {
    Sdof,
    SixDof,
}
