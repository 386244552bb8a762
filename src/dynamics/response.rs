//! The periodic steady-state response over one mesh period, from the Floquet periodic state:
//! DTE, the tooth force of Fernandes eq 7 (total and per pair), the friction force the model applies,
//! friction torques, dynamic factor, tooth separation, the DTE spectrum in mesh orders and the mean
//! efficiency from the tooth force.
//!
//! No reported number is read off a grid ([`super::trajectory`]): maxima, minima and peak-to-peak
//! values are located as roots of the time derivative (ẋ for the DTE, dF/dt for the tooth force,
//! a central difference of the friction quantities, whose μ(u) has no closed derivative) plus the
//! one-sided values at every switch time; the separation intervals are the located zeros of F; the
//! means and the Fourier coefficients are integrated cell by cell with Gauss–Kronrod (15 points,
//! QUADPACK error estimate) on the propagated state. The plot series are sampled on a uniform grid
//! merged with both sides of every switch time and the located extrema.
//!
//! The friction force the model applies (physics notes, "Dynamics"): the external formulation puts
//! μ_j w_j F0 into its equation (the static load), the internal one μ_j w_j F (the tooth force), with
//! w_j = 1/n the force share of contact j. For the external formulation μ_j w_j F is also shown, named
//! "μ × tooth force", since it is not what its equation applies.

use nalgebra::Vector2;
use serde::Serialize;

use super::floquet::Floquet;
use super::sdof::{DynamicFormulation, SdofSystem};
use super::trajectory::{Extremum, Trajectory};
use crate::numerics::quadrature::{integrate_pieces_n, Integral};

/// Uniform plot samples per mesh period (merged with switch times and located extrema).
pub(crate) const PLOT_SAMPLES: usize = 256;
/// Mesh orders kept in the DTE spectrum.
pub(crate) const ORDERS: usize = 10;
/// Tolerance of the means and Fourier coefficients, relative to their scale (|x|max, 1 for η).
pub(crate) const MEAN_TOLERANCE: f64 = 1e-10;
/// Number of integrands in the one Gauss–Kronrod pass: x, η, and cos/sin of each order.
const N_INTEGRANDS: usize = 2 + 2 * ORDERS;

/// The response series at the plot times.
#[derive(Debug, Clone, Default, Serialize)]
pub struct ResponseSeries {
    /// Times in mesh periods, [0, 1], sorted; a switch time appears twice (both one-sided values).
    pub tau: Vec<f64>,
    /// DTE x (m).
    pub dte: Vec<f64>,
    /// Tooth force F (N).
    pub tooth_force: Vec<f64>,
    /// Tooth force of each pair slot k (the pair that entered k periods ago), NaN when out of contact.
    pub pair_force: Vec<Vec<f64>>,
    /// The friction force the model applies, Σ μ_j w_j N (N = F0 external, F internal) (N).
    pub friction_force: Vec<f64>,
}

#[derive(Debug, Clone, Serialize)]
pub struct PeriodicResponse {
    pub series: ResponseSeries,
    /// Located extrema of the DTE (time in mesh periods).
    pub dte_min: Extremum,
    pub dte_max: Extremum,
    pub dte_peak_to_peak: f64,
    /// Time mean of x over the period, with its error estimate.
    pub dte_mean: Integral,
    pub tooth_force_min: Extremum,
    pub tooth_force_max: Extremum,
    /// max F / F0 (F0 = T_p / r_b1, the static tooth force).
    pub dynamic_factor: f64,
    /// Intervals (τ from, τ to) in mesh periods where F < 0: the teeth separate.
    pub separation: Vec<(f64, f64)>,
    /// (mesh order, amplitude of the DTE harmonic, m), orders 1..=ORDERS.
    pub spectrum: Vec<(usize, f64)>,
    /// Time mean of 1 − Σ |μ_j| w_j F v_s,j / (T_p ω_p), with its error estimate.
    pub mean_dynamic_efficiency: Option<Integral>,
    /// Largest instantaneous efficiency of that kind (above 1 only where F < 0).
    pub max_dynamic_efficiency: Option<f64>,
    /// Peak |applied friction force| (N) and peak |friction torque| on pinion and wheel (N·m); None
    /// for a law that diverges at P (no finite peak).
    pub peak_friction_force: Option<Extremum>,
    pub peak_friction_torque: Option<[Extremum; 2]>,
    /// External formulation only: peak |Σ μ_j w_j F| (μ × tooth force, not applied by its equation).
    pub peak_mu_times_tooth_force: Option<Extremum>,
}

/// What the friction does at one instant.
#[derive(Debug, Clone, Copy, Default)]
struct FrictionNow {
    applied: f64,
    mu_times_tooth_force: f64,
    torque: [f64; 2],
    loss: f64,
}

/// The SDOF trajectory.
type SdofTrajectory<'s, 'a> = Trajectory<'s, SdofSystem<'a>, 2>;

