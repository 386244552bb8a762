//! The top of a drive's report folder at several oil temperatures: report.md comparing the runs
//! (total loss and η of every shown row at each temperature, meshes and bearings beside) and
//! report.json; each run's own report is in its folder.

use crate::render::markup::md;
use crate::render::table::{fixed, header, row};
use crate::report::drive_oil_sweep::DriveOilSweepReport;
use crate::report::units::Units;

/// report.md and report.json of the comparison.
pub(crate) fn render_drive_oil_sweep(r: &DriveOilSweepReport) -> Vec<(String, String)> {
    let mut out = String::new();
    let w = Units::of_system(r.unit_system).power();
    md!(out, "# {} — oil temperatures\n", r.title);
    md!(
        out,
        "The drive at {} oil temperatures, one report each (the oil read at each: ν, ρ, η and α move with it):\n",
        r.runs.len()
    );
    for run in &r.runs {
        md!(out, "- [{}]({}/report.md)", run.label, run.folder);
    }
    let runs: Vec<_> = r.runs.iter().map(|x| (x.label.as_str(), x.lubricant.as_ref())).collect();
    crate::render::oil_sweep::lubricant_table(&mut out, &runs, Units::of_system(r.unit_system));
    md!(out);
    md!(out, "## Total loss ({}) and η (%)\n", w.unit);
    let mut head = vec!["row".to_string()];
    head.extend(r.runs.iter().map(|run| format!("{}: loss ({}) / η (%)", run.label, w.unit)));
    header(&mut out, &head);
    for (i, label) in r.rows.iter().enumerate() {
        let mut cells = vec![label.clone()];
        cells.extend(r.runs.iter().map(|run| {
            let (loss, eta, _, _) = run.rows[i];
            format!("{} / {}", w.cell(loss, 2), fixed(100.0 * eta, 4))
        }));
        row(&mut out, &cells);
    }
    md!(out, "\n## Meshes and bearings ({})\n", w.unit);
    let mut head = vec!["row".to_string()];
    head.extend(r.runs.iter().map(|run| format!("{}: meshes / bearings", run.label)));
    header(&mut out, &head);
    for (i, label) in r.rows.iter().enumerate() {
        let mut cells = vec![label.clone()];
        cells.extend(r.runs.iter().map(|run| format!("{} / {}", w.cell(run.rows[i].2, 2), w.cell(run.rows[i].3, 2))));
        row(&mut out, &cells);
    }
    let pretty = serde_json::to_string_pretty(r).expect("the comparison serialises");
    let mut json = crate::render::inline_plain_arrays(&pretty);
    json.push('\n');
    vec![("report.md".into(), out), ("report.json".into(), json)]
}
