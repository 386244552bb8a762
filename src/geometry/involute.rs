//! The involute function and its inverse (ISO 21771).

use std::f64::consts::PI;

/// inv α = tan α − α (ISO 21771).
pub fn involute(alpha: f64) -> f64 {
    alpha.tan() - alpha
}

/// Inverse of the involute function on [0, π/2), by Newton's method from Cheng's start value.
pub(crate) fn inverse_involute(inv: f64) -> f64 {
    if inv <= 0.0 {
        return 0.0;
    }
    let mut a = (3.0 * inv).cbrt().min(1.5);
    for _ in 0..60 {
        let f = involute(a) - inv;
        let df = a.tan().powi(2);
        let next = (a - f / df).clamp(1e-9, PI / 2.0 - 1e-9);
        if (next - a).abs() < 1e-15 {
            return next;
        }
        a = next;
    }
    a
}
