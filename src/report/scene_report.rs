//! The report of one scene: the serde data every renderer reads.

use serde::{Deserialize, Serialize};

use super::finding::Finding;
use super::geometry::GeometryReport;
use super::points::{Curves, OperatingPointReport};
use super::scene::InputRow;
use super::{dynamics, friction, losses, number, sweep};

/// The report of one scene.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Report {
    pub title: String,
    /// Folder name: the title in lower case, words joined by `_`.
    pub slug: String,
    pub inputs: Vec<InputRow>,
    pub geometry: GeometryReport,
    /// The operating points reported in full: every point of a small sweep, a bounded set of a large one.
    pub operating_points: Vec<OperatingPointReport>,
    /// One record per (operating point, law, formulation) kept in the report (every point of a small
    /// sweep, the plotted ones of a large one; records.csv has all); empty unless the scene asks for `efficiency`.
    pub efficiency: Vec<friction::EfficiencyRecord>,
    /// The record files: one row per operating point × law × formulation.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub records: Option<sweep::RecordsReport>,
    /// Extremes over every operating point of a sweep (more than one point).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sweep: Option<sweep::SweepReport>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dynamics: Option<dynamics::DynamicsReport>,
    /// The lubricant at the oil temperature, when the scene has one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lubricant: Option<losses::LubricantReport>,
    pub findings: Vec<Finding>,
    pub plots: Vec<PlotRef>,
    /// Sampled curves for the plots (they repeat the tables at finer spacing).
    pub curves: Curves,
    /// The unit the scene wrote the pinion speed in, for tables and plot axes.
    pub speed_unit: number::DisplayUnit,
    /// The unit the scene wrote the pinion torque in: operating points are named in it.
    #[serde(default = "number::DisplayUnit::newton_metre")]
    pub torque_unit: number::DisplayUnit,
    /// The unit system report.md shows results in: `inch` when the scene sizes its pair in inch
    /// units (absent: SI). Every value in this file is SI.
    #[serde(default, skip_serializing_if = "number::UnitSystem::is_si")]
    pub unit_system: number::UnitSystem,
    /// The map plots' grid (torque and speed indices), when the sweep has a map.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub map_grid: Option<(Vec<usize>, Vec<usize>)>,
    /// The torque and speed indices the sweep plots draw a curve for.
    pub sweep_curves: (Vec<usize>, Vec<usize>),
    /// Mean |μ| of the composite law at the kept points: (torque index, torque N·m, speed rad/s, law
    /// label, mean |μ|), in sweep order, one per point and law.
    #[serde(with = "super::floats")]
    pub composite_mu: Vec<(usize, f64, f64, String, f64)>,
    /// The mesh stiffness from the teeth, when the scene asks for it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stiffness: Option<super::teeth::TeethStiffnessReport>,
    /// One static transmission error per asked torque.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub transmission_error: Vec<super::teeth::TransmissionErrorReport>,
}

impl Report {
    /// The units report.md and the plots show this report's results in: inch–pound when its scene
    /// is written in inches ([`super::number::UnitSystem`]).
    pub fn units(&self) -> super::units::Units {
        super::units::Units::of_system(self.unit_system)
    }
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct PlotRef {
    pub kind: PlotKind,
    pub file: String,
    pub title: String,
}

impl PlotRef {
    /// The plot of `kind`, in its file.
    pub fn new(kind: PlotKind, title: impl Into<String>) -> PlotRef {
        PlotRef { kind, file: kind.file().into(), title: title.into() }
    }
}

/// Which plot a [`PlotRef`] is: the renderer draws it by its kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PlotKind {
    ContactState,
    PlaneOfAction,
    StabilityMap,
    WorkPrecision,
    SweepSpeed,
    SweepMu,
    SweepTorque,
    MapEfficiency,
    CompositeMuVsSpeed,
    Film,
    HeatBalance,
    DutyCycleTemperature,
    DutyCycleEnergy,
    MeshStiffness,
    TransmissionError,
    LoadShare,
}

impl PlotKind {
    /// The plot's file in the report folder.
    pub fn file(self) -> &'static str {
        match self {
            PlotKind::ContactState => "contact_state.svg",
            PlotKind::PlaneOfAction => "plane_of_action.svg",
            PlotKind::StabilityMap => "stability_map.svg",
            PlotKind::WorkPrecision => "timing_work_precision.svg",
            PlotKind::SweepSpeed => "sweep_speed.svg",
            PlotKind::SweepMu => "sweep_mu.svg",
            PlotKind::SweepTorque => "sweep_torque.svg",
            PlotKind::MapEfficiency => "map_efficiency.svg",
            PlotKind::CompositeMuVsSpeed => "composite_mu_vs_speed.svg",
            PlotKind::Film => "film.svg",
            PlotKind::HeatBalance => "heat_balance.svg",
            PlotKind::DutyCycleTemperature => "duty_cycle_temperature.svg",
            PlotKind::DutyCycleEnergy => "duty_cycle_energy.svg",
            PlotKind::MeshStiffness => "mesh_stiffness.svg",
            PlotKind::TransmissionError => "transmission_error.svg",
            PlotKind::LoadShare => "load_share.svg",
        }
    }
}
