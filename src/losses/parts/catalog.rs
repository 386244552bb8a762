//! The catalogue of loss parts: each part's typed identity, its name, its file, the columns it
//! fills and the part itself.

use super::loss_column::LossColumn;
use super::loss_part::{LossPart, PartLosses, PartState};
pub use super::part_id::LossPartId;
use super::{bearings, gear_no_load, seals};
use crate::losses::oil::Oil;

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
    /// The part.
    pub part: &'static (dyn LossPart + Sync),
}

/// Every loss part, in the budget's column order.
pub const PARTS: &[LossPartEntry] = &[
    LossPartEntry {
        id: LossPartId::GearNoLoad,
        name: "gear_no_load",
        file: "gear_no_load.rs",
        title: "gears without load: churning (dip) or jet impulse and windage (injection), ISO/TR 14179-2",
        columns: &[LossColumn::GearNoLoad],
        part: &gear_no_load::GearNoLoad,
    },
    LossPartEntry {
        id: LossPartId::Bearings,
        name: "bearings",
        file: "bearings.rs",
        title: "rolling bearings on the mesh force's reactions: Palmgren's M_0 and M_1, or the SKF model",
        columns: &[LossColumn::BearingsNoLoad, LossColumn::BearingsLoad],
        part: &bearings::Bearings,
    },
    LossPartEntry {
        id: LossPartId::Seals,
        name: "seals",
        file: "seals.rs",
        title: "radial lip seals, ISO/TR 14179-2 after Linke",
        columns: &[LossColumn::Seals],
        part: &seals::Seals,
    },
];

/// The columns the drive `on` fills, in order.
pub(crate) fn columns_of(on: &PartState) -> Vec<LossColumn> {
    let mut out: Vec<LossColumn> =
        PARTS.iter().filter(|p| p.part.present(on)).flat_map(|p| p.columns.iter().copied()).collect();
    out.sort();
    out
}

/// Every part of the catalogue the drive `on` has that reads the bearing places' loads
/// (`loaded`) or not, its powers on `on` in `oil` added to `out`.
pub(crate) fn add_parts(on: &PartState, oil: &Oil, loaded: bool, out: &mut PartLosses) {
    for p in PARTS.iter().filter(|p| p.part.reads_loads() == loaded && p.part.present(on)) {
        p.part.losses(on, oil, out);
    }
}