struct Eval<'t, 's, 'a> {
    tr: &'t SdofTrajectory<'s, 'a>,
}

impl Eval<'_, '_, '_> {
    fn sys(&self) -> &SdofSystem<'_> {
        self.tr.sys
    }

    fn x(&self, p: usize, t: f64) -> [f64; 2] {
        let s = self.tr.state(p, t);
        [s[0], s[1]]
    }

    fn force(&self, p: usize, t: f64) -> f64 {
        self.sys().tooth_force(t, self.tr.parameter_time(p, t), &self.x(p, t))
    }

    fn force_rate(&self, p: usize, t: f64) -> f64 {
        self.sys().tooth_force_rate(t, self.tr.parameter_time(p, t), &self.x(p, t))
    }

    fn friction(&self, p: usize, t: f64) -> FrictionNow {
        let sys = self.sys();
        let mut out = FrictionNow::default();
        if sys.law.is_none() {
            return out;
        }
        let g = sys.ctx.geometry;
        // The tooth force F is along the transverse line of action; the normal force of a helical
        // pair is F / cos β_b (He & Singh eq 3), and friction is μ times the normal force.
        let to_normal = if g.is_helical() { 1.0 / g.base_helix_angle.cos() } else { 1.0 };
        let f = self.force(p, t) * to_normal;
        let normal = match sys.formulation {
            DynamicFormulation::Internal | DynamicFormulation::InternalChord => f,
            _ => sys.static_force * to_normal,
        };
        let tau = self.tr.parameter_time(p, t) / sys.period;
        for c in &sys.ctx.mesh().contacts_at(tau.rem_euclid(1.0)) {
            let m = sys.friction_mu(c) * c.force_share;
            out.applied += m * normal;
            out.mu_times_tooth_force += m * f;
            out.torque[0] -= m * normal * c.u;
            out.torque[1] += m * normal * (g.line_of_action_length - c.u);
            out.loss += m.abs() * f * c.sliding_velocity;
        }
        out
    }

    fn efficiency(&self, p: usize, t: f64) -> f64 {
        let s = self.sys();
        1.0 - self.friction(p, t).loss / (s.ctx.state.pinion_torque * s.ctx.state.pinion_speed)
    }
}

/// Central-difference slope of `g` at t, for quantities whose μ(u) has no closed derivative.
fn slope(g: &impl Fn(usize, f64) -> f64, p: usize, t: f64, h: f64) -> f64 {
    (g(p, t + h) - g(p, t - h)) / (2.0 * h)
}

/// Largest |g| over the period, located.
fn peak_abs(tr: &SdofTrajectory, g: impl Fn(usize, f64) -> f64) -> Extremum {
    let h = 1e-7 * tr.sys.period;
    let e = tr.extrema(&g, |p, t| slope(&g, p, t, h));
    if e.max.value.abs() >= e.min.value.abs() {
        e.max
    } else {
        Extremum { value: e.min.value.abs(), time: e.min.time }
    }
}

fn in_periods(e: Extremum, period: f64) -> Extremum {
    Extremum { value: e.value, time: e.time / period }
}

