//! Findings for results that are impossible or outside the formulas' assumptions: an efficiency
//! outside [0, 1], a power loss above the input power, a Hertz half-width comparable to the radius of
//! curvature (b_H > R/10, where the line-contact formulas no longer hold). Each comes with the number
//! and where it occurs, next to the result in the report. They are found at every point of the run
//! ([`crate::evaluate::tally`]); the first [`LISTED_FINDINGS`] are listed, the rest counted.

use super::finding::{Finding, Severity};
use crate::evaluate::tally::{Implausible, Tally, LISTED_FINDINGS};

/// A contact past line contact in words, in the report's length unit `len`: its half-width b_H,
/// the limit R/10 and its place from T1 (m), with its name where it has one; a pair's finding and
/// a drive's stage's say the same.
pub(crate) fn half_width_words(
    (half_width, limit, u): (f64, f64, f64),
    named: &Option<String>,
    len: super::units::Shown,
) -> String {
    format!(
        "Hertz half-width b_H = {} exceeds R/10 = {} at {} from T1{}: the line-contact formulas (pressure, film, every law that reads them) no longer hold",
        len.with(half_width, 4),
        len.with(limit, 4),
        len.with(u, 3),
        named.as_ref().map_or(String::new(), |n| format!(" (point {n})"))
    )
}

pub(crate) fn plausibility_findings(tally: &Tally, u: super::units::Units) -> Vec<Finding> {
    let (len, w) = (u.length(), u.power());
    let warn = |m: String| Finding { severity: Severity::Warning, message: m };
    let mut out: Vec<Finding> = tally
        .implausible
        .iter()
        .map(|at| {
            let (k, label) = (at.point + 1, &at.label);
            warn(match &at.what {
                Implausible::HalfWidth { half_width, limit, u, named } => {
                    format!("operating point {k} ({label}): {}", half_width_words((*half_width, *limit, *u), named, len))
                }
                Implausible::Efficiency { law, formulation, mean, min, max } => format!(
                    "operating point {k} ({label}), {law} ({formulation}): efficiency outside [0, 1] by more than rounding (4 ulps) (η̄ = {mean:.6}, η from {min:.6} to {max:.6}): the law gives friction no gear mesh can have here"
                ),
                Implausible::PowerLoss { law, formulation, loss, input } => format!(
                    "operating point {k} ({label}), {law} ({formulation}): power loss {} above the input power {}",
                    w.with(*loss, 3),
                    w.with(*input, 3)
                ),
            })
        })
        .collect();
    if tally.implausible_count > tally.implausible.len() {
        out.push(warn(format!(
            "{} more results like the {LISTED_FINDINGS} above are not listed ({} in all); records.csv has every operating point",
            tally.implausible_count - tally.implausible.len(),
            tally.implausible_count
        )));
    }
    out
}
