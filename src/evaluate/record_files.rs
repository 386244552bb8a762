//! Which record files a run writes (`--records parquet,csv,jsonl`), and the sink that writes them
//! as the sweep streams.
//!
//! The default is `csv,jsonl`: the files a report folder has always held, readable in any editor
//! and diffable in review (the committed reports hold them). A big sweep asks for `parquet`: typed
//! and compressed, a tenth of the CSV's size and read by pandas, polars, DuckDB and Dask in a
//! fraction of the time (README, "Record files").

use std::io::Write;

use super::record_cells::csv_line;
use super::record_parquet::ParquetRecords;
use super::records::{csv_header, jsonl_line, ExtraColumns, RecordSink, SummaryRow};

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

/// The text record files.
pub(crate) const RECORDS_CSV: &str = "records.csv";
pub(crate) const RECORDS_JSONL: &str = "records.jsonl";
/// The Parquet record file.
pub(crate) const RECORDS_PARQUET: &str = "records.parquet";

/// The record files being written.
pub struct RecordFiles<W: Write + Send> {
    csv: Option<W>,
    jsonl: Option<W>,
    parquet: Option<ParquetRecords<W>>,
    widths: [usize; 3],
}

impl<W: Write + Send> RecordFiles<W> {
    /// The files `open` gives for each of the formats asked for (the CSV's header written).
    pub fn new(
        formats: RecordFormats,
        extra: &ExtraColumns,
        mut open: impl FnMut(&str) -> std::io::Result<W>,
    ) -> std::io::Result<Self> {
        let mut csv = formats.csv.then(|| open(RECORDS_CSV)).transpose()?;
        if let Some(c) = &mut csv {
            c.write_all(csv_header(extra).as_bytes())?;
        }
        let jsonl = formats.jsonl.then(|| open(RECORDS_JSONL)).transpose()?;
        let parquet =
            formats.parquet.then(|| open(RECORDS_PARQUET).map(|w| ParquetRecords::new(w, extra))).transpose()?;
        Ok(RecordFiles { csv, jsonl, parquet, widths: extra.widths() })
    }

    /// Flushes every file and writes the Parquet footer; the CSV and JSON Lines writers back (an
    /// in-memory run reads its buffers).
    pub fn finish(mut self) -> std::io::Result<(Option<W>, Option<W>)> {
        for w in [&mut self.csv, &mut self.jsonl].into_iter().flatten() {
            w.flush()?;
        }
        if let Some(p) = self.parquet {
            p.finish()?;
        }
        Ok((self.csv, self.jsonl))
    }
}

impl<W: Write + Send> RecordSink for RecordFiles<W> {
    fn write_rows(&mut self, rows: &[SummaryRow]) -> std::io::Result<()> {
        if let Some(c) = &mut self.csv {
            for row in rows {
                c.write_all(csv_line(row, self.widths).as_bytes())?;
            }
        }
        if let Some(j) = &mut self.jsonl {
            for row in rows {
                j.write_all(jsonl_line(row).as_bytes())?;
            }
        }
        if let Some(p) = &mut self.parquet {
            p.write_rows(rows)?;
        }
        Ok(())
    }
}
