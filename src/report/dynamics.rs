//! The dynamics part of the report (serde data). Run times of the numerics study are kept out of it
//! (they go to `timing_numerics.json` only), so report.json stays deterministic.

use serde::{Deserialize, Serialize};

use super::number::{DisplayUnit, Num, Q};
pub(crate) use super::numerics::{NumericsReport, NumericsRow, Timings};
use crate::dynamics::DynamicFormulation;
use crate::evaluate::dynamics::DynamicsEvaluation;
use crate::evaluate::Evaluation;
use crate::geometry::stiffness::StiffnessShape;
use crate::mesh::MeshProblem;

use super::dynamics_records::formulation_report;
pub(crate) use super::dynamics_records::{FormulationReport, Located};

#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(untagged)]
pub enum StiffnessReport {
    Pairs {
        single: Q,
        double: Q,
        triple: Q,
    },
    Table {
        table: Vec<Q>,
    },
    /// Stiffness density along the contact lines (N/m²) and the factor cos²β_b of k(t) = k cos²β_b L(t).
    PerLength {
        per_length: Q,
        cos2_base_helix_angle: Num,
    },
    /// Computed from the teeth: the mean over a cycle (the curve is report.json's `stiffness`).
    Computed {
        mean_mesh_stiffness: Q,
    },
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct DynamicsPointReport {
    pub label: String,
    pub pinion_torque: Q,
    pub pinion_speed: Q,
    pub mesh_frequency: Q,
    /// f_n / f_mesh.
    pub frequency_ratio: Num,
    pub formulations: Vec<FormulationReport>,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct StabilityRow {
    pub pinion_speed: Q,
    pub spectral_radius: Vec<Num>,
    /// A number, or `unstable` where no steady state exists.
    pub dynamic_factor: Vec<super::friction::MuValue>,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct StabilityMapReport {
    pub pinion_torque: Q,
    pub formulations: Vec<DynamicFormulation>,
    /// Per formulation: speed ranges [from, to] (rad/s) where ρ > 1, bounds located by root finding.
    pub unstable_ranges: Vec<Vec<[Q; 2]>>,
    pub points: Vec<StabilityRow>,
    /// The unit the map's speeds were written in.
    pub speed_unit: DisplayUnit,
}

/// Curves of one operating point for plots.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct DynamicsCurves {
    pub file: String,
    pub label: String,
    /// (formulation, [(τ in mesh periods, DTE m)]): each on its own times (switch times twice, extrema).
    #[serde(with = "super::floats")]
    pub dte: Vec<(String, Vec<(f64, f64)>)>,
    /// (pair label, [(τ, tooth force of the pair N)])
    #[serde(with = "super::floats")]
    pub pair_force: Vec<(String, Vec<(f64, f64)>)>,
    /// (formulation, [(τ, applied friction force N)])
    #[serde(with = "super::floats")]
    pub friction_force: Vec<(String, Vec<(f64, f64)>)>,
    /// (formulation, amplitudes by order 1..)
    #[serde(with = "super::floats")]
    pub spectrum: Vec<(String, Vec<f64>)>,
    /// Zone boundary and pitch-point passage times (mesh periods).
    #[serde(with = "super::floats")]
    pub marks: Vec<(String, f64)>,
    /// 6-DOF: (label, [(τ, OLOA bearing force N)]) per gear and formulation.
    #[serde(with = "super::floats")]
    pub oloa: Vec<(String, Vec<(f64, f64)>)>,
    /// free_response_point_K.svg and its series (formulation, [(t in mesh periods, DTE m)]).
    pub free_file: String,
    #[serde(with = "super::floats")]
    pub free: Vec<(String, Vec<(f64, f64)>)>,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct DynamicsReport {
    pub model: String,
    /// What the model is, as the report prints it.
    pub description: String,
    /// k_double / k_single of a rectangular stiffness (None for a table).
    #[serde(with = "super::floats", skip_serializing_if = "Option::is_none", default)]
    pub stiffness_step_ratio: Option<f64>,
    pub stiffness_source: String,
    pub stiffness: StiffnessReport,
    /// With `mesh_stiffness = iso_6336`: ISO 6336-1 Method B's figures and readings.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub iso_6336: Option<super::teeth::IsoReport>,
    pub damping_ratio: Num,
    pub equivalent_mass: Q,
    pub damping: Q,
    pub mean_stiffness: Q,
    pub natural_frequency: Q,
    /// 6-DOF: natural frequencies of the mean undamped system, ascending, and highest/lowest.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub natural_frequencies: Vec<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stiffness_ratio: Option<Num>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub friction: Option<String>,
    /// The law diverges at the pitch point: its peak friction force and torques are infinite and not reported.
    pub friction_diverges_at_pitch: bool,
    pub points: Vec<DynamicsPointReport>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stability_map: Option<StabilityMapReport>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub numerics: Option<NumericsReport>,
    pub curves: Vec<DynamicsCurves>,
}

fn finite(x: f64) -> Option<Num> {
    x.is_finite().then_some(Num(x))
}

/// The run times of the numerics study (machine-dependent: never in report.json; `run` writes them
/// to `timing_numerics.json` and the work-precision plot).
pub(crate) fn timings(d: &DynamicsEvaluation) -> Option<Timings> {
    let (_, _, study) = d.numerics.as_ref()?;
    Some(Timings {
        reference_seconds: study.reference_seconds,
        runs: study.runs.iter().map(|r| (r.method.clone(), r.rtol, r.error, r.seconds)).collect(),
    })
}

pub(crate) fn dynamics_report(problem: &MeshProblem, eval: &Evaluation, d: &DynamicsEvaluation) -> DynamicsReport {
    let shape = d.stiffness.shape();
    let stiffness = stiffness_report(&shape);
    let g = &eval.geometry;
    let tau_b = g.contact_ratio.fract();
    let tau_p = ((g.points.p - g.points.a) / g.base_pitch).fract();
    let picked = crate::evaluate::pick(d.points.len());
    let mut curves = Vec::new();
    let points = d
        .points
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let label = eval.cases[p.case].label.clone();
            if picked.contains(&k) {
                curves.extend(point_curves(k, p, &label, [tau_b, tau_p]));
            }
            DynamicsPointReport {
                label,
                pinion_torque: Q::new(p.state.pinion_torque, "N*m"),
                pinion_speed: Q::new(p.state.pinion_speed, "rad/s"),
                mesh_frequency: Q::new(p.mesh_frequency, "Hz"),
                frequency_ratio: Num(d.natural_frequency / p.mesh_frequency),
                formulations: p.results.iter().map(formulation_report).collect(),
            }
        })
        .collect();
    let stability_map = stability_map_report(problem, d);
    let numerics = numerics_report(d);
    DynamicsReport {
        model: d.model.into(),
        description: d.description.into(),
        stiffness_step_ratio: match shape {
            StiffnessShape::Pairs { single, double, .. } => Some(double / single),
            StiffnessShape::Table(_) | StiffnessShape::PerLength { .. } | StiffnessShape::Computed { .. } => None,
        },
        stiffness_source: d.stiffness_source.into(),
        stiffness,
        iso_6336: d.iso_6336.as_ref().map(super::teeth::IsoReport::from),
        damping_ratio: Num(d.damping_ratio),
        equivalent_mass: Q::new(d.equivalent_mass, "kg"),
        damping: Q::new(d.damping, "N*s/m"),
        mean_stiffness: Q::new(d.mean_stiffness, "N/m"),
        natural_frequency: Q::new(d.natural_frequency, "Hz"),
        natural_frequencies: d.natural_frequencies.iter().map(|f| Q::new(*f, "Hz")).collect(),
        stiffness_ratio: d.stiffness_ratio.map(Num),
        friction: problem.dynamics.as_ref().and_then(|s| s.friction.as_ref()).map(super::friction::law_label),
        friction_diverges_at_pitch: d.friction_diverges_at_pitch,
        points,
        stability_map,
        numerics,
        curves,
    }
}

/// The stability map over speed at the first torque: ρ and K_v per formulation, the unstable ranges.
fn stability_map_report(problem: &MeshProblem, d: &DynamicsEvaluation) -> Option<StabilityMapReport> {
    d.stability_map.as_ref().map(|rows| {
        let unstable_ranges = d
            .unstable_ranges
            .iter()
            .map(|ranges| ranges.iter().map(|(a, b)| [Q::new(*a, "rad/s"), Q::new(*b, "rad/s")]).collect())
            .collect();
        StabilityMapReport {
            pinion_torque: Q::new(problem.operating.pinion_torque.values[0].value, "N*m"),
            formulations: d.formulations.clone(),
            unstable_ranges,
            speed_unit: problem.analyses.stability_map.as_ref().map(DisplayUnit::of).unwrap_or_default(),
            points: rows
                .iter()
                .map(|r| StabilityRow {
                    pinion_speed: Q::new(r.pinion_speed, "rad/s"),
                    spectral_radius: r.spectral_radius.iter().map(|x| Num(*x)).collect(),
                    dynamic_factor: r
                        .dynamic_factor
                        .iter()
                        .map(|x| {
                            x.map_or(super::friction::MuValue::Text("unstable"), |v| {
                                super::friction::MuValue::Value(Num(v))
                            })
                        })
                        .collect(),
                })
                .collect(),
        }
    })
}

/// The numerics study: each integrator's error and work at each tolerance.
fn numerics_report(d: &DynamicsEvaluation) -> Option<NumericsReport> {
    d.numerics.as_ref().map(|(f, _, study)| NumericsReport {
        formulation: *f,
        reference: study.reference,
        periods: study.periods,
        runs: study
            .runs
            .iter()
            .map(|r| NumericsRow {
                method: r.method.clone(),
                rtol: Num(r.rtol),
                error: r.error.and_then(finite),
                final_state_error: r.final_state_error.and_then(finite),
                steps: r.counts.steps,
                rejected: r.counts.rejected,
                evaluations: r.counts.evaluations,
                failure: r.failure.clone(),
            })
            .collect(),
    })
}

/// The curves of picked point `k` (0-based): DTE, bearing forces, friction force, spectrum and pair
/// forces of each formulation's periodic response, and its free response; None when it has none.
/// `marks` are the mesh-period fractions of B|E and P.
fn point_curves(
    k: usize,
    p: &crate::evaluate::dynamics::DynamicsPoint,
    label: &str,
    [tau_b, tau_p]: [f64; 2],
) -> Option<DynamicsCurves> {
    let mut c = DynamicsCurves {
        file: format!("dynamics_point_{}.svg", k + 1),
        free_file: format!("free_response_point_{}.svg", k + 1),
        label: label.to_string(),
        marks: vec![("B|E".into(), tau_b), ("P".into(), tau_p)],
        ..Default::default()
    };
    for r in &p.results {
        if let Some(fr) = &r.free {
            let pts = fr.series.0.iter().copied().zip(fr.series.1.iter().copied()).collect();
            c.free.push((r.formulation.name().to_string(), pts));
        }
        let Some(resp) = &r.response else { continue };
        let name = r.formulation.name().to_string();
        let ser = &resp.curves;
        let xy = |v: &[f64]| ser.tau.iter().copied().zip(v.iter().copied()).collect::<Vec<_>>();
        c.dte.push((name.clone(), xy(&ser.dte)));
        for (gear, v) in &ser.bearing_force_oloa {
            c.oloa.push((format!("{name}: {gear}"), xy(v)));
        }
        if r.formulation != DynamicFormulation::Base {
            c.friction_force.push((name.clone(), xy(&ser.friction_force)));
        }
        c.spectrum.push((name.clone(), resp.dte.spectrum.clone()));
        if !ser.pair_force.is_empty() && (c.pair_force.is_empty() || r.formulation != DynamicFormulation::Base) {
            c.pair_force = ser
                .pair_force
                .iter()
                .enumerate()
                .filter(|(_, f)| f.iter().any(|x| x.is_finite()))
                .map(|(slot, f)| (format!("{name}: pair entered {slot} period(s) ago"), xy(f)))
                .collect();
        }
    }
    (!c.dte.is_empty() || !c.free.is_empty()).then_some(c)
}

/// The stiffness as the report writes it.
fn stiffness_report(shape: &StiffnessShape) -> StiffnessReport {
    match shape {
        StiffnessShape::Pairs { single, double, triple } => StiffnessReport::Pairs {
            single: Q::new(*single, "N/m"),
            double: Q::new(*double, "N/m"),
            triple: Q::new(*triple, "N/m"),
        },
        StiffnessShape::Table(v) => StiffnessReport::Table { table: v.iter().map(|k| Q::new(*k, "N/m")).collect() },
        StiffnessShape::PerLength { density, cos2_base_helix } => StiffnessReport::PerLength {
            per_length: Q::new(*density, "N/m^2"),
            cos2_base_helix_angle: Num(*cos2_base_helix),
        },
        StiffnessShape::Computed { mean } => StiffnessReport::Computed { mean_mesh_stiffness: Q::new(*mean, "N/m") },
    }
}
