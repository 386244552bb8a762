//! The typed identity of each loss part of the catalogue.

/// The typed identity of a loss part (its index in [`super::PARTS`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LossPartId {
    GearNoLoad,
    Bearings,
    Seals,
}
