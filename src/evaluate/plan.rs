//! The plan of a run over a sweep: which operating points it evaluates (all, or one shard's share),
//! which it reports in full (the detail points: contact tables, μ along the line of action, plots)
//! and which it keeps the summary rows of for the report's tables and plots (the kept points).
//! Every point gets its summary record; the report's size is bounded whatever the sweep's.

use std::ops::Range;

pub use super::cases::evenly;
use super::cases::{case_at, Case, MAX_CURVES};
use crate::model::Operating;

/// Sweeps of up to this many operating points report every point in full (as small scenes always did).
pub const ALL_IN_DETAIL: usize = 100;
/// Larger sweeps report this many values of each sweep in full (their products: up to 9 points).
pub(crate) const DETAIL_PER_SWEEP: usize = 3;
/// A sweep plot draws at most this many values along its x axis.
pub const PLOTTED_VALUES: usize = 200;
/// A map plot's grid has at most this many values of each sweep.
pub const MAP_VALUES: usize = 40;

/// One share of a sharded run: `index` of `count`, 1-based (`--shard 2/4`). What a user writes is
/// validated in one place, [`Shard::new`] (and the `K/N` parse on it), which holds 1 ≤ K ≤ N ≤
/// `MAX_SHARDS`: the CLI and Python both go through it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Shard {
    pub index: usize,
    pub count: usize,
}

/// The most shards a sweep is cut into.
pub(crate) const MAX_SHARDS: usize = 1_000_000;

const SHARD_HINT: &str = "write K/N with whole numbers 1 ≤ K ≤ N ≤ 1000000, e.g. 2/4";

impl Shard {
    /// Shard `index` of `count`, or why it does not exist (with the hint).
    ///
    /// ```
    /// assert!(gearloss::Shard::new(2, 4).is_ok());
    /// assert!(gearloss::Shard::new(7, 6).is_err());
    /// assert!(gearloss::Shard::new(0, 6).is_err());
    /// assert!(gearloss::Shard::new(1, 0).is_err());
    /// assert_eq!("3/5".parse::<gearloss::Shard>(), gearloss::Shard::new(3, 5));
    /// ```
    pub fn new(index: usize, count: usize) -> Result<Shard, String> {
        if index == 0 || index > count || count > MAX_SHARDS {
            return Err(format!("shard {index}/{count} does not exist: {SHARD_HINT}"));
        }
        Ok(Shard { index, count })
    }

    /// The operating points of this share of `n`: a contiguous block, so that the shards' record
    /// files concatenate in order to a single run's.
    pub fn range(&self, n: usize) -> Range<usize> {
        let at = |i: usize| ((i as u128 * n as u128) / self.count as u128) as usize;
        at(self.index - 1)..at(self.index)
    }
}

impl std::str::FromStr for Shard {
    type Err = String;

    /// `K/N`, as `--shard` and Python's `shard="K/N"` take it.
    fn from_str(text: &str) -> Result<Shard, String> {
        let (k, n) = text.split_once('/').ok_or_else(|| format!("`{text}` is not K/N: {SHARD_HINT}"))?;
        let whole =
            |t: &str| t.trim().parse::<usize>().map_err(|_| format!("`{t}` is not a whole number: {SHARD_HINT}"));
        Shard::new(whole(k)?, whole(n)?)
    }
}

/// Which points a run evaluates, details and keeps.
#[derive(Debug, Clone)]
pub struct Plan {
    pub torques: usize,
    pub speeds: usize,
    /// The points this run evaluates (all of them unless sharded).
    pub range: Range<usize>,
    /// Points reported in full, ascending (the first point always among them).
    pub detail: Vec<usize>,
    /// Detail points whose curves (μ, η(t), local power loss) are plotted.
    pub curves: Vec<usize>,
    everything: bool,
    curve_torques: Vec<usize>,
    curve_speeds: Vec<usize>,
    plot_torques: Vec<usize>,
    plot_speeds: Vec<usize>,
    map_torques: Vec<usize>,
    map_speeds: Vec<usize>,
}

impl Plan {
    /// The plan for a scene's sweeps; `named` are points the scene asks to see in full (0-based).
    pub fn new(op: &Operating, shard: Option<Shard>, named: &[usize]) -> Plan {
        let (nt, ns) = (op.pinion_torque.values.len(), op.pinion_speed.values.len());
        let n = nt * ns;
        let everything = n <= ALL_IN_DETAIL;
        let (detail, curves) = if everything {
            ((0..n).collect(), evenly(n, MAX_CURVES))
        } else {
            let mut d: Vec<usize> = evenly(nt, DETAIL_PER_SWEEP)
                .into_iter()
                .flat_map(|t| evenly(ns, DETAIL_PER_SWEEP).into_iter().map(move |s| t * ns + s))
                .collect();
            d.extend(named.iter().copied().filter(|k| *k < n));
            d.sort_unstable();
            d.dedup();
            (d.clone(), d)
        };
        Plan {
            torques: nt,
            speeds: ns,
            range: shard.map_or(0..n, |s| s.range(n)),
            detail,
            curves,
            everything,
            curve_torques: evenly(nt, MAX_CURVES),
            curve_speeds: evenly(ns, MAX_CURVES),
            plot_torques: evenly(nt, PLOTTED_VALUES),
            plot_speeds: evenly(ns, PLOTTED_VALUES),
            map_torques: evenly(nt, MAP_VALUES),
            map_speeds: evenly(ns, MAP_VALUES),
        }
    }

