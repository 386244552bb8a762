//! The report of a drive of several stages as data: what the drive is made of (stages, shafts,
//! oil, laws), every operating point's [`DrivePointReport`] (per law and formulation) with the
//! readings it rests on, the thermal balance and duty cycle, the loss map over the ends' torque ×
//! speed, and the findings. Serde data; `super::drive` builds it, the renderers read it.

use serde::{Deserialize, Serialize};

use super::drive_inputs::{ShaftInputs, StageInputs};
use super::drive_map::DriveMapReport;
use super::drive_point::DrivePointReport;
use super::finding::Finding;
use super::number::DisplayUnit;
use crate::drive::ShaftEnd;

/// The report of a drive.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct DriveReport {
    pub title: String,
    pub slug: String,
    pub stages: Vec<StageInputs>,
    pub shafts: Vec<ShaftInputs>,
    /// ω_in/ω_out of the chain (signed: negative when the output turns the other way).
    pub overall_ratio: f64,
    /// The sump's oil temperature (°C; at `equilibrium` the balance of point 1, said in words).
    pub oil: Vec<(String, f64, String)>,
    /// The lubricant as every mesh, film and loss reads it at that temperature (η, ν, ρ, α, X_L),
    /// its data sheet values and their source: the same report a pair's gives.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lubricant: Option<super::losses::LubricantReport>,
    /// Every input of the stages, the oil, the lubrication, the bearing places and seals and the
    /// housing as written and in SI (a pair's Scene table, keyed by stage and shaft).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub inputs: Vec<super::scene::InputRow>,
    /// Each stage mesh's geometry, as a pair's report gives its own (not `geometry`: that key
    /// marks a pair's report.json when `gearloss render` reads one back).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub stage_geometry: Vec<super::drive_geometry::StageGeometryReport>,
    pub laws: Vec<String>,
    /// Rows of the operating points (points × laws × formulations), all in drive_records.csv; the
    /// report shows the first `crate::evaluate::drive::DETAIL_ROWS` in full and every row of its
    /// detail points.
    pub rows: usize,
    /// Where the shown rows go beyond the first: how many first rows and the detail points
    /// (1-based) whose rows follow them; None when the shown rows are the first alone.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shown_rows: Option<ShownRows>,
    /// The least and greatest η over every row where one end delivers, with the row's label, law
    /// and formulation; rows where both ends deliver.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub least_efficiency: Option<(f64, String)>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub greatest_efficiency: Option<(f64, String)>,
    pub both_ends_rows: usize,
    /// Rows where a stage's law leaves its validity range (drive_records.csv's
    /// `stage_<name>_validity_outside` say where).
    pub outside_rows: usize,
    /// Rows whose fixed point did not settle or whose books do not balance, and the first in words.
    #[serde(default, skip_serializing_if = "crate::evaluate::drive::is_zero")]
    pub unsettled_rows: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_unsettled: Option<String>,
    /// Values of the record files that are not finite numbers, and the first: its row in words
    /// and its column.
    #[serde(default, skip_serializing_if = "crate::evaluate::drive::is_zero")]
    pub non_finite_values: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_non_finite: Option<(String, String)>,
    /// At `oil_temperature = equilibrium`: rows whose sump settles above the limit or finds no
    /// balance, and the first in words.
    #[serde(default, skip_serializing_if = "crate::evaluate::drive::is_zero")]
    pub off_balance_rows: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_off_balance: Option<String>,
    /// Rows with a stage result no gear mesh can have or whose formulas no longer hold (a mesh
    /// efficiency outside [0, 1], a contact with b_H > R/10), and the first in words with what.
    #[serde(default, skip_serializing_if = "crate::evaluate::drive::is_zero")]
    pub implausible_rows: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_implausible: Option<String>,
    pub torque_at: ShaftEnd,
    pub speed_at: ShaftEnd,
    /// The unit the scene wrote its speeds in, which report.md shows every speed in (report.json
    /// keeps rad/s, and rpm in the fields so named); left out when rpm.
    #[serde(default = "DisplayUnit::rpm", skip_serializing_if = "DisplayUnit::is_rpm")]
    pub speed_unit: DisplayUnit,
    /// The unit the scene wrote its torques in, likewise (report.json keeps N·m); left out when N·m.
    #[serde(default = "DisplayUnit::newton_metre", skip_serializing_if = "DisplayUnit::is_newton_metre")]
    pub torque_unit: DisplayUnit,
    /// The units report.md shows forces, powers, lengths and temperatures in: inch–pound when every
    /// stage's pair is sized in inches (as a pair's report), else SI; report.json stays SI.
    #[serde(default, skip_serializing_if = "super::number::UnitSystem::is_si")]
    pub unit_system: super::number::UnitSystem,
    pub points: Vec<DrivePointReport>,
    pub maps: Vec<DriveMapReport>,
    /// The housing, the balance of every shown row (the torque and speed the given ends', the point
    /// in words; the ratings at the given end), the heat-balance curve at the first row and the duty
    /// cycle under the first law and formulation: a pair's report's own (report.json's `housing`,
    /// `thermal`, `heat_balance`, `duty_cycle`).
    #[serde(flatten)]
    pub heat: super::thermal_sections::ThermalSections,
    /// The vehicle over its drive cycle.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cycle: Option<super::drive_cycle::DriveCycleReport>,
    /// The scene is one pair run as its one-stage drive: report.md adds the pair's own total
    /// efficiency beside the drive's ([`super::drive_point::DrivePointReport::pinion_efficiency`]).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub one_pair: bool,
    /// The readings the loss parts rest on, in words, for the parts the drive uses
    /// (`super::loss_readings`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub loss_readings: Vec<String>,
    /// The analyses of one pair on the drive's stages' meshes, each with its own report folder.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub stage_pairs: Vec<super::drive_stage_pairs::StagePairReport>,
    pub findings: Vec<Finding>,
}

/// The rows a drive's report shows beyond its first rows: those of its detail points.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ShownRows {
    /// The first rows shown (`crate::evaluate::drive::DETAIL_ROWS`, or every row of a shorter run).
    pub first: usize,
    /// The detail points (1-based, torque-major) with a row beyond the first, every row of each
    /// (law × formulation) shown.
    pub detail_points: Vec<usize>,
}
