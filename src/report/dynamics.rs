//! The dynamics part of the report (serde data). Run times of the numerics study are kept out of it
//! (they go to `timing_numerics.json` only), so report.json stays deterministic.

use serde::Serialize;

use super::number::{m, DisplayUnit, Num, Q};
pub use super::numerics::{NumericsReport, NumericsRow, Timings};
use crate::dynamics::floquet::Verdict;
use crate::dynamics::propagator::Method;
use crate::dynamics::{DynamicFormulation, StiffnessModel};
use crate::evaluate::dynamics::DynamicsEvaluation;
use crate::evaluate::Evaluation;
use crate::model::Scene;

#[derive(Debug, Clone, Serialize)]
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
}

/// A located extremum: value and time in mesh periods.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Located {
    pub value: Q,
    pub tau: Num,
}

fn located(e: crate::dynamics::trajectory::Extremum, unit: &'static str) -> Located {
    Located { value: Q::new(e.value, unit), tau: Num(e.time) }
}

#[derive(Debug, Clone, Serialize)]
pub struct SpectrumLine {
    pub order: usize,
    pub amplitude: Q,
}

#[derive(Debug, Clone, Serialize)]
pub struct FormulationReport {
    pub formulation: DynamicFormulation,
    pub method: Method,
    pub spectral_radius: Num,
    /// [re, im] pairs.
    pub floquet_multipliers: Vec<[Num; 2]>,
    pub verdict: Verdict,
    pub monodromy_determinant: Num,
    /// exp(∫ tr A dt), which det Φ(T) must equal.
    pub liouville_determinant: Num,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dte_peak_to_peak: Option<Q>,
    /// Located extrema of the DTE (roots of ẋ = 0) with their times in mesh periods.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dte_min: Option<Located>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dte_max: Option<Located>,
    /// Time mean of the DTE (Gauss–Kronrod on the state) and its error estimate.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dte_mean: Option<Q>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dte_mean_error: Option<Q>,
    /// Located extrema of the tooth force F = c(ẋ − ε̇) + k(x − ε) (Fernandes eq 7).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tooth_force_min: Option<Located>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tooth_force_max: Option<Located>,
    /// max F / F0.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dynamic_factor: Option<Num>,
    /// Mesh-period fractions [from, to] where the tooth force is negative (teeth separate), located.
    pub tooth_separation: Vec<[Num; 2]>,
    pub spectrum: Vec<SpectrumLine>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mean_dynamic_efficiency: Option<Num>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mean_dynamic_efficiency_error: Option<Num>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_dynamic_efficiency: Option<Num>,
    /// Peak |friction force the model applies| (external: μ F0 shares; internal: μ F shares) and peak
    /// |friction torque| on pinion and wheel over the cycle, located.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub peak_applied_friction_force: Option<Located>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub peak_friction_torque: Vec<Located>,
    /// External formulation: peak |Σ μ_j w_j F| (μ × tooth force), which its equation does not apply.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub peak_mu_times_tooth_force: Option<Located>,
    /// The free (homogeneous) response from the scene's initial state, when asked for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub free_response: Option<FreeResponseReport>,
    /// 6-DOF model: the largest force on one pair (N/n, located), the mean friction force Σ μ_i N_i
    /// and per gear [pinion, wheel] the bearing forces and displacements.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pair_force_max: Option<Located>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction_force_mean: Option<Q>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub gears: Vec<GearDynamicsReport>,
}

/// One gear of the 6-DOF model: bearing forces K x (LOA) and K y (OLOA) and displacements, located
/// extremes, integrated means with error estimates, the OLOA bearing force spectrum in mesh orders.
#[derive(Debug, Clone, Serialize)]
pub struct GearDynamicsReport {
    pub gear: &'static str,
    pub bearing_force_loa_peak_to_peak: Q,
    pub bearing_force_loa_mean: Q,
    pub bearing_force_oloa_peak_to_peak: Q,
    pub bearing_force_oloa_mean: Q,
    pub bearing_force_oloa_mean_error: Q,
    pub bearing_force_oloa_min: Located,
    pub bearing_force_oloa_max: Located,
    pub bearing_force_oloa_spectrum: Vec<SpectrumLine>,
    pub loa_displacement_peak_to_peak: Q,
    pub oloa_displacement_peak_to_peak: Q,
}

