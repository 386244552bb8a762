//! The free (homogeneous) response of a periodic SDOF system from initial conditions X(0) = (x0, v0),
//! X(t + nT) = Φ(t, 0) Φ(T)ⁿ X(0) (He & Singh eq 36, their Figs 8–9), and its spectrum.
//!
//! The spectrum is not read off samples: by Floquet's theorem each eigenvector e_i of the monodromy
//! Φ(T), with multiplier λ_i and exponent ν_i = ln λ_i / T, gives a solution e^{ν_i t} p_i(t) with p_i
//! T-periodic. With X(0) = Σ c_i e_i, the DTE is x(t) = Σ_i Σ_k c_i P_ik e^{(ν_i + i2πk/T) t}, where
//! P_ik are the Fourier coefficients of p_i (integrated over one period with adaptive Gauss–Kronrod
//! on the propagated state). So the free response holds lines at the frequencies
//! f = arg λ_i / (2πT) + k f_mesh, each with the amplitude 2|Σ c_i P_ik| (one-sided) at t = 0 and
//! growing by |λ_i| per period: a natural frequency f_n near 9.5 f_mesh shows as a line there with
//! sidebands at 8.5 and 10.5 f_mesh (He & Singh, after Fig. 6). Extremes over the window are located
//! period by period ([`super::trajectory::Trajectory::extrema`]).

use nalgebra::{Complex, Matrix2, Vector2};
use serde::Serialize;

use super::floquet::Floquet;
use super::model::PeriodicModel;
use super::trajectory::{Extremum, Trajectory};
use crate::numerics::quadrature::integrate_pieces_n;

/// Highest mesh order of the spectrum lines (|k| ≤ this).
pub(crate) const MAX_ORDER: usize = 14;
/// Lines kept in the report, largest first.
pub(crate) const LINES: usize = 8;
/// Plot samples per mesh period.
const PLOT_SAMPLES: usize = 64;
const TERMS: usize = 2 * MAX_ORDER + 1;
/// Two modes × TERMS orders × (re, im).
const N_INTEGRANDS: usize = 4 * TERMS;

/// The free response asked for: X(0) = (x0, v0) followed over `periods` mesh periods.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FreeResponseSpec {
    pub x0: f64,
    pub v0: f64,
    pub periods: usize,
}

/// One line of the free response's spectrum.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct SpectralLine {
    /// Frequency in mesh orders (f / f_mesh).
    pub order: f64,
    /// One-sided amplitude of the DTE at t = 0 (m).
    pub amplitude: f64,
    /// Error estimate of the amplitude (m), from the Fourier integrals.
    pub error: f64,
    /// Growth factor of the line per mesh period, |λ|.
    pub growth: f64,
}

#[derive(Debug, Clone, Serialize)]
pub struct FreeResponse {
    pub initial: [f64; 2],
    pub periods: usize,
    /// Largest |x| over the window, located (time in mesh periods from the start).
    pub peak: Extremum,
    /// Largest |x| in the first and in the last period: their ratio shows growth or decay.
    pub first_period_peak: f64,
    pub last_period_peak: f64,
    /// Lines, largest amplitude first.
    pub lines: Vec<SpectralLine>,
    /// Plot samples: time in mesh periods and x (m).
    #[serde(skip)]
    pub series: (Vec<f64>, Vec<f64>),
}

/// Eigenvalues and eigenvectors of a real 2×2 matrix (complex in general).
fn eigen(m: &Matrix2<f64>) -> [(Complex<f64>, Vector2<Complex<f64>>); 2] {
    let (a, b, c, d) = (m[(0, 0)], m[(0, 1)], m[(1, 0)], m[(1, 1)]);
    let half = 0.5 * (a + d);
    let disc = Complex::new(half * half - (a * d - b * c), 0.0).sqrt();
    let lambdas = [half + disc, half - disc];
    lambdas.map(|l| {
        let v = if b.abs() >= c.abs() && b != 0.0 {
            Vector2::new(Complex::new(b, 0.0), l - a)
        } else if c != 0.0 {
            Vector2::new(l - d, Complex::new(c, 0.0))
        } else if (l - a).norm() <= (l - d).norm() {
            Vector2::new(Complex::new(1.0, 0.0), Complex::new(0.0, 0.0))
        } else {
            Vector2::new(Complex::new(0.0, 0.0), Complex::new(1.0, 0.0))
        };
        let n = v.norm();
        (l, v.map(|x| x / n))
    })
}

