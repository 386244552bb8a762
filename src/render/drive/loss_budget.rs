//! A drive's loss_budget.svg: the loss budget of every operating point the report keeps (its first
//! [`crate::evaluate::drive::DETAIL_ROWS`] rows and every row of its detail points) under the first formulation, one stacked bar per
//! point and law: the meshes, then the gears' no-load losses, the bearings' and the seals' (the
//! headline's columns, the parts a pair's budget has). Drawn where the drive has a loss beside its
//! meshes (a gearbox), as a pair's report draws its own.

use crate::losses::parts::COLUMNS;
use crate::report::drive::{DrivePointReport, DriveReport};
use crate::report::units::{Shown, Units};

pub(crate) const FILE: &str = "loss_budget.svg";

/// The rows drawn: the kept rows of the first formulation; None where none has a loss beside its
/// meshes.
pub(crate) fn drawn(r: &DriveReport) -> Option<Vec<&DrivePointReport>> {
    let first = r.points.first()?;
    let rows: Vec<_> = r.points.iter().filter(|p| p.formulation == first.formulation).collect();
    rows.iter().any(|p| p.point.losses.beside_meshes() != 0.0).then_some(rows)
}

/// loss_budget.svg of `r`; None where it is not drawn ([`drawn`]).
pub(crate) fn loss_budget(r: &DriveReport) -> Option<Result<String, String>> {
    let rows = drawn(r)?;
    let power = Units::of_system(r.unit_system).power();
    let caption = format!("{}: loss budget ({} formulation)", r.title, rows[0].formulation);
    Some(crate::render::svg::budget_bars(&caption, "meshes (load-dependent)", power, &bars(&rows, power)))
}

/// Each row's bar: its label and its parts in `power`'s unit, the meshes first.
fn bars(rows: &[&DrivePointReport], power: Shown) -> Vec<(String, Vec<f64>)> {
    rows.iter()
        .map(|p| {
            let l = &p.point.losses;
            let parts = std::iter::once(l.meshes).chain(COLUMNS.iter().map(|c| l.part(c.column)));
            let label = format!("{} ({})", p.label, p.point.flow.name());
            (format!("{label}: {}", crate::render::table::law_words(&p.law)), parts.map(|w| power.value(w)).collect())
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each bar of the committed two-stage reducer's report stacks to its row's total loss
    /// P_in − P_out (to 1e-9 relative: the parts are the walk's, summed in another order), and a
    /// bar is drawn for each kept row of the first formulation.
    #[test]
    fn each_bar_stacks_to_its_rows_total_loss() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/reports/two_stage_ev_reducer/report.json");
        let r: DriveReport = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
        let rows = drawn(&r).expect("a drive with a gearbox draws its budget");
        assert_eq!(rows.len(), r.points.iter().filter(|p| p.formulation == r.points[0].formulation).count());
        for ((label, parts), row) in bars(&rows, Units::si().power()).iter().zip(&rows) {
            let total: f64 = parts.iter().sum();
            assert!((total - row.total_loss).abs() <= 1e-9 * row.total_loss, "{label}: {total} vs {}", row.total_loss);
            assert!(parts[1..].iter().any(|&w| w > 0.0), "{label}: the gearbox's parts are drawn");
        }
    }
}
