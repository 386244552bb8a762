//! Findings about bearings beyond their models' range: a bearing whose static equivalent load
//! P_0 = max(0.6 F_r + 0.5 F_a, F_r) exceeds its static load rating C_0 somewhere in the sweep (one
//! warning a bearing, at its worst row or point: the sweep's tally, `evaluate/static_loads.rs`,
//! beyond `losses::bearing_type::MAX_STATIC_LOAD_RATIO`). Palmgren's f_1 (and the SKF model's sliding friction)
//! read P_0/C_0 for bearings inside their rating; beyond it the loss is extrapolated, and the
//! bearing itself is overloaded (ISO 76: static safety s_0 = C_0/P_0 < 1).

use super::finding::{Finding, Severity};

/// The warning of a bearing place (`place`, in words) whose worst P_0/C_0 is `ratio` (C_0 in N),
/// met at `point` (in words).
pub(crate) fn overload_finding(place: &str, ratio: f64, c0: f64, point: &str) -> Finding {
    Finding {
        severity: Severity::Warning,
        message: format!(
            "{place}: P_0/C_0 = {} at {point} (C_0 = {} kN): the bearing is loaded beyond its static rating, and its load-dependent loss is extrapolated (f_1 is read for P_0/C_0 ≤ 1)",
            crate::numerics::rounding::fixed(ratio, 2),
            crate::numerics::rounding::fixed(c0 * 1e-3, 2)
        ),
    }
}
