//! Numbers as reports keep them: ten significant digits, so that output does not change with the
//! last bit of a libm call.

/// Significant digits kept in report.json and the map's CSV.
pub const SIGNIFICANT_DIGITS: usize = 10;

/// Rounds to [`SIGNIFICANT_DIGITS`] significant digits (non-finite values pass through).
pub fn round_sig(x: f64) -> f64 {
    if !x.is_finite() || x == 0.0 {
        return if x == 0.0 { 0.0 } else { x };
    }
    format!("{:.*e}", SIGNIFICANT_DIGITS - 1, x).parse().unwrap_or(x)
}
