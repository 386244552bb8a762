//! Findings about bearings beyond their models' range: a bearing whose static equivalent load
//! P_0 = max(0.6 F_r + 0.5 F_a, F_r) exceeds its static load rating C_0 somewhere in the sweep (one
//! warning a bearing, at its worst row or point: the sweep's tally, `evaluate/static_loads.rs`,
//! beyond [`MAX_STATIC_LOAD_RATIO`]). Palmgren's f_1 (and the SKF model's sliding friction)
//! read P_0/C_0 for bearings inside their rating; beyond it the loss is extrapolated, and the
//! bearing itself is overloaded (ISO 76: static safety s_0 = C_0/P_0 < 1).

use super::finding::{Finding, Severity};
use super::units::Units;
use crate::drive::Drive;
use crate::evaluate::static_loads::StaticLoads;
use crate::losses::bearing_type::MAX_STATIC_LOAD_RATIO;

/// Where a bearing place is: `at 30.00 mm` (in the report's length unit), or `without \`at\`` (a
/// place of a one-pair scene).
pub(super) fn place_at(position: Option<f64>, units: Units) -> String {
    position.map_or_else(|| "without `at`".into(), |x| format!("at {}", units.length().with(x, 2)))
}

/// Every bearing place of a drive in words with its C_0 (N) where given, shaft after shaft in the
/// layout's order (the order of a drive's [`StaticLoads`]).
pub(super) fn drive_places(layout: &Drive, units: Units) -> Vec<(String, Option<f64>)> {
    layout
        .shafts
        .iter()
        .flat_map(|shaft| {
            shaft.bearings.iter().map(move |b| {
                let place =
                    format!("shaft `{}`, bearing {} ({})", shaft.name, place_at(b.position, units), b.kind.name());
                (place, b.static_load_rating)
            })
        })
        .collect()
}

/// The warnings of the bearing places beyond their static rating: `places`, each in words with
/// its C_0 (N) where given, in the order of `loads` (the sweep's tally), each at the row or point
/// where its worst P_0 was met (`point` names it).
pub(crate) fn overloaded(
    places: impl IntoIterator<Item = (String, Option<f64>)>,
    loads: &StaticLoads,
    point: &dyn Fn(usize) -> String,
) -> Vec<Finding> {
    places
        .into_iter()
        .zip(&loads.0)
        .filter_map(|((place, c0), worst)| {
            let ((p0, at), c0) = ((*worst)?, c0.filter(|c| *c > 0.0)?);
            (p0 / c0 > MAX_STATIC_LOAD_RATIO).then(|| overload_finding(&place, p0 / c0, c0, &point(at)))
        })
        .collect()
}

/// The warning of a bearing place (`place`, in words) whose worst P_0/C_0 is `ratio` (C_0 in N),
/// met at `point` (in words).
fn overload_finding(place: &str, ratio: f64, c0: f64, point: &str) -> Finding {
    Finding {
        severity: Severity::Warning,
        message: format!(
            "{place}: P_0/C_0 = {} at {point} (C_0 = {} kN): the bearing is loaded beyond its static rating, and its load-dependent loss is extrapolated (f_1 is read for P_0/C_0 ≤ 1)",
            crate::numerics::rounding::fixed(ratio, 2),
            crate::numerics::rounding::fixed(c0 * 1e-3, 2)
        ),
    }
}
