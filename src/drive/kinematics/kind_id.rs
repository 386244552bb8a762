//! The typed identity of a stage kind: its index in the catalogue's `STAGE_KINDS`.

/// A stage kind of the catalogue.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum StageKindId {
    Parallel,
    Planetary,
}
