//! The summary records of a run: one row per operating point × law × formulation, streamed to
//! `records.csv` and `records.jsonl` as the points are evaluated, so that memory does not grow with
//! the sweep. Every number is in SI; the CSV header names the unit of each column.
//!
//! Rows of one point come in a fixed order: the efficiency rows (the scene's laws in order, each
//! with its formulations), or one friction row per law when the scene asks for friction without
//! efficiency, then the dynamics rows (one per dynamic formulation). Points come in the order of
//! the sweep (torque-major), so the records of a sharded run concatenate to those of a single run.

use serde::{Deserialize, Serialize};

use crate::geometry::OperatingState;

/// One parameter of a law at the point (SI value and unit; `1` for a plain number).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ParameterValue {
    pub name: String,
    pub value: f64,
    pub unit: String,
}

/// What a row reports.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RowKind {
    /// Mean efficiency and power loss of a law in one formulation.
    Efficiency,
    /// μ̄ and validity of a law (the scene asks for friction, not efficiency).
    Friction,
    /// The dynamics summary of one dynamic formulation.
    Dynamics,
    /// The static transmission error at one torque of the `transmission_error` analysis (point 0:
    /// not an operating point of the sweep; speed 0, the error is static).
    TransmissionError,
}

/// One summary record.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SummaryRow {
    /// Operating point number, 1-based, torque-major (as in the report).
    pub point: usize,
    pub torque_index: usize,
    pub speed_index: usize,
    #[serde(rename = "pinion_torque_N_m")]
    pub pinion_torque: f64,
    #[serde(rename = "pinion_speed_rad_s")]
    pub pinion_speed: f64,
    pub kind: RowKind,
    /// Index of the law in the scene's friction list (dynamics rows: none).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub law_index: Option<usize>,
    /// Catalogue name of the law (`coulomb`), empty when the row has none.
    pub law: String,
    /// The law as written, `coulomb(mu = 0.04)`.
    pub label: String,
    /// `external`, `internal`, `base`, or empty for friction rows.
    pub formulation: String,
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub mean_abs_mu: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub mean_efficiency: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub mean_efficiency_error: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub min_efficiency: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub max_efficiency: Option<f64>,
    #[serde(rename = "power_loss_W", skip_serializing_if = "Option::is_none", default)]
    pub power_loss: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub validity_samples: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub validity_outside: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub spectral_radius: Option<f64>,
    #[serde(rename = "dte_peak_to_peak_m", skip_serializing_if = "Option::is_none", default)]
    pub dte_peak_to_peak: Option<f64>,
    #[serde(rename = "dte_mean_m", skip_serializing_if = "Option::is_none", default)]
    pub dte_mean: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub dynamic_factor: Option<f64>,
    #[serde(skip_serializing_if = "Vec::is_empty", default)]
    pub parameters: Vec<ParameterValue>,
    /// The static transmission error of a `transmission_error` row.
    #[serde(flatten, skip_serializing_if = "Option::is_none", default)]
    pub ste: Option<super::ste_row::SteRow>,
}

impl SummaryRow {
    /// A row of `point` (1-based; 0 for rows of no operating point) with nothing computed yet.
    pub fn blank(point: usize, (torque_index, speed_index): (usize, usize), state: OperatingState) -> SummaryRow {
        SummaryRow {
            point,
            torque_index,
            speed_index,
            pinion_torque: state.pinion_torque,
            pinion_speed: state.pinion_speed,
            kind: RowKind::Friction,
            law_index: None,
            law: String::new(),
            label: String::new(),
            formulation: String::new(),
            mean_abs_mu: None,
            mean_efficiency: None,
            mean_efficiency_error: None,
            min_efficiency: None,
            max_efficiency: None,
            power_loss: None,
            validity_samples: None,
            validity_outside: None,
            spectral_radius: None,
            dte_peak_to_peak: None,
            dte_mean: None,
            dynamic_factor: None,
            parameters: Vec::new(),
            ste: None,
        }
    }

