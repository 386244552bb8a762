//! Propagators of an n-state periodic model over a segment: X(t1) = Φ X(t0) + q.
//!
//! - **Exact**: where A is constant and b(t) = b0 + b1 (t − t0) on a segment ([`AffineSegment`]), the
//!   augmented matrix M = [[A, b0, b1], [0, 0, 0], [0, 1, 0]] on [X, 1, τ] (d1/dt = 0, dτ/dt = 1)
//!   gives exp(M h) exactly (nalgebra's Padé matrix exponential): Φ is its top-left block, q its
//!   last two columns.
//! - **Magnus**: otherwise, the 4th-order Magnus expansion with two Gauss–Legendre nodes on the
//!   augmented [X, 1] system, Ω = h/2 (A1 + A2) + (√3/12) h² [A2, A1] (Blanes, Casas, Oteo, Ros,
//!   Phys. Rep. 470, 2009, eq 253), with substeps doubled until two successive results agree.
//!
//! - **Spectral (rank one)**: where A(t) varies along one row only (A0 + w(t) nᵀ, the 6-DOF model
//!   with friction), Chebyshev collocation of the scalar Volterra equation for nᵀX in A0's modal
//!   form (`super::rank_one`), whose cost does not grow with the fast modes as Magnus' does.
//!
//! The augmented matrices are static (4×4, 3×3) for the 2-state models and dynamic otherwise, so the
//! SDOF path allocates nothing.

use std::sync::Arc;

use nalgebra::allocator::Allocator;
use nalgebra::{DefaultAllocator, Dim, DimMin, Dyn, OMatrix, SMatrix, SVector, U3, U4};

pub(crate) use super::model::Propagation;
use super::model::{just_inside, PeriodicModel};
use super::rank_one::RankOneSegment;

/// How a segment was propagated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    Exact,
    Magnus4,
    /// Chebyshev collocation of the rank-one (Volterra) form on every segment where A varies.
    Spectral,
}

/// Relative error at which a Magnus segment is accepted. Halving the substep of a 4th-order method
/// divides the error by 16, so the error of the finer result is estimated as |P_2n − P_n| / 15.
pub(crate) const MAGNUS_TOLERANCE: f64 = 1e-11;

/// A segment on which A is constant and b(t) = b0 + b1 (t − start).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AffineSegment<const N: usize> {
    pub start: f64,
    pub a: SMatrix<f64, N, N>,
    pub b0: SVector<f64, N>,
    pub b1: SVector<f64, N>,
}

/// exp(M h) of an [`AffineSegment`], as the blocks that matter: X(start + τ + h) = Φ X + q0 + q1 τ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SegmentExponential<const N: usize> {
    pub phi: SMatrix<f64, N, N>,
    pub q0: SVector<f64, N>,
    pub q1: SVector<f64, N>,
}

impl<const N: usize> SegmentExponential<N> {
    /// The propagation over h from `start + tau`.
    pub fn from(&self, tau: f64) -> Propagation<N> {
        Propagation { phi: self.phi, q: self.q0 + self.q1 * tau }
    }
}

/// exp of an n×n matrix given by its entries, returned as its entries: a static matrix of size `dim`
/// (U3, U4) or a dynamic one.
fn exponential<D>(dim: D, entry: impl Fn(usize, usize) -> f64) -> OMatrix<f64, D, D>
where
    D: Dim + DimMin<D, Output = D>,
    DefaultAllocator: Allocator<D, D> + Allocator<D>,
{
    OMatrix::<f64, D, D>::from_fn_generic(dim, dim, entry).exp()
}

impl<const N: usize> AffineSegment<N> {
    /// The affine form of a model's segment [start, end], from A and b sampled at its quarter points
    /// (away from the jumps at its ends).
    pub fn of<M: PeriodicModel<N> + ?Sized>(model: &M, start: f64, end: f64) -> Self {
        let seg = end - start;
        let (t1, t2) = (start + 0.25 * seg, start + 0.75 * seg);
        let (a, b1) = model.system(t1);
        let (_, b2) = model.system(t2);
        let slope = (b2 - b1) / (t2 - t1);
        let b0 = b1 - slope * (t1 - start);
        AffineSegment { start, a, b0, b1: slope }
    }

