//! The periodic state X(t) of any [`PeriodicModel`] over one period as a function that can be evaluated at any
//! time, and the location of the extrema and zeros of quantities built on it.
//!
//! The period is cut into *pieces* at every switch time of the system (zone boundaries, pitch-point
//! passages, regime switches) and at the model's smooth cuts (nodes of a stiffness table, where
//! k'(t) jumps), so every quantity is smooth inside a piece. Each piece carries a grid fine enough to
//! bracket every oscillation: at least [`NODES_PER_OSCILLATION`] nodes per period of the fastest free
//! oscillation ω on the piece ([`PeriodicModel::highest_frequency`]; sqrt(|A₂₁|) for the SDOF
//! model), so that between two nodes the velocity of any oscillating part changes sign at most
//! once, and at least [`MIN_NODES`] per piece. The state at the nodes is
//! marched from the Floquet periodic state X*(0); the state at any other time is propagated from
//! the node before it (the exact propagator where it applies, Magnus otherwise).
//!
//! [`Trajectory::extrema`] finds a quantity's extrema on each piece as the roots of its derivative,
//! bracketed on the grid and refined by Brent's method (`roots` crate) to 1e-13 of the period, together
//! with the one-sided values at both ends of every piece (where a force may jump). This is what
//! every reported maximum, minimum and peak-to-peak comes from; the grid itself is only a bracket.

use crate::numerics::roots::{bracketed_roots, brent};
use nalgebra::SVector;

use super::model::PeriodicModel;
use super::propagator::{PeriodPropagation, SegmentRoute};

/// Grid nodes per period of the fastest free oscillation on a piece.
pub(crate) const NODES_PER_OSCILLATION: f64 = 16.0;
/// Grid nodes per piece at least.
pub(crate) const MIN_NODES: usize = 8;

/// One smooth piece of the period.
#[derive(Debug, Clone)]
pub struct Piece<const N: usize> {
    /// Start and end (s from the start of the period).
    pub start: f64,
    pub end: f64,
    /// Index of the model's segment it lies in.
    pub segment: usize,
    /// How the segment is propagated (exact affine form, or Magnus with its substep density).
    route: SegmentRoute<N>,
    /// Grid times and states (both ends included).
    pub times: Vec<f64>,
    pub states: Vec<SVector<f64, N>>,
}

/// A located extremum: its value and time (s).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Extremum {
    pub value: f64,
    pub time: f64,
}

/// Minimum and maximum of a quantity over the period, and every interior critical time found.
#[derive(Debug, Clone, PartialEq)]
pub struct Extrema {
    pub min: Extremum,
    pub max: Extremum,
    /// Per piece: the sorted critical times (roots of the derivative) inside it.
    pub critical: Vec<Vec<f64>>,
}

/// The periodic state on its pieces.
pub struct Trajectory<'s, M: ?Sized, const N: usize> {
    pub sys: &'s M,
    pub pieces: Vec<Piece<N>>,
}

impl<'s, M: PeriodicModel<N> + ?Sized, const N: usize> Trajectory<'s, M, N> {
    /// The periodic trajectory from X*(0), on the routes of the period's propagation (from Floquet).
    pub fn new(sys: &'s M, period: &PeriodPropagation<N>, x0: SVector<f64, N>) -> Self {
        let cuts = sys.smooth_cuts();
        let mut pieces = Vec::new();
        let mut x = x0;
        for (j, seg) in sys.segments().iter().enumerate() {
            let route = period.routes[j].clone();
            let mut bounds = vec![seg.start];
            bounds.extend(cuts.iter().copied().filter(|t| *t > seg.start && *t < seg.end));
            bounds.push(seg.end);
            for w in bounds.windows(2) {
                let (a, b) = (w[0], w[1]);
                let omega =
                    [0.02, 0.5, 0.98].iter().map(|f| sys.highest_frequency(a + f * (b - a))).fold(0.0, f64::max);
                let n = ((b - a) * omega / (2.0 * std::f64::consts::PI) * NODES_PER_OSCILLATION).ceil() as usize;
                let n = n.max(MIN_NODES);
                let mut piece =
                    Piece { start: a, end: b, segment: j, route: route.clone(), times: Vec::new(), states: Vec::new() };
                let h = (b - a) / n as f64;
                let step = match &route {
                    SegmentRoute::Exact(s) => Some(s.exponential(h)),
                    SegmentRoute::RankOne(_) | SegmentRoute::Magnus { .. } => None,
                };
                piece.times.push(a);
                piece.states.push(x);
                for i in 1..=n {
                    let from = a + (i - 1) as f64 * h;
                    let t = if i == n { b } else { a + i as f64 * h };
                    x = match (&step, i == n) {
                        (Some(e), false) => e.from(from - seg.start).apply(&x),
                        _ => piece.advance(sys, &x, from, t - from),
                    };
                    piece.times.push(t);
                    piece.states.push(x);
                }
                pieces.push(piece);
            }
        }
        Trajectory { sys, pieces }
    }

