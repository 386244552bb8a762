//! The top of a drive's report folder at several oil temperatures: report.md comparing the runs
//! (total loss and η of every shown row at each temperature, meshes and bearings beside),
//! report.json and efficiency_vs_oil_temperature.svg (η of the drive, its total loss and its
//! meshes' against the temperature); each run's own report is in its
//! folder.

use crate::evaluate::plan::evenly;
use crate::render::markup::{counted, md};
use crate::render::svg::{figure_with_legend, Panel};
use crate::render::table::{fixed, header, row};
use crate::report::drive_oil_sweep::DriveOilSweepReport;
use crate::report::losses::LubricantReport;
use crate::report::units::{Shown, Units};

/// The plot of the efficiency against the oil temperature.
pub(crate) const OIL_SWEEP_PLOT: &str = "efficiency_vs_oil_temperature.svg";
/// Curves of the plot: evenly picked rows.
const PLOTTED_ROWS: usize = 8;

/// report.md, report.json and the plot of the comparison.
pub(crate) fn render_drive_oil_sweep(r: &DriveOilSweepReport) -> Result<Vec<(String, String)>, String> {
    let mut out = String::new();
    let w = Units::of_system(r.unit_system).power();
    md!(out, "# {} — oil temperatures\n", r.title);
    md!(
        out,
        "The drive at {} oil temperatures, one report each (the oil read at each: ν, ρ, η and α move with it):\n",
        r.runs.len()
    );
    for run in &r.runs {
        md!(
            out,
            "- [{}]({}/report.md): {}, {}",
            run.label,
            run.folder,
            counted(run.warnings, "warning", "warnings"),
            counted(run.notes, "note", "notes")
        );
    }
    let runs: Vec<_> = r.runs.iter().map(|x| (x.label.as_str(), x.lubricant.as_ref())).collect();
    lubricant_table(&mut out, &runs, Units::of_system(r.unit_system));
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
    let mut files = Vec::new();
    if !r.rows.is_empty() {
        md!(out, "\n![efficiency against oil temperature]({OIL_SWEEP_PLOT})");
        files.push((OIL_SWEEP_PLOT.to_string(), plot(r)?));
    }
    let json = crate::render::json_text::json_text(r, "the comparison");
    files.splice(0..0, [("report.md".into(), out), ("report.json".into(), json)]);
    Ok(files)
}

/// One value of a run's row (total loss W, η, meshes W, bearings W).
type RowValue<'a> = dyn Fn(&(f64, f64, f64, f64)) -> f64 + 'a;

/// The drive's η, total loss and meshes' loss against the oil temperature (°C), one curve per
/// evenly picked row, as a pair's comparison draws its own.
fn plot(r: &DriveOilSweepReport) -> Result<String, String> {
    let w = Units::of_system(r.unit_system).power();
    let x: Vec<f64> = r.runs.iter().map(|run| run.kelvin - 273.15).collect();
    let picked = evenly(r.rows.len(), PLOTTED_ROWS);
    let series = |f: &RowValue<'_>| -> Vec<(String, Vec<f64>)> {
        picked.iter().map(|&i| (r.rows[i].clone(), r.runs.iter().map(|run| f(&run.rows[i])).collect())).collect()
    };
    let panel = |y_label: String, f: &RowValue<'_>| Panel {
        y_label,
        x_label: "oil temperature (°C)".into(),
        x: x.clone(),
        series: series(f),
        ..Default::default()
    };
    let panels = [
        panel("efficiency of the drive η (%)".into(), &|v| 100.0 * v.1),
        panel(w.titled("total loss"), &|v| w.value(v.0)),
        panel(w.titled("meshes' loss"), &|v| w.value(v.2)),
    ];
    // The legend as wide as its longest label (a drive's row names its ends, law and formulation):
    // about 5.5 px a character at the legend's font, and its margins.
    let longest = picked.iter().map(|&i| r.rows[i].chars().count()).max().unwrap_or(0);
    let legend = 420.max((5.5 * longest as f64) as u32 + 60);
    figure_with_legend(&format!("{}: efficiency against oil temperature", r.title), &panels, legend)
}

/// The lubricant's values at each temperature (`runs`: each run's label and its lubricant): the
/// comparison's.
pub(crate) fn lubricant_table(out: &mut String, runs: &[(&str, Option<&LubricantReport>)], u: Units) {
    if runs.iter().any(|x| x.1.is_some()) {
        md!(out, "\n## Lubricant at each temperature\n");
        let (nu, eta, rho, alpha) =
            (u.kinematic_viscosity(), u.dynamic_viscosity(), u.density(), u.pressure_viscosity());
        let cols =
            ["oil temperature".to_string(), nu.heading("ν"), eta.heading("η"), rho.heading("ρ"), alpha.heading("α")];
        header(out, &cols);
        for (label, l) in runs {
            let Some(l) = l else { continue };
            let opt =
                |q: Option<crate::report::number::Q>, s: Shown, d: usize| q.map_or("—".to_string(), |q| s.q(&q, d));
            row(
                out,
                &[
                    label.to_string(),
                    opt(l.kinematic_viscosity, nu, 3),
                    eta.q(&l.dynamic_viscosity, 3),
                    opt(l.density, rho, 1),
                    opt(l.pressure_viscosity, alpha, 3),
                ],
            );
        }
        if let Some(l) = runs[0].1 {
            md!(out, "\nSource: {}.", l.source);
        }
    }
}