    /// A X + b(t).
    pub fn rhs(&self, t: f64, x: &SVector<f64, N>) -> SVector<f64, N> {
        self.a * x + self.b0 + self.b1 * (t - self.start)
    }

    /// The augmented matrix entry (i, j) of M = [[A, b0, b1], [0, 0, 0], [0, 1, 0]], times h.
    fn augmented(&self, h: f64, i: usize, j: usize) -> f64 {
        let m = if i < N {
            match j {
                j if j < N => self.a[(i, j)],
                j if j == N => self.b0[i],
                _ => self.b1[i],
            }
        } else if i == N + 1 && j == N {
            1.0
        } else {
            0.0
        };
        m * h
    }

    /// exp(M h).
    pub fn exponential(&self, h: f64) -> SegmentExponential<N> {
        if N == 2 {
            let e = exponential(U4, |i, j| self.augmented(h, i, j));
            split(|i, j| e[(i, j)])
        } else {
            let e = exponential(Dyn(N + 2), |i, j| self.augmented(h, i, j));
            split(|i, j| e[(i, j)])
        }
    }

    /// Exact propagation from `from` over `h` inside the segment.
    pub fn propagate(&self, from: f64, h: f64) -> Propagation<N> {
        self.exponential(h).from(from - self.start)
    }
}

/// The blocks of exp(M h) from its entries. (Kept free of allocator bounds: inside a function with a
/// `DefaultAllocator: Allocator<D, D>` clause, rustc no longer finds the static matrices' constructors.)
fn split<const N: usize>(e: impl Fn(usize, usize) -> f64) -> SegmentExponential<N> {
    SegmentExponential {
        phi: SMatrix::from_fn(&e),
        q0: SVector::from_fn(|i, _| e(i, N)),
        q1: SVector::from_fn(|i, _| e(i, N + 1)),
    }
}

/// Magnus over [t0, t0 + h] in `n` equal substeps: 4th order for the 2-state SDOF model, 6th order
/// for the 10-state 6-DOF model (whose fast bearing modes make the 4th order need ~8× the substeps).
pub(crate) fn magnus<M: PeriodicModel<N> + ?Sized, const N: usize>(
    model: &M,
    t0: f64,
    h: f64,
    n: usize,
) -> Propagation<N> {
    if N == 2 {
        magnus_in(model, U3, t0, h, n)
    } else if N == 10 {
        magnus6_in(model, nalgebra::Const::<11>, t0, h, n)
    } else {
        magnus6_in(model, Dyn(N + 1), t0, h, n)
    }
}

/// The order of [`magnus`] for an `N`-state model.
pub(crate) fn magnus_order(n: usize) -> usize {
    if n == 2 {
        4
    } else {
        6
    }
}

/// [[A(t), b(t)], [0, 0]]: the homogeneous form of Ẋ = A X + b whose exponential holds Φ and q.
fn augmented_at<M: PeriodicModel<N> + ?Sized, D, const N: usize>(model: &M, dim: D, t: f64) -> OMatrix<f64, D, D>
where
    D: Dim,
    DefaultAllocator: Allocator<D, D>,
{
    let (a, b) = model.system(t);
    OMatrix::<f64, D, D>::from_fn_generic(dim, dim, |i, j| match (i < N, j < N) {
        (true, true) => a[(i, j)],
        (true, false) => b[i],
        _ => 0.0,
    })
}

/// Chains `n` equal substeps of [t0, t0 + h], each the exponential of the Ω that `omega` builds from
/// the augmented matrix at any time, the substep's start and its length; returns (Φ, q).
fn chained<M: PeriodicModel<N> + ?Sized, D, const N: usize>(
    model: &M,
    dim: D,
    (t0, h, n): (f64, f64, usize),
    omega: impl Fn(&dyn Fn(f64) -> OMatrix<f64, D, D>, f64, f64) -> OMatrix<f64, D, D>,
) -> Propagation<N>
where
    D: Dim + DimMin<D, Output = D>,
    DefaultAllocator: Allocator<D, D> + Allocator<D>,
{
    let augmented = |t: f64| augmented_at(model, dim, t);
    let dt = h / n as f64;
    let mut e = OMatrix::<f64, D, D>::identity_generic(dim, dim);
    for i in 0..n {
        let t = t0 + i as f64 * dt;
        e = omega(&augmented, t, dt).exp() * e;
    }
    let blocks = split::<N>(|i, j| if j <= N { e[(i, j)] } else { 0.0 });
    Propagation { phi: blocks.phi, q: blocks.q0 }
}

