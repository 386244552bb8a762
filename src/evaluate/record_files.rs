//! Which record files a run writes (`--records parquet,csv,jsonl`), and the sink that writes them
//! as the sweep streams.
//!
//! The default is `csv,jsonl`: the files a report folder has always held, readable in any editor
//! and diffable in review (the committed reports hold them). A big sweep asks for `parquet`: typed
//! and compressed, a tenth of the CSV's size and read by pandas, polars, DuckDB and Dask in a
//! fraction of the time (README, "Record files").

use std::io::Write;

use super::record_cells::Cell;
use super::record_parquet::{ColumnType, ParquetRecords};

/// The record files of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RecordFormats {
    pub csv: bool,
    pub jsonl: bool,
    pub parquet: bool,
}

impl Default for RecordFormats {
    fn default() -> RecordFormats {
        RecordFormats { csv: true, jsonl: true, parquet: false }
    }
}

/// The formats' names, as `--records` takes them.
pub(crate) const FORMAT_NAMES: [&str; 3] = ["csv", "jsonl", "parquet"];

impl std::str::FromStr for RecordFormats {
    type Err = String;

    /// `parquet,csv`: a comma-separated list of `csv`, `jsonl`, `parquet` (at least one).
    fn from_str(text: &str) -> Result<RecordFormats, String> {
        let mut f = RecordFormats { csv: false, jsonl: false, parquet: false };
        for name in text.split(',').map(str::trim).filter(|n| !n.is_empty()) {
            match name {
                "csv" => f.csv = true,
                "jsonl" => f.jsonl = true,
                "parquet" => f.parquet = true,
                other => {
                    return Err(format!("`{other}` is not a record format: give a list of {}", FORMAT_NAMES.join(", ")))
                }
            }
        }
        if f == (RecordFormats { csv: false, jsonl: false, parquet: false }) {
            return Err(format!("give at least one record format: {}", FORMAT_NAMES.join(", ")));
        }
        Ok(f)
    }
}

impl RecordFormats {
    /// The files these formats write, in order.
    pub fn files(&self) -> Vec<&'static str> {
        [(self.csv, RECORDS_CSV), (self.jsonl, RECORDS_JSONL), (self.parquet, RECORDS_PARQUET)]
            .into_iter()
            .filter_map(|(on, f)| on.then_some(f))
            .collect()
    }
}

/// A scene of one pair's text record files.
pub(crate) const RECORDS_CSV: &str = "records.csv";
pub(crate) const RECORDS_JSONL: &str = "records.jsonl";
/// Its Parquet record file.
pub(crate) const RECORDS_PARQUET: &str = "records.parquet";

