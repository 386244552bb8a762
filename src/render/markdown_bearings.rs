//! report.md's bearing tables: every bearing place of the budget at each operating point (its
//! shaft, type, model, position, the loads of one bearing and the losses of all of them), so that a
//! bearing loss can be audited from the loads behind it. Loads do not depend on the law, so a point
//! is shown once; a sweep of more than [`super::budget_points::ALL_POINTS_UP_TO`] points shows its
//! detail points only.

use super::markup::md;

use super::table::{header, row};
use crate::report::friction::EfficiencyRecord;
use crate::report::Report;

/// The section, empty when no record has bearings.
pub(crate) fn bearings_section(r: &Report) -> String {
    let mut out = String::new();
    let (shown, all) = super::budget_points::shown_budgets(r);
    let mut points: Vec<&EfficiencyRecord> = Vec::new();
    for e in shown.into_iter().filter(|e| e.budget.as_ref().is_some_and(|b| !b.bearings.is_empty())) {
        if !points.iter().any(|p| same_point(p, e)) {
            points.push(e);
        }
    }
    if points.is_empty() {
        return out;
    }
    let u = r.units();
    md!(out, "\n### Bearings\n");
    md!(
        out,
        "Each bearing place in the scene's order (pinion shaft, then wheel shaft): the radial and axial load of one bearing from the mesh force (with positions `at`, by the statics of the shaft on its two places; without, F_bt shared equally), and the no-load and load-dependent losses of all `count` bearings of the place. {}\n",
        if all {
            "Every operating point.".to_string()
        } else {
            format!(
                "The detail operating points only (the sweep has more than {}); records.csv has every point.",
                super::budget_points::ALL_POINTS_UP_TO
            )
        }
    );
    for e in points {
        let Some(b) = &e.budget else { continue };
        md!(out, "{}:\n", super::headline::point_at(r, &e.pinion_torque, &e.pinion_speed));
        let cols = [
            "#".to_string(),
            "shaft".into(),
            "type".into(),
            "model".into(),
            "count".into(),
            u.length().heading("at"),
            u.force().heading("F_r"),
            u.force().heading("F_a"),
            u.power().heading("no-load"),
            u.power().heading("load"),
        ];
        header(&mut out, &cols);
        for (i, x) in b.bearings.iter().enumerate() {
            row(
                &mut out,
                &[
                    (i + 1).to_string(),
                    x.shaft.to_string(),
                    x.kind.to_string(),
                    x.model.to_string(),
                    x.count.to_string(),
                    x.position.map_or("—".into(), |p| u.length().q(&p, 1)),
                    u.force().q(&x.radial_load, 1),
                    u.force().q(&x.axial_load, 1),
                    u.power().q(&x.no_load, 3),
                    x.load.map_or("—".into(), |l| u.power().q(&l, 3)),
                ],
            );
        }
        md!(out);
    }
    out
}

fn same_point(a: &EfficiencyRecord, b: &EfficiencyRecord) -> bool {
    a.pinion_torque.si() == b.pinion_torque.si() && a.pinion_speed.si() == b.pinion_speed.si()
}
