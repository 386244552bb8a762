//! The sweep, streamed: the plan's points are evaluated in blocks of [`BLOCK`] (in parallel within
//! a block), each point's summary rows go to the record sink in sweep order and its tally is folded
//! in; nothing of a point is kept beyond its block, so memory is bounded whatever the sweep's size
//! and time grows linearly with it.

use rayon::prelude::*;

use super::cases::{case_at, state_at};
use super::dynamics::{DynamicsPoint, DynamicsSetup};
use super::laws::{evaluate_law, LawEvaluation};
use super::plan::Plan;
use super::records::{RecordSink, RowKind, SummaryRow};
use super::setup::{contact_table, Setup};
use super::tally::{furthest_beyond_half_width, implausible_efficiency};
use super::tally::{Implausible, ImplausibleAt, LawNote, LawTally, Tally, WorstValidity, HALF_WIDTH_LIMIT};
use crate::efficiency::EfficiencyResult;
use crate::mesh::MeshProblem;

/// Points evaluated together before their rows are written.
pub(crate) const BLOCK: usize = 1024;

/// What the stream computed beyond the tally: the dynamics of the detail points in its range, and
/// the teeth when its first point wrote their rows, so that the details of a single run do not
/// compute them twice.
#[derive(Debug, Default)]
pub struct Streamed {
    pub tally: Tally,
    /// (point, its dynamics), for the plan's detail points.
    pub detail_dynamics: Vec<(usize, DynamicsPoint)>,
    /// The pair's stiffness and transmission error, when the stream computed them.
    pub teeth: Option<super::teeth::TeethDetails>,
}

/// Evaluates the plan's range of points, writes their rows to `sink` and returns their tally;
/// `tick(n)` is called after each block with the number of points it held; when it answers false
/// the run stops there with an `Interrupted` error.
pub fn evaluate_records(
    problem: &MeshProblem,
    eval: &Setup,
    plan: &Plan,
    sink: &mut dyn RecordSink,
    tick: &(dyn Fn(usize) -> bool + Sync),
) -> std::io::Result<Streamed> {
    let labels: Vec<String> = problem.friction.iter().map(|l| l.label()).collect();
    let dynamics = DynamicsSetup::new(problem, eval.law_context(state_at(&problem.operating, 0)))
        .filter(|_| problem.analyses.dynamics);
    let mut out = Streamed::default();
    // The transmission error's rows come first, from the run (or shard) that holds point 1.
    if plan.range.start == 0 && problem.analyses.transmission_error.is_some() {
        out.teeth = super::teeth::teeth_details(problem, &eval.geometry);
        if let Some(teeth) = &out.teeth {
            sink.write_rows(&transmission_error_rows(teeth))?;
        }
    }
    let mut start = plan.range.start;
    while start < plan.range.end {
        let end = (start + BLOCK).min(plan.range.end);
        let block: Vec<Summary> = (start..end)
            .into_par_iter()
            .map(|k| point_summary(problem, eval, plan, &labels, dynamics.as_ref(), k))
            .collect();
        for (k, (rows, t, d)) in (start..end).zip(block) {
            sink.write_rows(&rows)?;
            out.tally.absorb(t);
            if let Some(d) = d.filter(|_| plan.detail.binary_search(&k).is_ok()) {
                out.detail_dynamics.push((k, d));
            }
        }
        if !tick(end - start) {
            return Err(std::io::Error::new(std::io::ErrorKind::Interrupted, "the run was interrupted"));
        }
        start = end;
    }
    Ok(out)
}

/// A point's rows, tally and dynamics (when the scene asks for them).
type Summary = (Vec<SummaryRow>, Tally, Option<DynamicsPoint>);

