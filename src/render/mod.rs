//! Stage 5, render: report → files (report.md, report.json, SVG plots). Renderers only read the report.

pub(crate) mod drive;
pub(crate) mod headline;
pub(crate) mod json_text;
pub mod markdown;
pub(crate) mod markdown_dynamics;
pub(crate) mod markdown_friction;
pub(crate) mod markdown_geometry;
pub(crate) mod markdown_helical;
pub(crate) mod markdown_losses;
pub(crate) mod markdown_sweep;
pub(crate) mod markdown_teeth;
pub(crate) mod markdown_thermal;
pub(crate) mod markup;
pub mod svg;
pub(crate) mod table;
pub mod terminal;

use crate::report::numerics::Timings;
use crate::report::{PlotKind, Report};

/// Files whose names start with this hold run times: machine-dependent, never snapshotted or
/// compared with the committed reports.
pub const TIMING_PREFIX: &str = "timing_";
/// The numerics study's run times beside report.json.
pub const TIMINGS_FILE: &str = "timing_numerics.json";

/// The files of a report folder: (file name, content).
#[derive(Debug, Clone)]
pub struct RenderedReport {
    pub slug: String,
    pub files: Vec<(String, String)>,
}

/// report.json: the report's serde data, pretty-printed, each array of plain values (numbers,
/// strings, `null`) on one line so that a plot's series stays readable (`render/json_text.rs`).
pub fn render_json(report: &Report) -> String {
    json_text::json_text(report, "the report")
}

/// Joins every array of serde_json's pretty output whose elements are all plain values onto the
/// line that opens it: `[\n  1.0,\n  2.0\n]` → `[1.0, 2.0]`. Nested arrays and objects keep
/// their lines.
///
/// ```
/// let pretty = "{\n  \"x\": [\n    1.5,\n    null\n  ],\n  \"y\": [\n    [\n      1,\n      2\n    ]\n  ]\n}";
/// let joined = gearloss::render::inline_plain_arrays(pretty);
/// assert_eq!(joined, "{\n  \"x\": [1.5, null],\n  \"y\": [\n    [1, 2]\n  ]\n}");
/// ```
pub fn inline_plain_arrays(pretty: &str) -> String {
    let mut bytes = pretty.as_bytes().to_vec();
    json_text::join_plain_arrays(&mut bytes);
    String::from_utf8(bytes).expect("joining whole lines and elements keeps the text UTF-8")
}

/// Renders every file of the report folder; `timings`, the numerics study's run times (not part of
/// report.json: they change from run to run), add `timing_numerics.json` and the work-precision plot.
pub fn render_report(report: &Report, timings: Option<&Timings>) -> Result<RenderedReport, String> {
    render_report_with_json(report, render_json(report), timings)
}

/// [`render_report`] with report.json already written (`json` = [`render_json`] of `report`, as a
/// run has it from reading the report back: serialising a large sweep's report twice cost a
/// tenth of the run).
pub fn render_report_with_json(
    report: &Report,
    json: String,
    timings: Option<&Timings>,
) -> Result<RenderedReport, String> {
    let mut files =
        vec![("report.md".to_string(), markdown::render_markdown(report)), ("report.json".to_string(), json)];
    for plot in &report.plots {
        let svg = match plot.kind {
            PlotKind::ContactState => svg::contact_state(report)?,
            PlotKind::PlaneOfAction => svg::plane_of_action(report)?,
            PlotKind::SweepSpeed => svg::sweep(report, true)?,
            PlotKind::SweepTorque => svg::sweep(report, false)?,
            PlotKind::SweepMu => svg::sweep_mu(report)?,
            PlotKind::MapEfficiency => svg::efficiency_map(report)?,
            PlotKind::Film => svg::film(report)?,
            PlotKind::CompositeMuVsSpeed => svg::composite_mu_vs_speed(report)?,
            PlotKind::StabilityMap => svg::stability_map(report)?,
            PlotKind::MeshStiffness => svg::mesh_stiffness(report)?,
            PlotKind::TransmissionError => svg::transmission_error(report)?,
            PlotKind::LoadShare => svg::load_share(report)?,
            // A drive's plots (its thermal balance and duty cycle), which its own renderer draws.
            PlotKind::HeatBalance | PlotKind::DutyCycleTemperature | PlotKind::DutyCycleEnergy => {
                return Err(format!("{} is a drive's plot, not a pair's", plot.file))
            }
            PlotKind::WorkPrecision => match timings {
                Some(t) => svg::work_precision(report, t)?,
                None => continue,
            },
        };
        files.push((plot.file.clone(), svg));
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
    }
    if let Some(t) = timings {
        let mut json = serde_json::to_string_pretty(t).expect("timings serialise");
        json.push('\n');
        files.push((TIMINGS_FILE.to_string(), json));
    }
    Ok(RenderedReport { slug: report.slug.clone(), files })
}
