//! Bracketed root finding: Brent's method (the `roots` crate) with a bisection fallback.

use roots::{find_root_brent, SimpleConvergency};

/// A root of `f` in [a, b] where f(a) and f(b) differ in sign, to `xtol` in x.
///
/// ```
/// use gearloss::numerics::roots::brent;
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
