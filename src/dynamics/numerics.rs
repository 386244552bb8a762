//! The error-against-run-time study (`numerics` analysis): every method over a tolerance ladder
//! against the exact (or converged Magnus) reference, started from the static deflection and run for
//! [`PERIODS`] mesh periods. Error = max |x − x_ref| over the last period / peak-to-peak DTE of the
//! reference there; final-state error = |X − X_ref| at the end in the scaled state norm. Run time is
//! the minimum of [`REPEATS`] runs. Timings never enter snapshotted text: they are written to
//! `timing_numerics.json` and `timing_work_precision.svg` only.

use std::time::Instant;

use nalgebra::SVector;
use serde::Serialize;

use super::integrators::{integrate, Counts, Integrator};
use super::model::PeriodicModel;
use super::propagator::{period_segments, Method, PeriodPropagation, SegmentExponential, SegmentRoute};

pub const PERIODS: usize = 10;
pub const REPEATS: usize = 3;
pub const SAMPLES_LAST_PERIOD: usize = 128;
/// rtol 1e-3 … 1e-12.
pub const LADDER: [f64; 10] = [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12];
/// A method stops climbing the ladder once one run needs more right-hand-side evaluations than this
/// (a count, not a time, so that the table is the same on every machine).
pub const EVALUATION_BUDGET: usize = 2_000_000;

#[derive(Debug, Clone, Serialize)]
pub struct Run {
    pub method: String,
    pub rtol: f64,
    /// max |x − x_ref| over the last period / peak-to-peak DTE (none for a failed run).
    pub error: Option<f64>,
    pub final_state_error: Option<f64>,
    pub seconds: f64,
    pub counts: Counts,
    pub failure: Option<String>,
}

#[derive(Debug, Clone, Serialize)]
pub struct Study {
    pub reference: Method,
    pub reference_seconds: f64,
    pub periods: usize,
    pub runs: Vec<Run>,
}

/// The state at each sample time (τ in periods, sorted, within [0, 1)), marching segment by segment
/// from X(0) on the period's routes. On an exact route exp(M dt) is computed once for the common
/// sample step, and a segment without samples is crossed with its known propagation.
pub fn states<M: PeriodicModel<N> + ?Sized, const N: usize>(
    sys: &M,
    period: &PeriodPropagation<N>,
    x0: SVector<f64, N>,
    taus: &[f64],
) -> Vec<SVector<f64, N>> {
    let mut out = Vec::with_capacity(taus.len());
    let mut x = x0;
    let mut k = 0;
    let length = sys.period();
    for ((seg, route), whole) in sys.segments().iter().zip(&period.routes).zip(&period.segments) {
        if !(k < taus.len() && taus[k] * length < seg.end) {
            x = whole.apply(&x);
            continue;
        }
        let mut t = seg.start;
        let mut cache: Option<(f64, SegmentExponential<N>)> = None;
        let mut step = |x: &SVector<f64, N>, from: f64, dt: f64| -> SVector<f64, N> {
            match route {
                SegmentRoute::Exact(s) => {
                    let e = match &cache {
                        Some((h, e)) if (*h - dt).abs() <= 1e-12 * dt => *e,
                        _ => {
                            let e = s.exponential(dt);
                            cache = Some((dt, e));
                            e
                        }
                    };
                    e.from(from - seg.start).apply(x)
                }
                SegmentRoute::RankOne(_) | SegmentRoute::Magnus { .. } => route.propagate(sys, from, dt).apply(x),
            }
        };
        let entry = x;
        while k < taus.len() && taus[k] * length < seg.end {
            let target = taus[k] * length;
            if target > t {
                x = step(&x, t, target - t);
                t = target;
            }
            out.push(x);
            k += 1;
        }
        // The segment's end from its entry state, as in the monodromy (no extra exponential).
        x = whole.apply(&entry);
    }
    out
}

/// The reference states at `times` (absolute), marching the propagators from x0.
pub fn reference<M: PeriodicModel<N> + ?Sized, const N: usize>(
    sys: &M,
    x0: SVector<f64, N>,
    times: &[f64],
) -> Vec<SVector<f64, N>> {
    reference_by_method(sys, x0, times).0
}

