//! The error-against-run-time study (`numerics` analysis): every method over a tolerance ladder
//! against the exact (or converged Magnus) reference, started from the static deflection and run for
//! [`PERIODS`] mesh periods. Error = max |x − x_ref| over the last period / peak-to-peak DTE of the
//! reference there; final-state error = |X − X_ref| at the end in the scaled state norm. Run time is
//! the minimum of [`REPEATS`] runs. Timings never enter snapshotted text: they are written to
//! `timing_numerics.json` and `timing_work_precision.svg` only.

use std::time::Instant;

use nalgebra::{Matrix4, Vector2};
use serde::Serialize;

use super::integrators::{integrate, Counts, Integrator};
use super::propagator::{from_exponential, magnus, magnus_adaptive, segment_matrix};
use super::propagator::{period_segments, Method};
use super::sdof::SdofSystem;

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
    /// max |x − x_ref| over the last period / peak-to-peak DTE.
    pub error: f64,
    pub final_state_error: f64,
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

/// The state at each sample time (τ in mesh periods, sorted, within [0, 1)), marching segment by
/// segment from X(0). For the exact propagator exp(M dt) is cached for the common sample step.
pub fn states(sys: &SdofSystem, x0: Vector2<f64>, taus: &[f64]) -> Vec<Vector2<f64>> {
    let mut out = Vec::with_capacity(taus.len());
    let mut x = x0;
    let mut t = 0.0;
    let mut k = 0;
    let exact = sys.exact_applies();
    for seg in &sys.segments {
        let m = exact.then(|| segment_matrix(sys, seg.start, seg.end));
        // Magnus: the substep density that converged over the whole segment, reused for each sample step.
        let density = if exact {
            0.0
        } else {
            magnus_adaptive(sys, seg.start, seg.end - seg.start).1 as f64 / (seg.end - seg.start)
        };
        let mut cache: Option<(f64, Matrix4<f64>)> = None;
        let mut step = |x: &Vector2<f64>, from: f64, dt: f64| -> Vector2<f64> {
            match &m {
                Some(m) => {
                    let e = match &cache {
                        Some((h, e)) if (*h - dt).abs() <= 1e-12 * dt => *e,
                        _ => {
                            let e = (m * dt).exp();
                            cache = Some((dt, e));
                            e
                        }
                    };
                    from_exponential(&e, from - seg.start).apply(x)
                }
                None => magnus(sys, from, dt, ((density * dt).ceil() as usize).max(2)).apply(x),
            }
        };
        while k < taus.len() && taus[k] * sys.period < seg.end {
            let target = taus[k] * sys.period;
            if target > t {
                x = step(&x, t, target - t);
                t = target;
            }
            out.push(x);
            k += 1;
        }
        if seg.end > t {
            x = step(&x, t, seg.end - t);
            t = seg.end;
        }
    }
    out
}

/// The reference states at `times` (absolute), marching the propagators from x0.
pub fn reference(sys: &SdofSystem, x0: Vector2<f64>, times: &[f64]) -> Vec<Vector2<f64>> {
    let (segs, _) = period_segments(sys);
    let mut out = Vec::with_capacity(times.len());
    let mut start = x0;
    let mut k = 0;
    for p in 0..PERIODS {
        let offset = p as f64 * sys.period;
        let local: Vec<f64> =
            times[k..].iter().take_while(|t| **t < offset + sys.period).map(|t| (t - offset) / sys.period).collect();
        out.extend(states(sys, start, &local));
        k += local.len();
        start = segs.iter().fold(start, |x, s| s.apply(&x));
    }
    while out.len() < times.len() {
        out.push(start);
    }
    out
}

pub fn study(sys: &SdofSystem) -> Study {
    let x0 = Vector2::new(sys.static_force / sys.mean_stiffness, 0.0);
    let last = (PERIODS - 1) as f64 * sys.period;
    let mut times: Vec<f64> =
        (0..SAMPLES_LAST_PERIOD).map(|i| last + sys.period * i as f64 / SAMPLES_LAST_PERIOD as f64).collect();
    times.push(PERIODS as f64 * sys.period);
    let mut best = f64::INFINITY;
    let mut reference_states = Vec::new();
    for _ in 0..REPEATS {
        let t0 = Instant::now();
        reference_states = reference(sys, x0, &times);
        best = best.min(t0.elapsed().as_secs_f64());
    }
    let xs: Vec<f64> = reference_states[..SAMPLES_LAST_PERIOD].iter().map(|x| x[0]).collect();
    let p2p = xs.iter().fold(f64::NEG_INFINITY, |a, b| a.max(*b)) - xs.iter().fold(f64::INFINITY, |a, b| a.min(*b));
    let scale = sys.static_force / sys.mean_stiffness;
    let vscale = scale * (sys.mean_stiffness / sys.equivalent_mass).sqrt();
    let (_, method) = period_segments(sys);
    let mut runs = Vec::new();
    for integrator in Integrator::ALL {
        for rtol in LADDER {
            let mut seconds = f64::INFINITY;
            let mut result = None;
            for _ in 0..REPEATS {
                let t0 = Instant::now();
                let r = integrate(sys, integrator, rtol, [x0[0], x0[1]], &times);
                seconds = seconds.min(t0.elapsed().as_secs_f64());
                let failed = r.is_err();
                result = Some(r);
                if failed {
                    break;
                }
            }
            let run = match result.expect("one repeat ran") {
                Ok((states, counts)) => {
                    let err = states[..SAMPLES_LAST_PERIOD]
                        .iter()
                        .zip(&reference_states)
                        .map(|(a, b)| (a[0] - b[0]).abs())
                        .fold(0.0, f64::max)
                        / p2p.max(f64::MIN_POSITIVE);
                    let (a, b) = (states[SAMPLES_LAST_PERIOD], reference_states[SAMPLES_LAST_PERIOD]);
                    let fse = ((a[0] - b[0]) / scale).hypot((a[1] - b[1]) / vscale);
                    Run {
                        method: integrator.name().into(),
                        rtol,
                        error: err,
                        final_state_error: fse,
                        seconds,
                        counts,
                        failure: None,
                    }
                }
                Err(e) => Run {
                    method: integrator.name().into(),
                    rtol,
                    error: f64::NAN,
                    final_state_error: f64::NAN,
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