/// The 6-DOF response in the report's fields: the DTE, mesh force (as the tooth force), dynamic
/// factor, friction force and the gears' bearings.
fn six_dof_fields(f: &mut FormulationReport, x: &crate::dynamics::six_dof_response::SixDofResponse) {
    f.dte_peak_to_peak = Some(m(x.dte.peak_to_peak()));
    f.dte_min = Some(located(x.dte.min, "m"));
    f.dte_max = Some(located(x.dte.max, "m"));
    f.dte_mean = Some(m(x.dte.mean.value));
    f.dte_mean_error = Some(m(x.dte.mean.error));
    f.tooth_force_min = Some(located(x.mesh_force[0], "N"));
    f.tooth_force_max = Some(located(x.mesh_force[1], "N"));
    f.dynamic_factor = Some(Num(x.dynamic_factor));
    f.spectrum =
        x.dte.spectrum.iter().enumerate().map(|(o, a)| SpectrumLine { order: o + 1, amplitude: m(*a) }).collect();
    let (lo, hi) = (x.friction_force.min, x.friction_force.max);
    let peak = if hi.value.abs() >= lo.value.abs() {
        hi
    } else {
        crate::dynamics::trajectory::Extremum { value: lo.value.abs(), time: lo.time }
    };
    f.peak_applied_friction_force = Some(located(peak, "N"));
    f.pair_force_max = Some(located(x.pair_force_max, "N"));
    f.friction_force_mean = Some(Q::new(x.friction_force.mean.value, "N"));
    f.gears = vec![gear_dynamics("pinion", &x.gears[0]), gear_dynamics("wheel", &x.gears[1])];
}

fn gear_dynamics(name: &'static str, g: &crate::dynamics::six_dof_response::GearResponse) -> GearDynamicsReport {
    let n = |x: f64| Q::new(x, "N");
    GearDynamicsReport {
        gear: name,
        bearing_force_loa_peak_to_peak: n(g.bearing_force_loa.peak_to_peak()),
        bearing_force_loa_mean: n(g.bearing_force_loa.mean.value),
        bearing_force_oloa_peak_to_peak: n(g.bearing_force_oloa.peak_to_peak()),
        bearing_force_oloa_mean: n(g.bearing_force_oloa.mean.value),
        bearing_force_oloa_mean_error: n(g.bearing_force_oloa.mean.error),
        bearing_force_oloa_min: located(g.bearing_force_oloa.min, "N"),
        bearing_force_oloa_max: located(g.bearing_force_oloa.max, "N"),
        bearing_force_oloa_spectrum: g
            .bearing_force_oloa
            .spectrum
            .iter()
            .enumerate()
            .map(|(o, a)| SpectrumLine { order: o + 1, amplitude: Q::new(*a, "N") })
            .collect(),
        loa_displacement_peak_to_peak: m(g.displacement_loa[1].value - g.displacement_loa[0].value),
        oloa_displacement_peak_to_peak: m(g.displacement_oloa[1].value - g.displacement_oloa[0].value),
    }
}

/// The free response X(t + nT) = Φ(t, 0) Φ(T)ⁿ X(0) and its Floquet-mode spectrum lines.
#[derive(Debug, Clone, Serialize)]
pub struct FreeResponseReport {
    pub x0: Q,
    pub v0: Q,
    pub periods: usize,
    /// Largest |DTE| over the window, located; time in mesh periods from the start.
    pub peak: Located,
    pub first_period_peak: Q,
    pub last_period_peak: Q,
    /// Largest lines first: frequency in mesh orders, one-sided amplitude at t = 0, its error
    /// estimate, growth per period |λ|.
    pub lines: Vec<FreeLine>,
}

#[derive(Debug, Clone, Serialize)]
pub struct FreeLine {
    pub order: Num,
    pub amplitude: Q,
    pub amplitude_error: Q,
    pub growth_per_period: Num,
}

fn free_report(f: &crate::dynamics::free::FreeResponse) -> FreeResponseReport {
    FreeResponseReport {
        x0: m(f.initial[0]),
        v0: Q::new(f.initial[1], "m/s"),
        periods: f.periods,
        peak: located(f.peak, "m"),
        first_period_peak: m(f.first_period_peak),
        last_period_peak: m(f.last_period_peak),
        lines: f
            .lines
            .iter()
            .map(|l| FreeLine {
                order: Num(l.order),
                amplitude: m(l.amplitude),
                amplitude_error: m(l.error),
                growth_per_period: Num(l.growth),
            })
            .collect(),
    }
}

