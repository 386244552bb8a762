//! A scene of one pair's summary rows as the one record writer
//! ([`super::record_files::RecordFiles`]) writes them: their table ([`PairRecords`]), the
//! writer's constructor for them, and the writer as the sweep's [`RecordSink`].

use std::io::Write;

use super::record_cells::{cells, Cell};
use super::record_files::{RecordFiles, RecordFormats, RecordTable, RECORDS_CSV, RECORDS_JSONL, RECORDS_PARQUET};
use super::record_parquet::ColumnType;
use super::records::{ExtraColumns, RecordSink, SummaryRow, CSV_COLUMNS};

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
        cells(row, self.extra.width())
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
const TEXTS: &[&str] = &["kind", "law", "label", "formulation", "parameters"];

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

impl<W: Write + Send> RecordFiles<W, PairRecords> {
    /// A scene of one pair's record files (records.csv, .jsonl, .parquet as `formats` asks), each
    /// opened by `open(its name)`; the CSV's header written.
    pub fn new(
        formats: RecordFormats,
        extra: &ExtraColumns,
        open: impl FnMut(&str) -> std::io::Result<W>,
    ) -> std::io::Result<Self> {
        let mut files = RecordFiles::of(PairRecords::new(extra), formats, open)?;
        files.header()?;
        Ok(files)
    }
}

impl<W: Write + Send> RecordSink for RecordFiles<W, PairRecords> {
    fn write_rows(&mut self, rows: &[SummaryRow]) -> std::io::Result<()> {
        self.write(rows)
    }
}
