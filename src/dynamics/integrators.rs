//! General ODE integrators from the `differential-equations` crate — DOP853 and DOPRI5 (explicit,
//! adaptive), Radau IIA 5 and Kværnø 7(4,5) ESDIRK (implicit, L-stable) — run segment by segment on
//! any [`PeriodicModel`]: every integration restarts at every switch time (zone boundaries,
//! pitch-point passages, regime switches), so no step ever crosses a jump of A(t) or b(t).
//!
//! The state is scaled, z = X / s with s the model's [`PeriodicModel::state_scale`] (for the SDOF
//! model x_s = F0/k̄ and x_s ω_n), so that one absolute tolerance (= the relative one) fits every
//! component. Each restart keeps only the state at its end (no step history is stored).

use differential_equations::control::ControlFlag;
use differential_equations::interpolate::Interpolation;
use differential_equations::ode::solve_ode;
use differential_equations::prelude::*;
use differential_equations::solout::Solout;
use nalgebra::{SMatrix, SVector};
use serde::Serialize;

use super::model::PeriodicModel;
use super::propagator::AffineSegment;

/// An integrator of the study.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Integrator {
    Dop853,
    Dopri5,
    Radau5,
    Kvaerno745,
}

impl Integrator {
    pub const ALL: [Integrator; 4] =
        [Integrator::Dop853, Integrator::Dopri5, Integrator::Radau5, Integrator::Kvaerno745];

    pub fn name(self) -> &'static str {
        match self {
            Integrator::Dop853 => "dop853",
            Integrator::Dopri5 => "dopri5",
            Integrator::Radau5 => "radau5",
            Integrator::Kvaerno745 => "esdirk_kvaerno745",
        }
    }
}

/// Counts of one integration.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct Counts {
    pub steps: usize,
    pub rejected: usize,
    pub evaluations: usize,
}

/// The scaled system on one restart interval: on an affine segment its scaled affine form
/// (dz/dt = A_s z + b0_s + b1_s (t − start), a few multiply-adds), the model itself otherwise.
/// Either way the right-hand side is one-sided: the model is read at times clamped just inside the
/// segment (`window`), so a stage at the segment's end never sees the next segment's k(t) or μ sign.
struct Scaled<'a, M: ?Sized, const N: usize> {
    model: &'a M,
    scale: SVector<f64, N>,
    affine: Option<AffineSegment<N>>,
    window: (f64, f64),
}

impl<M: PeriodicModel<N> + ?Sized, const N: usize> Scaled<'_, M, N> {
    /// A_s = S⁻¹ A S, b_s = S⁻¹ b of an affine segment.
    fn scaled(&self, seg: &AffineSegment<N>) -> AffineSegment<N> {
        let s = &self.scale;
        AffineSegment {
            start: seg.start,
            a: scaled_matrix(&seg.a, s),
            b0: seg.b0.component_div(s),
            b1: seg.b1.component_div(s),
        }
    }
}

impl<M: PeriodicModel<N> + ?Sized, const N: usize> ODE<f64, [f64; N]> for Scaled<'_, M, N> {
    fn diff(&self, t: f64, z: &[f64; N], dz: &mut [f64; N]) {
        if let Some(seg) = &self.affine {
            let d = seg.rhs(t, &SVector::from(*z));
            dz.copy_from_slice(d.as_slice());
            return;
        }
        let (a, b) = self.model.system(t.clamp(self.window.0, self.window.1));
        let x = SVector::<f64, N>::from_fn(|i, _| z[i] * self.scale[i]);
        let d = a * x + b;
        for i in 0..N {
            dz[i] = d[i] / self.scale[i];
        }
    }

    /// The exact Jacobian of the scaled linear system (the implicit methods need no finite differences).
    fn jacobian(&self, t: f64, _z: &[f64; N], j: &mut Matrix<f64>) {
        if let Some(seg) = &self.affine {
            for r in 0..N {
                for c in 0..N {
                    j[(r, c)] = seg.a[(r, c)];
                }
            }
            return;
        }
        let (a, _) = self.model.system(t.clamp(self.window.0, self.window.1));
        let a = scaled_matrix(&a, &self.scale);
        for r in 0..N {
            for c in 0..N {
                j[(r, c)] = a[(r, c)];
            }
        }
    }
}

/// S⁻¹ A S for the scaled state z = X / s (the diagonal kept as it is, exactly).
fn scaled_matrix<const N: usize>(a: &SMatrix<f64, N, N>, s: &SVector<f64, N>) -> SMatrix<f64, N, N> {
    SMatrix::from_fn(|r, c| if r == c { a[(r, c)] } else { a[(r, c)] * s[c] / s[r] })
}

/// Keeps the last state the solver reached, and nothing else.
struct LastState<const N: usize> {
    t: f64,
    y: [f64; N],
}

impl<const N: usize> Solout<f64, [f64; N]> for LastState<N> {
    fn solout<I>(
        &mut self,
        t_curr: f64,
        _t_prev: f64,
        y_curr: &[f64; N],
        _y_prev: &[f64; N],
        _interpolator: &mut I,
        _solution: &mut Solution<f64, [f64; N]>,
    ) -> ControlFlag<f64, [f64; N]>
    where
        I: Interpolation<f64, [f64; N]> + ?Sized,
    {
        self.t = t_curr;
        self.y = *y_curr;
        ControlFlag::Continue
    }
}

