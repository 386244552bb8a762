//! A summary record's cells, typed, in the order of records.csv's columns: what records.csv
//! writes as text and records.parquet as typed columns, from one function, so that both files
//! hold the same values (a float's shortest text reads back to the same bits).

use super::record_files::{RecordTable, RECORDS_CSV, RECORDS_JSONL, RECORDS_PARQUET};
use super::record_parquet::ColumnType;
use super::records::{ExtraColumns, RowKind, SummaryRow, CSV_COLUMNS};

/// One cell of a record.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    Int(i64),
    /// A float; a non-finite one is written as a missing value (an empty CSV cell, a Parquet null).
    Real(f64),
    Text(String),
    /// The row has no value here.
    Empty,
}

impl Cell {
    fn of_count(n: Option<usize>) -> Cell {
        n.map_or(Cell::Empty, |n| Cell::Int(n as i64))
    }

    fn of_real(x: Option<f64>) -> Cell {
        x.map_or(Cell::Empty, Cell::Real)
    }

    /// The cell as records.csv writes it.
    pub fn csv(&self) -> String {
        match self {
            Cell::Int(i) => i.to_string(),
            Cell::Real(x) => number(Some(*x)),
            Cell::Text(t) => text(t),
            Cell::Empty => String::new(),
        }
    }
}

/// A number as the record files write it: the shortest text that reads back to the same f64
/// (serde_json's), integers without a fraction; empty for a missing or non-finite value.
fn number(x: Option<f64>) -> String {
    match x {
        Some(x) if x.is_finite() => {
            if x.fract() == 0.0 && x.abs() < 1e15 {
                format!("{}", x as i64)
            } else {
                serde_json::to_string(&x).expect("a finite f64 serialises")
            }
        }
        _ => String::new(),
    }
}