/// The rows and the tally of point `k`.
fn point_summary(
    problem: &MeshProblem,
    eval: &Setup,
    plan: &Plan,
    labels: &[String],
    dynamics: Option<&DynamicsSetup>,
    k: usize,
) -> Summary {
    let op = &problem.operating;
    let state = state_at(op, k);
    let (ti, si) = (k / plan.speeds, k % plan.speeds);
    let table = contact_table(eval, &state);
    let blank = SummaryRow::blank(k + 1, (ti, si), state);
    let mut rows = Vec::new();
    let mut laws = Vec::new();
    let mut implausible: Vec<Implausible> = Vec::new();
    implausible.extend(furthest_beyond_half_width(table.iter().copied()).map(|(name, c)| Implausible::HalfWidth {
        half_width: c.hertz_half_width,
        limit: HALF_WIDTH_LIMIT * c.reduced_radius,
        u: c.u,
        named: name.map(str::to_string),
    }));
    if eval.wants_friction {
        let input = state.pinion_torque * state.pinion_speed;
        for (i, spec) in problem.friction.iter().enumerate() {
            let law = evaluate_law(eval, spec, state, &table, false, false);
            let law_row = SummaryRow {
                law_index: Some(i),
                law: law.id.name().to_string(),
                label: labels[i].clone(),
                mean_abs_mu: Some(law.mean_abs_mu.value),
                validity_samples: Some(law.validity.samples),
                validity_outside: Some(law.validity.outside),
                parameters: law.parameter_values(),
                ..blank.clone()
            };
            if law.efficiency.is_empty() {
                rows.push(law_row.clone());
            }
            for e in &law.efficiency {
                rows.push(efficiency_row(&law_row, e));
                implausible.extend(implausible_efficiency(law.id.name(), e, input));
            }
            laws.push(law_tally(k, &law));
        }
    }
    let mut dynamics_point = None;
    if let Some(setup) = dynamics {
        let point = setup.point(k, state);
        let law = problem.dynamics.as_ref().and_then(|d| d.friction.as_ref());
        for r in &point.results {
            let friction = law.filter(|_| r.formulation != crate::dynamics::DynamicFormulation::Base);
            let resp = r.response.as_ref();
            rows.push(SummaryRow {
                kind: RowKind::Dynamics,
                law: friction.map_or(String::new(), |l| l.law.name().to_string()),
                label: friction.map_or(String::new(), |l| l.label()),
                formulation: r.formulation.name().to_string(),
                spectral_radius: Some(r.spectral_radius),
                dte_peak_to_peak: resp.map(|x| x.dte.peak_to_peak()),
                dte_mean: resp.map(|x| x.dte.mean.value),
                dynamic_factor: resp.map(|x| x.dynamic_factor),
                ..blank.clone()
            });
        }
        dynamics_point = Some(point);
    }
    let implausible =
        implausible.into_iter().map(|what| ImplausibleAt { point: k, label: case_at(op, k).label, what }).collect();
    let tally = Tally::of_point(k, &rows, plan.kept(k), laws, implausible);
    (rows, tally, dynamics_point)
}

fn efficiency_row(law_row: &SummaryRow, e: &EfficiencyResult) -> SummaryRow {
    SummaryRow {
        kind: RowKind::Efficiency,
        formulation: e.formulation.name().to_string(),
        mean_efficiency: Some(e.mean.value),
        mean_efficiency_error: Some(e.mean.error),
        min_efficiency: Some(e.min),
        max_efficiency: Some(e.max),
        power_loss: Some(e.power_loss),
        ..law_row.clone()
    }
}

fn law_tally(k: usize, law: &LawEvaluation) -> LawTally {
    LawTally {
        points: 1,
        notes: law.notes.iter().map(|t| LawNote { text: t.clone(), points: vec![k], count: 1 }).collect(),
        diverges_at_pitch: law.diverges_at_pitch,
        capped_points: usize::from(law.internal_cap_band.is_some()),
        widest_cap: law.internal_cap_band.map(|(a, b)| (k, a, b)),
        flagged_points: usize::from(law.validity.outside > 0),
        worst: (law.validity.outside > 0).then(|| WorstValidity {
            point: k,
            outside: law.validity.outside,
            samples: law.validity.samples,
            intervals: law.validity.intervals.iter().map(|(a, b, r)| (*a, *b, r.to_string())).collect(),
        }),
    }
}

/// One `transmission_error` record per torque of the analysis, in its order: point 0 (not an
/// operating point), the torque's index in the analysis, speed 0 (the error is static).
fn transmission_error_rows(details: &super::teeth::TeethDetails) -> Vec<SummaryRow> {
    details
        .transmission_error
        .iter()
        .enumerate()
        .map(|(i, te)| SummaryRow {
            kind: RowKind::TransmissionError,
            ste: Some(super::ste_row::SteRow::of(te)),
            ..SummaryRow::blank(
                0,
                (i, 0),
                crate::geometry::OperatingState { pinion_torque: te.pinion_torque, pinion_speed: 0.0 },
            )
        })
        .collect()
}
