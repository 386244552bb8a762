//! The catalogue of stage kinds: each kind's typed identity, name and file; what the drive's walk
//! reads of a kind is its `StageModel` (`crate::drive::stage_model`).

use super::kind_id::StageKindId;

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