/// One kind of record as the one record writer ([`RecordFiles`]) writes it: a scene of one pair's
/// summary rows (records.csv, .jsonl, .parquet; `super::pair_records`) and a drive's rows (drive_records.csv, .jsonl,
/// .parquet). Every file of a row comes from its one list of cells, written alike: the shortest
/// text that reads back to the same f64, a value that is not a finite number an empty CSV cell,
/// `null` in JSON Lines, a Parquet null.
pub trait RecordTable {
    /// One row as the evaluation gives it.
    type Row<'a>;
    /// The files' names: CSV, JSON Lines, Parquet.
    const FILES: [&'static str; 3];
    /// The columns' names, in the CSV's order.
    fn names(&self) -> Vec<String>;
    /// A row's cells, in the columns' order.
    fn cells(&self, row: &Self::Row<'_>) -> Vec<Cell>;
    /// A row's JSON Lines line appended to `out` (`cells`: its cells).
    fn jsonl_line(&self, row: &Self::Row<'_>, cells: &[Cell], out: &mut Vec<u8>);
    /// The Parquet file's columns, fixed by the table and the first rows written (a pair's law
    /// parameters: a column each).
    fn parquet_columns(&self, first: &[Self::Row<'_>]) -> Vec<(String, ColumnType)>;
    /// A row's Parquet cells: its `cells` and the cells of the columns [`Self::parquet_columns`]
    /// adds after them.
    fn parquet_cells(&self, row: &Self::Row<'_>, cells: Vec<Cell>, columns: &[(String, ColumnType)]) -> Vec<Cell>;
}

/// The record files being written, one writer for every kind of record (`T`): each format asked
/// for into its `W`.
pub struct RecordFiles<W: Write + Send, T: RecordTable> {
    table: T,
    csv: Option<W>,
    jsonl: Option<W>,
    /// The Parquet file: its writer before the first rows fix its columns, then the file.
    parquet: Option<Parquet<W>>,
    /// One JSON Lines line, its buffer kept from row to row.
    line: Vec<u8>,
}

/// The Parquet file of [`RecordFiles`]: not started until the first rows, then writing.
enum Parquet<W: Write + Send> {
    Waiting(W),
    Writing(Box<ParquetRecords<W>>),
}

impl<W: Write + Send, T: RecordTable> RecordFiles<W, T> {
    /// The files of `formats` for `table`'s rows, each opened by `open(its name)`.
    pub(crate) fn of(
        table: T,
        formats: RecordFormats,
        mut open: impl FnMut(&str) -> std::io::Result<W>,
    ) -> std::io::Result<Self> {
        let [csv_file, jsonl_file, parquet_file] = T::FILES;
        let csv = formats.csv.then(|| open(csv_file)).transpose()?;
        let jsonl = formats.jsonl.then(|| open(jsonl_file)).transpose()?;
        let parquet = formats.parquet.then(|| open(parquet_file).map(Parquet::Waiting)).transpose()?;
        Ok(RecordFiles { table, csv, jsonl, parquet, line: Vec::new() })
    }

    /// Writes the CSV's header line (before any row).
    pub(crate) fn header(&mut self) -> std::io::Result<()> {
        if let Some(c) = &mut self.csv {
            // A name may be the scene's text (a stage's): quoted where it holds a comma.
            let names: Vec<String> = self.table.names().into_iter().map(|n| Cell::Text(n).csv()).collect();
            writeln!(c, "{}", names.join(","))?;
        }
        Ok(())
    }

    /// Writes `rows` (consecutive, in order) into every file.
    pub(crate) fn write(&mut self, rows: &[T::Row<'_>]) -> std::io::Result<()> {
        for row in rows {
            let cells = self.table.cells(row);
            self.write_made(row, cells, rows)?;
        }
        Ok(())
    }

    /// Writes one row whose cells are made (`cells`: the table's cells of `row`), the Parquet
    /// file started by the block of rows it is the first of (`block`).
    pub(crate) fn write_made(
        &mut self,
        row: &T::Row<'_>,
        cells: Vec<Cell>,
        block: &[T::Row<'_>],
    ) -> std::io::Result<()> {
        if let Some(Parquet::Waiting(_)) = &self.parquet {
            let Some(Parquet::Waiting(w)) = self.parquet.take() else { unreachable!("just matched") };
            let columns = self.table.parquet_columns(block);
            self.parquet = Some(Parquet::Writing(Box::new(ParquetRecords::with_columns(w, columns)?)));
        }
        if let Some(c) = &mut self.csv {
            c.write_all(csv_line(&cells).as_bytes())?;
        }
        if let Some(j) = &mut self.jsonl {
            self.line.clear();
            self.table.jsonl_line(row, &cells, &mut self.line);
            j.write_all(&self.line)?;
        }
        if let Some(Parquet::Writing(p)) = &mut self.parquet {
            let cells = self.table.parquet_cells(row, cells, p.columns());
            p.write_cells([cells])?;
        }
        Ok(())
    }

    /// Flushes every file and writes the Parquet footer (its columns those of no rows when none
    /// came); the CSV and JSON Lines writers back (an in-memory run reads its buffers).
    pub fn finish(mut self) -> std::io::Result<(Option<W>, Option<W>)> {
        for w in [&mut self.csv, &mut self.jsonl].into_iter().flatten() {
            w.flush()?;
        }
        match self.parquet {
            Some(Parquet::Waiting(w)) => {
                ParquetRecords::with_columns(w, self.table.parquet_columns(&[]))?.finish()?;
            }
            Some(Parquet::Writing(p)) => {
                p.finish()?;
            }
            None => {}
        }
        Ok((self.csv, self.jsonl))
    }
}

/// A row's CSV line.
fn csv_line(cells: &[Cell]) -> String {
    let mut line = cells.iter().map(Cell::csv).collect::<Vec<_>>().join(",");
    line.push('\n');
    line
}
