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
//! **A settled step in closed form.** Once θ sits at the step's balance θ* within the tolerance
//! (|θ − θ*| ≤ tol · θ, θ* − θ = (P_V − P_Q)/g read from the losses and their slope
//! g = d(P_Q − P_V)/dθ > 0), the rest of the step is the linear system's exact solution: over the
//! remaining time T, with τ = C/g and a = θ* − θ, θ_end = θ + a (1 − e^(−T/τ)), and the energies
//! E_lost = P_V T + P_V′ a (T − τ (1 − e^(−T/τ))), E_dissipated likewise with P_Q. The books still
//! balance exactly (C a (1 − e^(−T/τ)) = E_lost − E_dissipated), and a step of 10⁶ h costs what its
//! first hours cost instead of marching through a million hours at the balance.
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
pub(crate) const TOLERANCE: f64 = 1e-12;

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
    transient_settling(p_v, housing, c, durations, true)
}

/// [`transient`], with `settle` false integrating every step to its end even where θ has long sat
/// at the balance (the reference the closed form is tested against).
pub(crate) fn transient_settling(
    p_v: impl Fn(usize, f64) -> f64,
    housing: &Housing,
    c: f64,
    durations: &[f64],
    settle: bool,
) -> Result<Transient, String> {
    let fine = run(&p_v, housing, c, durations, TOLERANCE, true, settle)?;
    let coarse = run(&p_v, housing, c, durations, 100.0 * TOLERANCE, false, settle)?;
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
struct Samples<'a> {
    keep: bool,
    at: Vec<(f64, f64)>,
    last: (f64, [f64; 3]),
    /// The longest accepted step (s): the next cycle step starts with it.
    longest: f64,
    /// Whether θ sits at the step's balance: the integration stops there.
    settled: &'a dyn Fn(f64) -> bool,
}

impl Solout<f64, [f64; 3]> for Samples<'_> {
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
        if (self.settled)(y_curr[0]) {
            return ControlFlag::Terminate;
        }
        ControlFlag::Continue
    }
}

/// The net power P_V − P_Q of a step at θ and the slopes of both (W, W/K).
struct Net {
    lost: f64,
    given: f64,
    lost_slope: f64,
    given_slope: f64,
}

impl Net {
    fn at(p_v: &dyn Fn(f64) -> f64, housing: &Housing, t: f64) -> Net {
        // Central differences over ±1 mK: P_V and P_Q are smooth in θ (viscosity, radiation).
        let d = 1e-3;
        let q = |t: f64| housing.dissipation(t).total;
        Net {
            lost: p_v(t),
            given: q(t),
            lost_slope: (p_v(t + d) - p_v(t - d)) / (2.0 * d),
            given_slope: (q(t + d) - q(t - d)) / (2.0 * d),
        }
    }

    /// g = d(P_Q − P_V)/dθ (W/K): positive where the balance is stable.
    fn restoring(&self) -> f64 {
        self.given_slope - self.lost_slope
    }

    /// θ* − θ (K) of the linearised balance.
    fn offset(&self) -> f64 {
        (self.lost - self.given) / self.restoring()
    }
}

/// Whether θ sits at the balance of `p_v` within `tol` (relative): nearly balanced powers first (no
/// slope read), then |θ* − θ| ≤ tol θ at a stable balance.
fn settled(p_v: &dyn Fn(f64) -> f64, housing: &Housing, t: f64, tol: f64) -> bool {
    let (lost, given) = (p_v(t), housing.dissipation(t).total);
    if (lost - given).abs() > 1e-6 * lost.abs().max(given.abs()).max(1.0) {
        return false;
    }
    let net = Net::at(p_v, housing, t);
    net.restoring() > 0.0 && net.offset().abs() <= tol * t
}

/// The rest of a settled step in closed form: from state `y` at θ over `remaining` seconds.
fn settled_rest(p_v: &dyn Fn(f64) -> f64, housing: &Housing, c: f64, y: [f64; 3], remaining: f64) -> [f64; 3] {
    let net = Net::at(p_v, housing, y[0]);
    let (g, a) = (net.restoring(), net.offset());
    let tau = c / g;
    let approach = -(-remaining / tau).exp_m1(); // 1 − e^(−T/τ)
    let ramp = a * (remaining - tau * approach); // ∫ (θ − θ_0) dt
    [
        y[0] + a * approach,
        y[1] + (net.lost * remaining + net.lost_slope * ramp) / c,
        y[2] + (net.given * remaining + net.given_slope * ramp) / c,
    ]
}