/// A text cell: quoted when it holds a comma, a quote or a line end (RFC 4180).
fn text(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// The `parameters` cell: `name=value unit; …`.
pub(crate) fn parameters_text(row: &SummaryRow) -> String {
    let parameters: Vec<String> = row
        .parameters
        .iter()
        .map(|p| {
            let unit = if p.unit == "1" { "" } else { p.unit.as_str() };
            format!("{}={} {unit}", p.name, number(Some(p.value))).trim_end().to_string()
        })
        .collect();
    parameters.join("; ")
}

/// A row's cells, with the cells of each group of [`super::records::ExtraColumns`] after the
/// fixed ones (`widths` of them; empty where the row has not that group: friction and dynamics
/// rows have no budget).
pub(crate) fn cells(row: &SummaryRow, widths: [usize; 3]) -> Vec<Cell> {
    let kind = match row.kind {
        RowKind::Efficiency => "efficiency",
        RowKind::Friction => "friction",
        RowKind::Dynamics => "dynamics",
        RowKind::TransmissionError => "transmission_error",
    };
    let mut cells = vec![
        Cell::Int(row.point as i64),
        Cell::Int(row.torque_index as i64),
        Cell::Int(row.speed_index as i64),
        Cell::Real(row.pinion_torque),
        Cell::Real(row.pinion_speed),
        Cell::Text(kind.to_string()),
        Cell::of_count(row.law_index),
        Cell::Text(row.law.clone()),
        Cell::Text(row.label.clone()),
        Cell::Text(row.formulation.clone()),
        Cell::of_real(row.mean_abs_mu),
        Cell::of_real(row.mean_efficiency),
        Cell::of_real(row.mean_efficiency_error),
        Cell::of_real(row.min_efficiency),
        Cell::of_real(row.max_efficiency),
        Cell::of_real(row.power_loss),
        Cell::of_count(row.validity_samples),
        Cell::of_count(row.validity_outside),
        Cell::of_real(row.spectral_radius),
        Cell::of_real(row.dte_peak_to_peak),
        Cell::of_real(row.dte_mean),
        Cell::of_real(row.dynamic_factor),
        Cell::Text(parameters_text(row)),
    ];
    let mut group = |values: Vec<Cell>, width: usize| {
        debug_assert!(values.len() <= width, "a row's cells match the scene's columns");
        let start = cells.len();
        cells.extend(values);
        cells.resize(start + width, Cell::Empty);
    };
    group(
        row.budget.as_ref().map_or_else(Vec::new, |b| crate::losses::columns::values(b).map(Cell::of_real).collect()),
        widths[0],
    );
    let thermal = row.thermal.as_ref().map_or_else(Vec::new, |t| {
        let mut v = vec![Cell::of_real(t.oil_temperature), Cell::Text(t.thermal_status.name().to_string())];
        v.extend(t.numbers().map(Cell::of_real));
        v
    });
    group(thermal, widths[1]);
    group(row.ste.as_ref().map_or_else(Vec::new, |s| s.numbers().map(Cell::Real).to_vec()), widths[2]);
    cells
}

/// A scene of one pair's summary rows as the record writer writes them: records.csv's columns
/// (`super::records::CSV_COLUMNS`, then the scene's [`ExtraColumns`]), each row's JSON Lines
/// line its serde form (nested, as `Report.records` reads it back), and in records.parquet one
/// DOUBLE column per law parameter the first rows report, `param_<name>_<unit>` (the
/// `parameters` text column keeps them all).
pub struct PairRecords {
    extra: ExtraColumns,
    /// The (name, unit) of records.parquet's parameter columns, fixed by its first rows.
    parameters: std::sync::OnceLock<Vec<(String, String)>>,
}

impl PairRecords {
    pub(crate) fn new(extra: &ExtraColumns) -> PairRecords {
        PairRecords { extra: extra.clone(), parameters: std::sync::OnceLock::new() }
    }
}

impl RecordTable for PairRecords {
    type Row<'a> = SummaryRow;
    const FILES: [&'static str; 3] = [RECORDS_CSV, RECORDS_JSONL, RECORDS_PARQUET];

    fn names(&self) -> Vec<String> {
        CSV_COLUMNS.iter().map(|c| c.to_string()).chain(self.extra.names().cloned()).collect()
    }

    fn cells(&self, row: &SummaryRow) -> Vec<Cell> {
        cells(row, self.extra.widths())
    }

    fn jsonl_line(&self, row: &SummaryRow, _: &[Cell], out: &mut Vec<u8>) {
        serde_json::to_writer(&mut *out, row).expect("a row serialises");
        out.push(b'\n');
    }

    fn parquet_columns(&self, first: &[SummaryRow]) -> Vec<(String, ColumnType)> {
        let parameters = self.parameters.get_or_init(|| {
            let mut seen: Vec<(String, String)> = Vec::new();
            for p in first.iter().flat_map(|row| &row.parameters) {
                if !seen.iter().any(|(n, u)| *n == p.name && *u == p.unit) {
                    seen.push((p.name.clone(), p.unit.clone()));
                }
            }
            seen
        });
        let mut columns: Vec<(String, ColumnType)> =
            self.names().into_iter().map(|n| (n.clone(), type_of(&n))).collect();
        columns.extend(parameters.iter().map(|(n, u)| (parameter_column(n, u), ColumnType::Real)));
        columns
    }

    fn parquet_cells(&self, row: &SummaryRow, mut cells: Vec<Cell>, _: &[(String, ColumnType)]) -> Vec<Cell> {
        let parameters = self.parameters.get().map_or(&[][..], Vec::as_slice);
        cells.extend(parameters.iter().map(|(n, u)| {
            row.parameters.iter().find(|p| p.name == *n && p.unit == *u).map_or(Cell::Empty, |p| Cell::Real(p.value))
        }));
        cells
    }
}

/// records.csv's integer and text columns; every other one is a number.
const INTS: &[&str] = &["point", "torque_index", "speed_index", "law_index", "validity_samples", "validity_outside"];
const TEXTS: &[&str] = &["kind", "law", "label", "formulation", "parameters", "thermal_status"];

fn type_of(name: &str) -> ColumnType {
    if INTS.contains(&name) {
        ColumnType::Int
    } else if TEXTS.contains(&name) {
        ColumnType::Text
    } else {
        ColumnType::Real
    }
}

/// A parameter's column name: `param_<name>_<unit>` (`_` for what a name cannot hold).
fn parameter_column(name: &str, unit: &str) -> String {
    let clean = |s: &str| s.chars().map(|c| if c.is_ascii_alphanumeric() { c } else { '_' }).collect::<String>();
    if unit == "1" || unit.is_empty() {
        format!("param_{}", clean(name))
    } else {
        format!("param_{}_{}", clean(name), clean(unit))
    }
}
