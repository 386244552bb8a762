//! Findings about bearings beyond their models' range: a bearing whose static equivalent load
//! P_0 = max(0.6 F_r + 0.5 F_a, F_r) exceeds its static load rating C_0 at a reported point (one
//! warning a bearing, at its worst point; a drive's over every row of its sweep, from its tally). Palmgren's f_1 (and the SKF model's sliding friction)
//! read P_0/C_0 for bearings inside their rating; beyond it the loss is extrapolated, and the
//! bearing itself is overloaded (ISO 76: static safety s_0 = C_0/P_0 < 1).

use super::finding::{Finding, Severity};
use crate::losses::bearing_type::{static_equivalent_load, MAX_STATIC_LOAD_RATIO};

/// One bearing's loads at a point: (where, in words; C_0 if given; F_r, F_a of one bearing (N);
/// the point, in words).
pub(crate) struct BearingAtPoint<'a> {
    pub(crate) place: String,
    pub(crate) c0: Option<f64>,
    pub(crate) radial: f64,
    pub(crate) axial: f64,
    pub(crate) point: &'a str,
}

/// A warning for each bearing place (by `place`) whose P_0/C_0 exceeds
/// [`MAX_STATIC_LOAD_RATIO`] at some point, naming the worst point.
pub(crate) fn overloaded<'a>(loads: impl IntoIterator<Item = BearingAtPoint<'a>>) -> Vec<Finding> {
    let mut worst: Vec<(String, f64, f64, String)> = Vec::new();
    for b in loads {
        let Some(c0) = b.c0.filter(|c| *c > 0.0) else { continue };
        let ratio = static_equivalent_load(b.radial, b.axial) / c0;
        if ratio.is_nan() || ratio <= MAX_STATIC_LOAD_RATIO {
            continue;
        }
        match worst.iter_mut().find(|w| w.0 == b.place) {
            Some(w) if w.1 >= ratio => {}
            Some(w) => *w = (b.place, ratio, c0, b.point.to_string()),
            None => worst.push((b.place, ratio, c0, b.point.to_string())),
        }
    }
    worst.into_iter().map(|(place, ratio, c0, point)| overload_finding(&place, ratio, c0, &point)).collect()
}

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