fn run<F: Fn(usize, f64) -> f64>(
    p_v: &F,
    housing: &Housing,
    c: f64,
    durations: &[f64],
    tol: f64,
    keep: bool,
    settle: bool,
) -> Result<Transient, String> {
    let mut y = [housing.ambient, 0.0, 0.0];
    let mut t0 = 0.0;
    let mut out = Transient { steps: Vec::new(), samples: vec![(0.0, y[0])], error: 0.0 };
    let mut h0: f64 = 0.0;
    for (step, &dt) in durations.iter().enumerate() {
        let ode = Cycle { p_v, housing, c, step };
        let start = y;
        let step_loss = |t: f64| p_v(step, t);
        let is_settled = |t: f64| settle && settled(&step_loss, housing, t, tol);
        let mut samples = Samples { keep, at: Vec::new(), last: (t0, start), longest: 0.0, settled: &is_settled };
        let mut m = ExplicitRungeKutta::dop853().rtol(tol).atol(tol).max_steps(1_000_000);
        if h0 > 0.0 {
            m = m.h0(h0.min(dt));
        }
        solve_ode(&mut m, &ode, t0, t0 + dt, &start, &mut samples)
            .map_err(|e| format!("the duty cycle's transient failed in step {}: {e:?}", step + 1))?;
        let (t_end, mut end) = samples.last;
        h0 = samples.longest;
        let remaining = t0 + dt - t_end;
        if remaining > 1e-9 * (t0 + dt) {
            if !is_settled(end[0]) {
                return Err(format!("the duty cycle's transient stopped at {t_end} s in step {}", step + 1));
            }
            end = settled_rest(&step_loss, housing, c, end, remaining);
            samples.at.push((t0 + dt, end[0]));
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

    /// θ-dependent losses of one step, the FZG C14 thermal scene's order of magnitude.
    fn losses(_: usize, t: f64) -> f64 {
        900.0 * (1.0 - 2e-3 * (t - 298.15))
    }

    /// Issue 40: a settled step is finished in closed form, and gives the energies of an integration
    /// that runs to the end: over 1 000 h (about 1 300 time constants) θ_end to 1e-9 K and both
    /// energies to 1e-9 relative, the books balanced to 1e-9 of E_lost.
    #[test]
    fn settled_step_equals_the_full_integration() {
        let h = housing();
        let steps = [600.0, 3.6e6, 300.0];
        let closed = transient(losses, &h, 18e3, &steps).unwrap();
        let full = transient_settling(losses, &h, 18e3, &steps, false).unwrap();
        for (a, b) in closed.steps.iter().zip(&full.steps) {
            assert!((a.temperature - b.temperature).abs() < 1e-9, "{} {}", a.temperature, b.temperature);
            assert!((a.energy_lost / b.energy_lost - 1.0).abs() < 1e-9, "{} {}", a.energy_lost, b.energy_lost);
            let rel = (a.energy_dissipated / b.energy_dissipated - 1.0).abs();
            assert!(rel < 1e-9, "{} {}", a.energy_dissipated, b.energy_dissipated);
        }
        let lost: f64 = closed.steps.iter().map(|s| s.energy_lost).sum();
        let given: f64 = closed.steps.iter().map(|s| s.energy_dissipated).sum();
        let end = closed.steps.last().unwrap().temperature;
        assert!((18e3 * (end - 298.15) - (lost - given)).abs() < 1e-9 * lost);
        // The closed form saved the march: fewer accepted steps than the full integration.
        assert!(closed.samples.len() < full.samples.len(), "{} {}", closed.samples.len(), full.samples.len());
    }

    /// A 10⁶ h step ends at the step's balance θ* (1e-9 K), and its energies are those of the first
    /// 1 000 h integrated to their end (by then settled) plus P_V(θ*) and P_Q(θ*) times the rest, to
    /// 1e-9 relative.
    #[test]
    fn a_million_hours_settle_in_closed_form() {
        let h = housing();
        let (t, first) = (3.6e9, 3.6e6);
        let run = transient(losses, &h, 18e3, &[t]).unwrap();
        let head = transient_settling(losses, &h, 18e3, &[first], false).unwrap().steps[0];
        let star = crate::thermal::balance(|x| losses(0, x), &h).temperature.unwrap();
        let s = run.steps[0];
        assert!((s.temperature - star).abs() < 1e-9, "{} {star}", s.temperature);
        let lost = head.energy_lost + losses(0, star) * (t - first);
        let given = head.energy_dissipated + h.dissipation(star).total * (t - first);
        assert!((s.energy_lost / lost - 1.0).abs() < 1e-9, "{} {lost}", s.energy_lost);
        assert!((s.energy_dissipated / given - 1.0).abs() < 1e-9, "{} {given}", s.energy_dissipated);
    }

    /// The 10⁶ h step against an integration run to its end (with these losses the full march is
    /// half a second; with a scene's P_V, 84 s at the time of issue 40).
    #[test]
    fn settled_million_hours_against_the_full_integration() {
        let h = housing();
        let closed = transient(losses, &h, 18e3, &[3.6e9]).unwrap();
        let full = transient_settling(losses, &h, 18e3, &[3.6e9], false).unwrap();
        let (a, b) = (closed.steps[0], full.steps[0]);
        assert!((a.energy_lost / b.energy_lost - 1.0).abs() < 1e-9, "{} {}", a.energy_lost, b.energy_lost);
        assert!((a.energy_dissipated / b.energy_dissipated - 1.0).abs() < 1e-9);
        assert!((a.temperature - b.temperature).abs() < 1e-9);
    }
}
