//! General ODE integrators from the `differential-equations` crate — DOP853 and DOPRI5 (explicit,
//! adaptive), Radau IIA 5 and Kværnø 7(4,5) ESDIRK (implicit, L-stable) — run segment by segment:
//! every integration restarts at every switch time (zone boundaries, pitch-point passages, regime
//! switches), so no step ever crosses a jump of k(t) or a kink of f(t).
//!
//! The state is scaled, z = [x / x_s, ẋ / (x_s ω_n)] with x_s = F0/k̄ and ω_n = sqrt(k̄/m_e), so that
//! one absolute tolerance (= the relative one) fits both components.

use differential_equations::prelude::*;
use serde::Serialize;

use super::sdof::SdofSystem;

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

struct Scaled<'a> {
    sys: &'a SdofSystem<'a>,
    xs: f64,
    vs: f64,
}

impl ODE<f64, [f64; 2]> for Scaled<'_> {
    fn diff(&self, t: f64, z: &[f64; 2], dz: &mut [f64; 2]) {
        let d = self.sys.rhs(t, &[z[0] * self.xs, z[1] * self.vs]);
        dz[0] = d[0] / self.xs;
        dz[1] = d[1] / self.vs;
    }

    /// The exact Jacobian of the scaled linear system (the implicit methods need no finite differences).
    fn jacobian(&self, t: f64, _z: &[f64; 2], j: &mut Matrix<f64>) {
        let (a, _) = self.sys.matrices(t);
        j[(0, 0)] = a[0][0];
        j[(0, 1)] = a[0][1] * self.vs / self.xs;
        j[(1, 0)] = a[1][0] * self.xs / self.vs;
        j[(1, 1)] = a[1][1];
    }
}

/// Integrates from `x0` at t = 0 to the last of `times` (absolute, sorted, within the switch times),
/// restarting at every switch time; returns the states at `times` and the counts.
pub fn integrate(
    sys: &SdofSystem,
    method: Integrator,
    rtol: f64,
    x0: [f64; 2],
    times: &[f64],
) -> Result<(Vec<[f64; 2]>, Counts), String> {
    let xs = sys.static_force / sys.mean_stiffness;
    let vs = xs * (sys.mean_stiffness / sys.equivalent_mass).sqrt();
    let ode = Scaled { sys, xs, vs };
    let t_end = *times.last().ok_or("no output times")?;
    let periods = (t_end / sys.period).ceil() as usize + 1;
    // Restart at every switch time, and stop at every output time (the crate's t_eval output is not
    // reliable for every method, so outputs are taken as segment ends).
    let mut stops: Vec<f64> = sys.switch_times(periods).into_iter().filter(|t| *t < t_end).collect();
    stops.extend(times.iter().copied().filter(|t| *t > 0.0));
    stops.sort_by(f64::total_cmp);
    stops.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * b.abs().max(sys.period));
    let mut z = [x0[0] / xs, x0[1] / vs];
    let mut out: Vec<Option<[f64; 2]>> = times.iter().map(|t| (*t <= 0.0).then_some(x0)).collect();
    let mut counts = Counts::default();
    let same = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs().max(sys.period);
    for w in stops.windows(2) {
        let (ta, tb) = (w[0], w[1]);
        if tb <= ta {
            continue;
        }
        let ivp = IVP::ode(&ode, ta, tb, z);
        let sol = match method {
            Integrator::Dop853 => {
                ivp.method(ExplicitRungeKutta::dop853().rtol(rtol).atol(rtol).max_steps(10_000_000)).solve()
            }
            Integrator::Dopri5 => {
                ivp.method(ExplicitRungeKutta::dopri5().rtol(rtol).atol(rtol).max_steps(10_000_000)).solve()
            }
            // Newton tolerance 0 selects Hairer's RADAU5 rule, FNEWT = max(10 u/rtol', min(0.03, sqrt(rtol'))),
            // instead of the crate's fixed 3.2e-3. Radau5 controls the error on rtol' = 0.1 rtol^(2/3)
            // (Hairer & Wanner's convention, which the crate follows): rtol = 1e-12 asks for 1e-9 per step,
            // so over ~1e4 steps its global error stays near 1e-7 of the DTE peak-to-peak (README, limits).
            Integrator::Radau5 => ivp
                .method(ImplicitRungeKutta::radau5().rtol(rtol).atol(rtol).newton_tol(0.0).max_steps(10_000_000))
                .solve(),
            Integrator::Kvaerno745 => ivp
                .method(
                    DiagonallyImplicitRungeKutta::kvaerno745()
                        .rtol(rtol)
                        .atol(rtol)
                        .max_steps(10_000_000)
                        .max_rejects(1000),
                )
                .solve(),
        }
        .map_err(|e| format!("{} failed on [{ta:e}, {tb:e}] s: {e:?}", method.name()))?;
        counts.steps += sol.steps.accepted + sol.steps.rejected;
        counts.rejected += sol.steps.rejected;
        counts.evaluations += sol.evals.function;
        let (t_last, y_last) = match (sol.t.last(), sol.y.last()) {
            (Some(t), Some(y)) if same(*t, tb) => (*t, *y),
            _ => return Err(format!("{} stopped before {tb:e} s ({:?})", method.name(), sol.status)),
        };
        z = y_last;
        if !z.iter().all(|v| v.is_finite()) {
            return Err(format!("{} produced a non-finite state at t = {t_last:e} s", method.name()));
        }
        for (i, ti) in times.iter().enumerate() {
            if same(*ti, tb) {
                out[i] = Some([z[0] * xs, z[1] * vs]);
            }
        }
    }
    let out: Vec<[f64; 2]> = out.into_iter().collect::<Option<_>>().ok_or("an output time was not reached")?;
    Ok((out, counts))
}
