//! The typed identity of a stage kind: its index in [`super::catalog::STAGE_KINDS`].

/// A stage kind of the catalogue.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StageKindId {
    Parallel,
}

impl StageKindId {
    pub fn entry(self) -> &'static super::catalog::StageKindEntry {
        &super::catalog::STAGE_KINDS[self as usize]
    }
}