impl PeriodicResponse {
    /// The response from a Floquet analysis; None when there is no periodic state (unstable).
    pub fn compute(sys: &SdofSystem, floquet: &Floquet<2>) -> Option<PeriodicResponse> {
        let x0 = floquet.periodic_state?;
        let tr = Trajectory::new(sys, &floquet.period, x0);
        let ev = Eval { tr: &tr };
        let period = sys.period;
        let dte = tr.extrema(|p, t| ev.x(p, t)[0], |p, t| ev.x(p, t)[1]);
        let force = tr.extrema(|p, t| ev.force(p, t), |p, t| ev.force_rate(p, t));
        let separation = tr
            .negative_intervals(|p, t| ev.force(p, t), &force.critical, 1e-13 * period)
            .into_iter()
            .map(|(a, b)| (a / period, b / period))
            .collect();
        let with_law = sys.law.is_some();
        // One Gauss–Kronrod pass over the grid cells: x, η and the Fourier coefficients of x.
        let xscale = dte.max.value.abs().max(dte.min.value.abs()).max(f64::MIN_POSITIVE);
        let mut tol = [MEAN_TOLERANCE * xscale * period; N_INTEGRANDS];
        tol[1] = MEAN_TOLERANCE * period;
        let w = 2.0 * std::f64::consts::PI / period;
        let integrals = integrate_pieces_n(
            |t| {
                let p = tr.piece_of(t);
                let x = ev.x(p, t)[0];
                let mut v = [0.0; N_INTEGRANDS];
                v[0] = x;
                v[1] = if with_law { ev.efficiency(p, t) } else { 1.0 };
                for h in 1..=ORDERS {
                    let arg = w * h as f64 * t;
                    v[2 * h] = x * arg.cos();
                    v[2 * h + 1] = x * arg.sin();
                }
                v
            },
            &tr.cell_breaks(),
            tol,
        );
        let mean =
            |i: Integral| Integral { value: i.value / period, error: i.error / period, evaluations: i.evaluations };
        let spectrum = (1..=ORDERS)
            .map(|h| (h, 2.0 / period * integrals[2 * h].value.hypot(integrals[2 * h + 1].value)))
            .collect();
        let ev = &ev;
        let friction = |f: fn(&FrictionNow) -> f64| move |p: usize, t: f64| f(&ev.friction(p, t));
        // A law that diverges at P (Benedict–Kelley's log, Xu's power) has no finite peak friction
        // force: its supremum is reached only at P itself, so none is reported (the report says so).
        let finite_peaks = sys.law.is_some_and(|l| !l.diverges_at_pitch());
        let peak = |f: fn(&FrictionNow) -> f64| finite_peaks.then(|| in_periods(peak_abs(&tr, friction(f)), period));
        let peak_friction_force = peak(|f| f.applied);
        let peak_friction_torque = peak(|f| f.torque[0]).zip(peak(|f| f.torque[1])).map(|(p, w)| [p, w]);
        let external = sys.formulation == DynamicFormulation::External;
        let peak_mu_f = if external { peak(|f| f.mu_times_tooth_force) } else { None };
        let max_eta = with_law.then(|| {
            let eta = |p: usize, t: f64| ev.efficiency(p, t);
            let h = 1e-7 * period;
            tr.extrema(eta, |p, t| slope(&eta, p, t, h)).max.value
        });
        let extremes = [dte.min, dte.max, force.min, force.max];
        Some(PeriodicResponse {
            series: plot_series(&tr, ev, &extremes),
            dte_peak_to_peak: dte.max.value - dte.min.value,
            dte_min: in_periods(dte.min, period),
            dte_max: in_periods(dte.max, period),
            dte_mean: mean(integrals[0]),
            tooth_force_min: in_periods(force.min, period),
            tooth_force_max: in_periods(force.max, period),
            dynamic_factor: force.max.value / sys.static_force,
            separation,
            spectrum,
            mean_dynamic_efficiency: with_law.then(|| mean(integrals[1])),
            max_dynamic_efficiency: max_eta,
            peak_friction_force,
            peak_friction_torque,
            peak_mu_times_tooth_force: peak_mu_f,
        })
    }

    /// The dynamic factor alone (located max F / F0), for stability maps; None when unstable.
    pub fn dynamic_factor(sys: &SdofSystem, floquet: &Floquet<2>) -> Option<f64> {
        let tr = Trajectory::new(sys, &floquet.period, floquet.periodic_state?);
        let ev = Eval { tr: &tr };
        Some(tr.extrema(|p, t| ev.force(p, t), |p, t| ev.force_rate(p, t)).max.value / sys.static_force)
    }
}

/// The plot series: uniform samples, both sides of every piece boundary, and the located extrema.
fn plot_series(tr: &SdofTrajectory, ev: &Eval, extremes: &[Extremum]) -> ResponseSeries {
    let sys = tr.sys;
    let period = sys.period;
    let mut at: Vec<(f64, usize)> = (0..PLOT_SAMPLES)
        .map(|i| i as f64 / PLOT_SAMPLES as f64 * period)
        .map(|t| (t, tr.piece_of(t)))
        .filter(|(t, p)| *t > tr.pieces[*p].start && *t < tr.pieces[*p].end)
        .collect();
    for (p, piece) in tr.pieces.iter().enumerate() {
        at.push((piece.start, p));
        at.push((piece.end, p));
    }
    at.extend(extremes.iter().map(|e| (e.time, tr.piece_of(e.time))));
    at.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    at.dedup();
    let g = sys.ctx.geometry;
    let mut s = ResponseSeries { pair_force: vec![vec![f64::NAN; at.len()]; 3], ..Default::default() };
    for (i, &(t, p)) in at.iter().enumerate() {
        let x: Vector2<f64> = tr.state(p, t);
        let f = ev.force(p, t);
        s.tau.push(t / period);
        s.dte.push(x[0]);
        s.tooth_force.push(f);
        s.friction_force.push(ev.friction(p, t).applied);
        let tau = tr.parameter_time(p, t) / period;
        if g.is_helical() {
            // Each line carries its share L_k / L of the force (constant stiffness density).
            let lines = g.contact_lines(tau.rem_euclid(1.0));
            let total: f64 = lines.iter().map(|l| l.length).sum();
            for l in lines.iter().filter(|l| l.index < 3) {
                s.pair_force[l.index][i] = l.length / total * f;
            }
            continue;
        }
        for c in &sys.ctx.mesh().contacts_at(tau.rem_euclid(1.0)) {
            let slot = (((c.u - g.points.a) / g.base_pitch) - tau).round();
            if (0.0..3.0).contains(&slot) {
                s.pair_force[slot as usize][i] = c.force_share * f;
            }
        }
    }
    s
}
