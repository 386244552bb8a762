//! A summary record's cells, typed, in the order of records.csv's columns: what records.csv
//! writes as text and records.parquet as typed columns, from one function, so that both files
//! hold the same values (a float's shortest text reads back to the same bits).

use super::records::{RowKind, SummaryRow};

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

/// A row's cells, with the cells of [`super::records::ExtraColumns`] after the fixed ones (`width`
/// of them; empty where the row has none: only a transmission-error row has them).
pub(crate) fn cells(row: &SummaryRow, width: usize) -> Vec<Cell> {
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
    let ste = row.ste.as_ref().map_or_else(Vec::new, |s| s.numbers().map(Cell::Real).to_vec());
    debug_assert!(ste.len() <= width, "a row's cells match the scene's columns");
    let start = cells.len();
    cells.extend(ste);
    cells.resize(start + width, Cell::Empty);
    cells
}
