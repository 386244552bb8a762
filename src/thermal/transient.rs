//! The sump temperature over a duty cycle: C dθ/dt = P_V(θ; T_k, n_k) − P_Q(θ), from ambient, the
//! steps in order, θ continuous across them.
//!
//! The energies lost and given off are integrated as two more states, each divided by C so that all
//! three states are in kelvin and one tolerance fits them: e_lost' = P_V/C, e_given' = P_Q/C. Then
//! C (θ_end − θ_0) = E_lost − E_dissipated is the balance of the books. The integrator (DOP853 of the
//! `differential-equations` crate, adaptive, error-controlled) restarts at every step boundary, where
//! P_V jumps. The run is made twice, at tolerances [`TOLERANCE`] and 100 × [`TOLERANCE`]; the largest
//! difference of a step-end temperature between them is the reported error estimate.
//!
//! Within a step θ moves monotonically towards that step's balance, so the highest temperature of a
//! cycle is the largest step end (or the start).
//!
//! ```
//! use gearloss::thermal::{transient, Housing};
//! // 300 W for 100 hours into 18 kJ/K (about 130 time constants C/(dP_Q/dθ) ≈ 2800 s): the sump
//! // ends at the balance of 300 W.
//! let h = Housing { heat_capacity: Some(18e3), ..Housing::still_air(0.42, 298.15) };
//! let run = transient(|_, _| 300.0, &h, 18e3, &[360_000.0]).unwrap();
//! let balance = gearloss::thermal::balance(|_| 300.0, &h).temperature.unwrap();
//! assert!((run.steps[0].temperature - balance).abs() < 1e-8);
//! ```

use differential_equations::control::ControlFlag;
use differential_equations::interpolate::Interpolation;
use differential_equations::ode::solve_ode;
use differential_equations::prelude::*;
use differential_equations::solout::Solout;

use super::housing::Housing;

/// The integrator's relative and absolute tolerance on the scaled states (K).
pub const TOLERANCE: f64 = 1e-12;

/// The state at the end of one step of the cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepEnd {
    /// θ at the step's end (K).
    pub temperature: f64,
    /// Energy lost and given off during the step (J).
    pub energy_lost: f64,
    pub energy_dissipated: f64,
}

/// A duty cycle's transient.
#[derive(Debug, Clone, PartialEq)]
pub struct Transient {
    pub steps: Vec<StepEnd>,
    /// (time s, θ K) at every accepted step of the integrator and every step boundary.
    pub samples: Vec<(f64, f64)>,
    /// The largest difference of a step-end θ between the two tolerances (K).
    pub error: f64,
}

impl Transient {
    /// θ_max (K): the start or the largest step end.
    pub fn max_temperature(&self, start: f64) -> f64 {
        self.steps.iter().map(|s| s.temperature).fold(start, f64::max)
    }
}

/// The transient of losses `p_v(step, T)` (W, step index, oil temperature K) against `housing`, with
/// heat capacity `c` (J/K), over steps of `durations` (s), from ambient.
pub fn transient(
    p_v: impl Fn(usize, f64) -> f64,
    housing: &Housing,
    c: f64,
    durations: &[f64],
) -> Result<Transient, String> {
    let fine = run(&p_v, housing, c, durations, TOLERANCE, true)?;
    let coarse = run(&p_v, housing, c, durations, 100.0 * TOLERANCE, false)?;
    let error =
        fine.steps.iter().zip(&coarse.steps).map(|(a, b)| (a.temperature - b.temperature).abs()).fold(0.0, f64::max);
    Ok(Transient { error, ..fine })
}

struct Cycle<'a, F> {
    p_v: &'a F,
    housing: &'a Housing,
    c: f64,
    step: usize,
}

impl<F: Fn(usize, f64) -> f64> ODE<f64, [f64; 3]> for Cycle<'_, F> {
    fn diff(&self, _t: f64, y: &[f64; 3], dy: &mut [f64; 3]) {
        let lost = (self.p_v)(self.step, y[0]);
        let given = self.housing.dissipation(y[0]).total;
        *dy = [(lost - given) / self.c, lost / self.c, given / self.c];
    }
}

/// The last state reached, and every accepted step's (t, θ) when asked for.
struct Samples {
    keep: bool,
    at: Vec<(f64, f64)>,
    last: (f64, [f64; 3]),
    /// The longest accepted step (s): the next cycle step starts with it.
    longest: f64,
}

