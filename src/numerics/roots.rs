//! Bracketed root finding: Brent's method (the `roots` crate) with a bisection fallback.

use roots::{find_root_brent, SimpleConvergency};

/// A root of `f` in [a, b] where f(a) and f(b) differ in sign, to `xtol` in x.
///
/// ```
/// use gearloss::numerics::brent;
/// let r = brent(|x| x * x - 2.0, 0.0, 2.0, 1e-14);
/// assert!((r - 2f64.sqrt()).abs() < 1e-13);
/// ```
pub fn brent(f: impl Fn(f64) -> f64, a: f64, b: f64, xtol: f64) -> f64 {
    let mut conv = SimpleConvergency { eps: xtol, max_iter: 200 };
    find_root_brent(a, b, &f, &mut conv).unwrap_or_else(|_| {
        // Brent failed to converge (a sign change of a non-finite value): fall back to bisection.
        let (mut lo, mut hi) = (a, b);
        let flo = f(lo);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi || hi - lo <= xtol {
                break;
            }
            if (f(mid) > 0.0) == (flo > 0.0) {
                lo = mid
            } else {
                hi = mid
            }
        }
        0.5 * (lo + hi)
    })
}

/// ((minimum, where), (maximum, where)) of a function over an interval.
pub(crate) type Extremes = ((f64, f64), (f64, f64));

/// Minimum and maximum (value, x) of `f` over `[breaks[0], breaks[last]]`, where `f` is smooth between
/// consecutive breaks and may jump at them. Located, not sampled: on each piece the sign changes of a
/// central-difference f' are bracketed on `nodes` equal steps and refined by [`brent`] to `xtol`; the
/// one-sided limits at both ends of every piece (f read `xtol` inside) are candidates too.
///
/// ```
/// use gearloss::numerics::extrema;
/// // sin on [0, 2π] split at 1: max 1 at π/2, min −1 at 3π/2.
/// let ((lo, at_lo), (hi, at_hi)) = extrema(f64::sin, &[0.0, 1.0, 6.283185307179586], 8, 1e-13);
/// assert!((hi - 1.0).abs() < 1e-15 && (at_hi - std::f64::consts::FRAC_PI_2).abs() < 1e-7);
/// assert!((lo + 1.0).abs() < 1e-15 && (at_lo - 3.0 * std::f64::consts::FRAC_PI_2).abs() < 1e-7);
/// ```
pub fn extrema(f: impl Fn(f64) -> f64, breaks: &[f64], nodes: usize, xtol: f64) -> Extremes {
    extrema_each(|x| [f(x)], breaks, nodes, xtol)[0]
}

/// [`extrema`] of each of the `N` components of `f` at once: the pieces' ends and the grid on which
/// the slopes are bracketed are read once for all components (two mesh efficiencies share every
/// contact state), each component's slope roots refined on their own. Each component's result is
/// exactly [`extrema`] of that component alone.
///
/// ```
/// use gearloss::numerics::{extrema, extrema_each};
/// let breaks = [0.0, 1.0, 6.283185307179586];
/// let both = extrema_each(|x| [x.sin(), x.cos()], &breaks, 8, 1e-13);
/// assert_eq!(both[0], extrema(f64::sin, &breaks, 8, 1e-13));
/// assert_eq!(both[1], extrema(f64::cos, &breaks, 8, 1e-13));
/// ```
pub fn extrema_each<const N: usize>(
    f: impl Fn(f64) -> [f64; N],
    breaks: &[f64],
    nodes: usize,
    xtol: f64,
) -> [Extremes; N] {
    let mut out: [Extremes; N] = [((f64::INFINITY, f64::NAN), (f64::NEG_INFINITY, f64::NAN)); N];
    let consider = |out: &mut [Extremes; N], x: f64, v: [f64; N]| {
        for (o, v) in out.iter_mut().zip(v) {
            if v < o.0 .0 {
                o.0 = (v, x);
            }
            if v > o.1 .0 {
                o.1 = (v, x);
            }
        }
    };
    for w in breaks.windows(2) {
        let (a, b) = (w[0] + xtol, w[1] - xtol);
        if b <= a {
            continue;
        }
        let h = 1e-6 * (b - a) / nodes as f64;
        let slope = |x: f64| {
            let (up, down) = (f((x + h).min(b)), f((x - h).max(a)));
            std::array::from_fn::<f64, N, _>(|k| up[k] - down[k])
        };
        consider(&mut out, a, f(a));
        consider(&mut out, b, f(b));
        let grid: Vec<(f64, [f64; N])> =
            (0..=nodes).map(|i| a + (b - a) * i as f64 / nodes as f64).map(|x| (x, slope(x))).collect();
        for k in 0..N {
            let last = grid[grid.len() - 1].0;
            let mut prev = (grid[0].0, grid[0].1[k]);
            for &(x, d) in &grid[1..] {
                let d = d[k];
                // As [`bracketed_roots`]: an exact zero at a node, or a sign change refined by Brent.
                let root = if d == 0.0 && x < last {
                    Some(x)
                } else if prev.1 != 0.0 && (d > 0.0) != (prev.1 > 0.0) {
                    Some(brent(|t| slope(t)[k], prev.0, x, xtol))
                } else {
                    None
                };
                if let Some(r) = root {
                    let v = f(r);
                    let o = &mut out[k];
                    if v[k] < o.0 .0 {
                        o.0 = (v[k], r);
                    }
                    if v[k] > o.1 .0 {
                        o.1 = (v[k], r);
                    }
                }
                prev = (x, d);
            }
        }
    }
    out
}

/// The roots of `f` between the first and last of `nodes` (sorted): every sign change between two
/// neighbouring nodes refined by [`brent`] to `xtol`, and every node before the last where f is
/// exactly 0. Two roots between the same two nodes are not seen: the nodes must be fine enough.
///
/// ```
/// use gearloss::numerics::bracketed_roots;
/// let r = bracketed_roots(f64::cos, &[0.0, 1.0, 2.0, 3.0, 4.0, 5.0], 1e-14);
/// assert_eq!(r.len(), 2);
/// assert!((r[0] - std::f64::consts::FRAC_PI_2).abs() < 1e-13 && (r[1] - 1.5 * std::f64::consts::PI).abs() < 1e-13);
/// ```
pub fn bracketed_roots(f: impl Fn(f64) -> f64, nodes: &[f64], xtol: f64) -> Vec<f64> {
    let mut roots = Vec::new();
    let Some(&first) = nodes.first() else { return roots };
    let last = nodes[nodes.len() - 1];
    let mut prev = (first, f(first));
    for &x in &nodes[1..] {
        let d = f(x);
        if d == 0.0 && x < last {
            roots.push(x);
        } else if prev.1 != 0.0 && (d > 0.0) != (prev.1 > 0.0) {
            roots.push(brent(&f, prev.0, x, xtol));
        }
        prev = (x, d);
    }
    roots
}
