//! records.parquet: the summary records as typed Parquet columns (Apache Parquet through the
//! pure-Rust `parquet` crate, Snappy-compressed, text columns dictionary-encoded), written in row
//! groups of [`ROW_GROUP`] rows as the sweep streams, so memory stays bounded. The columns are
//! records.csv's, in its order and with its names (integers INT64, numbers DOUBLE, text UTF-8; a
//! missing or non-finite value, and an empty text, is null, as an empty CSV cell reads), then one DOUBLE column per law parameter the run's first
//! point reports, `param_<name>_<unit>` (the `parameters` text column keeps them all).

use std::io::Write;
use std::sync::Arc;

use parquet::basic::{Compression, LogicalType, Repetition, Type as PhysicalType};
use parquet::column::writer::ColumnWriter;
use parquet::data_type::ByteArray;
use parquet::file::properties::WriterProperties;
use parquet::file::writer::SerializedFileWriter;
use parquet::schema::types::Type;

use super::record_cells::{cells, Cell};
use super::records::{csv_header, ExtraColumns, RecordSink, SummaryRow};

/// Rows held before they are written as a row group.
pub(crate) const ROW_GROUP: usize = 8_192;

/// A column's Parquet type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ColumnType {
    Int,
    Real,
    Text,
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

/// Writes records.parquet: the columns fixed by the scene and the first rows' parameters.
pub(crate) struct ParquetRecords<W: Write + Send> {
    out: Option<W>,
    writer: Option<SerializedFileWriter<W>>,
    extra: ExtraColumns,
    columns: Vec<(String, ColumnType)>,
    /// (name, unit) of the parameter columns.
    parameters: Vec<(String, String)>,
    rows: Vec<Vec<Cell>>,
}

impl<W: Write + Send> ParquetRecords<W> {
    /// A writer for a run with the scene's `extra` columns; the file starts with the first rows.
    pub(crate) fn new(out: W, extra: &ExtraColumns) -> ParquetRecords<W> {
        ParquetRecords {
            out: Some(out),
            writer: None,
            extra: extra.clone(),
            columns: Vec::new(),
            parameters: Vec::new(),
            rows: Vec::new(),
        }
    }

    /// A writer of the given columns (a merge, from its shards' schema).
    pub(crate) fn with_columns(out: W, columns: Vec<(String, ColumnType)>) -> std::io::Result<ParquetRecords<W>> {
        let mut w = ParquetRecords {
            out: Some(out),
            writer: None,
            extra: ExtraColumns::default(),
            columns,
            parameters: Vec::new(),
            rows: Vec::new(),
        };
        w.open()?;
        Ok(w)
    }

    fn open(&mut self) -> std::io::Result<()> {
        let fields = self
            .columns
            .iter()
            .map(|(name, t)| {
                let builder = match t {
                    ColumnType::Int => Type::primitive_type_builder(name, PhysicalType::INT64),
                    ColumnType::Real => Type::primitive_type_builder(name, PhysicalType::DOUBLE),
                    ColumnType::Text => Type::primitive_type_builder(name, PhysicalType::BYTE_ARRAY)
                        .with_logical_type(Some(LogicalType::String)),
                };
                builder.with_repetition(Repetition::OPTIONAL).build().map(Arc::new)
            })
            .collect::<Result<Vec<_>, _>>()
            .map_err(io)?;
        let schema = Type::group_type_builder("records").with_fields(fields).build().map_err(io)?;
        let props = WriterProperties::builder().set_compression(Compression::SNAPPY).build();
        let out = self.out.take().expect("opened once");
        self.writer = Some(SerializedFileWriter::new(out, Arc::new(schema), Arc::new(props)).map_err(io)?);
        Ok(())
    }

    /// Takes rows given as cells in the writer's column order.
    pub(crate) fn write_cells(&mut self, rows: impl IntoIterator<Item = Vec<Cell>>) -> std::io::Result<()> {
        for row in rows {
            self.rows.push(row);
            if self.rows.len() >= ROW_GROUP {
                self.flush_group()?;
            }
        }
        Ok(())
    }

