//! Floquet analysis of a periodic model with n states (He & Singh §4; physics notes, "Dynamics"):
//! monodromy Φ(T) = Π Φ_j, multipliers = eig Φ(T), stable while every |λ| < 1, and the periodic
//! forced response directly from (I − Φ(T)) X*(0) = q(T), with no marching through transients.
//! Liouville's formula det Φ(T) = exp(∫₀ᵀ tr A dt) checks the propagators.
//!
//! The multipliers of a 2-state model come from the closed form of a 2×2 eigenproblem; for n > 2
//! from nalgebra's real Schur decomposition (`complex_eigenvalues`).

use nalgebra::{DMatrix, DVector, Matrix2, SMatrix, SVector, Vector2};
use serde::Serialize;

use super::model::PeriodicModel;
use super::propagator::{monodromy, period_segments, Method, PeriodPropagation, Propagation};

/// A Floquet multiplier.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Multiplier {
    pub re: f64,
    pub im: f64,
}

impl Multiplier {
    pub fn abs(&self) -> f64 {
        self.re.hypot(self.im)
    }
}

/// Stability verdict from the spectral radius ρ.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// ρ < 1 − 1e-9: perturbations decay; the periodic response is the steady state.
    Stable,
    /// |ρ − 1| ≤ 1e-9 (undamped): neither decay nor growth.
    Marginal,
    /// ρ > 1 + 1e-9: parametric instability; no steady state exists in the linear model.
    Unstable,
}

/// Everything Floquet theory gives at one operating point and formulation.
#[derive(Debug, Clone)]
pub struct Floquet<const N: usize> {
    /// The propagation of every segment of the period, and how each was propagated.
    pub period: PeriodPropagation<N>,
    pub method: Method,
    pub monodromy: Propagation<N>,
    /// Sorted by decreasing modulus.
    pub multipliers: Vec<Multiplier>,
    pub spectral_radius: f64,
    pub verdict: Verdict,
    /// det Φ(T) and exp(∫ tr A) (Liouville).
    pub determinant: f64,
    pub liouville: f64,
    /// X*(0) of the periodic response; None when I − Φ(T) is singular or the system is unstable.
    pub periodic_state: Option<SVector<f64, N>>,
}

/// Eigenvalues of a real 2×2 matrix (closed form; the larger-modulus one first for real pairs).
pub(crate) fn eigenvalues_2x2(tr: f64, det: f64) -> [Multiplier; 2] {
    let disc = 0.25 * tr * tr - det;
    if disc >= 0.0 {
        let r = disc.sqrt();
        [Multiplier { re: 0.5 * tr + r, im: 0.0 }, Multiplier { re: 0.5 * tr - r, im: 0.0 }]
    } else {
        let i = (-disc).sqrt();
        [Multiplier { re: 0.5 * tr, im: i }, Multiplier { re: 0.5 * tr, im: -i }]
    }
}

/// Eigenvalues of a real n×n matrix: closed form for n = 2, the real Schur form otherwise (sorted
/// by decreasing modulus, then by decreasing imaginary part).
pub(crate) fn eigenvalues<const N: usize>(m: &SMatrix<f64, N, N>) -> Vec<Multiplier> {
    if N == 2 {
        return eigenvalues_2x2(m.trace(), determinant(m)).to_vec();
    }
    let d = DMatrix::from_fn(N, N, |i, j| m[(i, j)]);
    let mut v: Vec<Multiplier> = d.complex_eigenvalues().iter().map(|c| Multiplier { re: c.re, im: c.im }).collect();
    v.sort_by(|a, b| b.abs().total_cmp(&a.abs()).then(b.im.total_cmp(&a.im)));
    v
}

/// det m (nalgebra's closed form for n = 2, LU otherwise).
pub(crate) fn determinant<const N: usize>(m: &SMatrix<f64, N, N>) -> f64 {
    if N == 2 {
        Matrix2::from_fn(|i, j| m[(i, j)]).determinant()
    } else {
        DMatrix::from_fn(N, N, |i, j| m[(i, j)]).determinant()
    }
}

/// x with m x = b, None when m is singular (nalgebra's closed-form inverse for n = 2, LU otherwise).
pub(crate) fn solve<const N: usize>(m: &SMatrix<f64, N, N>, b: &SVector<f64, N>) -> Option<SVector<f64, N>> {
    if N == 2 {
        let inv = Matrix2::from_fn(|i, j| m[(i, j)]).try_inverse()?;
        let x = inv * Vector2::new(b[0], b[1]);
        Some(SVector::from_fn(|i, _| x[i]))
    } else {
        let x = DMatrix::from_fn(N, N, |i, j| m[(i, j)]).lu().solve(&DVector::from_fn(N, |i, _| b[i]))?;
        Some(SVector::from_fn(|i, _| x[i]))
    }
}

impl<const N: usize> Floquet<N> {
    pub fn analyse<M: PeriodicModel<N> + ?Sized>(model: &M) -> Floquet<N> {
        let period = period_segments(model);
        let mono = monodromy(&period.segments);
        let multipliers = eigenvalues(&mono.phi);
        let rho = multipliers.iter().map(Multiplier::abs).fold(0.0, f64::max);
        let verdict = if rho > 1.0 + 1e-9 {
            Verdict::Unstable
        } else if rho >= 1.0 - 1e-9 {
            Verdict::Marginal
        } else {
            Verdict::Stable
        };
        let periodic_state = match verdict {
            Verdict::Unstable => None,
            _ => solve(&(SMatrix::<f64, N, N>::identity() - mono.phi), &mono.q)
                .filter(|x| x.iter().all(|v| v.is_finite())),
        };
        Floquet {
            determinant: determinant(&mono.phi),
            liouville: model.trace_integral().exp(),
            method: period.method,
            period,
            monodromy: mono,
            multipliers,
            spectral_radius: rho,
            verdict,
            periodic_state,
        }
    }
}