/// 6th-order Magnus with three Gauss–Legendre nodes and four commutators (Blanes, Casas & Ros,
/// BIT 40 (2000) 434–450; Blanes, Casas, Oteo & Ros, Phys. Rep. 470 (2009) eq 4.22): with A_1..A_3 at
/// the nodes, α1 = h A_2, α2 = (√15 h/3)(A_3 − A_1), α3 = (10 h/3)(A_3 − 2A_2 + A_1),
/// C1 = [α1, α2], C2 = −[α1, 2α3 + C1]/60, Ω = α1 + α3/12 + [−20α1 − α3 + C1, α2 + C2]/240.
fn magnus6_in<M: PeriodicModel<N> + ?Sized, D, const N: usize>(
    model: &M,
    dim: D,
    t0: f64,
    h: f64,
    n: usize,
) -> Propagation<N>
where
    D: Dim + DimMin<D, Output = D>,
    DefaultAllocator: Allocator<D, D> + Allocator<D>,
{
    let comm = |x: &OMatrix<f64, D, D>, y: &OMatrix<f64, D, D>| x * y - y * x;
    let (c, s15) = (0.15f64.sqrt(), 15f64.sqrt());
    chained(model, dim, (t0, h, n), |augmented, t, dt| {
        let a1 = augmented(t + (0.5 - c) * dt);
        let a2 = augmented(t + 0.5 * dt);
        let a3 = augmented(t + (0.5 + c) * dt);
        let al1 = &a2 * dt;
        let al2 = (&a3 - &a1) * (s15 * dt / 3.0);
        let al3 = (&a3 - &a2 * 2.0 + &a1) * (10.0 * dt / 3.0);
        let c1 = comm(&al1, &al2);
        let c2 = comm(&al1, &(&al3 * 2.0 + &c1)) * (-1.0 / 60.0);
        &al1 + &al3 * (1.0 / 12.0) + comm(&(&al1 * -20.0 - &al3 + &c1), &(&al2 + &c2)) * (1.0 / 240.0)
    })
}

/// 4th-order Magnus with two Gauss–Legendre nodes: Ω = h (A_1 + A_2)/2 + (√3 h²/12) [A_2, A_1].
fn magnus_in<M: PeriodicModel<N> + ?Sized, D, const N: usize>(
    model: &M,
    dim: D,
    t0: f64,
    h: f64,
    n: usize,
) -> Propagation<N>
where
    D: Dim + DimMin<D, Output = D>,
    DefaultAllocator: Allocator<D, D> + Allocator<D>,
{
    let c = 3f64.sqrt() / 6.0;
    chained(model, dim, (t0, h, n), |augmented, t, dt| {
        let a1 = augmented(t + (0.5 - c) * dt);
        let a2 = augmented(t + (0.5 + c) * dt);
        (&a1 + &a2) * (0.5 * dt) + (&a2 * &a1 - &a1 * &a2) * (3f64.sqrt() / 12.0 * dt * dt)
    })
}

/// Magnus with substeps doubled until successive results agree to `MAGNUS_TOLERANCE`; returns
/// the propagation and the substeps used.
pub fn magnus_adaptive<M: PeriodicModel<N> + ?Sized, const N: usize>(
    model: &M,
    t0: f64,
    h: f64,
) -> (Propagation<N>, usize) {
    let mut n = 2;
    let mut prev = magnus(model, t0, h, n);
    loop {
        n *= 2;
        let next = magnus(model, t0, h, n);
        let diff = model.propagation_size(&(next.phi - prev.phi), &(next.q - prev.q));
        // Halving the substep divides the error by 2^p: the finer result's error is |P_2n − P_n|/(2^p − 1).
        let gain = ((1usize << magnus_order(N)) - 1) as f64;
        if diff / gain <= MAGNUS_TOLERANCE * model.propagation_size(&next.phi, &next.q) || n >= 1 << 14 {
            return (next, n);
        }
        prev = next;
    }
}

/// How one segment of the period is propagated: its exact affine form, its rank-one modal form, or
/// the Magnus substep density (substeps per second) that converged over the whole segment.
#[derive(Debug, Clone)]
pub enum SegmentRoute<const N: usize> {
    Exact(AffineSegment<N>),
    RankOne(Arc<RankOneSegment<N>>),
    Magnus { density: f64 },
}