/// The free response over `periods` mesh periods from `x0` = (x, ẋ).
pub fn free_response<M: PeriodicModel<2> + ?Sized>(
    sys: &M,
    floquet: &Floquet<2>,
    x0: [f64; 2],
    periods: usize,
) -> FreeResponse {
    let t_mesh = sys.period();
    let zero = Trajectory::new(sys, &floquet.period, Vector2::zeros());
    let unit = [
        Trajectory::new(sys, &floquet.period, Vector2::new(1.0, 0.0)),
        Trajectory::new(sys, &floquet.period, Vector2::new(0.0, 1.0)),
    ];
    // Φ(t, 0) X by linearity: the trajectories from the unit states minus the one from rest.
    let hom = |p: usize, t: f64, x: &Vector2<f64>| -> Vector2<f64> {
        let z = zero.state(p, t);
        (unit[0].state(p, t) - z) * x[0] + (unit[1].state(p, t) - z) * x[1]
    };
    let phi = floquet.monodromy.phi;
    let mut x = Vector2::new(x0[0], x0[1]);
    let mut peak = Extremum { value: f64::NEG_INFINITY, time: 0.0 };
    let (mut first, mut last) = (0.0, 0.0);
    let mut series = (Vec::new(), Vec::new());
    for n in 0..periods {
        let e = zero.extrema(|p, t| hom(p, t, &x)[0], |p, t| hom(p, t, &x)[1]);
        let (value, time) = if e.max.value.abs() >= e.min.value.abs() {
            (e.max.value.abs(), e.max.time)
        } else {
            (e.min.value.abs(), e.min.time)
        };
        if value > peak.value {
            peak = Extremum { value, time: n as f64 + time / t_mesh };
        }
        if n == 0 {
            first = value;
        }
        last = value;
        for i in 0..PLOT_SAMPLES {
            let t = i as f64 / PLOT_SAMPLES as f64 * t_mesh;
            series.0.push(n as f64 + i as f64 / PLOT_SAMPLES as f64);
            series.1.push(hom(zero.piece_of(t), t, &x)[0]);
        }
        x = phi * x;
    }
    FreeResponse {
        initial: x0,
        periods,
        peak,
        first_period_peak: first,
        last_period_peak: last,
        lines: lines(sys, floquet, &zero, &hom, x0),
        series,
    }
}

/// The spectrum lines of the free response from `x0` (module doc).
fn lines<M: PeriodicModel<2> + ?Sized>(
    sys: &M,
    floquet: &Floquet<2>,
    zero: &Trajectory<M, 2>,
    hom: &impl Fn(usize, f64, &Vector2<f64>) -> Vector2<f64>,
    x0: [f64; 2],
) -> Vec<SpectralLine> {
    let t_mesh = sys.period();
    let modes = eigen(&floquet.monodromy.phi);
    // X(0) = c1 e1 + c2 e2.
    let e = nalgebra::Matrix2::from_columns(&[modes[0].1, modes[1].1]);
    let Some(inv) = e.try_inverse() else { return Vec::new() };
    let c = inv * Vector2::new(Complex::new(x0[0], 0.0), Complex::new(x0[1], 0.0));
    let nu: [Complex<f64>; 2] = modes.map(|(l, _)| l.ln() / t_mesh);
    let scale = x0[0].abs().max(x0[1].abs() * t_mesh).max(1e-300);
    let integrand = |t: f64| -> [f64; N_INTEGRANDS] {
        let p = zero.piece_of(t);
        let h = [hom(p, t, &Vector2::new(1.0, 0.0))[0], hom(p, t, &Vector2::new(0.0, 1.0))[0]];
        let mut out = [0.0; N_INTEGRANDS];
        for (i, (_, v)) in modes.iter().enumerate() {
            let x = v[0] * h[0] + v[1] * h[1];
            let base = x * (-nu[i] * t).exp();
            for k in 0..TERMS {
                let order = k as f64 - MAX_ORDER as f64;
                let w = base * Complex::new(0.0, -2.0 * std::f64::consts::PI * order * t / t_mesh).exp();
                out[(i * TERMS + k) * 2] = w.re;
                out[(i * TERMS + k) * 2 + 1] = w.im;
            }
        }
        out
    };
    let integrals = integrate_pieces_n(integrand, &zero.cell_breaks(), [1e-12 * t_mesh; N_INTEGRANDS]);
    // Bucket the terms by frequency (in mesh orders) and sum their complex amplitudes.
    let mut buckets: Vec<(f64, Complex<f64>, f64, f64)> = Vec::new();
    for (i, (lambda, _)) in modes.iter().enumerate() {
        for k in 0..TERMS {
            let order = lambda.arg() / (2.0 * std::f64::consts::PI) + k as f64 - MAX_ORDER as f64;
            let re = integrals[(i * TERMS + k) * 2];
            let im = integrals[(i * TERMS + k) * 2 + 1];
            let a = c[i] * Complex::new(re.value, im.value) / t_mesh;
            let err = c[i].norm() * (re.error + im.error) / t_mesh;
            // Merge terms at one frequency from modes of equal growth (a complex pair); real
            // multipliers of different modulus stay apart.
            let growth = lambda.norm();
            match buckets.iter_mut().find(|b| (b.0 - order).abs() < 1e-9 && (b.3 - growth).abs() <= 1e-12 * growth) {
                Some(b) => {
                    b.1 += a;
                    b.2 += err;
                }
                None => buckets.push((order, a, err, lambda.norm())),
            }
        }
    }
    let mut out: Vec<SpectralLine> = buckets
        .into_iter()
        .filter(|b| b.0 >= -1e-12 && b.0 <= MAX_ORDER as f64 - 1.0)
        .map(|(order, a, err, growth)| {
            let factor = if order.abs() < 1e-9 { 1.0 } else { 2.0 };
            SpectralLine { order: order.abs(), amplitude: factor * a.norm(), error: factor * err, growth }
        })
        .filter(|l| l.amplitude > 1e-9 * scale)
        .collect();
    out.sort_by(|a, b| b.amplitude.total_cmp(&a.amplitude));
    out.truncate(LINES);
    out
}