    /// Operating points of the scene (not only of this run's range).
    pub fn count(&self) -> usize {
        self.torques * self.speeds
    }

    /// Whether every point of the sweep is reported in full.
    pub fn everything_in_detail(&self) -> bool {
        self.everything
    }

    /// Whether the report keeps the summary rows of point `k`: every point of a small sweep; else
    /// the picked curves of the sweep plots (each at up to [`PLOTTED_VALUES`] x values), the map grid
    /// and the detail points.
    pub fn kept(&self, k: usize) -> bool {
        if self.everything {
            return true;
        }
        let (t, s) = (k / self.speeds, k % self.speeds);
        let has = |v: &[usize], i: usize| v.binary_search(&i).is_ok();
        (has(&self.curve_torques, t) && has(&self.plot_speeds, s))
            || (has(&self.curve_speeds, s) && has(&self.plot_torques, t))
            || (has(&self.map_torques, t) && has(&self.map_speeds, s))
            || has(&self.detail, k)
    }

    /// The grid of the map plots: (torque indices, speed indices).
    pub fn map_grid(&self) -> (&[usize], &[usize]) {
        (&self.map_torques, &self.map_speeds)
    }

    /// The torque and speed indices drawn as curves in the sweep plots (at most [`MAX_CURVES`] each).
    pub fn curve_indices(&self) -> (&[usize], &[usize]) {
        (&self.curve_torques, &self.curve_speeds)
    }

    /// The cases of the detail points.
    pub fn detail_cases(&self, op: &Operating) -> Vec<Case> {
        self.detail.iter().map(|k| case_at(op, *k)).collect()
    }
}

/// The rows a drive's report shows in full, as sorted disjoint ranges of row indices: the first
/// `first` of its `rows` and every row (`per_point` of them, laws × formulations, point-major) of
/// each detail point (0-based).
pub(crate) fn drive_kept_rows(
    (rows, per_point): (usize, usize),
    first: usize,
    detail_points: &[usize],
) -> Vec<std::ops::Range<usize>> {
    let first = 0..rows.min(first);
    let points = detail_points_past(first.end, per_point, detail_points)
        .map(|p| (p * per_point).min(rows)..((p + 1) * per_point).min(rows));
    let mut ranges: Vec<_> = std::iter::once(first).chain(points).filter(|r| !r.is_empty()).collect();
    ranges.sort_by_key(|r| r.start);
    let mut out: Vec<std::ops::Range<usize>> = Vec::new();
    for r in ranges {
        match out.last_mut() {
            Some(last) if r.start <= last.end => last.end = last.end.max(r.end),
            _ => out.push(r),
        }
    }
    out
}

/// The detail points (0-based, in the order given) with a row past the first `first` rows, when
/// each point has `per_point` rows (laws × formulations, point-major): those a drive's report
/// shows beyond its first rows ([`drive_kept_rows`], the report's `ShownRows`).
pub(crate) fn detail_points_past(
    first: usize,
    per_point: usize,
    detail_points: &[usize],
) -> impl Iterator<Item = usize> + '_ {
    detail_points.iter().copied().filter(move |p| (p + 1) * per_point > first)
}

#[cfg(test)]
mod tests {
    use super::drive_kept_rows;

    /// The first rows and each detail point's rows, joined where they touch or overlap, in order
    /// whatever order the points come in; nothing past the last row.
    #[test]
    fn a_drives_kept_rows_are_its_first_and_its_detail_points() {
        assert_eq!(drive_kept_rows((288, 2), 12, &[]), vec![0..12]);
        assert_eq!(drive_kept_rows((288, 2), 12, &[99, 16]), vec![0..12, 32..34, 198..200]);
        // Point 5 (rows 10..12) lies in the first rows; point 6 (12..14) touches them; 7 follows.
        assert_eq!(drive_kept_rows((288, 2), 12, &[5, 6, 7]), vec![0..16]);
        // Five rows a point: point 2's rows 10..15 straddle the first 12.
        assert_eq!(drive_kept_rows((100, 5), 12, &[2, 19]), vec![0..15, 95..100]);
        // Fewer rows than the first: every row, once.
        assert_eq!(drive_kept_rows((6, 3), 12, &[1]), vec![0..6]);
        assert_eq!(drive_kept_rows((0, 3), 12, &[]), Vec::<std::ops::Range<usize>>::new());
    }
}
