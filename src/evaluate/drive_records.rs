//! drive_records.csv: one row per operating point, law and formulation of a drive, with every part
//! of its loss: the ends (torque, speed, power), the loss parts, η and the passes, each stage's
//! driving member, mesh efficiency and mesh loss, each bearing place's loads and losses, each
//! shaft's speed (signed), torques received and passed on, gears' no-load parts and seals. SI but
//! speeds in rpm. The same rows go to drive_records.jsonl (an object a row, keyed by the CSV's
//! column names) and drive_records.parquet (typed columns) as `--records` asks, every file from
//! one list of cells ([`cells`]) by the one record writer
//! ([`super::record_files::RecordFiles`]: the shortest text that reads back to the same f64; a value that
//! is not a finite number is an empty CSV cell, `null` in JSON Lines, a Parquet null).

use crate::losses::parts::COLUMNS;
use std::io::Write;

use super::drive_setup::DriveRow;
use super::drive_thermal::DriveBalanceRow;
use super::record_cells::Cell;
use super::record_files::{RecordFiles, RecordFormats, RecordTable};
use super::record_parquet::ColumnType;
use crate::drive::PowerFlow;
use crate::model::SceneDrive;

/// The file's name in the report folder.
pub(crate) const FILE: &str = "drive_records.csv";
/// The same rows as JSON Lines (`--records jsonl`; with the CSV by default).
pub(crate) const JSONL_FILE: &str = "drive_records.jsonl";
/// The same rows as typed Parquet columns (`--records parquet`).
pub(crate) const PARQUET_FILE: &str = "drive_records.parquet";

const RPM: f64 = 30.0 / std::f64::consts::PI;

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
    ]
    .iter()
    .map(|c| c.to_string())
    .chain(COLUMNS.iter().map(|c| format!("{}_W", c.key)))
    .chain(["total_W", "efficiency", "both_ends_deliver", "passes"].map(String::from))
    .collect();
    if drive.oil_at_balance {
        cols.extend(BALANCE_COLUMNS.iter().map(|c| c.to_string()));
    }
    if drive.balance_rows {
        cols.extend(ROW_BALANCE_COLUMNS.iter().map(|c| c.to_string()));
    }
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
const TEXTS: &[&str] = &["formulation", "flow", "both_ends_deliver", "thermal_status"];

/// At `oil_temperature = equilibrium`: the row's balance θ* (K, as a pair's records.csv; empty
/// without one) and the sump's status (`ok`, `above_limit`, `no_equilibrium`), after `passes`.
const BALANCE_COLUMNS: [&str; 2] = ["oil_temperature_K", "thermal_status"];

/// With `analyses { thermal_balance }` at a given oil temperature: the row's balance θ* (K, empty
/// without one), the sump's status, P_V at θ* and what the housing gives off there by path and in
/// all (W; at the search's limit, 200 °C, without a balance), the wall's h_c and, in drive, the
/// speed's two rating torques at the given end (N·m; empty in coast or where none is found).
const ROW_BALANCE_COLUMNS: [&str; 11] = [
    "oil_temperature_K",
    "thermal_status",
    "loss_at_balance_W",
    "dissipation_convection_W",
    "dissipation_radiation_W",
    "dissipation_foundation_W",
    "dissipation_cooler_W",
    "dissipation_W",
    "heat_transfer_coefficient_W_m2_K",
    "thermal_rating_N_m",
    "thermal_rating_95_N_m",
];

/// One row's JSON Lines line into `out`: an object keyed by `keys` (the columns' names as JSON
/// strings, each with its colon), in their order; an empty cell and a value that is not a finite
/// number are `null`.
pub(crate) fn jsonl_line(keys: &[String], cells: &[Cell], out: &mut Vec<u8>) {
    out.push(b'{');
    for (i, (key, cell)) in keys.iter().zip(cells).enumerate() {
        if i > 0 {
            out.push(b',');
        }
        out.extend_from_slice(key.as_bytes());
        match cell {
            Cell::Int(n) => out.extend_from_slice(n.to_string().as_bytes()),
            Cell::Real(x) if x.is_finite() => serde_json::to_writer(&mut *out, x).expect("a finite f64 serialises"),
            Cell::Text(t) => serde_json::to_writer(&mut *out, t).expect("a string serialises"),
            Cell::Real(_) | Cell::Empty => out.extend_from_slice(b"null"),
        }
    }
    out.extend_from_slice(b"}\n");
}

