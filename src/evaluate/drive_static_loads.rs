//! The static load of every bearing place of a drive over every row of its sweep: each shaft's
//! place with a static load rating C_0 keeps its worst P_0/C_0 (P_0 = max(0.6 F_r + 0.5 F_a, F_r)
//! of one bearing, ISO 76) and the first row where it is met. The report warns of a place beyond
//! its rating from this tally, so a row the report does not keep (it keeps the first few) is never
//! missed; shards fold to the single run's tally.

use serde::{Deserialize, Serialize};

use crate::drive::{Drive, DrivePoint};
use crate::losses::bearing_type::static_equivalent_load;

/// By bearing place (each shaft's places in the layout's order, shaft after shaft): the worst
/// P_0/C_0 over the rows and the first row it was met at; None for a place without C_0 (or before
/// any row).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub(crate) struct StaticLoads(pub(crate) Vec<Option<(f64, usize)>>);

impl StaticLoads {
    pub(crate) fn is_empty(&self) -> bool {
        self.0.iter().all(Option::is_none)
    }

    /// Row `i`'s loads at `point` on the places of `drive`'s shafts.
    pub(crate) fn add(&mut self, drive: &Drive, i: usize, point: &DrivePoint) {
        // One entry a place of the layout, whether or not the point lists it.
        let places = drive.shafts.iter().zip(&point.shafts).flat_map(|(shaft, at)| {
            let mut own = at.bearings.iter().filter(|b| b.is_shaft_place());
            shaft.bearings.iter().map(move |b| {
                let at = own.next()?;
                let c0 = b.static_load_rating.filter(|c0| *c0 > 0.0)?;
                Some(static_equivalent_load(at.radial_load, at.axial_load) / c0)
            })
        });
        for (k, ratio) in places.enumerate() {
            if k >= self.0.len() {
                self.0.resize(k + 1, None);
            }
            // NaN never replaces a number (the record files flag a value that is not finite).
            let Some(ratio) = ratio.filter(|r| !r.is_nan()) else { continue };
            if self.0[k].is_none_or(|(worst, _)| ratio > worst) {
                self.0[k] = Some((ratio, i));
            }
        }
    }

    /// Folds the tally of the rows that follow (a later shard's): the worse of the two, the
    /// earlier row where they are equal.
    pub(crate) fn absorb(&mut self, next: StaticLoads) {
        if next.0.len() > self.0.len() {
            self.0.resize(next.0.len(), None);
        }
        for (mine, theirs) in self.0.iter_mut().zip(next.0) {
            if let Some((ratio, i)) = theirs {
                if mine.is_none_or(|(worst, _)| ratio > worst) {
                    *mine = Some((ratio, i));
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::StaticLoads;

    /// Two shards' tallies fold to the worse of each place, the earlier row on a tie, and a place
    /// only one shard saw is kept.
    #[test]
    fn shards_fold_to_the_worst_place_by_place() {
        let mut first = StaticLoads(vec![Some((0.5, 1)), Some((1.2, 3)), None]);
        first.absorb(StaticLoads(vec![Some((0.7, 10)), Some((1.2, 12)), Some((0.1, 14)), Some((2.0, 15))]));
        assert_eq!(first.0, vec![Some((0.7, 10)), Some((1.2, 3)), Some((0.1, 14)), Some((2.0, 15))]);
        assert!(StaticLoads(vec![None, None]).is_empty() && !first.is_empty());
    }
}
