//! The periodic steady state of the 6-DOF model over one mesh period: DTE, mesh force (total and
//! per pair), friction force, and per gear the bearing forces and displacements along and off the
//! line of action, with their spectra in mesh orders.
//!
//! As for the SDOF model nothing is read off a grid: every maximum and minimum is located from the
//! roots of its time derivative (ẋ of each coordinate, dN/dt = k'δ + kδ̇ + cδ̈ for the mesh force)
//! plus the one-sided values at every switch ([`Trajectory::extrema`]); means and Fourier
//! coefficients are integrated cell by cell with Gauss–Kronrod and their QUADPACK error estimates.

use nalgebra::SVector;
use serde::Serialize;

use super::analysis::{GearResponse, Range};
use super::floquet::Floquet;
use super::model::PeriodicModel;
use super::six_dof::{SixDofSystem, STATES};
use super::trajectory::{Extremum, Trajectory};
use crate::numerics::quadrature::{integrate_pieces_n, Integral};

/// Mesh orders of the spectra.
pub(crate) const ORDERS: usize = 10;
/// Relative tolerance of the means and Fourier coefficients.
pub(crate) const MEAN_TOLERANCE: f64 = 1e-10;
/// Plot samples per period.
const PLOT_SAMPLES: usize = 256;
/// Quantities integrated: DTE, bearing forces x_p, x_g, y_p, y_g, friction force; each with its
/// mean and ORDERS cos/sin pairs.
const QUANTITIES: usize = 6;
const N_INTEGRANDS: usize = QUANTITIES * (1 + 2 * ORDERS);

#[derive(Debug, Clone, Serialize)]
pub struct SixDofResponse {
    pub dte: Range,
    /// Total mesh force N = k δ + c δ̇, located.
    pub mesh_force: [Extremum; 2],
    /// Largest force on one pair, N / n, located.
    pub pair_force_max: Extremum,
    /// Largest friction force on one pair, max_i |μ_i| N / n, located.
    pub pair_friction_force_max: Extremum,
    /// max N / F0.
    pub dynamic_factor: f64,
    /// The friction force Σ μ_i N_i along y (on the pinion), with its mean and spectrum.
    pub friction_force: Range,
    /// [pinion, wheel].
    pub gears: [GearResponse; 2],
    /// Plot series: τ, DTE, OLOA bearing force pinion, wheel, friction force.
    #[serde(skip)]
    pub series: [Vec<f64>; 5],
}

fn in_periods(e: Extremum, period: f64) -> Extremum {
    Extremum { value: e.value, time: e.time / period }
}

impl SixDofResponse {
    /// The steady state from a Floquet analysis; None when there is none (unstable).
    pub fn compute(sys: &SixDofSystem, floquet: &Floquet<STATES>) -> Option<SixDofResponse> {
        let x0 = floquet.periodic_state?;
        let tr = Trajectory::new(sys, &floquet.period, x0);
        let period = sys.period();
        let state = |p: usize, t: f64| tr.state(p, t);
        let rate = |p: usize, t: f64| -> SVector<f64, STATES> {
            let (a, b) = sys.system(tr.parameter_time(p, t));
            a * tr.state(p, t) + b
        };
        let located = |i: usize, scale: f64| {
            let e = tr.extrema(|p, t| scale * state(p, t)[i], |p, t| scale * state(p, t)[i + 5]);
            (in_periods(e.min, period), in_periods(e.max, period))
        };
        let dte = tr
            .extrema(|p, t| SixDofSystem::deflection(&state(p, t)).0, |p, t| SixDofSystem::deflection(&state(p, t)).1);
        let force = |p: usize, t: f64| sys.mesh_force(tr.parameter_time(p, t), &state(p, t));
        let force_rate = |p: usize, t: f64| {
            let tp = tr.parameter_time(p, t);
            let x = state(p, t);
            let dx = rate(p, t);
            let (d, v) = SixDofSystem::deflection(&x);
            let acc = dx[5] + dx[6] - dx[7];
            let tau = (tp / period).rem_euclid(1.0);
            let k_rate = sys.mesh.stiffness.slope(sys.mesh.ctx.geometry, tau) / period;
            k_rate * d + sys.mesh.stiffness_at(tp) * v + sys.mesh.damping * acc
        };
        let n = tr.extrema(force, force_rate);
        let pairs = |p: usize, t: f64| {
            sys.mesh.ctx.geometry.pairs_at((tr.parameter_time(p, t) / period).rem_euclid(1.0)).max(1) as f64
        };
        let per_pair = tr.extrema(|p, t| force(p, t) / pairs(p, t), |p, t| force_rate(p, t) / pairs(p, t));
        let friction = |p: usize, t: f64| sys.mean_mu(tr.parameter_time(p, t)) * force(p, t);
        let h = 1e-7 * period;
        let pair_friction = |p: usize, t: f64| sys.largest_pair_mu(tr.parameter_time(p, t)) * force(p, t).abs();
        let pair_friction_ext =
            tr.extrema(pair_friction, |p, t| (pair_friction(p, t + h) - pair_friction(p, t - h)) / (2.0 * h));
        let friction_ext = tr.extrema(friction, |p, t| (friction(p, t + h) - friction(p, t - h)) / (2.0 * h));
        let k = [sys.bearings[0].loa, sys.bearings[1].loa, sys.bearings[0].oloa, sys.bearings[1].oloa];
        // Bearing forces K q on the gear's bearing (q = x_p, x_g, y_p, y_g: states 1..=4).
        let bearing: Vec<(Extremum, Extremum)> = (0..4).map(|j| located(j + 1, k[j])).collect();
        let values = |p: usize, t: f64| -> [f64; QUANTITIES] {
            let x = state(p, t);
            [SixDofSystem::deflection(&x).0, k[0] * x[1], k[1] * x[2], k[2] * x[3], k[3] * x[4], friction(p, t)]
        };
        let scale = |i: usize| -> f64 {
            let (lo, hi) = match i {
                0 => (dte.min.value, dte.max.value),
                5 => (friction_ext.min.value, friction_ext.max.value),
                j => (bearing[j - 1].0.value, bearing[j - 1].1.value),
            };
            lo.abs().max(hi.abs()).max(f64::MIN_POSITIVE)
        };
        let scales: Vec<f64> = (0..QUANTITIES).map(scale).collect();
        let integrals = harmonic_integrals(period, &scales, &tr.cell_breaks(), |t| values(tr.piece_of(t), t));
        let range = |q: usize, min: Extremum, max: Extremum| {
            let base = q * (1 + 2 * ORDERS);
            let i = integrals[base];
            Range {
                min,
                max,
                mean: Integral { value: i.value / period, error: i.error / period, evaluations: i.evaluations },
                spectrum: (1..=ORDERS)
                    .map(|o| 2.0 / period * integrals[base + 2 * o - 1].value.hypot(integrals[base + 2 * o].value))
                    .collect(),
            }
        };
        // A displacement's extremes are its bearing force's divided by the (positive) stiffness.
        let per = |e: Extremum, kk: f64| Extremum { value: e.value / kk, time: e.time };
        let gear = |i: usize| {
            let (lo_x, hi_x) = bearing[i];
            let (lo_y, hi_y) = bearing[i + 2];
            let (dx0, dx1) = (per(lo_x, k[i]), per(hi_x, k[i]));
            let (dy0, dy1) = (per(lo_y, k[i + 2]), per(hi_y, k[i + 2]));
            GearResponse {
                bearing_force_loa: range(1 + i, lo_x, hi_x),
                bearing_force_oloa: range(3 + i, lo_y, hi_y),
                displacement_loa: [dx0, dx1],
                displacement_oloa: [dy0, dy1],
            }
        };
        let series = plot_series(period, |t| values(tr.piece_of(t.min(period * (1.0 - 1e-12))), t));
        Some(SixDofResponse {
            dte: range(0, in_periods(dte.min, period), in_periods(dte.max, period)),
            mesh_force: [in_periods(n.min, period), in_periods(n.max, period)],
            pair_force_max: in_periods(per_pair.max, period),
            pair_friction_force_max: in_periods(pair_friction_ext.max, period),
            dynamic_factor: n.max.value / sys.mesh.static_force,
            friction_force: range(5, in_periods(friction_ext.min, period), in_periods(friction_ext.max, period)),
            gears: [gear(0), gear(1)],
            series,
        })
    }
}