    /// The state at `t` inside piece `p`.
    pub fn state(&self, p: usize, t: f64) -> SVector<f64, N> {
        let piece = &self.pieces[p];
        let i = piece.times.partition_point(|s| *s <= t).saturating_sub(1).min(piece.times.len() - 1);
        let from = piece.times[i];
        if t <= from {
            return piece.states[i];
        }
        piece.advance(self.sys, &piece.states[i], from, t - from)
    }

    /// The time at which the system's coefficients are read for `t` in piece `p`: `t` itself inside,
    /// a point just inside at the ends (one-sided limits where k or μ jump).
    pub fn parameter_time(&self, p: usize, t: f64) -> f64 {
        let piece = &self.pieces[p];
        let d = (1e-12 * self.sys.period()).min(0.25 * (piece.end - piece.start));
        t.clamp(piece.start + d, piece.end - d)
    }

    /// All grid times of the period (both ends of every piece), for plots.
    pub fn grid(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.pieces.iter().enumerate().flat_map(|(p, piece)| piece.times.iter().map(move |t| (p, *t)))
    }

    /// The breaks of every grid cell over the period (sorted, no duplicates), for quadrature.
    pub fn cell_breaks(&self) -> Vec<f64> {
        let mut v: Vec<f64> = self.grid().map(|(_, t)| t).collect();
        v.dedup();
        v
    }

    /// The piece containing `t` (the first one whose end is beyond it).
    pub fn piece_of(&self, t: f64) -> usize {
        self.pieces.partition_point(|p| p.end <= t).min(self.pieces.len() - 1)
    }

    /// Extrema of `g(p, t)` over the period. `dg(p, t)` is its time derivative inside piece `p`;
    /// its sign changes between grid nodes are refined by Brent's method; the one-sided values at
    /// both ends of each piece are candidates too.
    pub fn extrema(&self, g: impl Fn(usize, f64) -> f64, dg: impl Fn(usize, f64) -> f64) -> Extrema {
        let xtol = 1e-13 * self.sys.period();
        let mut min = Extremum { value: f64::INFINITY, time: 0.0 };
        let mut max = Extremum { value: f64::NEG_INFINITY, time: 0.0 };
        let mut critical = Vec::with_capacity(self.pieces.len());
        let mut consider = |value: f64, time: f64| {
            if value < min.value {
                min = Extremum { value, time };
            }
            if value > max.value {
                max = Extremum { value, time };
            }
        };
        for (p, piece) in self.pieces.iter().enumerate() {
            consider(g(p, piece.start), piece.start);
            consider(g(p, piece.end), piece.end);
            let roots = bracketed_roots(|s| dg(p, s), &piece.times, xtol);
            for t in &roots {
                consider(g(p, *t), *t);
            }
            critical.push(roots);
        }
        Extrema { min, max, critical }
    }

    /// The intervals (s) where `g < 0`, with the crossings located by Brent's method to `xtol` (s).
    /// `critical` are the critical times of `g` per piece (from [`Trajectory::extrema`]): between two
    /// of them and the piece ends `g` is monotone, so each such stretch holds at most one zero.
    pub fn negative_intervals(
        &self,
        g: impl Fn(usize, f64) -> f64,
        critical: &[Vec<f64>],
        xtol: f64,
    ) -> Vec<(f64, f64)> {
        let mut out: Vec<(f64, f64)> = Vec::new();
        let mut open: Option<f64> = None;
        for (p, piece) in self.pieces.iter().enumerate() {
            let mut knots = vec![piece.start];
            knots.extend(critical[p].iter().copied());
            knots.push(piece.end);
            let mut prev = (piece.start, g(p, piece.start));
            if prev.1 < 0.0 && open.is_none() {
                open = Some(piece.start);
            } else if prev.1 >= 0.0 {
                if let Some(s) = open.take() {
                    out.push((s, piece.start));
                }
            }
            for &t in &knots[1..] {
                let v = g(p, t);
                if (v < 0.0) != (prev.1 < 0.0) {
                    let root = brent(|s| g(p, s), prev.0, t, xtol);
                    match open.take() {
                        Some(s) => out.push((s, root)),
                        None => open = Some(root),
                    }
                }
                prev = (t, v);
            }
        }
        if let Some(s) = open {
            // A separation running through the end of the period continues at τ = 0 of the next one
            // (reported as two intervals, [s, T] and the one starting at 0).
            out.push((s, self.sys.period()));
        }
        out
    }
}

impl<const N: usize> Piece<N> {
    /// Propagates `x` from `from` over `h` (inside this piece).
    fn advance<M: PeriodicModel<N> + ?Sized>(
        &self,
        sys: &M,
        x: &SVector<f64, N>,
        from: f64,
        h: f64,
    ) -> SVector<f64, N> {
        if h <= 0.0 {
            return *x;
        }
        self.route.propagate(sys, from, h).apply(x)
    }
}
