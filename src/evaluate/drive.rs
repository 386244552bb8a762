//! A drive's evaluation: the drive walked through at every operating point, friction law and
//! formulation (rows streamed to the records, the first and the detail points' kept for the
//! report), over the map's grid, and the thermal balance of the kept rows.

use super::drive_records::{drive_records_csv, DriveRecord, DriveRecordSink};
use super::drive_setup::DriveSetup;
use crate::drive::DrivePoint;
use crate::model::{Scene, SceneDrive};
use crate::progress::Progress;

pub(crate) use super::drive_setup::DriveRow;

/// A drive's results: its operating points and its map (torque-major, then law, then formulation).
#[derive(Debug, Clone, Default)]
pub struct DriveEvaluation {
    pub rows: Vec<DriveRow>,
    pub map: Vec<super::drive_map_cell::DriveMapCell>,
    /// The map's best point of each half (drive, coast), per law and formulation, located.
    pub map_best: Vec<super::drive_map_best::DriveMapBest>,
    /// For every kept row, each stage's validity of the row's law.
    pub validity: Vec<Vec<super::laws::ValiditySummary>>,
    /// The thermal balance of every kept row, when the scene asks for it.
    pub balances: Vec<super::drive_thermal::DriveBalanceRow>,
    /// P_V(θ) and P_Q(θ) at the first row, when the scene asks for the thermal balance or the
    /// oil at its balance.
    pub heat_balance: Option<super::thermal::HeatBalanceCurve>,
    /// The duty cycle, when the scene asks for it.
    pub duty: Option<super::thermal::DutyCycleResult>,
    /// The vehicle's drive cycle, when the scene asks for it.
    pub cycle: Option<super::drive_cycle::CycleEvaluation>,
    pub tally: DriveTally,
    /// Each stage's meshes' H_V as the walk integrates them (`DriveSetup::loss_factors`).
    pub loss_factors: Vec<Vec<f64>>,
}

/// Operating points (rows) a drive's report shows in full from the first on, beside the rows of its
/// detail points ([`kept_rows`]); the records hold every one.
pub(crate) const DETAIL_ROWS: usize = 12;
/// Rows evaluated together before they are written.
const BLOCK: usize = 4096;

/// Evaluates a drive scene in memory (its records dropped): its operating points (the kept rows:
/// the first `DETAIL_ROWS` and the detail points'), its map and its thermal balance.
pub fn evaluate_drive(scene: &Scene, drive: &SceneDrive) -> DriveEvaluation {
    evaluate_drive_into(scene, drive, &mut std::io::sink()).expect("a sink takes every row")
}

/// Evaluates a drive scene, every row of its operating points written to `records` as it goes
/// (`super::drive_records`); the kept rows (`kept_rows`) are kept for the report, with the
/// count and the least and greatest efficiency over every row (exact: the rows are the points
/// asked for).
pub fn evaluate_drive_into(
    scene: &Scene,
    drive: &SceneDrive,
    records: &mut (dyn std::io::Write + Send),
) -> std::io::Result<DriveEvaluation> {
    let mut csv = drive_records_csv(drive, records);
    evaluate_drive_into_with(scene, drive, &mut csv, &crate::progress::Quiet)
}

/// [`evaluate_drive_into`] announcing each block of rows to `progress`: where it says the run is
/// cancelled (Ctrl-C in Python), the run stops after that block with an `Interrupted` error.
pub(crate) fn evaluate_drive_into_with(
    scene: &Scene,
    drive: &SceneDrive,
    records: &mut dyn DriveRecordSink,
    progress: &dyn Progress,
) -> std::io::Result<DriveEvaluation> {
    let setup = DriveSetup::new(scene, drive);
    let n = row_count(scene, &setup);
    progress.stage("evaluate", n as u64);
    let (keep, table) = (kept_rows(scene, &setup), row_ratings(scene, drive));
    let (kept, tally) = stream_rows(&setup, (scene, drive, &keep, table.as_ref()), (0..n, records), true, progress)?;
    Ok(finish(&setup, scene, drive, kept, tally))
}

/// One shard of a drive's run (`gearloss run --shard K/N`): the rows of its operating points
/// ([`super::plan::Shard::range`] over the points) streamed to `records` (each shard's CSV with
/// its header, as a pair's shards', which the merge keeps from the first shard only), and their tally;
/// each block of rows announced to `progress` (stopping where it is cancelled).
pub(crate) fn evaluate_drive_shard_with(
    scene: &Scene,
    drive: &SceneDrive,
    shard: super::plan::Shard,
    records: &mut dyn DriveRecordSink,
    progress: &dyn Progress,
) -> std::io::Result<DriveTally> {
    let setup = DriveSetup::new(scene, drive);
    let per_point = setup.rows_per_point();
    let points = shard.range(scene.operating.count());
    let rows = points.start * per_point..points.end * per_point;
    progress.stage("evaluate", rows.len() as u64);
    let table = row_ratings(scene, drive);
    Ok(stream_rows(&setup, (scene, drive, &[], table.as_ref()), (rows, records), true, progress)?.1)
}

