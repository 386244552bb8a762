//! One mesh's problem ([`MeshProblem`]) run after its sweep: the details evaluated, reported
//! and rendered (`finish_exact`), and the whole run in memory with its record files
//! ([`run_mesh_to_files`]): the per-mesh evaluation each stage mesh a drive's run analyses goes
//! through (a scene of one pair's, `stages/pair/`, among them): into a folder, as a shard's part and
//! merged from shards, as the drive's run ([`crate::run_stage_pairs`]) asks; and a pair's
//! report.json drawn again ([`redraw`], for `gearloss render`).

use std::path::Path;

use crate::evaluate::record_files::{RecordFiles, RecordFormats};
use crate::evaluate::stages::{details, stream};
use crate::evaluate::stream::Streamed;
use crate::evaluate::{self, Plan, Shard, Tally};
use crate::folder::ReportFolder;
use crate::mesh::MeshProblem;
use crate::progress::{Progress, Quiet};
use crate::render::RenderedReport;
use crate::render::TIMINGS_FILE;
use crate::report::numerics::Timings;
use crate::report::{self, Report};
use crate::run_error::{Failure, FailureKind, RunError};
use crate::run_kind::Redrawn;
use crate::shard::{self, ShardSet};

/// Whether the mesh's run writes record files (it asks for friction or per-point dynamics).
pub fn has_records(problem: &MeshProblem) -> bool {
    let a = &problem.analyses;
    a.friction_along_loa
        || a.efficiency.is_some()
        || (a.dynamics && problem.dynamics.is_some())
        || a.transmission_error.is_some()
}

/// Stages 3 to 5 after the sweep: details (reusing the dynamics the stream computed), report,
/// render; the report as built, before report.json rounds its numbers, and as report.json reads
/// it back.
fn finish_exact(
    problem: &MeshProblem,
    plan: &Plan,
    tally: &Tally,
    known: &evaluate::stream::Streamed,
    progress: &dyn Progress,
) -> Result<(Report, Report, RenderedReport), RunError> {
    let eval = details(problem, plan, known, progress);
    progress.stage("report", 1);
    let report = report::build_report(problem, &eval, tally, plan);
    let timings = eval.dynamics.as_ref().and_then(report::dynamics::timings);
    progress.stage("render", 1);
    let (written, rendered) = render_as_written(&report, timings.as_ref())?;
    Ok((report, written, rendered))
}

/// One mesh's problem run in memory: its report (as report.json reads back) and
/// files, the record files included.
pub(crate) fn run_mesh_to_files(problem: &MeshProblem) -> Result<(Report, Vec<(String, String)>), RunError> {
    run_mesh_exact(problem).map(|(_, report, files)| (report, files))
}

/// A pair's run in memory: the report as built, as report.json reads it back, and the files.
pub(crate) type ExactRun = (Report, Report, Vec<(String, String)>);

/// [`run_mesh_to_files`] with the report as built, its numbers unrounded, first.
pub(crate) fn run_mesh_exact(problem: &MeshProblem) -> Result<ExactRun, RunError> {
    let plan = Plan::new(&problem.operating, None, &problem.operating.detail_points);
    let extra = evaluate::records::ExtraColumns::of(problem);
    let mut sink =
        RecordFiles::new(RecordFormats::default(), &extra, |_| Ok(Vec::new())).map_err(RunError::io("records"))?;
    let streamed = stream(problem, &plan, &mut sink, &Quiet).map_err(RunError::io("records"))?;
    let (exact, report, mut rendered) = finish_exact(problem, &plan, &streamed.tally, &streamed, &Quiet)?;
    if has_records(problem) {
        let (csv, jsonl) = sink.finish().map_err(RunError::io("records"))?;
        let text = |b: Option<Vec<u8>>| String::from_utf8(b.expect("the default formats")).expect("records are UTF-8");
        rendered.files.push((report::sweep::RECORDS_CSV.into(), text(csv)));
        rendered.files.push((report::sweep::RECORDS_JSONL.into(), text(jsonl)));
    }
    Ok((exact, report, rendered.files))
}

/// A pair's run into `folder` under `dir` (`""`: the top), its record files of `formats` streamed
/// as its sweep runs: the report as built, as report.json reads it back, and the files written.
pub(crate) fn run_in_folder_exact(
    problem: &MeshProblem,
    (folder, dir): (&ReportFolder, &str),
    formats: RecordFormats,
    progress: &dyn Progress,
) -> Result<(Report, Report, Vec<String>), RunError> {
    let plan = Plan::new(&problem.operating, None, &problem.operating.detail_points);
    let path = |f: &str| crate::folder::in_dir(dir, f);
    let (streamed, mut files) = stream_into(problem, &plan, (folder, dir), formats, progress)?;
    let (exact, report, rendered) = finish_exact(problem, &plan, &streamed.tally, &streamed, progress)?;
    progress.stage("write", rendered.files.len() as u64);
    for (file, content) in &rendered.files {
        folder.write(&path(file), content.as_bytes()).map_err(RunError::io("the report folder"))?;
        files.push(path(file));
        progress.advance(1);
    }
    Ok((exact, report, files))
}

