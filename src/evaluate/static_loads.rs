//! The static load of every bearing place over every row (a drive's) or point (a pair's) of a
//! sweep: each place keeps its worst static equivalent load P_0 = max(0.6 F_r + 0.5 F_a, F_r) of one
//! bearing (ISO 76) and the first row or point where it is met. The report warns of a place whose
//! P_0 passes its static load rating C_0 from this tally, so a row or point the report does not
//! keep is never missed; shards fold to the single run's tally.

use serde::{Deserialize, Serialize};

use crate::drive::{Drive, DrivePoint};
use crate::losses::bearing_type::static_equivalent_load;

/// By bearing place (a drive's: each shaft's places in the layout's order, shaft after shaft; a
/// pair's: its budget's places): the worst P_0 (N) over the rows and the first row it was met at;
/// None before any row lists the place.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub(crate) struct StaticLoads(pub(crate) Vec<Option<(f64, usize)>>);

impl StaticLoads {
    pub(crate) fn is_empty(&self) -> bool {
        self.0.iter().all(Option::is_none)
    }

    /// Row `i`'s loads `(F_r, F_a)` of one bearing (N) at each place, in place order (None: a place
    /// the row does not list).
    pub(crate) fn add(&mut self, i: usize, loads: impl IntoIterator<Item = Option<(f64, f64)>>) {
        for (k, load) in loads.into_iter().enumerate() {
            if k >= self.0.len() {
                self.0.resize(k + 1, None);
            }
            // NaN never replaces a number (the record files flag a value that is not finite).
            let Some(p0) = load.map(|(radial, axial)| static_equivalent_load(radial, axial)).filter(|p| !p.is_nan())
            else {
                continue;
            };
            if self.0[k].is_none_or(|(worst, _)| p0 > worst) {
                self.0[k] = Some((p0, i));
            }
        }
    }

    /// Row `i` of a drive at `point`: the loads of every place of `drive`'s shafts.
    pub(crate) fn add_drive_row(&mut self, drive: &Drive, i: usize, point: &DrivePoint) {
        // One entry a place of the layout, whether or not the point lists it.
        let places = drive.shafts.iter().zip(&point.shafts).flat_map(|(shaft, at)| {
            let mut own = at.bearings.iter().filter(|b| b.is_shaft_place());
            shaft.bearings.iter().map(move |_| own.next().map(|b| (b.radial_load, b.axial_load)))
        });
        self.add(i, places);
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

    /// P_0 = max(0.6 F_r + 0.5 F_a, F_r) of each place, the worst row kept, NaN never kept.
    #[test]
    fn each_place_keeps_its_worst_static_equivalent_load() {
        let mut t = StaticLoads::default();
        t.add(0, [Some((1000.0, 0.0)), Some((1000.0, 1000.0)), None]);
        t.add(1, [Some((900.0, 500.0)), Some((f64::NAN, 0.0)), Some((10.0, 0.0))]);
        // 0.6·900 + 0.5·500 = 790 < 900 = F_r < 1000; 0.6·1000 + 0.5·1000 = 1100 > 1000.
        assert_eq!(t.0, vec![Some((1000.0, 0)), Some((1100.0, 0)), Some((10.0, 1))]);
    }
}