/// After the shards are merged: the report's rows (the [`kept_rows`]) evaluated again, the map,
/// thermal balance and duty cycle, with `tally` folded from the shards (exactly a single run's).
pub(crate) fn evaluate_drive_merged(scene: &Scene, drive: &SceneDrive, tally: DriveTally) -> DriveEvaluation {
    let setup = DriveSetup::new(scene, drive);
    let (keep, table) = (kept_rows(scene, &setup), row_ratings(scene, drive));
    let mut kept: Kept = Default::default();
    for range in &keep {
        let sink = &mut drive_records_csv(drive, std::io::sink());
        let of = (scene, drive, &keep[..], table.as_ref());
        let (rows, validity, balanced) = stream_rows(&setup, of, (range.clone(), sink), false, &crate::progress::Quiet)
            .expect("a sink takes every row")
            .0;
        kept.0.extend(rows);
        kept.1.extend(validity);
        kept.2.extend(balanced);
    }
    finish(&setup, scene, drive, kept, tally)
}

/// The rows a drive's report shows in full (`super::plan::drive_kept_rows`).
fn kept_rows(scene: &Scene, setup: &DriveSetup) -> Vec<std::ops::Range<usize>> {
    let (rows, per_point) = (row_count(scene, setup), setup.rows_per_point());
    super::plan::drive_kept_rows((rows, per_point), DETAIL_ROWS, &scene.operating.detail_points)
}

/// Where the drive's rows carry their balance (`SceneDrive::balance_rows`): the table its speeds'
/// ratings are located in once, for every range of rows a run streams; None otherwise.
fn row_ratings(scene: &Scene, drive: &SceneDrive) -> Option<super::thermal::RatingTable> {
    (drive.balance_rows && scene.housing.is_some()).then(|| super::thermal::RatingTable::new(scene))
}

/// Rows of the operating points: points × laws × formulations.
fn row_count(scene: &Scene, setup: &DriveSetup) -> usize {
    scene.operating.count() * setup.rows_per_point()
}

/// The kept rows, their validity by stage and, where the drive's rows carry their balance
/// (`SceneDrive::balance_rows`), the kept rows' balances as streamed (else none).
type Kept = (Vec<DriveRow>, Vec<Vec<super::laws::ValiditySummary>>, Vec<super::drive_thermal::DriveBalanceRow>);

/// Rows `range` of the operating points in blocks, each written to `records` (after the header,
/// when `header`) and tallied; those in `keep` ([`kept_rows`]) kept with their validity and, with
/// a `table` of ratings ([`row_ratings`]), every row balanced. After each block
/// `progress` advances; where it is cancelled the rows stop with an `Interrupted` error.
fn stream_rows(
    setup: &DriveSetup,
    (scene, drive, keep, table): (&Scene, &SceneDrive, &[std::ops::Range<usize>], Option<&super::thermal::RatingTable>),
    (range, records): (std::ops::Range<usize>, &mut dyn DriveRecordSink),
    header: bool,
    progress: &dyn Progress,
) -> std::io::Result<(Kept, DriveTally)> {
    let si = |v: &[crate::model::Torque]| v.iter().map(|t| t.value).collect::<Vec<_>>();
    let op = &scene.operating;
    let speeds: Vec<f64> = op.pinion_speed.values.iter().map(|w| w.value).collect();
    let torques = si(&op.pinion_torque.values);
    let mut rows = Vec::new();
    let mut tally = DriveTally { rows: range.len(), ..Default::default() };
    if header {
        records.header(drive)?;
    }
    let mut validity = Vec::new();
    let mut balanced = Vec::new();
    // Every row's balance, when the drive's rows carry theirs; its speeds' ratings located once.
    let heat = scene.housing.as_ref().zip(table);
    for start in range.clone().step_by(BLOCK) {
        use rayon::prelude::*;
        let block = setup.grid_rows(&torques, &speeds, drive.layout.operating, start..(start + BLOCK).min(range.end));
        // At `oil_temperature = equilibrium` each row at its own balance, its validity read there.
        let (block, checked): (Vec<DriveRow>, Vec<_>) = match (scene.operating.equilibrium, &scene.housing) {
            (Some(_), Some(housing)) => {
                block.into_par_iter().map(|r| super::drive_thermal::row_at_balance(setup, scene, housing, r)).unzip()
            }
            _ => {
                let checked = block.par_iter().map(|r| setup.validity(r.law_index, &r.point)).collect();
                (block, checked)
            }
        };
        let odd: Vec<_> = block.par_iter().map(|r| setup.implausible(&r.point)).collect();
        let balances: Vec<_> = match heat {
            Some(heat) => {
                block.par_iter().map(|r| Some(super::drive_thermal::row_balance(setup, scene, heat, r))).collect()
            }
            None => vec![None; block.len()],
        };
        for (i, (((row, valid), odd), balance)) in block.into_iter().zip(checked).zip(odd).zip(balances).enumerate() {
            if let Some(what) = odd {
                tally.implausible_rows += 1;
                tally.first_implausible.get_or_insert((start + i, what));
            }
            let outside: Vec<usize> = valid.iter().map(|v| v.outside).collect();
            let record = DriveRecord {
                i: start + i,
                flow: row.point.flow,
                row: &row,
                outside: &outside,
                heat: balance.as_ref(),
            };
            let cells = super::drive_records::cells(&record);
            tally.add(start + i, &row.point);
            tally.static_loads.add_drive_row(setup.layout(), start + i, &row.point);
            tally.add_cells(start + i, &cells);
            if row.balance.is_some_and(|b| b.status != crate::thermal::BalanceStatus::Ok) {
                tally.off_balance_rows += 1;
                tally.first_off_balance.get_or_insert(start + i);
            }
            records.row(record, cells)?;
            if !row.point.settled() {
                tally.unsettled_rows += 1;
                tally.first_unsettled.get_or_insert(start + i);
            }
            if outside.iter().any(|o| *o > 0) {
                tally.outside_rows += 1;
                tally.first_outside.get_or_insert(start + i);
            }
            if keep.iter().any(|k| k.contains(&(start + i))) {
                rows.push(row);
                validity.push(valid);
                balanced.extend(balance);
            }
        }
        progress.advance(BLOCK.min(range.end - start) as u64);
        if progress.cancelled() {
            return Err(std::io::Error::new(std::io::ErrorKind::Interrupted, "the run was interrupted"));
        }
    }
    Ok(((rows, validity, balanced), tally))
}

