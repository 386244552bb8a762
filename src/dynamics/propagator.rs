//! Propagators of the SDOF state over a segment: X(t1) = Φ X(t0) + q.
//!
//! - **Exact**: where A is constant and b(t) = b0 + b1 (t − t0) on the segment, the augmented matrix
//!   M = [[A, b0, b1], [0, 0, 0, 0], [0, 0, 1, 0]] on [x, ẋ, 1, τ] (d1/dt = 0, dτ/dt = 1) gives exp(M h) exactly
//!   (nalgebra's Padé matrix exponential): Φ is its top-left block, q its third column.
//! - **Magnus**: otherwise, the 4th-order Magnus expansion with two Gauss–Legendre nodes on the
//!   augmented [x, ẋ, 1] system, Ω = h/2 (A1 + A2) + (√3/12) h² [A2, A1] (Blanes, Casas, Oteo, Ros,
//!   Phys. Rep. 470, 2009, eq 253), with substeps doubled until two successive results agree.

use nalgebra::{Matrix2, Matrix3, Matrix4, Vector2};

use super::sdof::SdofSystem;

/// X(end) = Φ X(start) + q.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Propagation {
    pub phi: Matrix2<f64>,
    pub q: Vector2<f64>,
}

impl Propagation {
    pub fn identity() -> Self {
        Propagation { phi: Matrix2::identity(), q: Vector2::zeros() }
    }

    /// `self` followed by `next`.
    pub fn then(&self, next: &Propagation) -> Propagation {
        Propagation { phi: next.phi * self.phi, q: next.phi * self.q + next.q }
    }

    pub fn apply(&self, x: &Vector2<f64>) -> Vector2<f64> {
        self.phi * x + self.q
    }
}

/// How a segment was propagated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    Exact,
    Magnus4,
}

/// Relative error at which a Magnus segment is accepted. Halving the substep of a 4th-order method
/// divides the error by 16, so the error of the finer result is estimated as |P_2n − P_n| / 15.
pub const MAGNUS_TOLERANCE: f64 = 1e-11;

/// The augmented matrix of a segment [start, end] on which A is constant and b affine:
/// on [x, ẋ, 1, τ] with τ = t − start, M = [[A, b(start), b'], [0, 0, 0, 0], [0, 0, 1, 0]].
/// (b is sampled at the segment's quarter points, away from the jumps at its ends.)
pub fn segment_matrix(sys: &SdofSystem, start: f64, end: f64) -> Matrix4<f64> {
    let seg = end - start;
    let (t1, t2) = (start + 0.25 * seg, start + 0.75 * seg);
    let (a, b1) = sys.matrices(t1);
    let (_, b2) = sys.matrices(t2);
    let slope = [(b2[0] - b1[0]) / (t2 - t1), (b2[1] - b1[1]) / (t2 - t1)];
    let b0 = [b1[0] - slope[0] * (t1 - start), b1[1] - slope[1] * (t1 - start)];
    #[rustfmt::skip]
    let m = Matrix4::new(
        a[0][0], a[0][1], b0[0], slope[0],
        a[1][0], a[1][1], b0[1], slope[1],
        0.0, 0.0, 0.0, 0.0,
        0.0, 0.0, 1.0, 0.0,
    );
    m
}

/// The propagation over `h` from `from` (τ = from − start) given E = exp(M h).
pub fn from_exponential(e: &Matrix4<f64>, tau: f64) -> Propagation {
    Propagation {
        phi: Matrix2::new(e[(0, 0)], e[(0, 1)], e[(1, 0)], e[(1, 1)]),
        q: Vector2::new(e[(0, 2)] + e[(0, 3)] * tau, e[(1, 2)] + e[(1, 3)] * tau),
    }
}

/// Exact propagation from `from` over `h` inside the segment [start, end].
pub fn exact(sys: &SdofSystem, start: f64, end: f64, from: f64, h: f64) -> Propagation {
    let e = (segment_matrix(sys, start, end) * h).exp();
    from_exponential(&e, from - start)
}

fn augmented(sys: &SdofSystem, t: f64) -> Matrix3<f64> {
    let (a, b) = sys.matrices(t);
    Matrix3::new(a[0][0], a[0][1], b[0], a[1][0], a[1][1], b[1], 0.0, 0.0, 0.0)
}

/// 4th-order Magnus over [t0, t0 + h] in `n` equal substeps.
pub fn magnus(sys: &SdofSystem, t0: f64, h: f64, n: usize) -> Propagation {
    let dt = h / n as f64;
    let c = 3f64.sqrt() / 6.0;
    let mut e = Matrix3::<f64>::identity();
    for i in 0..n {
        let t = t0 + i as f64 * dt;
        let a1 = augmented(sys, t + (0.5 - c) * dt);
        let a2 = augmented(sys, t + (0.5 + c) * dt);
        let omega = (a1 + a2) * (0.5 * dt) + (a2 * a1 - a1 * a2) * (3f64.sqrt() / 12.0 * dt * dt);
        e = omega.exp() * e;
    }
    Propagation { phi: Matrix2::new(e[(0, 0)], e[(0, 1)], e[(1, 0)], e[(1, 1)]), q: Vector2::new(e[(0, 2)], e[(1, 2)]) }
}

/// Magnus with substeps doubled until successive results agree to [`MAGNUS_TOLERANCE`]; returns
/// the propagation and the substeps used.
pub fn magnus_adaptive(sys: &SdofSystem, t0: f64, h: f64) -> (Propagation, usize) {
    let scale = |p: &Propagation| p.phi.norm() + p.q.norm() / sys.static_force.abs().max(1e-300) * sys.mean_stiffness;
    let mut n = 2;
    let mut prev = magnus(sys, t0, h, n);
    loop {
        n *= 2;
        let next = magnus(sys, t0, h, n);
        let diff = (next.phi - prev.phi).norm()
            + (next.q - prev.q).norm() / sys.static_force.abs().max(1e-300) * sys.mean_stiffness;
        if diff / 15.0 <= MAGNUS_TOLERANCE * scale(&next) || n >= 1 << 14 {
            return (next, n);
        }
        prev = next;
    }
}

/// Propagation from `from` over `h` inside `segment` (start, end), by the method that applies.
pub fn advance(sys: &SdofSystem, segment: (f64, f64), from: f64, h: f64) -> Propagation {
    if sys.exact_applies() {
        exact(sys, segment.0, segment.1, from, h)
    } else {
        magnus_adaptive(sys, from, h).0
    }
}

/// Propagation over each segment of one mesh period, and the method used.
pub fn period_segments(sys: &SdofSystem) -> (Vec<Propagation>, Method) {
    if sys.exact_applies() {
        (sys.segments.iter().map(|s| exact(sys, s.start, s.end, s.start, s.end - s.start)).collect(), Method::Exact)
    } else {
        (sys.segments.iter().map(|s| magnus_adaptive(sys, s.start, s.end - s.start).0).collect(), Method::Magnus4)
    }
}

/// The monodromy propagation over one period (Φ(T), q(T)).
pub fn monodromy(segments: &[Propagation]) -> Propagation {
    segments.iter().fold(Propagation::identity(), |acc, s| acc.then(s))
}
