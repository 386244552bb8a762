//! The Parquet record files (records.parquet, drive_records.parquet): typed columns through the
//! pure-Rust `parquet` crate, Snappy-compressed, text columns dictionary-encoded, written in row
//! groups of [`ROW_GROUP`] rows as the sweep streams, so memory stays bounded. The columns are the
//! CSV's, in its order and with its names (integers INT64, numbers DOUBLE, text UTF-8; a missing
//! or non-finite value, and an empty text, is null, as an empty CSV cell reads); which columns a
//! kind of record has is its `super::record_files::RecordTable`'s.

use std::io::Write;
use std::sync::Arc;

use parquet::basic::{Compression, LogicalType, Repetition, Type as PhysicalType};
use parquet::column::writer::ColumnWriter;
use parquet::data_type::ByteArray;
use parquet::file::properties::WriterProperties;
use parquet::file::writer::SerializedFileWriter;
use parquet::schema::types::Type;

use super::record_cells::Cell;

/// Rows held before they are written as a row group.
pub(crate) const ROW_GROUP: usize = 8_192;

/// A column's Parquet type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ColumnType {
    Int,
    Real,
    Text,
}

/// Writes a Parquet record file of the given columns (`super::record_files::RecordTable::parquet_columns`).
pub(crate) struct ParquetRecords<W: Write + Send> {
    out: Option<W>,
    writer: Option<SerializedFileWriter<W>>,
    columns: Vec<(String, ColumnType)>,
    rows: Vec<Vec<Cell>>,
}

impl<W: Write + Send> ParquetRecords<W> {
    /// A writer of the given columns (a merge, from its shards' schema).
    pub(crate) fn with_columns(out: W, columns: Vec<(String, ColumnType)>) -> std::io::Result<ParquetRecords<W>> {
        let mut w = ParquetRecords { out: Some(out), writer: None, columns, rows: Vec::new() };
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
        self.flush_group()?;
        let mut out = self.writer.take().expect("open").into_inner().map_err(io)?;
        out.flush()?;
        Ok(out)
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
