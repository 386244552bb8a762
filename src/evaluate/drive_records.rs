//! drive_records.csv: one row per operating point, law and formulation of a drive, with every part
//! of its loss: the ends (torque, speed, power), the loss parts, η and the passes, each stage's
//! driving member, mesh efficiency and mesh loss, each bearing place's loads and losses, each
//! shaft's speed (signed), torques received and passed on, gears' no-load parts and seals. SI but speeds in rpm; numbers in Rust's shortest round-trip form.

use std::io::Write;

use super::drive_setup::DriveRow;
use super::record_cells::Cell;
use super::record_parquet::ColumnType;
use crate::drive::PowerFlow;
use crate::model::SceneDrive;

/// The file's name in the report folder.
pub(crate) const FILE: &str = "drive_records.csv";
/// The same rows as typed Parquet columns (`--records parquet`).
pub(crate) const PARQUET_FILE: &str = "drive_records.parquet";

const RPM: f64 = 30.0 / std::f64::consts::PI;

/// The header line: [`columns`]' names.
pub(crate) fn header(out: &mut dyn Write, drive: &SceneDrive) -> std::io::Result<()> {
    let cols: Vec<String> = columns(drive).into_iter().map(|(name, _)| name).collect();
    writeln!(out, "{}", cols.join(","))
}

/// The columns, named and typed (drive_records.parquet's schema): the fixed columns, then per stage
/// and per bearing place and shaft.
pub(crate) fn columns(drive: &SceneDrive) -> Vec<(String, ColumnType)> {
    let mut cols: Vec<String> = [
        "row",
        "torque_index",
        "speed_index",
        "law_index",
        "formulation",
        "flow",
        "input_torque_N_m",
        "input_speed_rpm",
        "input_power_W",
        "output_torque_N_m",
        "output_speed_rpm",
        "output_power_W",
        "meshes_W",
        "gear_no_load_W",
        "bearings_no_load_W",
        "bearings_load_W",
        "seals_W",
        "total_W",
        "efficiency",
        "both_ends_deliver",
        "passes",
    ]
    .iter()
    .map(|c| c.to_string())
    .collect();
    for s in &drive.layout.stages {
        for c in ["driving", "driving_torque_N_m", "mesh_efficiency", "mesh_loss_W", "no_load_W", "validity_outside"] {
            cols.push(format!("stage_{}_{c}", s.name));
        }
        cols.extend(s.model().record_columns().iter().map(|c| format!("stage_{}_{c}", s.name)));
    }
    for s in &drive.layout.shafts {
        for i in 0..s.bearings.len() {
            for c in ["radial_N", "axial_N", "no_load_W", "load_W"] {
                cols.push(format!("bearing_{}_{}_{c}", s.name, i + 1));
            }
        }
        for c in ["speed_rpm", "received_torque_N_m", "passed_torque_N_m", "gear_no_load_W", "seals_W"] {
            cols.push(format!("shaft_{}_{c}", s.name));
        }
    }
    cols.into_iter()
        .map(|c| {
            let t = if INTS.contains(&c.as_str()) || c.ends_with("_validity_outside") {
                ColumnType::Int
            } else if TEXTS.contains(&c.as_str()) || c.ends_with("_driving") {
                ColumnType::Text
            } else {
                ColumnType::Real
            };
            (c, t)
        })
        .collect()
}

/// The whole-number and the text columns; every other column is a number.
const INTS: &[&str] = &["row", "torque_index", "speed_index", "law_index", "passes"];
const TEXTS: &[&str] = &["formulation", "flow", "both_ends_deliver"];

/// One row, written as CSV (numbers in Rust's shortest round-trip form, as every file of the
/// report writes them).
pub(crate) fn row(
    out: &mut dyn Write,
    i: usize,
    flow: PowerFlow,
    r: &DriveRow,
    outside: &[usize],
) -> std::io::Result<()> {
    let text: Vec<String> = cells(i, flow, r, outside)
        .into_iter()
        .map(|c| match c {
            Cell::Int(n) => n.to_string(),
            Cell::Real(x) => x.to_string(),
            Cell::Text(t) => t,
            Cell::Empty => String::new(),
        })
        .collect();
    writeln!(out, "{}", text.join(","))
}