/// [`reference()`] and the method its period was propagated by.
pub fn reference_by_method<M: PeriodicModel<N> + ?Sized, const N: usize>(
    sys: &M,
    x0: SVector<f64, N>,
    times: &[f64],
) -> (Vec<SVector<f64, N>>, Method) {
    let period = period_segments(sys);
    let length = sys.period();
    let mut out = Vec::with_capacity(times.len());
    let mut start = x0;
    let mut k = 0;
    for p in 0..PERIODS {
        let offset = p as f64 * length;
        let local: Vec<f64> =
            times[k..].iter().take_while(|t| **t < offset + length).map(|t| (t - offset) / length).collect();
        if !local.is_empty() {
            out.extend(states(sys, &period, start, &local));
            k += local.len();
        }
        start = period.segments.iter().fold(start, |x, s| s.apply(&x));
    }
    while out.len() < times.len() {
        out.push(start);
    }
    (out, period.method)
}

/// The output times of the study: [`SAMPLES_LAST_PERIOD`] equal steps over the last of [`PERIODS`]
/// periods, and the end of the run.
pub fn study_times(period: f64) -> Vec<f64> {
    let last = (PERIODS - 1) as f64 * period;
    let mut times: Vec<f64> =
        (0..SAMPLES_LAST_PERIOD).map(|i| last + period * i as f64 / SAMPLES_LAST_PERIOD as f64).collect();
    times.push(PERIODS as f64 * period);
    times
}

/// max |x − x_ref| over the last period / peak-to-peak of x_ref there (x: the model's observed displacement).
pub fn relative_error<M: PeriodicModel<N> + ?Sized, const N: usize>(
    sys: &M,
    states: &[[f64; N]],
    reference: &[SVector<f64, N>],
) -> f64 {
    let xs: Vec<f64> = reference[..SAMPLES_LAST_PERIOD].iter().map(|x| sys.observed(x)).collect();
    let p2p = xs.iter().fold(f64::NEG_INFINITY, |a, b| a.max(*b)) - xs.iter().fold(f64::INFINITY, |a, b| a.min(*b));
    states[..SAMPLES_LAST_PERIOD]
        .iter()
        .zip(reference)
        .map(|(a, b)| (sys.observed(&SVector::from(*a)) - sys.observed(b)).abs())
        .fold(0.0, f64::max)
        / p2p.max(f64::MIN_POSITIVE)
}

/// The study on `sys`, started from `x0` (the static deflection).
pub fn study<M: PeriodicModel<N> + ?Sized, const N: usize>(sys: &M, x0: SVector<f64, N>) -> Study {
    let length = sys.period();
    let times = study_times(length);
    let mut best = f64::INFINITY;
    let mut reference_states = Vec::new();
    let mut method = Method::Exact;
    for _ in 0..REPEATS {
        let t0 = Instant::now();
        (reference_states, method) = reference_by_method(sys, x0, &times);
        best = best.min(t0.elapsed().as_secs_f64());
    }
    let scale = sys.state_scale();
    let mut runs = Vec::new();
    for integrator in Integrator::ALL {
        for rtol in LADDER {
            let mut seconds = f64::INFINITY;
            let mut result = None;
            for _ in 0..REPEATS {
                let t0 = Instant::now();
                let r = integrate(sys, integrator, rtol, std::array::from_fn(|i| x0[i]), &times);
                seconds = seconds.min(t0.elapsed().as_secs_f64());
                let failed = r.is_err();
                result = Some(r);
                if failed {
                    break;
                }
            }
            let run = match result.expect("one repeat ran") {
                Ok((states, counts)) => {
                    let err = relative_error(sys, &states, &reference_states);
                    let (a, b) = (states[SAMPLES_LAST_PERIOD], reference_states[SAMPLES_LAST_PERIOD]);
                    // The scaled state norm, as a chain of hypot (no overflow, exact for one component).
                    let fse =
                        (SVector::<f64, N>::from(a) - b).component_div(&scale).iter().fold(0.0_f64, |n, v| n.hypot(*v));
                    Run {
                        method: integrator.name().into(),
                        rtol,
                        error: Some(err),
                        final_state_error: Some(fse),
                        seconds,
                        counts,
                        failure: None,
                    }
                }
                Err(e) => Run {
                    method: integrator.name().into(),
                    rtol,
                    error: None,
                    final_state_error: None,
                    seconds,
                    counts: Counts::default(),
                    failure: Some(e),
                },
            };
            let stop = run.failure.is_some() || run.counts.evaluations > EVALUATION_BUDGET;
            runs.push(run);
            if stop {
                break;
            }
        }
    }
    Study { reference: method, reference_seconds: best, periods: PERIODS, runs }
}
