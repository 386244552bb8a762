//! Stage 5, render: report → files (report.md, report.json, SVG plots). Renderers only read the report.

pub mod markdown;
pub mod markdown_bearings;
pub mod markdown_dynamics;
pub mod markdown_friction;
pub mod markdown_helical;
pub mod markdown_losses;
pub mod markdown_sweep;
pub mod oil_sweep;
pub mod svg;
pub mod table;

use crate::report::Report;

/// Files whose names start with this hold run times: machine-dependent, never snapshotted or
/// compared with the committed reports.
pub const TIMING_PREFIX: &str = "timing_";

/// The files of a report folder: (file name, content).
#[derive(Debug, Clone)]
pub struct RenderedReport {
    pub slug: String,
    pub files: Vec<(String, String)>,
}

/// report.json: the report's serde data, pretty-printed.
pub fn render_json(report: &Report) -> String {
    let mut s = serde_json::to_string_pretty(report).expect("the report serialises: all keys are strings");
    s.push('\n');
    s
}

/// Renders every file of the report folder.
pub fn render_report(report: &Report) -> Result<RenderedReport, String> {
    let mut files = vec![
        ("report.md".to_string(), markdown::render_markdown(report)),
        ("report.json".to_string(), render_json(report)),
    ];
    for plot in &report.plots {
        let svg = match plot.file.as_str() {
            "contact_state.svg" => svg::contact_state(report)?,
            "plane_of_action.svg" => svg::plane_of_action(report)?,
            "sweep_speed.svg" => svg::sweep(report, true)?,
            "sweep_torque.svg" => svg::sweep(report, false)?,
            "sweep_mu.svg" => svg::sweep_mu(report)?,
            "map_efficiency.svg" => svg::efficiency_map(report)?,
            "loss_budget.svg" => svg::loss_budget(report)?,
            "film.svg" => svg::film(report)?,
            "efficiency_map.svg" => svg::efficiency_contours(report)?,
            "composite_mu_vs_speed.svg" => svg::composite_mu_vs_speed(report)?,
            "stability_map.svg" => svg::stability_map(report)?,
            "timing_work_precision.svg" => svg::work_precision(report)?,
            other => return Err(format!("no renderer for plot {other}")),
        };
        files.push((plot.file.clone(), svg));
    }
    if let Some(m) = &report.efficiency_map {
        files.push((m.csv.clone(), markdown_losses::map_csv(m)));
    }
    for (k, pc) in report.curves.points.iter().enumerate() {
        files.push((pc.file.clone(), svg::point_friction(report, k)?));
    }
    if let Some(d) = &report.dynamics {
        for (k, c) in d.curves.iter().enumerate() {
            if !c.dte.is_empty() {
                files.push((c.file.clone(), svg::dynamics_point(report, k)?));
            }
            if !c.free.is_empty() {
                files.push((c.free_file.clone(), svg::free_response(report, k)?));
            }
        }
        if let Some(t) = &d.timings {
            let mut json = serde_json::to_string_pretty(t).expect("timings serialise");
            json.push('\n');
            files.push((TIMING_PREFIX.to_string() + "numerics.json", json));
        }
    }
    Ok(RenderedReport { slug: report.slug.clone(), files })
}