/// The evaluation around the kept rows: the map, the thermal balance of the kept rows, the duty cycle.
fn finish(
    setup: &DriveSetup,
    scene: &Scene,
    drive: &SceneDrive,
    (rows, validity, balanced): Kept,
    tally: DriveTally,
) -> DriveEvaluation {
    let si = |v: &[crate::model::Torque]| v.iter().map(|t| t.value).collect::<Vec<_>>();
    let (map, map_best) = match (&scene.analyses.efficiency_map, scene.analyses.map_ends) {
        (Some((t, s)), Some(ends)) => {
            let (torques, speeds) = (si(&t.values), s.values.iter().map(|w| w.value).collect::<Vec<_>>());
            let map = super::drive_map_cell::map_cells(setup, &torques, &speeds, ends);
            let best = super::drive_map_best::drive_map_best(setup, (&torques, &speeds), (ends, drive.one_pair), &map);
            (map, best)
        }
        _ => (Vec::new(), Vec::new()),
    };
    // The kept rows' balances: as streamed where every row carries its own, else located here.
    let balances = match (&scene.housing, scene.analyses.thermal_balance) {
        (Some(_), Some(_)) if drive.balance_rows => balanced,
        (Some(h), Some(_)) => super::drive_thermal::drive_balances(scene, drive, h, &rows),
        _ => Vec::new(),
    };
    let wants_balance = scene.analyses.thermal_balance.is_some() || scene.operating.equilibrium.is_some();
    let heat_balance = match (&scene.housing, rows.first()) {
        (Some(h), Some(first)) if wants_balance => {
            Some(super::drive_thermal::heat_balance_curve(scene, drive, h, first))
        }
        _ => None,
    };
    let duty = match (&scene.housing, &scene.duty_cycle, scene.analyses.duty_cycle) {
        (Some(h), Some(c), Some(_)) => Some(super::drive_thermal::drive_duty(scene, drive, h, c)),
        _ => None,
    };
    let cycle = drive
        .cycle
        .as_ref()
        .filter(|_| scene.analyses.drive_cycle.is_some())
        .map(|spec| super::drive_cycle::evaluate_cycle(scene, drive, spec));
    let loss_factors = setup.loss_factors();
    DriveEvaluation { rows, map, map_best, validity, balances, heat_balance, duty, cycle, tally, loss_factors }
}

