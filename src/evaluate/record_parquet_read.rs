//! records.parquet read back (a merge's shards, the tests): its columns and its rows as cells.

use parquet::basic::Type as PhysicalType;
use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::record::Field;

use super::record_cells::Cell;
use super::record_parquet::ColumnType;

/// A records.parquet file's columns (name, type) and its rows as cells.
pub(crate) type ParquetTable = (Vec<(String, ColumnType)>, Vec<Vec<Cell>>);

/// A records.parquet file's columns and rows; an error naming `what` (the file) when it cannot be read.
pub fn read_parquet_records(file: std::fs::File, what: &str) -> std::io::Result<ParquetTable> {
    let bad = |e: parquet::errors::ParquetError| {
        std::io::Error::new(std::io::ErrorKind::InvalidData, format!("{what} is not a readable Parquet file: {e}"))
    };
    let reader = SerializedFileReader::new(file).map_err(bad)?;
    let schema = reader.metadata().file_metadata().schema_descr_ptr();
    let columns: Vec<(String, ColumnType)> = schema
        .columns()
        .iter()
        .map(|c| {
            let t = match c.physical_type() {
                PhysicalType::INT64 => ColumnType::Int,
                PhysicalType::DOUBLE => ColumnType::Real,
                _ => ColumnType::Text,
            };
            (c.name().to_string(), t)
        })
        .collect();
    let mut rows = Vec::new();
    for row in reader.get_row_iter(None).map_err(bad)? {
        let row = row.map_err(bad)?;
        rows.push(
            row.get_column_iter()
                .map(|(_, f)| match f {
                    Field::Long(i) => Cell::Int(i.to_owned()),
                    Field::Double(x) => Cell::Real(x.to_owned()),
                    Field::Str(s) => Cell::Text(s.clone()),
                    _ => Cell::Empty,
                })
                .collect(),
        );
    }
    Ok((columns, rows))
}
