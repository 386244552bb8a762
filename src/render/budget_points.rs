//! The operating points the loss budget is shown at, in report.md's budget and bearing tables and
//! in loss_budget.svg: every point of a sweep of up to [`ALL_POINTS_UP_TO`] points, else its detail
//! points only (those reported in full), as the efficiency table does. The report keeps a bounded
//! set of points for its sweep plots (thousands for a large sweep); a table or a bar per kept point
//! would be unreadable. records.csv holds the budget of every point.

use crate::report::friction::EfficiencyRecord;
use crate::report::Report;

/// Sweeps up to this many points show the budget at every point.
pub(crate) const ALL_POINTS_UP_TO: usize = 100;

/// The records with a budget that are shown, in the report's order, and whether they are every
/// point's (else the detail points' only).
pub(crate) fn shown_budgets(r: &Report) -> (Vec<&EfficiencyRecord>, bool) {
    let with_budget: Vec<&EfficiencyRecord> = r.efficiency.iter().filter(|e| e.budget.is_some()).collect();
    let mut points: Vec<usize> = with_budget.iter().map(|e| e.case).collect();
    points.sort_unstable();
    points.dedup();
    if points.len() <= ALL_POINTS_UP_TO {
        return (with_budget, true);
    }
    let detail = |e: &EfficiencyRecord| {
        r.operating_points
            .iter()
            .any(|p| p.pinion_torque.si() == e.pinion_torque.si() && p.pinion_speed.si() == e.pinion_speed.si())
    };
    (with_budget.into_iter().filter(|e| detail(e)).collect(), false)
}
