//! One pair's scene (at one oil temperature) run after its sweep: the details evaluated, reported
//! and rendered ([`finish`]), and the whole run in memory with its record files
//! ([`run_scene_to_files`]). Both a scene of one pair and each stage analysed in a drive's run go
//! through here.

use crate::evaluate::record_files::{RecordFiles, RecordFormats};
use crate::evaluate::stages::{details, stream};
use crate::evaluate::{self, Plan, Tally};
use crate::model::Scene;
use crate::progress::{Progress, Quiet};
use crate::render::RenderedReport;
use crate::report::{self, Report};
use crate::rerender;
use crate::run_error::RunError;

/// Whether the scene's run writes record files (it asks for friction or per-point dynamics).
pub fn has_records(scene: &Scene) -> bool {
    let a = &scene.analyses;
    a.friction_along_loa
        || a.efficiency.is_some()
        || (a.dynamics && scene.dynamics.is_some())
        || a.transmission_error.is_some()
}

/// Stages 3 to 5 after the sweep: details (reusing the dynamics the stream computed), report, render;
/// the report as report.json reads back.
pub(crate) fn finish(
    scene: &Scene,
    plan: &Plan,
    tally: &Tally,
    known: &evaluate::stream::Streamed,
    progress: &dyn Progress,
) -> Result<(Report, RenderedReport), RunError> {
    finish_exact(scene, plan, tally, known, progress).map(|(_, report, rendered)| (report, rendered))
}

/// [`finish`] with the report as built, before report.json rounds its numbers.
fn finish_exact(
    scene: &Scene,
    plan: &Plan,
    tally: &Tally,
    known: &evaluate::stream::Streamed,
    progress: &dyn Progress,
) -> Result<(Report, Report, RenderedReport), RunError> {
    let eval = details(scene, plan, known, progress);
    progress.stage("report", 1);
    let report = report::build_report(scene, &eval, tally, plan);
    let timings = eval.dynamics.as_ref().and_then(report::dynamics::timings);
    progress.stage("render", 1);
    let (written, mut rendered) = rerender::render_as_written(&report, timings.as_ref())?;
    // The map's cells are data of the run, as the record files are: written beside the report.
    if let (Some(map), Some(m)) = (&eval.efficiency_map, &written.efficiency_map) {
        let labels: Vec<String> = scene.friction.iter().map(|l| l.label()).collect();
        rendered.files.push((m.csv.clone(), map.csv(&labels)));
    }
    Ok((report, written, rendered))
}

/// One scene (at one oil temperature) run in memory: its report (as report.json reads back) and
/// files, the record files included.
pub(crate) fn run_scene_to_files(scene: &Scene) -> Result<(Report, Vec<(String, String)>), RunError> {
    run_scene_exact(scene).map(|(_, report, files)| (report, files))
}

/// A pair's run in memory: the report as built, as report.json reads it back, and the files.
pub(crate) type ExactRun = (Report, Report, Vec<(String, String)>);

/// [`run_scene_to_files`] with the report as built, its numbers unrounded, first.
pub(crate) fn run_scene_exact(scene: &Scene) -> Result<ExactRun, RunError> {
    let scene = &*evaluate::first_balance::at_first_balance(scene);
    let plan = Plan::new(&scene.operating, None, &scene.operating.detail_points);
    let extra = evaluate::records::ExtraColumns::of(scene);
    let mut sink =
        RecordFiles::new(RecordFormats::default(), &extra, |_| Ok(Vec::new())).map_err(RunError::io("records"))?;
    let streamed = stream(scene, &plan, &mut sink, &Quiet).map_err(RunError::io("records"))?;
    let (exact, report, mut rendered) = finish_exact(scene, &plan, &streamed.tally, &streamed, &Quiet)?;
    if has_records(scene) {
        let (csv, jsonl) = sink.finish().map_err(RunError::io("records"))?;
        let text = |b: Option<Vec<u8>>| String::from_utf8(b.expect("the default formats")).expect("records are UTF-8");
        rendered.files.push((report::sweep::RECORDS_CSV.into(), text(csv)));
        rendered.files.push((report::sweep::RECORDS_JSONL.into(), text(jsonl)));
    }
    Ok((exact, report, rendered.files))
}