impl<const N: usize> SegmentRoute<N> {
    /// Propagation from `from` over `h` inside the segment.
    pub fn propagate<M: PeriodicModel<N> + ?Sized>(&self, model: &M, from: f64, h: f64) -> Propagation<N> {
        match self {
            SegmentRoute::Exact(seg) => seg.propagate(from, h),
            SegmentRoute::RankOne(seg) => seg.propagate(model, from, h),
            SegmentRoute::Magnus { density } => magnus(model, from, h, ((density * h).ceil() as usize).max(2)),
        }
    }
}

/// The propagation over each segment of one period, the route of each segment, and the method used
/// (exact when every segment is affine).
#[derive(Debug, Clone)]
pub struct PeriodPropagation<const N: usize> {
    pub segments: Vec<Propagation<N>>,
    pub routes: Vec<SegmentRoute<N>>,
    pub method: Method,
}

/// Whether A is the same at the Chebyshev nodes of [start, end] (to 1e-14 of its size) and b
/// affine there: the exact propagator applies although the model cannot promise it (friction
/// arms that cancel between two pairs on either side of the pitch point).
fn constant_on<M: PeriodicModel<N> + ?Sized, const N: usize>(model: &M, start: f64, end: f64) -> bool {
    let at = |s: f64| model.system(just_inside(start, end, start + s * (end - start)));
    let (a0, b0) = at(0.0);
    let (_, b1) = at(1.0);
    let size = a0.abs().max() + b0.abs().max() + b1.abs().max();
    crate::numerics::chebyshev::Lobatto::get(8).nodes.iter().all(|s| {
        let (a, b) = at(*s);
        (a - a0).abs().max() + (b - b0 - (b1 - b0) * *s).abs().max() <= 1e-14 * size
    })
}

/// Propagates every segment of one period by the route that applies: exact where A is constant,
/// spectral where it varies along one row (a reference reused across segments with the same row,
/// as on both sides of the pitch point), Magnus otherwise.
pub fn period_segments<M: PeriodicModel<N> + ?Sized, const N: usize>(model: &M) -> PeriodPropagation<N> {
    let mut segments = Vec::with_capacity(model.segments().len());
    let mut routes = Vec::with_capacity(model.segments().len());
    let mut reference: Option<(SVector<f64, N>, Arc<RankOneSegment<N>>)> = None;
    for (j, s) in model.segments().iter().enumerate() {
        let h = s.end - s.start;
        // A model that gives a varying row accepts a structured route: the exact one where A
        // turns out constant on the segment.
        let affine =
            model.segment_is_affine(j) || (model.varying_row(j).is_some() && constant_on(model, s.start, s.end));
        let rank_one = || {
            let row = model.varying_row(j)?;
            if let Some((r, seg)) = &reference {
                if *r == row {
                    if let Some(seg) = seg.moved(model, s.start, s.end) {
                        return Some((row, Arc::new(seg)));
                    }
                }
            }
            RankOneSegment::new(model, s.start, s.end, row).map(|seg| (row, Arc::new(seg)))
        };
        let route = if affine {
            SegmentRoute::Exact(AffineSegment::of(model, s.start, s.end))
        } else if let Some((row, seg)) = rank_one() {
            reference = Some((row, seg.clone()));
            SegmentRoute::RankOne(seg)
        } else {
            let (p, n) = magnus_adaptive(model, s.start, h);
            segments.push(p);
            routes.push(SegmentRoute::Magnus { density: n as f64 / h });
            continue;
        };
        segments.push(route.propagate(model, s.start, h));
        routes.push(route);
    }
    let method = if routes.iter().all(|r| matches!(r, SegmentRoute::Exact(_))) {
        Method::Exact
    } else if routes.iter().any(|r| matches!(r, SegmentRoute::Magnus { .. })) {
        Method::Magnus4
    } else {
        Method::Spectral
    };
    PeriodPropagation { segments, routes, method }
}
/// The monodromy propagation over one period (Φ(T), q(T)).
pub(crate) fn monodromy<const N: usize>(segments: &[Propagation<N>]) -> Propagation<N> {
    segments.iter().fold(Propagation::identity(), |acc, s| acc.then(s))
}
