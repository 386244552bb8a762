//! The catalogue of stage kinds: each kind's typed identity, its data (one variant a kind), its
//! name and file; what the drive's walk reads of a kind is its `StageModel`
//! (`crate::drive::stage_model`).

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

impl StageKindId {
    pub fn entry(self) -> &'static StageKindEntry {
        &STAGE_KINDS[self as usize]
    }
}

/// One stage kind of the catalogue.
#[derive(Clone, Copy)]
pub struct StageKindEntry {
    pub id: StageKindId,
    pub name: &'static str,
    /// Its file in `src/drive/kinematics/`.
    pub file: &'static str,
    pub title: &'static str,
}

/// Every stage kind.
pub const STAGE_KINDS: &[StageKindEntry] = &[
    StageKindEntry {
        id: StageKindId::Parallel,
        name: "parallel",
        file: "parallel.rs",
        title: "an external pair on parallel shafts: ω_wheel = −ω_pinion z_pinion/z_wheel",
    },
    StageKindEntry {
        id: StageKindId::Planetary,
        name: "planetary",
        file: "planetary.rs",
        title: "sun, planets on a carrier, ring; one member held: Willis, n_s − i₀ n_r − (1 − i₀) n_c = 0",
    },
    StageKindEntry {
        id: StageKindId::Internal,
        name: "internal",
        file: "internal.rs",
        title: "a pinion inside a ring gear on parallel shafts: ω_ring = ω_pinion z_pinion/z_ring",
    },
];