/// The dynamic factor alone (located max N / F0), for stability maps; None when unstable.
pub(crate) fn dynamic_factor(sys: &SixDofSystem, floquet: &Floquet<STATES>) -> Option<f64> {
    let tr = Trajectory::new(sys, &floquet.period, floquet.periodic_state?);
    let period = sys.period();
    let force = |p: usize, t: f64| sys.mesh_force(tr.parameter_time(p, t), &tr.state(p, t));
    let h = 1e-7 * period;
    let e = tr.extrema(force, |p, t| (force(p, t + h) - force(p, t - h)) / (2.0 * h));
    Some(e.max.value / sys.mesh.static_force)
}

/// ∫ over one period of each quantity q and of q cos(2π o t/T), q sin(2π o t/T) for the orders
/// o = 1..=ORDERS, cell by cell (`breaks`) with Gauss–Kronrod, each to MEAN_TOLERANCE × its
/// quantity's scale × T.
fn harmonic_integrals(
    period: f64,
    scales: &[f64],
    breaks: &[f64],
    values: impl Fn(f64) -> [f64; QUANTITIES] + Sync,
) -> [Integral; N_INTEGRANDS] {
    let w = 2.0 * std::f64::consts::PI / period;
    let mut tol = [0.0; N_INTEGRANDS];
    for (q, s) in scales.iter().enumerate() {
        for j in 0..=2 * ORDERS {
            tol[q * (1 + 2 * ORDERS) + j] = MEAN_TOLERANCE * s * period;
        }
    }
    integrate_pieces_n(
        |t| {
            let v = values(t);
            let mut out = [0.0; N_INTEGRANDS];
            for (q, x) in v.iter().enumerate() {
                let base = q * (1 + 2 * ORDERS);
                out[base] = *x;
                for o in 1..=ORDERS {
                    let arg = w * o as f64 * t;
                    out[base + 2 * o - 1] = x * arg.cos();
                    out[base + 2 * o] = x * arg.sin();
                }
            }
            out
        },
        breaks,
        tol,
    )
}

/// The plot series at PLOT_SAMPLES + 1 uniform times over one period: τ, DTE, OLOA bearing force of
/// pinion and wheel, friction force (`values` at t as in [`harmonic_integrals`]).
fn plot_series(period: f64, values: impl Fn(f64) -> [f64; QUANTITIES]) -> [Vec<f64>; 5] {
    let mut series: [Vec<f64>; 5] = Default::default();
    for i in 0..=PLOT_SAMPLES {
        let t = i as f64 / PLOT_SAMPLES as f64 * period;
        let v = values(t);
        series[0].push(t / period);
        series[1].push(v[0]);
        series[2].push(v[3]);
        series[3].push(v[4]);
        series[4].push(v[5]);
    }
    series
}