/// One row's cells in [`columns`]' order; `outside`: by stage, the law's contacts outside its
/// validity (of [`super::drive_setup::VALIDITY_SAMPLES`]).
pub(crate) fn cells(i: usize, flow: PowerFlow, r: &DriveRow, outside: &[usize]) -> Vec<Cell> {
    let d = &r.point;
    let l = &d.losses;
    let int = |n: usize| Cell::Int(n as i64);
    let mut cells: Vec<Cell> = vec![
        int(i + 1),
        int(r.torque_index),
        int(r.speed_index),
        int(r.law_index),
        Cell::Text(r.formulation.name().to_string()),
        Cell::Text(flow.name().to_string()),
    ];
    let reals = |v: &[f64]| v.iter().map(|x| Cell::Real(*x)).collect::<Vec<_>>();
    cells.extend(reals(&[
        d.input_torque,
        d.input_speed * RPM,
        d.input_power,
        d.output_torque,
        d.output_speed * RPM,
        d.output_power,
        l.meshes,
        l.gear_no_load,
        l.bearings_no_load,
        l.bearings_load,
        l.seals,
        l.total(),
        d.efficiency,
    ]));
    cells.push(Cell::Text(d.both_ends_deliver.to_string()));
    cells.push(int(d.iterations));
    for (k, s) in d.stages.iter().enumerate() {
        cells.push(Cell::Text(s.member_name(s.driving).to_string()));
        cells.extend(reals(&[s.driving_torque, s.mesh_efficiency, s.mesh_loss, s.no_load]));
        cells.push(int(outside.get(k).copied().unwrap_or(0)));
        if let Some(kind) = &s.kind {
            cells.extend(reals(&kind.record_values()));
        }
    }
    for s in &d.shafts {
        for b in s.bearings.iter().filter(|b| !b.on_planets) {
            cells.extend(reals(&[b.radial_load, b.axial_load, b.no_load, b.load]));
        }
        cells.extend(reals(&[s.speed * RPM, s.received_torque, s.passed_torque, s.gear_no_load, s.seals]));
    }
    cells
}

/// Where a drive's rows go as they are computed.
pub(crate) trait DriveRecordSink {
    /// The header, written once before the rows (a CSV's first line; the first shard's only).
    fn header(&mut self, drive: &SceneDrive) -> std::io::Result<()>;
    fn row(&mut self, i: usize, flow: PowerFlow, r: &DriveRow, outside: &[usize]) -> std::io::Result<()>;
}

/// drive_records.csv into `C`, drive_records.parquet (typed columns, row groups as the rows come,
/// [`super::record_parquet`]) into `P`: either or both.
pub(crate) struct DriveRecordFiles<C: Write, P: Write + Send> {
    csv: Option<C>,
    parquet: Option<super::record_parquet::ParquetRecords<P>>,
}

impl<C: Write> DriveRecordFiles<C, Vec<u8>> {
    /// drive_records.csv only.
    pub(crate) fn csv(out: C) -> Self {
        DriveRecordFiles { csv: Some(out), parquet: None }
    }
}

impl<C: Write, P: Write + Send> DriveRecordFiles<C, P> {
    /// The files of `drive`'s rows: the CSV into `csv`, the Parquet file (its schema from
    /// [`columns`]) into `parquet`.
    pub(crate) fn new(drive: &SceneDrive, csv: Option<C>, parquet: Option<P>) -> std::io::Result<Self> {
        let parquet =
            parquet.map(|out| super::record_parquet::ParquetRecords::with_columns(out, columns(drive))).transpose()?;
        Ok(DriveRecordFiles { csv, parquet })
    }

    /// Writes what is held and the Parquet footer; the two writers back, flushed.
    pub(crate) fn finish(self) -> std::io::Result<(Option<C>, Option<P>)> {
        let mut csv = self.csv;
        if let Some(c) = &mut csv {
            c.flush()?;
        }
        let parquet = self.parquet.map(|p| p.finish()).transpose()?;
        Ok((csv, parquet))
    }
}

impl<C: Write, P: Write + Send> DriveRecordSink for DriveRecordFiles<C, P> {
    fn header(&mut self, drive: &SceneDrive) -> std::io::Result<()> {
        match &mut self.csv {
            Some(c) => header(c, drive),
            None => Ok(()),
        }
    }

    fn row(&mut self, i: usize, flow: PowerFlow, r: &DriveRow, outside: &[usize]) -> std::io::Result<()> {
        if let Some(c) = &mut self.csv {
            row(c, i, flow, r, outside)?;
        }
        if let Some(p) = &mut self.parquet {
            p.write_cells([cells(i, flow, r, outside)])?;
        }
        Ok(())
    }
}