    /// The columns, in order.
    pub(crate) fn columns(&self) -> &[(String, ColumnType)] {
        &self.columns
    }

    fn flush_group(&mut self) -> std::io::Result<()> {
        if self.rows.is_empty() {
            return Ok(());
        }
        let writer = self.writer.as_mut().expect("the file is open once rows come");
        let mut group = writer.next_row_group().map_err(io)?;
        let mut j = 0;
        while let Some(mut column) = group.next_column().map_err(io)? {
            let defs: Vec<i16> = self.rows.iter().map(|r| i16::from(present(&r[j]))).collect();
            match column.untyped() {
                ColumnWriter::Int64ColumnWriter(w) => {
                    let v: Vec<i64> =
                        self.rows.iter().filter_map(|r| if let Cell::Int(i) = r[j] { Some(i) } else { None }).collect();
                    w.write_batch(&v, Some(&defs), None).map_err(io)?;
                }
                ColumnWriter::DoubleColumnWriter(w) => {
                    let v: Vec<f64> = self
                        .rows
                        .iter()
                        .filter_map(|r| match r[j] {
                            Cell::Real(x) if x.is_finite() => Some(x),
                            _ => None,
                        })
                        .collect();
                    w.write_batch(&v, Some(&defs), None).map_err(io)?;
                }
                ColumnWriter::ByteArrayColumnWriter(w) => {
                    let v: Vec<ByteArray> = self
                        .rows
                        .iter()
                        .filter_map(|r| match &r[j] {
                            Cell::Text(t) if !t.is_empty() => Some(ByteArray::from(t.as_str())),
                            _ => None,
                        })
                        .collect();
                    w.write_batch(&v, Some(&defs), None).map_err(io)?;
                }
                _ => unreachable!("records.parquet has INT64, DOUBLE and UTF-8 columns only"),
            }
            column.close().map_err(io)?;
            j += 1;
        }
        group.close().map_err(io)?;
        self.rows.clear();
        Ok(())
    }

    /// Writes what is held and the footer; the inner writer flushed.
    pub(crate) fn finish(mut self) -> std::io::Result<W> {
        if self.writer.is_none() {
            self.start(&[])?;
        }
        self.flush_group()?;
        let mut out = self.writer.take().expect("open").into_inner().map_err(io)?;
        out.flush()?;
        Ok(out)
    }

    /// Fixes the columns from the scene's and the first rows' parameters, and opens the file.
    fn start(&mut self, first: &[SummaryRow]) -> std::io::Result<()> {
        let header = csv_header(&self.extra);
        self.columns = header.trim_end().split(',').map(|n| (n.to_string(), type_of(n))).collect();
        for row in first {
            for p in &row.parameters {
                if !self.parameters.iter().any(|(n, u)| *n == p.name && *u == p.unit) {
                    self.parameters.push((p.name.clone(), p.unit.clone()));
                }
            }
        }
        self.columns.extend(self.parameters.iter().map(|(n, u)| (parameter_column(n, u), ColumnType::Real)));
        self.open()
    }
}

fn present(c: &Cell) -> bool {
    match c {
        Cell::Real(x) => x.is_finite(),
        Cell::Text(t) => !t.is_empty(),
        Cell::Empty => false,
        _ => true,
    }
}

fn io(e: impl std::fmt::Display) -> std::io::Error {
    std::io::Error::other(format!("records.parquet: {e}"))
}

impl<W: Write + Send> RecordSink for ParquetRecords<W> {
    fn write_rows(&mut self, rows: &[SummaryRow]) -> std::io::Result<()> {
        if self.writer.is_none() {
            self.start(rows)?;
        }
        let widths = self.extra.widths();
        let params = self.parameters.clone();
        self.write_cells(rows.iter().map(|row| {
            let mut c = cells(row, widths);
            c.extend(params.iter().map(|(n, u)| {
                row.parameters
                    .iter()
                    .find(|p| p.name == *n && p.unit == *u)
                    .map_or(Cell::Empty, |p| Cell::Real(p.value))
            }));
            c
        }))
    }
}