/// Over every row of the operating points: the count, the rows where both ends deliver, and the
/// least and greatest efficiency (of rows where one end delivers) with their row index.
#[derive(Debug, Clone, Default, serde::Serialize, serde::Deserialize)]
pub struct DriveTally {
    pub rows: usize,
    pub both_ends: usize,
    pub least: Option<(f64, usize)>,
    pub greatest: Option<(f64, usize)>,
    /// Rows where a stage's law leaves its validity range somewhere on A–E, and the first of them.
    pub outside_rows: usize,
    pub first_outside: Option<usize>,
    /// Rows whose fixed point did not settle (or diverged) or whose books do not balance
    /// ([`crate::drive::DrivePoint::settled`]), and the first of them.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub unsettled_rows: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_unsettled: Option<usize>,
    /// Values of the record files that are not finite numbers (empty cells, JSON `null`), and the
    /// first: its row and its column's index in `super::drive_records::columns`.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub non_finite: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_non_finite: Option<(usize, usize)>,
    /// At `oil_temperature = equilibrium`: rows whose sump settles above the oil's limit or finds no
    /// balance, and the first of them.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub off_balance_rows: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_off_balance: Option<usize>,
    /// Rows with a stage result no gear mesh can have or whose formulas no longer hold (a mesh
    /// efficiency outside [0, 1], a contact with b_H > R/10: `evaluate/drive_plausibility.rs`), and
    /// the first of them with what.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub implausible_rows: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_implausible: Option<(usize, super::drive_plausibility::StageImplausible)>,
    /// Each bearing place's worst static equivalent load P_0 over the rows and its first row.
    #[serde(default, skip_serializing_if = "super::static_loads::StaticLoads::is_empty")]
    pub(crate) static_loads: super::static_loads::StaticLoads,
}

/// For serde: a count left out when it is zero.
pub(crate) fn is_zero(n: &usize) -> bool {
    *n == 0
}

impl DriveTally {
    /// Folds the tally of the rows that follow (the next shard's): the same as one tally of both.
    pub fn absorb(&mut self, next: DriveTally) {
        self.rows += next.rows;
        self.both_ends += next.both_ends;
        self.outside_rows += next.outside_rows;
        self.first_outside = self.first_outside.or(next.first_outside);
        self.unsettled_rows += next.unsettled_rows;
        self.first_unsettled = self.first_unsettled.or(next.first_unsettled);
        self.non_finite += next.non_finite;
        self.first_non_finite = self.first_non_finite.or(next.first_non_finite);
        self.off_balance_rows += next.off_balance_rows;
        self.first_off_balance = self.first_off_balance.or(next.first_off_balance);
        self.implausible_rows += next.implausible_rows;
        self.first_implausible = self.first_implausible.take().or(next.first_implausible);
        self.static_loads.absorb(next.static_loads);
        if let Some((e, i)) = next.least {
            if self.least.is_none_or(|(l, _)| e < l) {
                self.least = Some((e, i));
            }
        }
        if let Some((e, i)) = next.greatest {
            if self.greatest.is_none_or(|(g, _)| e > g) {
                self.greatest = Some((e, i));
            }
        }
    }

    /// Counts row `i`'s cells that hold a number that is not finite (the record files write it as
    /// an empty cell, `null`, a Parquet null: flagged in the report, never silent).
    fn add_cells(&mut self, i: usize, cells: &[super::record_cells::Cell]) {
        for (k, cell) in cells.iter().enumerate() {
            if matches!(cell, super::record_cells::Cell::Real(x) if !x.is_finite()) {
                self.non_finite += 1;
                self.first_non_finite.get_or_insert((i, k));
            }
        }
    }

    fn add(&mut self, i: usize, p: &DrivePoint) {
        if p.both_ends_deliver {
            self.both_ends += 1;
            return;
        }
        if self.least.is_none_or(|(e, _)| p.efficiency < e) {
            self.least = Some((p.efficiency, i));
        }
        if self.greatest.is_none_or(|(e, _)| p.efficiency > e) {
            self.greatest = Some((p.efficiency, i));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::record_cells::Cell;
    use super::DriveTally;

    /// A value that is not a finite number is counted where it stands, and shards' tallies fold
    /// to one run's (the first is the earlier shard's).
    #[test]
    fn non_finite_cells_are_counted_and_fold() {
        let mut first = DriveTally::default();
        first.add_cells(0, &[Cell::Int(1), Cell::Real(1.5), Cell::Text("a".into())]);
        assert_eq!((first.non_finite, first.first_non_finite), (0, None));
        first.add_cells(1, &[Cell::Int(2), Cell::Real(f64::NAN), Cell::Real(f64::INFINITY)]);
        assert_eq!((first.non_finite, first.first_non_finite), (2, Some((1, 1))));
        let mut next = DriveTally::default();
        next.add_cells(2, &[Cell::Real(f64::NEG_INFINITY), Cell::Empty]);
        assert_eq!(next.first_non_finite, Some((2, 0)));
        first.absorb(next);
        assert_eq!((first.non_finite, first.first_non_finite), (3, Some((1, 1))));
    }
}