impl Solout<f64, [f64; 3]> for Samples {
    fn solout<I>(
        &mut self,
        t_curr: f64,
        t_prev: f64,
        y_curr: &[f64; 3],
        _y_prev: &[f64; 3],
        _interpolator: &mut I,
        _solution: &mut Solution<f64, [f64; 3]>,
    ) -> ControlFlag<f64, [f64; 3]>
    where
        I: Interpolation<f64, [f64; 3]> + ?Sized,
    {
        self.last = (t_curr, *y_curr);
        self.longest = self.longest.max(t_curr - t_prev);
        if self.keep {
            self.at.push((t_curr, y_curr[0]));
        }
        ControlFlag::Continue
    }
}

fn run<F: Fn(usize, f64) -> f64>(
    p_v: &F,
    housing: &Housing,
    c: f64,
    durations: &[f64],
    tol: f64,
    keep: bool,
) -> Result<Transient, String> {
    let mut y = [housing.ambient, 0.0, 0.0];
    let mut t0 = 0.0;
    let mut out = Transient { steps: Vec::new(), samples: vec![(0.0, y[0])], error: 0.0 };
    let mut h0: f64 = 0.0;
    for (step, &dt) in durations.iter().enumerate() {
        let ode = Cycle { p_v, housing, c, step };
        let start = y;
        let mut samples = Samples { keep, at: Vec::new(), last: (t0, start), longest: 0.0 };
        let mut m = ExplicitRungeKutta::dop853().rtol(tol).atol(tol).max_steps(1_000_000);
        if h0 > 0.0 {
            m = m.h0(h0.min(dt));
        }
        solve_ode(&mut m, &ode, t0, t0 + dt, &start, &mut samples)
            .map_err(|e| format!("the duty cycle's transient failed in step {}: {e:?}", step + 1))?;
        let (t_end, end) = samples.last;
        h0 = samples.longest;
        if (t_end - (t0 + dt)).abs() > 1e-9 * (t0 + dt) {
            return Err(format!("the duty cycle's transient stopped at {t_end} s in step {}", step + 1));
        }
        y = end;
        if !y.iter().all(|v| v.is_finite()) {
            return Err(format!("the duty cycle's transient is not finite in step {}", step + 1));
        }
        out.samples.extend(samples.at.into_iter().filter(|(t, _)| *t > t0));
        t0 += dt;
        out.steps.push(StepEnd {
            temperature: y[0],
            energy_lost: c * (y[1] - start[1]),
            energy_dissipated: c * (y[2] - start[2]),
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn housing() -> Housing {
        Housing { heat_capacity: Some(18e3), ..Housing::still_air(0.42, 298.15) }
    }

    /// The books balance: C (θ_end − θ_0) = E_lost − E_dissipated over a cycle of three steps with
    /// temperature-dependent losses (to 1e-9 of E_lost), and the error estimate is below 1e-9 K.
    #[test]
    fn energy_is_conserved() {
        let h = housing();
        let p_v = |step: usize, t: f64| [400.0, 50.0, 900.0][step] * (1.0 - 2e-3 * (t - 298.15));
        let run = transient(p_v, &h, 18e3, &[600.0, 1200.0, 300.0]).unwrap();
        let lost: f64 = run.steps.iter().map(|s| s.energy_lost).sum();
        let given: f64 = run.steps.iter().map(|s| s.energy_dissipated).sum();
        let end = run.steps.last().unwrap().temperature;
        assert!((18e3 * (end - 298.15) - (lost - given)).abs() < 1e-9 * lost, "{end} {lost} {given}");
        assert!(run.error < 1e-9, "{}", run.error);
    }

    /// Standing still from ambient (no losses) stays at ambient exactly, giving off nothing.
    #[test]
    fn standing_still_stays_at_ambient() {
        let run = transient(|_, _| 0.0, &housing(), 18e3, &[120.0]).unwrap();
        assert_eq!(run.steps[0].temperature, 298.15);
        assert_eq!(run.steps[0].energy_dissipated, 0.0);
    }

    /// With constant losses and no radiation or natural convection (G_f only), θ follows the closed
    /// form θ_a + P/G (1 − e^(−G t / C)) to 1e-9 K.
    #[test]
    fn first_order_closed_form() {
        let h = Housing { emissivity: 0.0, area: 0.0, foundation_conductance: 5.0, ..housing() };
        let run = transient(|_, _| 250.0, &h, 18e3, &[1800.0, 1800.0]).unwrap();
        for (k, s) in run.steps.iter().enumerate() {
            let t = 1800.0 * (k + 1) as f64;
            let exact = 298.15 + 250.0 / 5.0 * (1.0 - (-5.0 * t / 18e3).exp());
            assert!((s.temperature - exact).abs() < 1e-9, "{} {exact}", s.temperature);
        }
    }
}
