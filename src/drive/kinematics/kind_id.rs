//! A stage's kind: its typed identity (its index in the catalogue's `STAGE_KINDS`) and its data,
//! one variant a kind.

use super::planetary::PlanetaryLayout;

/// A stage kind of the catalogue.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum StageKindId {
    Parallel,
    Planetary,
    Internal,
}

/// A stage's kind with what its physics reads beyond the stage's two places, teeth and hand: a
/// parallel stage nothing more, a planetary stage its layout.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum StageKind {
    Parallel,
    Planetary(Box<PlanetaryLayout>),
    /// A pinion inside a ring gear on parallel shafts (the stage's wheel is the ring).
    Internal,
}

impl StageKind {
    /// The kind's identity in the catalogue.
    pub fn id(&self) -> StageKindId {
        match self {
            StageKind::Parallel => StageKindId::Parallel,
            StageKind::Planetary(_) => StageKindId::Planetary,
            StageKind::Internal => StageKindId::Internal,
        }
    }
}
