//! What the power walk charges each shaft from the loss-part catalogue (`crate::losses::parts`):
//! the shafts as the parts read them, the load-independent parts of a point, and the statics the
//! load-dependent parts rest on at a pass (`super::walk` charges them).

use super::forces::GearLoad;
use super::layout::Drive;
use super::point::ShaftPoint;
use super::shaft_bending::ShaftBending;
use crate::losses::parts::{LossColumn, PartLosses, ShaftParts, COLUMNS, COLUMN_COUNT};

/// What the load-dependent parts rest on at one pass: each shaft's support reactions [x, y, z] at
/// its places (N), its bending (at the point, a shaft with sections) and every gear's load.
pub(super) struct Statics {
    pub(super) reactions: Vec<Vec<[f64; 3]>>,
    pub(super) bending: Vec<Option<ShaftBending>>,
    pub(super) loads: Vec<GearLoad>,
}

/// Load-independent losses (W) of each shaft and stage: the catalogue's parts that do not read the
/// bearing loads (seals; the gears' no-load parts, churning and jet impulse on the shaft the stage
/// charges them to, each gear's windage on its own).
pub(super) struct FixedLosses(pub(super) PartLosses);

impl FixedLosses {
    /// Shaft `j`'s own losses (W) with its bearings' `bearings`: bearings, then its columns of the
    /// load-independent parts.
    pub(super) fn own(&self, j: usize, bearings: f64) -> f64 {
        bearings + self.0.shaft_total(j)
    }

    pub(super) fn seals(&self, j: usize) -> f64 {
        self.0.shaft(j)[LossColumn::Seals as usize]
    }

    pub(super) fn gear_no_load(&self, j: usize) -> f64 {
        self.0.shaft(j)[LossColumn::GearNoLoad as usize]
    }

    /// A point's loss parts by column (W): each column over every shaft, the bearing columns over
    /// every bearing place of `shafts` (a stage's own members' included), as the point lists them.
    pub(super) fn point_parts(&self, shafts: &[ShaftPoint]) -> [f64; COLUMN_COUNT] {
        let mut parts = [0.0; COLUMN_COUNT];
        for (p, c) in parts.iter_mut().zip(COLUMNS) {
            *p = self.0.column(c.column);
        }
        let places = || shafts.iter().flat_map(|s| &s.bearings);
        parts[LossColumn::BearingsNoLoad as usize] = places().map(|b| b.no_load).sum();
        parts[LossColumn::BearingsLoad as usize] = places().map(|b| b.load).sum();
        parts
    }

    /// Stage `k`'s no-load parts (W).
    pub(super) fn stage_no_load(&self) -> &[f64] {
        &self.0.stages
    }
}

/// Every shaft of `drive` at the speeds `omega` as the loss parts read it, with the loads `loads`
/// on one bearing of each place (none: the parts that read no loads).
pub(super) fn shaft_parts<'a>(drive: &'a Drive, omega: &[f64], loads: &'a [Vec<[f64; 2]>]) -> Vec<ShaftParts<'a>> {
    drive
        .shafts
        .iter()
        .enumerate()
        .map(|(j, s)| ShaftParts {
            speed: omega[j].abs(),
            bearings: &s.bearings,
            loads: loads.get(j).map_or(&[], Vec::as_slice),
            seals: &s.seals,
        })
        .collect()
}
