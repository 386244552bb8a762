//! Complex numbers as the rank-one propagator uses them.

use nalgebra::Complex;

pub(super) type C64 = Complex<f64>;

/// Re(a b).
pub(super) fn re_mul(a: C64, b: C64) -> f64 {
    a.re * b.re - a.im * b.im
}
