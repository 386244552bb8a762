//! The one interface every dynamic model of the tool implements: a linear, T-periodic system with
//! n states, Ẋ = A(t) X + b(t), whose period is cut into segments at its switch times.
//!
//! The engine (exact and Magnus propagators, Floquet analysis, the periodic trajectory with located
//! extrema, the general integrators with restarts, stability maps and the error-against-run-time
//! study) reads a model only through [`PeriodicModel`]; it knows nothing of gears. Inside a segment
//! A and b are smooth; where A is constant and b affine in t on a segment
//! ([`PeriodicModel::segment_is_affine`]) the exact propagator applies there.
//!
//! ```
//! use gearloss::dynamics::{PeriodicModel, Segment};
//! use gearloss::dynamics::Floquet;
//! use nalgebra::{SMatrix, SVector};
//!
//! /// Meissner's equation ẍ + ω²(1 ± a) x = 0 (+ on the first half of the period, − on the
//! /// second), undamped: the piecewise-constant relative of Mathieu's equation.
//! struct Meissner { omega: f64, a: f64, segments: Vec<Segment> }
//!
//! impl PeriodicModel<2> for Meissner {
//!     fn name(&self) -> &'static str { "meissner" }
//!     fn period(&self) -> f64 { 1.0 }
//!     fn segments(&self) -> &[Segment] { &self.segments }
//!     fn system(&self, t: f64) -> (SMatrix<f64, 2, 2>, SVector<f64, 2>) {
//!         let k = self.omega.powi(2) * if t.rem_euclid(1.0) < 0.5 { 1.0 + self.a } else { 1.0 - self.a };
//!         (SMatrix::<f64, 2, 2>::new(0.0, 1.0, -k, 0.0), SVector::zeros())
//!     }
//!     fn segment_is_affine(&self, _segment: usize) -> bool { true }
//!     fn state_scale(&self) -> SVector<f64, 2> { SVector::<f64, 2>::new(1.0, self.omega) }
//!     fn highest_frequency(&self, _t: f64) -> f64 { self.omega * (1.0 + self.a).sqrt() }
//! }
//!
//! let segments = vec![Segment { start: 0.0, end: 0.5 }, Segment { start: 0.5, end: 1.0 }];
//! let m = Meissner { omega: 2.0, a: 0.1, segments };
//! let f = Floquet::analyse(&m);
//! // Undamped: det Φ(T) = 1 (Liouville), so the multipliers are on the unit circle or reciprocal.
//! assert!((f.determinant - 1.0).abs() < 1e-12);
//! assert!((f.multipliers[0].abs() * f.multipliers[1].abs() - 1.0).abs() < 1e-12);
//! ```

use nalgebra::{SMatrix, SVector};

/// A piece of the period between two switch times (s from the start of the period).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Segment {
    pub start: f64,
    pub end: f64,
}

/// A linear T-periodic system with `N` states, Ẋ = A(t) X + b(t).
pub trait PeriodicModel<const N: usize>: Sync {
    /// The model's name, written into the report (`sdof`).
    fn name(&self) -> &'static str;
    /// What the model is, in a paragraph the report prints (states, equations, sources).
    fn description(&self) -> &'static str {
        ""
    }
    /// The period T (s).
    fn period(&self) -> f64;
    /// The segments of one period, in order, covering [0, T).
    fn segments(&self) -> &[Segment];
    /// A(t) and b(t). At a switch time the value is that of either side; callers that need a
    /// one-sided value ask just inside the segment.
    fn system(&self, t: f64) -> (SMatrix<f64, N, N>, SVector<f64, N>);
    /// True when on segment `j` A is constant and b affine in t, so that the exact propagator applies.
    fn segment_is_affine(&self, segment: usize) -> bool;
    /// A row n such that on segment `j` A(t) − A(t') = w nᵀ for any t, t' in it (A varies along one
    /// row, with any column w(t)): the spectral rank-one propagator applies there. None by default.
    fn varying_row(&self, _segment: usize) -> Option<SVector<f64, N>> {
        None
    }
    /// A typical size of each state component (a displacement, a velocity), for tolerances and
    /// error norms: the integrators work on X / scale.
    fn state_scale(&self) -> SVector<f64, N>;
    /// The fastest angular frequency of free oscillation at t (rad/s), which sets how finely a
    /// trajectory is gridded to bracket every extremum.
    fn highest_frequency(&self, t: f64) -> f64;
    /// Times inside segments where A or b change slope without a switch (nodes of a stiffness
    /// table): a trajectory is cut there too, so every quantity is smooth inside a piece.
    fn smooth_cuts(&self) -> Vec<f64> {
        Vec::new()
    }
    /// The size of a propagation (Φ, q) for Magnus' convergence test: ‖Φ‖ + ‖q / scale‖.
    fn propagation_size(&self, phi: &SMatrix<f64, N, N>, q: &SVector<f64, N>) -> f64 {
        phi.norm() + q.component_div(&self.state_scale()).norm()
    }
    /// ∫₀ᵀ tr A dt for Liouville's check det Φ(T) = exp(∫ tr A); by default integrated segment by
    /// segment with adaptive Gauss–Kronrod to 1e-13.
    fn trace_integral(&self) -> f64 {
        crate::numerics::quadrature::integrate(|t| self.system(t).0.trace(), &self.breaks(), 1e-13).value
    }
    /// 0 and the end of every segment: the breaks of piecewise quadrature over one period.
    fn breaks(&self) -> Vec<f64> {
        std::iter::once(0.0).chain(self.segments().iter().map(|s| s.end)).collect()
    }
    /// The displacement the numerics study measures its error on (the DTE): the first state by default.
    fn observed(&self, x: &SVector<f64, N>) -> f64 {
        x[0]
    }
    /// All switch times within [0, n periods], for integrators that must restart there.
    fn switch_times(&self, periods: usize) -> Vec<f64> {
        let mut out = vec![0.0];
        for p in 0..periods {
            for s in self.segments() {
                out.push(p as f64 * self.period() + s.end);
            }
        }
        out
    }
}

/// t moved just inside [start, end], so that A and b read at a segment's ends are its one-sided
/// limits (k or μ jump at the switch times): by 1e-14 of the segment, at least 8 rounding units of t
/// (so that the model's own zone test sees the inside) and at most a quarter of the segment. A
/// smooth A varies by ~1e-14 of its change over the segment across that step.
pub(crate) fn just_inside(start: f64, end: f64, t: f64) -> f64 {
    let h = end - start;
    let d = (1e-14 * h).max(8.0 * f64::EPSILON * start.abs().max(end.abs())).min(0.25 * h);
    t.clamp(start + d, end - d)
}

/// X(end) = Φ X(start) + q.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Propagation<const N: usize> {
    pub phi: SMatrix<f64, N, N>,
    pub q: SVector<f64, N>,
}

impl<const N: usize> Propagation<N> {
    pub fn identity() -> Self {
        Propagation { phi: SMatrix::identity(), q: SVector::zeros() }
    }

    /// `self` followed by `next`.
    pub fn then(&self, next: &Propagation<N>) -> Propagation<N> {
        Propagation { phi: next.phi * self.phi, q: next.phi * self.q + next.q }
    }

    pub fn apply(&self, x: &SVector<f64, N>) -> SVector<f64, N> {
        self.phi * x + self.q
    }
}
