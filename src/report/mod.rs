//! Stage 4, report: the serde data every renderer reads. Nothing here formats text for a reader.

pub(crate) mod bearing_checks;
pub(crate) mod checks;
mod churning_checks;
pub mod drive;
pub(crate) mod drive_cycle;
pub(crate) mod drive_cycle_series;
pub(crate) mod drive_cycle_totals;
pub(crate) mod drive_findings;
pub(crate) mod drive_geometry;
pub(crate) mod drive_inputs;
pub(crate) mod drive_map;
pub(crate) mod drive_oil_sweep;
pub(crate) mod drive_point;
pub(crate) mod drive_report;
pub(crate) mod drive_stage_pairs;
pub(crate) mod dynamics;
pub(crate) mod dynamics_findings;
pub(crate) mod dynamics_records;
pub(crate) mod finding;
pub mod floats;
pub mod friction;
pub(crate) mod gearbox_inputs;
pub(crate) mod geometry;
pub(crate) mod helical;
mod housing_checks;
pub(crate) mod input_row;
pub(crate) mod law_values;
pub(crate) mod law_words;
pub(crate) mod loss_readings;
pub(crate) mod losses;
mod mesh_checks;
mod non_finite;
pub mod number;
pub(crate) mod numerics;
mod oil_checks;
pub(crate) mod plausibility;
pub(crate) mod points;
pub(crate) mod scene;
pub(crate) mod scene_report;
mod slug;
pub(crate) mod sweep;
pub(crate) mod teeth;
mod teeth_validity;
pub(crate) mod thermal;
pub(crate) mod thermal_sections;
pub mod units;

pub use finding::{Finding, Severity};
pub use geometry::{GearReport, GeometryReport, NamedPoint, PointsReport};
pub use points::{ContactRow, Curves, OperatingPointReport, PointCurves};
pub use scene::{InputRow, SiValue};
pub use scene_report::{PlotKind, PlotRef, Report};
pub use slug::slug;

use crate::evaluate::{Evaluation, Plan, Tally};
use crate::mesh::MeshProblem;

pub use crate::evaluate::{pick, MAX_CURVES};

/// The formulation's name in the report (`external`, `internal`, `base`).
pub fn formulation_name(f: crate::model::Formulation) -> &'static str {
    f.name()
}

/// Builds the report of an evaluated mesh problem: the detail points from `eval`, everything over the
/// sweep from the run's `tally`.
pub fn build_report(problem: &MeshProblem, eval: &Evaluation, tally: &Tally, plan: &Plan) -> Report {
    let mut findings = checks::findings(problem, eval);
    findings.extend(friction::law_findings(problem, eval, tally));
    findings.extend(plausibility::plausibility_findings(tally, scene::units(problem)));
    findings.extend(sweep::sweep_findings(tally, plan));
    let mut report = Report {
        title: problem.title.clone(),
        slug: slug(&problem.title),
        inputs: scene::inputs(problem),
        geometry: geometry::geometry_report(eval),
        operating_points: eval.points.iter().map(|p| points::operating_point_report(problem, eval, p)).collect(),
        efficiency: friction::efficiency_records(problem, eval, tally),
        records: sweep::records_report(tally, plan),
        sweep: sweep::sweep_report(tally, plan, &problem.operating),
        dynamics: eval.dynamics.as_ref().map(|d| dynamics::dynamics_report(problem, eval, d)),
        lubricant: problem.lubricant.as_ref().map(|l| losses::lubricant_report(l, &eval.tribology)),
        findings,
        plots: vec![PlotRef::new(
            PlotKind::ContactState,
            "Sliding velocity, slide-to-roll ratio and Hertzian pressure along the line of action",
        )],
        curves: points::curves(problem, eval),
        speed_unit: number::DisplayUnit::of(&problem.operating.pinion_speed),
        torque_unit: number::DisplayUnit::of(&problem.operating.pinion_torque),
        unit_system: scene::unit_system(problem),
        sweep_curves: (plan.curve_indices().0.to_vec(), plan.curve_indices().1.to_vec()),
        composite_mu: sweep::composite_mu(problem, tally),
        map_grid: sweep::has_map(plan).then(|| {
            let (t, s) = plan.map_grid();
            (t.to_vec(), s.to_vec())
        }),
        stiffness: None,
        transmission_error: Vec::new(),
    };
    if let Some(t) = &eval.teeth {
        with_teeth(&mut report, problem, eval, t);
    }
    if report.geometry.helical.is_some() {
        report.plots.push(PlotRef::new(
            PlotKind::PlaneOfAction,
            "Plane of action: contact lines at four instants over μ(u), and the contact length L(t)",
        ));
    }
    if let Some(d) = &report.dynamics {
        report.findings.extend(dynamics_findings::dynamics_findings(d));
        if d.stability_map.is_some() {
            report.plots.push(PlotRef::new(
                PlotKind::StabilityMap,
                "Floquet spectral radius and dynamic factor against pinion speed",
            ));
        }
        if d.numerics.is_some() {
            report.plots.push(PlotRef::new(
                PlotKind::WorkPrecision,
                "Work-precision: error against run time (machine-dependent)",
            ));
        }
    }
    for pc in &report.curves.points {
        if let Some(op) = report.operating_points.iter_mut().find(|o| o.label == pc.label) {
            op.plot = Some(pc.file.clone());
        }
    }
    sweep_plots(&mut report, problem, eval, plan);
    for path in non_finite_paths(&report) {
        report.findings.push(Finding { severity: Severity::Warning, message: format!("not a finite number: {path}") });
    }
    report
}