/// One row's cells in [`columns`]' order: the record's row `i` (0-based) and its flow, its
/// `outside` (by stage, the law's contacts outside its validity, of the contacts
/// `super::setup::curve_positions` gives) and its `heat` (the row's balance at a given oil
/// temperature, when the drive's rows carry theirs).
pub(crate) fn cells(record: &DriveRecord<'_>) -> Vec<Cell> {
    let DriveRecord { i, flow, row: r, outside, heat } = *record;
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
    ]));
    cells.extend(reals(&l.parts));
    cells.extend(reals(&[l.total(), d.efficiency]));
    cells.push(Cell::Text(d.both_ends_deliver.to_string()));
    cells.push(int(d.iterations));
    if let Some(b) = &r.balance {
        cells.push(b.temperature.map_or(Cell::Empty, Cell::Real));
        cells.push(Cell::Text(b.status.name().to_string()));
    }
    if let Some(h) = heat {
        cells.push(h.balance.temperature.map_or(Cell::Empty, Cell::Real));
        cells.push(Cell::Text(h.balance.status.name().to_string()));
        let d = &h.dissipation;
        let paths = [h.loss, d.convection, d.radiation, d.foundation, d.cooler, d.total, h.heat_transfer_coefficient];
        cells.extend(reals(&paths));
        cells.extend([h.rating, h.rating_95].map(|r| r.map_or(Cell::Empty, Cell::Real)));
    }
    for (k, s) in d.stages.iter().enumerate() {
        cells.push(Cell::Text(s.member_name(s.driving).to_string()));
        cells.extend(reals(&[s.driving_torque, s.mesh_efficiency, s.mesh_loss, s.no_load]));
        cells.push(int(outside.get(k).copied().unwrap_or(0)));
        if let Some(kind) = &s.kind {
            cells.extend(reals(&kind.record_values()));
        }
    }
    for s in &d.shafts {
        for b in s.bearings.iter().filter(|b| b.is_shaft_place()) {
            cells.extend(reals(&[b.radial_load, b.axial_load, b.no_load, b.load]));
        }
        cells.extend(reals(&[s.speed * RPM, s.received_torque, s.passed_torque, s.gear_no_load, s.seals]));
    }
    cells
}

/// Where a drive's rows go as they are computed.
pub(crate) trait DriveRecordSink {
    /// The header, written once before the rows (a CSV's first line; every shard's: the merge keeps
    /// the first's).
    fn header(&mut self, drive: &SceneDrive) -> std::io::Result<()>;
    /// Row `i` and its cells ([`cells`] of it).
    fn row(&mut self, record: DriveRecord<'_>, cells: Vec<Cell>) -> std::io::Result<()>;
}

/// One of a drive's rows as the record files take it: its index, flow, row and, by stage, the
/// law's contacts outside its validity.
pub(crate) struct DriveRecord<'a> {
    pub i: usize,
    pub flow: PowerFlow,
    pub row: &'a DriveRow,
    pub outside: &'a [usize],
    /// The row's balance, when the drive's rows carry theirs (`SceneDrive::balance_rows`).
    pub heat: Option<&'a DriveBalanceRow>,
}

/// A drive's rows as the one record writer writes them: the columns of [`columns`], each row's
/// JSON Lines line an object keyed by them.
pub(crate) struct DriveRecords {
    columns: Vec<(String, ColumnType)>,
    /// The names as JSON Lines keys (`"name":`).
    keys: Vec<String>,
}

impl RecordTable for DriveRecords {
    type Row<'a> = DriveRecord<'a>;
    const FILES: [&'static str; 3] = [FILE, JSONL_FILE, PARQUET_FILE];

    fn names(&self) -> Vec<String> {
        self.columns.iter().map(|(n, _)| n.clone()).collect()
    }

    fn cells(&self, r: &DriveRecord<'_>) -> Vec<Cell> {
        cells(r)
    }

    fn jsonl_line(&self, _: &DriveRecord<'_>, cells: &[Cell], out: &mut Vec<u8>) {
        jsonl_line(&self.keys, cells, out);
    }

    fn parquet_columns(&self, _: &[DriveRecord<'_>]) -> Vec<(String, ColumnType)> {
        self.columns.clone()
    }

    fn parquet_cells(&self, _: &DriveRecord<'_>, cells: Vec<Cell>, _: &[(String, ColumnType)]) -> Vec<Cell> {
        cells
    }
}

/// The record files of a drive's rows as `--records` asks (drive_records.csv, .jsonl, .parquet:
/// any of them), each into its `W`.
pub(crate) type DriveRecordFiles<W> = RecordFiles<W, DriveRecords>;

/// A drive's record files.
pub(crate) fn drive_record_files<W: Write + Send>(
    drive: &SceneDrive,
    formats: RecordFormats,
    open: impl FnMut(&str) -> std::io::Result<W>,
) -> std::io::Result<DriveRecordFiles<W>> {
    let columns = columns(drive);
    let keys =
        columns.iter().map(|(n, _)| format!("{}:", serde_json::to_string(n).expect("a string serialises"))).collect();
    RecordFiles::of(DriveRecords { columns, keys }, formats, open)
}

/// drive_records.csv only, into `out`.
pub(crate) fn drive_records_csv<W: Write + Send>(drive: &SceneDrive, out: W) -> DriveRecordFiles<W> {
    let mut out = Some(out);
    let formats = RecordFormats { csv: true, jsonl: false, parquet: false };
    drive_record_files(drive, formats, |_| Ok(out.take().expect("one file")))
        .expect("opening a given writer cannot fail")
}

impl<W: Write + Send> DriveRecordSink for DriveRecordFiles<W> {
    fn header(&mut self, _: &SceneDrive) -> std::io::Result<()> {
        RecordFiles::header(self)
    }

    fn row(&mut self, record: DriveRecord<'_>, cells: Vec<Cell>) -> std::io::Result<()> {
        let block = std::slice::from_ref(&record);
        self.write_made(&record, cells, block)
    }
}