    /// The row's numbers by CSV column name, in [`CSV_COLUMNS`] order after the text columns.
    fn numbers(&self) -> [(&'static str, Option<f64>); 14] {
        let count = |n: Option<usize>| n.map(|n| n as f64);
        [
            ("pinion_torque_N_m", Some(self.pinion_torque)),
            ("pinion_speed_rad_s", Some(self.pinion_speed)),
            ("mean_abs_mu", self.mean_abs_mu),
            ("mean_efficiency", self.mean_efficiency),
            ("mean_efficiency_error", self.mean_efficiency_error),
            ("min_efficiency", self.min_efficiency),
            ("max_efficiency", self.max_efficiency),
            ("power_loss_W", self.power_loss),
            ("validity_samples", count(self.validity_samples)),
            ("validity_outside", count(self.validity_outside)),
            ("spectral_radius", self.spectral_radius),
            ("dte_peak_to_peak_m", self.dte_peak_to_peak),
            ("dte_mean_m", self.dte_mean),
            ("dynamic_factor", self.dynamic_factor),
        ]
    }

    /// Names of the columns whose value is present but not a finite number.
    pub fn non_finite(&self) -> impl Iterator<Item = &'static str> + '_ {
        let ste = self.ste.iter().flat_map(|s| super::ste_row::SteRow::COLUMNS.into_iter().zip(s.numbers().map(Some)));
        self.numbers().into_iter().chain(ste).filter(|(_, v)| v.is_some_and(|x| !x.is_finite())).map(|(n, _)| n)
    }
}

/// The columns of `records.csv`, in order: the keys records.jsonl writes (a row leaves out there
/// what it has not, and the CSV leaves that cell empty); `parameters` is one cell
/// `name=value unit; …`.
pub(crate) const CSV_COLUMNS: [&str; 23] = [
    "point",
    "torque_index",
    "speed_index",
    "pinion_torque_N_m",
    "pinion_speed_rad_s",
    "kind",
    "law_index",
    "law",
    "label",
    "formulation",
    "mean_abs_mu",
    "mean_efficiency",
    "mean_efficiency_error",
    "min_efficiency",
    "max_efficiency",
    "power_loss_W",
    "validity_samples",
    "validity_outside",
    "spectral_radius",
    "dte_peak_to_peak_m",
    "dte_mean_m",
    "dynamic_factor",
    "parameters",
];

/// The columns of `records.csv` after `CSV_COLUMNS`, present as the scene asks: the static
/// transmission error's (`super::ste_row::SteRow::COLUMNS`). A row fills them where it has them and
/// leaves their cells empty otherwise. (A pair's loss budget and thermal balance are its one-stage
/// drive's: drive_records.csv.)
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ExtraColumns {
    pub ste: Vec<String>,
}

impl ExtraColumns {
    /// The mesh problem's columns.
    pub fn of(problem: &crate::mesh::MeshProblem) -> ExtraColumns {
        let ste = if problem.analyses.transmission_error.is_some() {
            super::ste_row::SteRow::COLUMNS.iter().map(|c| c.to_string()).collect()
        } else {
            Vec::new()
        };
        ExtraColumns { ste }
    }

    /// The names in the order the CSV writes them.
    pub fn names(&self) -> impl Iterator<Item = &String> {
        self.ste.iter()
    }

    /// How many cells the group holds.
    pub fn width(&self) -> usize {
        self.ste.len()
    }
}

/// Where the rows go as they are computed.
pub trait RecordSink {
    /// Takes the rows of consecutive operating points, in order.
    fn write_rows(&mut self, rows: &[SummaryRow]) -> std::io::Result<()>;
}

/// Drops the rows (a run that only wants the report's summary).
pub struct NoRecords;

impl RecordSink for NoRecords {
    fn write_rows(&mut self, _: &[SummaryRow]) -> std::io::Result<()> {
        Ok(())
    }
}