#[derive(Debug, Clone, Serialize)]
pub struct DynamicsPointReport {
    pub label: String,
    pub pinion_torque: Q,
    pub pinion_speed: Q,
    pub mesh_frequency: Q,
    /// f_n / f_mesh.
    pub frequency_ratio: Num,
    pub formulations: Vec<FormulationReport>,
}

#[derive(Debug, Clone, Serialize)]
pub struct StabilityRow {
    pub pinion_speed: Q,
    pub spectral_radius: Vec<Num>,
    /// A number, or `unstable` where no steady state exists.
    pub dynamic_factor: Vec<super::friction::MuValue>,
}

#[derive(Debug, Clone, Serialize)]
pub struct StabilityMapReport {
    pub pinion_torque: Q,
    pub formulations: Vec<DynamicFormulation>,
    /// Per formulation: speed ranges [from, to] (rad/s) where ρ > 1, bounds located by root finding.
    pub unstable_ranges: Vec<Vec<[Q; 2]>>,
    pub points: Vec<StabilityRow>,
    /// The unit the map's speeds were written in.
    #[serde(skip)]
    pub speed_unit: DisplayUnit,
}

/// Curves of one operating point for plots.
#[derive(Debug, Clone, Default)]
pub struct DynamicsCurves {
    pub file: String,
    pub label: String,
    /// (formulation, [(τ in mesh periods, DTE m)]): each on its own times (switch times twice, extrema).
    pub dte: Vec<(String, Vec<(f64, f64)>)>,
    /// (pair label, [(τ, tooth force of the pair N)])
    pub pair_force: Vec<(String, Vec<(f64, f64)>)>,
    /// (formulation, [(τ, applied friction force N)])
    pub friction_force: Vec<(String, Vec<(f64, f64)>)>,
    /// (formulation, amplitudes by order 1..)
    pub spectrum: Vec<(String, Vec<f64>)>,
    /// Zone boundary and pitch-point passage times (mesh periods).
    pub marks: Vec<(&'static str, f64)>,
    /// 6-DOF: (label, [(τ, OLOA bearing force N)]) per gear and formulation.
    pub oloa: Vec<(String, Vec<(f64, f64)>)>,
    /// free_response_point_K.svg and its series (formulation, [(t in mesh periods, DTE m)]).
    pub free_file: String,
    pub free: Vec<(String, Vec<(f64, f64)>)>,
}

#[derive(Debug, Clone, Serialize)]
pub struct DynamicsReport {
    pub model: &'static str,
    /// k_double / k_single of a rectangular stiffness (None for a table).
    #[serde(skip)]
    pub stiffness_step_ratio: Option<f64>,
    pub stiffness_source: &'static str,
    pub stiffness: StiffnessReport,
    pub damping_ratio: Num,
    pub equivalent_mass: Q,
    pub damping: Q,
    pub mean_stiffness: Q,
    pub natural_frequency: Q,
    /// 6-DOF: natural frequencies of the mean undamped system, ascending, and highest/lowest.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub natural_frequencies: Vec<Q>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stiffness_ratio: Option<Num>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction: Option<String>,
    /// The law diverges at the pitch point: its peak friction force and torques are infinite and not reported.
    pub friction_diverges_at_pitch: bool,
    pub points: Vec<DynamicsPointReport>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stability_map: Option<StabilityMapReport>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub numerics: Option<NumericsReport>,
    #[serde(skip)]
    pub curves: Vec<DynamicsCurves>,
    #[serde(skip)]
    pub timings: Option<Timings>,
}

fn finite(x: f64) -> Option<Num> {
    x.is_finite().then_some(Num(x))
}

pub fn dynamics_report(scene: &Scene, eval: &Evaluation, d: &DynamicsEvaluation) -> DynamicsReport {
    let stiffness = match &d.stiffness {
        StiffnessModel::PairsInContact { single, double, triple } => StiffnessReport::Pairs {
            single: Q::new(*single, "N/m"),
            double: Q::new(*double, "N/m"),
            triple: Q::new(*triple, "N/m"),
        },
        StiffnessModel::Table(v) => StiffnessReport::Table { table: v.iter().map(|k| Q::new(*k, "N/m")).collect() },
        StiffnessModel::PerLength { density, cos2_base_helix } => StiffnessReport::PerLength {
            per_length: Q::new(*density, "N/m^2"),
            cos2_base_helix_angle: Num(*cos2_base_helix),
        },
    };
    let g = &eval.geometry;
    let tau_b = g.contact_ratio.fract();
    let tau_p = ((g.points.p - g.points.a) / g.base_pitch).fract();
    let picked = super::pick(d.points.len());
    let mut curves = Vec::new();
    let points = d
        .points
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let label = eval.cases[p.case].label.clone();
            if picked.contains(&k) {
                let mut c = DynamicsCurves {
                    file: format!("dynamics_point_{}.svg", k + 1),
                    free_file: format!("free_response_point_{}.svg", k + 1),
                    label: label.clone(),
                    marks: vec![("B|E", tau_b), ("P", tau_p)],
                    ..Default::default()
                };
                for r in &p.results {
                    if let Some(fr) = &r.free {
                        let pts = fr.series.0.iter().copied().zip(fr.series.1.iter().copied()).collect();
                        c.free.push((r.formulation.name().to_string(), pts));
                    }
                    if let Some(x) = &r.six_dof {
                        let name = r.formulation.name();
                        let xy = |v: &[f64]| x.series[0].iter().copied().zip(v.iter().copied()).collect::<Vec<_>>();
                        c.dte.push((name.to_string(), xy(&x.series[1])));
                        c.oloa.push((format!("{name}: pinion"), xy(&x.series[2])));
                        c.oloa.push((format!("{name}: wheel"), xy(&x.series[3])));
                        if r.formulation != DynamicFormulation::Base {
                            c.friction_force.push((name.to_string(), xy(&x.series[4])));
                        }
                        c.spectrum.push((name.to_string(), x.dte.spectrum.clone()));
                    }
                    let Some(resp) = &r.response else { continue };
                    let name = r.formulation.name().to_string();
                    let ser = &resp.series;
                    let xy = |v: &[f64]| ser.tau.iter().copied().zip(v.iter().copied()).collect::<Vec<_>>();
                    c.dte.push((name.clone(), xy(&ser.dte)));
                    if r.formulation != DynamicFormulation::Base {
                        c.friction_force.push((name.clone(), xy(&ser.friction_force)));
                    }
                    c.spectrum.push((name.clone(), resp.spectrum.iter().map(|s| s.1).collect()));
                    if c.pair_force.is_empty() || r.formulation != DynamicFormulation::Base {
                        c.pair_force = ser
                            .pair_force
                            .iter()
                            .enumerate()
                            .filter(|(_, f)| f.iter().any(|x| x.is_finite()))
                            .map(|(slot, f)| (format!("{name}: pair entered {slot} period(s) ago"), xy(f)))
                            .collect();
                    }
                }
                if !c.dte.is_empty() || !c.free.is_empty() {
                    curves.push(c);
                }
            }
            DynamicsPointReport {
                label,
                pinion_torque: Q::new(p.state.pinion_torque, "N*m"),
                pinion_speed: Q::new(p.state.pinion_speed, "rad/s"),
                mesh_frequency: Q::new(p.mesh_frequency, "Hz"),
                frequency_ratio: Num(d.natural_frequency / p.mesh_frequency),
                formulations: p
                    .results
                    .iter()
                    .map(|r| {
                        let mut f = FormulationReport {
                            formulation: r.formulation,
                            method: r.method,
                            spectral_radius: Num(r.spectral_radius),
                            floquet_multipliers: r.multipliers.iter().map(|m| [Num(m.re), Num(m.im)]).collect(),
                            verdict: r.verdict,
                            monodromy_determinant: Num(r.determinant),
                            liouville_determinant: Num(r.liouville),
                            dte_peak_to_peak: r.response.as_ref().map(|x| m(x.dte_peak_to_peak)),
                            dte_min: r.response.as_ref().map(|x| located(x.dte_min, "m")),
                            dte_max: r.response.as_ref().map(|x| located(x.dte_max, "m")),
                            dte_mean: r.response.as_ref().map(|x| m(x.dte_mean.value)),
                            dte_mean_error: r.response.as_ref().map(|x| m(x.dte_mean.error)),
                            tooth_force_min: r.response.as_ref().map(|x| located(x.tooth_force_min, "N")),
                            tooth_force_max: r.response.as_ref().map(|x| located(x.tooth_force_max, "N")),
                            dynamic_factor: r.response.as_ref().map(|x| Num(x.dynamic_factor)),
                            tooth_separation: r.response.as_ref().map_or_else(Vec::new, |x| {
                                x.separation.iter().map(|(a, b)| [Num(*a), Num(*b)]).collect()
                            }),
                            spectrum: r.response.as_ref().map_or_else(Vec::new, |x| {
                                x.spectrum.iter().map(|(o, a)| SpectrumLine { order: *o, amplitude: m(*a) }).collect()
                            }),
                            mean_dynamic_efficiency: r
                                .response
                                .as_ref()
                                .and_then(|x| x.mean_dynamic_efficiency.map(|i| Num(i.value))),
                            mean_dynamic_efficiency_error: r
                                .response
                                .as_ref()
                                .and_then(|x| x.mean_dynamic_efficiency.map(|i| Num(i.error))),
                            max_dynamic_efficiency: r.response.as_ref().and_then(|x| x.max_dynamic_efficiency.map(Num)),
                            peak_applied_friction_force: r
                                .response
                                .as_ref()
                                .and_then(|x| x.peak_friction_force.map(|e| located(e, "N"))),
                            peak_friction_torque: r
                                .response
                                .as_ref()
                                .and_then(|x| x.peak_friction_torque)
                                .map_or_else(Vec::new, |t| t.iter().map(|e| located(*e, "N*m")).collect()),
                            peak_mu_times_tooth_force: r
                                .response
                                .as_ref()
                                .and_then(|x| x.peak_mu_times_tooth_force.map(|e| located(e, "N"))),
                            free_response: r.free.as_ref().map(free_report),
                            pair_force_max: None,
                            friction_force_mean: None,
                            gears: Vec::new(),
                        };
                        if let Some(x) = &r.six_dof {
                            six_dof_fields(&mut f, x);
                        }
                        f
                    })
                    .collect(),
            }
        })
        .collect();
    let stability_map = d.stability_map.as_ref().map(|rows| {
        let unstable_ranges = d
            .unstable_ranges
            .iter()
            .map(|ranges| ranges.iter().map(|(a, b)| [Q::new(*a, "rad/s"), Q::new(*b, "rad/s")]).collect())
            .collect();
        StabilityMapReport {
            pinion_torque: Q::new(scene.operating.pinion_torque.values[0].value, "N*m"),
            formulations: d.formulations.clone(),
            unstable_ranges,
            speed_unit: scene.analyses.stability_map.as_ref().map(DisplayUnit::of).unwrap_or_default(),
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
    });
    let (numerics, timings) = match &d.numerics {
        None => (None, None),
        Some((f, _, study)) => (
            Some(NumericsReport {
                formulation: *f,
                reference: study.reference,
                periods: study.periods,
                runs: study
                    .runs
                    .iter()
                    .map(|r| NumericsRow {
                        method: r.method.clone(),
                        rtol: Num(r.rtol),
                        error: finite(r.error),
                        final_state_error: finite(r.final_state_error),
                        steps: r.counts.steps,
                        rejected: r.counts.rejected,
                        evaluations: r.counts.evaluations,
                        failure: r.failure.clone(),
                    })
                    .collect(),
            }),
            Some(Timings {
                reference_seconds: study.reference_seconds,
                runs: study.runs.iter().map(|r| (r.method.clone(), r.rtol, r.error, r.seconds)).collect(),
            }),
        ),
    };
    DynamicsReport {
        model: d.model,
        stiffness_step_ratio: match &d.stiffness {
            StiffnessModel::PairsInContact { single, double, .. } => Some(double / single),
            StiffnessModel::Table(_) | StiffnessModel::PerLength { .. } => None,
        },
        stiffness_source: d.stiffness_source,
        stiffness,
        damping_ratio: Num(d.damping_ratio),
        equivalent_mass: Q::new(d.equivalent_mass, "kg"),
        damping: Q::new(d.damping, "N*s/m"),
        mean_stiffness: Q::new(d.mean_stiffness, "N/m"),
        natural_frequency: Q::new(d.natural_frequency, "Hz"),
        natural_frequencies: d.natural_frequencies.iter().map(|f| Q::new(*f, "Hz")).collect(),
        stiffness_ratio: d.stiffness_ratio.map(Num),
        friction: scene.dynamics.as_ref().and_then(|s| s.friction.as_ref()).map(super::friction::law_label),
        friction_diverges_at_pitch: d.friction_diverges_at_pitch,
        points,
        stability_map,
        numerics,
        curves,
        timings,
    }
}