/// One restart: integrates from `z` at `ta` to `tb`; returns the end state and the counts.
fn segment<M: PeriodicModel<N> + ?Sized, const N: usize>(
    ode: &Scaled<M, N>,
    method: Integrator,
    rtol: f64,
    ta: f64,
    tb: f64,
    z: [f64; N],
) -> Result<(f64, [f64; N], Counts), String> {
    let mut out = LastState { t: ta, y: z };
    let sol = match method {
        Integrator::Dop853 => {
            let mut m = ExplicitRungeKutta::dop853().rtol(rtol).atol(rtol).max_steps(10_000_000);
            solve_ode(&mut m, ode, ta, tb, &z, &mut out)
        }
        Integrator::Dopri5 => {
            let mut m = ExplicitRungeKutta::dopri5().rtol(rtol).atol(rtol).max_steps(10_000_000);
            solve_ode(&mut m, ode, ta, tb, &z, &mut out)
        }
        // Newton tolerance 0 selects Hairer's RADAU5 rule, FNEWT = max(10 u/rtol', min(0.03, sqrt(rtol'))),
        // instead of the crate's fixed 3.2e-3. Radau5 controls the error on rtol' = 0.1 rtol^(2/3)
        // (Hairer & Wanner's convention, which the crate follows): rtol = 1e-12 asks for 1e-9 per step,
        // so over ~1e4 steps its global error stays near 1e-7 of the DTE peak-to-peak (README, limits).
        Integrator::Radau5 => {
            let mut m = ImplicitRungeKutta::radau5().rtol(rtol).atol(rtol).newton_tol(0.0).max_steps(10_000_000);
            solve_ode(&mut m, ode, ta, tb, &z, &mut out)
        }
        Integrator::Kvaerno745 => {
            let mut m = DiagonallyImplicitRungeKutta::kvaerno745()
                .rtol(rtol)
                .atol(rtol)
                .max_steps(10_000_000)
                .max_rejects(1000);
            solve_ode(&mut m, ode, ta, tb, &z, &mut out)
        }
    }
    .map_err(|e| format!("{} failed on [{ta:e}, {tb:e}] s: {e:?}", method.name()))?;
    let counts = Counts {
        steps: sol.steps.accepted + sol.steps.rejected,
        rejected: sol.steps.rejected,
        evaluations: sol.evals.function,
    };
    Ok((out.t, out.y, counts))
}

/// Integrates from `x0` at t = 0 to the last of `times` (absolute, sorted, within the switch times),
/// restarting at every switch time; returns the states at `times` and the counts.
pub fn integrate<M: PeriodicModel<N> + ?Sized, const N: usize>(
    model: &M,
    method: Integrator,
    rtol: f64,
    x0: [f64; N],
    times: &[f64],
) -> Result<(Vec<[f64; N]>, Counts), String> {
    let scale = model.state_scale();
    let period = model.period();
    let base = Scaled { model, scale, affine: None, window: (0.0, 0.0) };
    // The affine form of every affine segment, computed once (scaled); None where the model is general.
    let forms: Vec<Option<AffineSegment<N>>> = model
        .segments()
        .iter()
        .enumerate()
        .map(|(j, s)| model.segment_is_affine(j).then(|| base.scaled(&AffineSegment::of(model, s.start, s.end))))
        .collect();
    let segment_of = |t: f64| {
        let p = (t / period).floor();
        let local = t - p * period;
        let j = model.segments().partition_point(|s| s.end <= local).min(model.segments().len() - 1);
        let s = model.segments()[j];
        let d = (1e-12 * period).min(0.25 * (s.end - s.start));
        (p * period, j, (p * period + s.start + d, p * period + s.end - d))
    };
    let t_end = *times.last().ok_or("no output times")?;
    let periods = (t_end / period).ceil() as usize + 1;
    // Restart at every switch time, and stop at every output time (the crate's t_eval output is not
    // reliable for every method, so outputs are taken as segment ends).
    let mut stops: Vec<f64> = model.switch_times(periods).into_iter().filter(|t| *t < t_end).collect();
    stops.extend(times.iter().copied().filter(|t| *t > 0.0));
    stops.sort_by(f64::total_cmp);
    stops.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * b.abs().max(period));
    let mut z: [f64; N] = std::array::from_fn(|i| x0[i] / scale[i]);
    let mut out: Vec<Option<[f64; N]>> = times.iter().map(|t| (*t <= 0.0).then_some(x0)).collect();
    let mut counts = Counts::default();
    let same = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs().max(period);
    for w in stops.windows(2) {
        let (ta, tb) = (w[0], w[1]);
        if tb <= ta {
            continue;
        }
        let (offset, j, window) = segment_of(0.5 * (ta + tb));
        let ode = Scaled { affine: forms[j].map(|f| AffineSegment { start: f.start + offset, ..f }), window, ..base };
        let (t_last, y_last, c) = segment(&ode, method, rtol, ta, tb, z)?;
        counts.steps += c.steps;
        counts.rejected += c.rejected;
        counts.evaluations += c.evaluations;
        if !same(t_last, tb) {
            return Err(format!("{} stopped before {tb:e} s (at {t_last:e} s)", method.name()));
        }
        z = y_last;
        if !z.iter().all(|v| v.is_finite()) {
            return Err(format!("{} produced a non-finite state at t = {t_last:e} s", method.name()));
        }
        for (i, ti) in times.iter().enumerate() {
            if same(*ti, tb) {
                out[i] = Some(std::array::from_fn(|k| z[k] * scale[k]));
            }
        }
    }
    let out: Vec<[f64; N]> = out.into_iter().collect::<Option<_>>().ok_or("an output time was not reached")?;
    Ok((out, counts))
}
