//! The top of a report folder of a scene run at several oil temperatures: report.md (which
//! temperature's report is where, the lubricant at each temperature, efficiency and losses against
//! the temperature), report.json and efficiency_vs_oil_temperature.svg.

use super::markup::md;

use super::svg::{figure_with_legend, Panel};
use super::table::{fixed, header, law_words, row};
use crate::evaluate::plan::evenly;
use crate::report::losses::LubricantReport;
use crate::report::oil_sweep::{OilSweepReport, OilSweepRow};
use crate::report::units::{Shown, Units};

/// The plot of the efficiency against the oil temperature.
pub(crate) const OIL_SWEEP_PLOT: &str = "efficiency_vs_oil_temperature.svg";
/// Rows of report.md's table (each row one point, law, formulation and temperature); report.json
/// holds every row.
const TABLE_ROWS: usize = 96;
/// Curves of the plot: evenly picked rows.
pub(crate) const PLOTTED_ROWS: usize = 8;

/// report.md, report.json and the plot.
pub(crate) fn render_oil_sweep(r: &OilSweepReport) -> Result<Vec<(String, String)>, String> {
    let mut json = serde_json::to_string_pretty(r).map_err(|e| e.to_string())?;
    json.push('\n');
    let mut files = vec![("report.md".to_string(), markdown(r)), ("report.json".to_string(), json)];
    if !r.efficiency.is_empty() {
        files.push((OIL_SWEEP_PLOT.to_string(), plot(r)?));
    }
    Ok(files)
}

/// `239.3 N·m, 1500 rpm`: in the units the scene wrote them in.
fn point(r: &OilSweepReport, e: &OilSweepRow) -> String {
    crate::report::number::operating_point_words(&r.torque_unit, &r.speed_unit, &e.pinion_torque, &e.pinion_speed)
}

fn celsius(r: &OilSweepReport, i: usize) -> f64 {
    r.runs[i].oil_temperature.si() - 273.15
}

fn markdown(r: &OilSweepReport) -> String {
    let mut out = String::new();
    let u = Units::of_system(r.unit_system);
    let n = r.runs.len();
    md!(out, "# {}\n", r.title);
    md!(out, "## Headline\n");
    let labels: Vec<&str> = r.runs.iter().map(|x| x.label.as_str()).collect();
    md!(
        out,
        "The scene run at {n} oil temperatures ({}): the lubricant's values, every law, film and loss \
         follow the temperature. Each temperature's full report is in its own folder:\n",
        labels.join(", ")
    );
    for x in &r.runs {
        md!(out, "- [{}]({}/report.md): {} warning(s), {} note(s)", x.label, x.folder, x.warnings, x.notes);
    }
    let runs: Vec<_> = r.runs.iter().map(|x| (x.label.as_str(), x.lubricant.as_ref())).collect();
    lubricant_table(&mut out, &runs, u);
    efficiency_table(&mut out, r, u);
    out
}

/// The lubricant's values at each temperature (`runs`: each run's label and its lubricant): a
/// pair's comparison and a drive's.
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

/// The efficiency of every record at each temperature (at most [`TABLE_ROWS`] rows).
fn efficiency_table(out: &mut String, r: &OilSweepReport, u: Units) {
    let n = r.runs.len();
    if !r.efficiency.is_empty() {
        md!(out, "\n## Efficiency against oil temperature\n");
        let w = u.power();
        let mut cols = vec![
            "operating point".to_string(),
            "law".into(),
            "formulation".into(),
            "oil temperature".into(),
            "η̄ mesh %".into(),
            w.heading("P mesh"),
        ];
        if r.loss_budget {
            cols.extend([w.heading("P total"), "η total %".into()]);
        }
        header(out, &cols);
        let mut rows = 0;
        'rows: for e in &r.efficiency {
            for (i, x) in r.runs.iter().enumerate() {
                if rows == TABLE_ROWS {
                    break 'rows;
                }
                let mut cells = vec![
                    point(r, e),
                    law_words(&e.label),
                    e.formulation.name().to_string(),
                    x.label.clone(),
                    fixed(100.0 * e.mean_efficiency[i].0, 3),
                    w.q(&e.power_loss[i], 2),
                ];
                if let (Some(t), Some(eta)) = (&e.total_loss, &e.total_efficiency) {
                    cells.extend([w.q(&t[i], 2), fixed(100.0 * eta[i].0, 3)]);
                }
                row(out, &cells);
                rows += 1;
            }
        }
        let all = r.efficiency.len() * n;
        if all > rows {
            md!(out, "\n… {} more rows in report.json.", all - rows);
        }
        md!(out, "\n![efficiency against oil temperature]({OIL_SWEEP_PLOT})");
    }
}

/// η̄ mesh (and total η with a gearbox) and the mesh loss against the oil temperature, one curve
/// per picked (operating point, law, formulation).
fn plot(r: &OilSweepReport) -> Result<String, String> {
    let x: Vec<f64> = (0..r.runs.len()).map(|i| celsius(r, i)).collect();
    let picked: Vec<&OilSweepRow> =
        evenly(r.efficiency.len(), PLOTTED_ROWS).into_iter().map(|k| &r.efficiency[k]).collect();
    let name = |e: &OilSweepRow| format!("{} {} @ {}", e.label, e.formulation.name(), point(r, e));
    // Legend labels name the law in words (`legend_words`) and the operating point as written.
    let series = |f: &dyn Fn(&OilSweepRow) -> Vec<f64>| -> Vec<(String, Vec<f64>)> {
        picked.iter().map(|e| (name(e), f(e))).collect()
    };
    let x_label = "oil temperature (°C)".to_string();
    let mut panels = vec![
        Panel {
            y_label: "mean mesh efficiency η̄ (%)".into(),
            x_label: x_label.clone(),
            x: x.clone(),
            series: series(&|e| e.mean_efficiency.iter().map(|v| 100.0 * v.0).collect()),
            ..Default::default()
        },
        Panel {
            y_label: "mesh friction power loss, all contacts (W)".into(),
            x_label: x_label.clone(),
            x: x.clone(),
            series: series(&|e| e.power_loss.iter().map(|q| q.si()).collect()),
            ..Default::default()
        },
    ];
    if r.loss_budget {
        panels.push(Panel {
            y_label: "total efficiency of the gearbox (%)".into(),
            x_label,
            x,
            series: series(&|e| e.total_efficiency.iter().flatten().map(|v| 100.0 * v.0).collect()),
            ..Default::default()
        });
    }
    figure_with_legend(&format!("{}: efficiency against oil temperature", r.title), &panels, 420)
}
