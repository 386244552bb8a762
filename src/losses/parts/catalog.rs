//! The catalogue of loss parts: each part's typed identity, its name, its file, the columns it
//! fills and how it is read off a scene's gearbox.

use super::loss_column::LossColumn;
use super::loss_part::LossPart;
pub use super::part_id::LossPartId;
use super::{bearings, gear_no_load, seals};
use crate::losses::gearbox::Gearbox;

impl LossPartId {
    pub fn entry(self) -> &'static LossPartEntry {
        &PARTS[self as usize]
    }
}

/// One part of the catalogue.
#[derive(Clone, Copy)]
pub struct LossPartEntry {
    pub id: LossPartId,
    pub name: &'static str,
    /// Its file in `src/losses/parts/`.
    pub file: &'static str,
    pub title: &'static str,
    /// The columns it fills, in [`super::COLUMNS`] order.
    pub columns: &'static [LossColumn],
    /// The part as the scene's gearbox describes it; None when the gearbox has none of it.
    pub of: for<'a> fn(&'a Gearbox) -> Option<Box<dyn LossPart + 'a>>,
}

/// Every loss part, in the budget's column order.
pub const PARTS: &[LossPartEntry] = &[
    LossPartEntry {
        id: LossPartId::GearNoLoad,
        name: "gear_no_load",
        file: "gear_no_load.rs",
        title: "gears without load: churning (dip) or jet impulse and windage (injection), ISO/TR 14179-2",
        columns: &[LossColumn::GearNoLoad],
        of: gear_no_load::of,
    },
    LossPartEntry {
        id: LossPartId::Bearings,
        name: "bearings",
        file: "bearings.rs",
        title: "rolling bearings on the mesh force's reactions: Palmgren's M_0 and M_1, or the SKF model",
        columns: &[LossColumn::BearingsNoLoad, LossColumn::BearingsLoad],
        of: bearings::of,
    },
    LossPartEntry {
        id: LossPartId::Seals,
        name: "seals",
        file: "seals.rs",
        title: "radial lip seals, ISO/TR 14179-2 after Linke",
        columns: &[LossColumn::Seals],
        of: seals::of,
    },
];

/// The columns a gearbox fills, in order.
pub(crate) fn columns_of(gearbox: &Gearbox) -> Vec<LossColumn> {
    let mut out: Vec<LossColumn> =
        PARTS.iter().filter(|p| (p.of)(gearbox).is_some()).flat_map(|p| p.columns.iter().copied()).collect();
    out.sort();
    out
}