/// A shard of a pair's sweep into `folder` under `dir` (`""`: the top): its points' tally and the
/// record files of `formats` written.
pub(crate) fn shard_in_folder(
    problem: &MeshProblem,
    shard: Shard,
    at: (&ReportFolder, &str),
    formats: RecordFormats,
    progress: &dyn Progress,
) -> Result<(Tally, Vec<String>), RunError> {
    let plan = Plan::new(&problem.operating, Some(shard), &problem.operating.detail_points);
    let (streamed, files) = stream_into(problem, &plan, at, formats, progress)?;
    Ok((streamed.tally, files))
}

/// A pair's shards (`set`) merged into `folder` under `dir` (`""`: the top): the record files
/// concatenated in shard order, the tallies folded, the details evaluated, reported and rendered.
/// The report as built, as report.json reads it back, and the files written.
pub(crate) fn merge_in_folder(
    set: &ShardSet,
    problem: &MeshProblem,
    (folder, dir): (&ReportFolder, &str),
    progress: &dyn Progress,
) -> Result<(Report, Report, Vec<String>), RunError> {
    let plan = Plan::new(&problem.operating, None, &problem.operating.detail_points);
    let path = |f: &str| crate::folder::in_dir(dir, f);
    let mut files = Vec::new();
    if has_records(problem) {
        progress.stage("merge", set.folders.len() as u64);
        files.extend(
            set.concatenate_into::<crate::evaluate::pair_records::PairRecords>((folder, dir), progress)
                .map_err(RunError::io("the record files"))?,
        );
    }
    let tally: Tally = set.tally().map_err(RunError::Shards)?;
    let (exact, report, rendered) = finish_exact(problem, &plan, &tally, &Default::default(), progress)?;
    for (file, content) in &rendered.files {
        folder.write(&path(file), content.as_bytes()).map_err(RunError::io("the report folder"))?;
        files.push(path(file));
    }
    Ok((exact, report, files))
}

/// What a pair's report.json is called and the top-level fields only it has, read by
/// `gearloss render`.
pub(crate) const REPORT: (&str, &[&str]) = ("a pair's report", &["geometry"]);

/// The files a pair's report.json (`text`, in `dir`) draws again, with its `timing_numerics.json`
/// when the run wrote one; `bad` names what in the text is not a pair's report.
pub(crate) fn redraw(dir: &Path, text: &str, bad: &dyn Fn(serde_json::Error) -> RunError) -> Result<Redrawn, RunError> {
    let report: Report = serde_json::from_str(text).map_err(bad)?;
    let timings = match std::fs::read_to_string(dir.join(TIMINGS_FILE)) {
        Ok(t) => Some(serde_json::from_str::<Timings>(&t).map_err(|e| timings_bad(dir, e))?),
        Err(_) => None,
    };
    Ok((crate::render::render_report(&report, timings.as_ref()).map_err(RunError::drawing)?.files, Vec::new()))
}

/// A `timing_numerics.json` that does not read back.
fn timings_bad(dir: &Path, e: serde_json::Error) -> RunError {
    RunError::Render(
        Failure::new(
            FailureKind::NotAReport,
            format!("{} is not the timings gearloss wrote: {e}", dir.join(TIMINGS_FILE).display()),
        )
        .hint("give the folder `gearloss run` wrote, unedited; `gearloss run` again rewrites it whole"),
    )
}

/// Stage 5 as a run does it: the files drawn from the report as report.json holds it (written,
/// then read back), so that `gearloss render` of the folder gives the same files byte for byte and
/// report.json is shown to hold everything the files show. report.json is the text the report was
/// read back from: writing the read report again gives the same bytes (tested for every spec), so
/// it is serialised once.
pub(crate) fn render_as_written(
    report: &Report,
    timings: Option<&Timings>,
) -> Result<(Report, RenderedReport), RunError> {
    let json = crate::render::render_json(report);
    let read: Report = serde_json::from_str(&json)
        .map_err(|e| format!("report.json does not read back: {e}"))
        .map_err(RunError::read_back)?;
    let rendered = crate::render::render_report_with_json(&read, json, timings).map_err(RunError::drawing)?;
    Ok((read, rendered))
}

/// The plan's points streamed into the record files of `folder` under `dir` (`""`: the top), when
/// the problem writes records; returns the stream and the record files written.
fn stream_into(
    problem: &MeshProblem,
    plan: &Plan,
    (folder, dir): (&ReportFolder, &str),
    formats: RecordFormats,
    progress: &dyn Progress,
) -> Result<(Streamed, Vec<String>), RunError> {
    let io = RunError::io("the record files");
    if !has_records(problem) {
        return Ok((stream(problem, plan, &mut evaluate::records::NoRecords, progress).map_err(io)?, Vec::new()));
    }
    let mut sink =
        shard::record_files(folder, dir, &evaluate::records::ExtraColumns::of(problem), formats).map_err(&io)?;
    let streamed = stream(problem, plan, &mut sink, progress).map_err(&io)?;
    sink.finish().map_err(&io)?;
    let path = |f: &str| crate::folder::in_dir(dir, f);
    Ok((streamed, formats.files().into_iter().map(path).collect()))
}