/// The mesh stiffness from the teeth and the transmission error: their records, findings and plots.
fn with_teeth(report: &mut Report, problem: &MeshProblem, eval: &Evaluation, t: &crate::evaluate::teeth::TeethDetails) {
    let s = teeth::stiffness_report(problem, t);
    report.findings.extend(teeth::teeth_findings(problem, &s));
    report.stiffness = Some(s);
    report.transmission_error = teeth::transmission_error_reports(t);
    report.findings.extend(teeth_validity::linear_range_findings(problem, eval, &report.transmission_error));
    report.plots.push(PlotRef::new(
        PlotKind::MeshStiffness,
        "Mesh stiffness from the teeth over two mesh cycles, one pair's stiffness, and ISO 6336-1's c_γα",
    ));
    if !report.transmission_error.is_empty() {
        report.plots.push(PlotRef::new(PlotKind::TransmissionError, "Static transmission error over one mesh cycle"));
        report.plots.push(PlotRef::new(PlotKind::LoadShare, "Load share of one tooth pair along the path of contact"));
    }
}

/// The plots of the sweeps, the map, the composite law, the film and the loss budget, as the
/// report's records call for them.
fn sweep_plots(report: &mut Report, problem: &MeshProblem, eval: &Evaluation, plan: &Plan) {
    let sweeps = &problem.operating;
    if !report.efficiency.is_empty() {
        if sweeps.pinion_speed.values.len() > 1 {
            report
                .plots
                .push(PlotRef::new(PlotKind::SweepSpeed, "Mean efficiency and power loss against pinion speed"));
        }
        if !friction::mu_swept_laws(&report.efficiency).is_empty() {
            report.plots.push(PlotRef::new(
                PlotKind::SweepMu,
                "Mean efficiency and power loss against the coefficient of friction",
            ));
        }
        if sweeps.pinion_torque.values.len() > 1 {
            report
                .plots
                .push(PlotRef::new(PlotKind::SweepTorque, "Mean efficiency and power loss against pinion torque"));
        }
    }
    if !report.efficiency.is_empty() && sweep::has_map(plan) {
        report
            .plots
            .push(PlotRef::new(PlotKind::MapEfficiency, "Mean efficiency and power loss over the torque × speed map"));
    }
    if sweeps.pinion_speed.values.len() > 1
        && problem.friction.iter().any(|l| l.law == crate::friction::catalog::LawId::Composite)
        && eval.wants_friction
    {
        report.plots.push(PlotRef::new(
            PlotKind::CompositeMuVsSpeed,
            "Composite law: mean |μ| against pinion speed (He–Cho–Singh Fig. 2b)",
        ));
    }
    if report.operating_points.iter().any(|o| o.film.is_some()) {
        report.plots.push(PlotRef::new(PlotKind::Film, "Film thickness and Λ_HCS along the line of action"));
    }
}

pub use non_finite::non_finite_paths;
