//! `gearloss render DIR`: a report folder's report.md and plots drawn again from its report.json
//! alone (and its `timing_numerics.json`, when the run wrote one). `run` renders the same way: the
//! report is written as report.json and read back before the other files are drawn, so the two
//! give the same files byte for byte, and report.json is shown to hold everything the files show.

use std::path::Path;

use crate::render::{self, RenderedReport, TIMINGS_FILE};
use crate::report::numerics::Timings;
use crate::report::oil_sweep::OilSweepReport;
use crate::report::Report;
use crate::run_error::{Failure, FailureKind, RunError};

/// The report as report.json holds it: written, then read back.
pub fn as_written(report: &Report) -> Result<Report, String> {
    serde_json::from_str(&render::render_json(report)).map_err(|e| format!("report.json does not read back: {e}"))
}

/// Stage 5 as a run does it: the files drawn from the report as report.json holds it.
/// report.json is the text the report was read back from: writing the read report again gives the
/// same bytes (tested for every spec), so it is serialised once.
pub fn render_as_written(report: &Report, timings: Option<&Timings>) -> Result<(Report, RenderedReport), RunError> {
    let json = render::render_json(report);
    let read: Report = serde_json::from_str(&json)
        .map_err(|e| format!("report.json does not read back: {e}"))
        .map_err(RunError::read_back)?;
    let rendered = render::render_report_with_json(&read, json, timings).map_err(RunError::drawing)?;
    Ok((read, rendered))
}

/// The files `render` draws for the report folder `dir` (a scene's, or a comparison of oil
/// temperatures with one such folder per temperature), as (path inside `dir`, content).
pub fn render_folder(dir: &Path) -> Result<Vec<(String, String)>, RunError> {
    let text = read(dir, "report.json")?;
    let kind = report_kind(&text).ok_or_else(|| {
        RunError::Render(
            Failure::new(
                FailureKind::NotAReport,
                format!(
                    "{} is not a report gearloss wrote: it is not JSON, or none of its kinds (a pair's, a drive's, a comparison of oil temperatures)",
                    dir.join("report.json").display()
                ),
            )
            .hint("give the folder `gearloss run` wrote, unedited; `gearloss run` again rewrites it whole"),
        )
    })?;
    let bad = |e| bad(dir, kind, e);
    match kind {
        "a pair's report" => {
            let report: Report = serde_json::from_str(&text).map_err(bad)?;
            let timings = match std::fs::read_to_string(dir.join(TIMINGS_FILE)) {
                Ok(t) => Some(serde_json::from_str::<Timings>(&t).map_err(|e| timings_bad(dir, e))?),
                Err(_) => None,
            };
            Ok(render::render_report(&report, timings.as_ref()).map_err(RunError::drawing)?.files)
        }
        "a drive's report" => {
            let drive: crate::report::drive::DriveReport = serde_json::from_str(&text).map_err(bad)?;
            let mut files = render::drive::render_drive(&drive).map_err(RunError::drawing)?.files;
            // Each stage mesh analysed as a pair alone has its report of one pair in its folder.
            for folder in drive.stage_pairs.iter().filter_map(|p| p.folder.as_ref()) {
                let inner = render_folder(&dir.join(folder))?;
                files.extend(inner.into_iter().map(|(f, c)| (format!("{folder}/{f}"), c)));
            }
            Ok(files)
        }
        "a drive's comparison of oil temperatures" => {
            let sweep: crate::report::drive_oil_sweep::DriveOilSweepReport =
                serde_json::from_str(&text).map_err(bad)?;
            let mut files = render::drive::oil_sweep::render_drive_oil_sweep(&sweep);
            for run in &sweep.runs {
                let inner = render_folder(&dir.join(&run.folder))?;
                files.extend(inner.into_iter().map(|(f, c)| (format!("{}/{f}", run.folder), c)));
            }
            Ok(files)
        }
        _ => {
            let sweep: OilSweepReport = serde_json::from_str(&text).map_err(bad)?;
            let mut files = render::oil_sweep::render_oil_sweep(&sweep).map_err(RunError::drawing)?;
            for run in &sweep.runs {
                let inner = render_folder(&dir.join(&run.folder))?;
                files.extend(inner.into_iter().map(|(f, c)| (format!("{}/{f}", run.folder), c)));
            }
            Ok(files)
        }
    }
}

/// Which of the four reports `text` is, by the top-level field only that kind has: a pair's its
/// `geometry`, a drive's its `shafts`, a comparison of oil temperatures its `runs` (a drive's with
/// `rows`, a pair's with `efficiency`); `None` when it is not a JSON object of any. An edited or
/// damaged report is then read as its own kind, and the error names that kind's field.
fn report_kind(text: &str) -> Option<&'static str> {
    let value: serde_json::Value = serde_json::from_str(text).ok()?;
    let has = |key: &str| value.get(key).is_some();
    if has("geometry") {
        Some("a pair's report")
    } else if has("shafts") {
        Some("a drive's report")
    } else if has("runs") && has("rows") {
        Some("a drive's comparison of oil temperatures")
    } else if has("runs") {
        Some("a pair's comparison of oil temperatures")
    } else {
        None
    }
}

/// `gearloss render DIR`: writes every file [`render_folder`] draws into `dir`, each to a
/// temporary file renamed into place (a reader never sees half a file). Returns the files written.
pub fn render_into(dir: &Path) -> Result<Vec<String>, RunError> {
    let files = render_folder(dir)?;
    let io = |what: &'static str| move |source| RunError::Io { what, source };
    for (name, content) in &files {
        let path = dir.join(name);
        let temp = path.with_file_name(format!(".{}.rendering", name.rsplit('/').next().unwrap_or(name)));
        std::fs::write(&temp, content).map_err(io("a rendered file"))?;
        std::fs::rename(&temp, &path).map_err(io("a rendered file"))?;
    }
    Ok(files.into_iter().map(|(f, _)| f).collect())
}

fn read(dir: &Path, file: &str) -> Result<String, RunError> {
    let path = dir.join(file);
    std::fs::read_to_string(&path).map_err(|e| {
        RunError::Render(
            Failure::new(FailureKind::NotAReport, format!("cannot read {}: {e}", path.display()))
                .hint("give the folder `gearloss run` wrote (it holds report.json)"),
        )
    })
}

fn bad(dir: &Path, kind: &str, e: serde_json::Error) -> RunError {
    RunError::Render(
        Failure::new(
            FailureKind::NotAReport,
            format!("{} is {kind} that gearloss did not write as it is: {e}", dir.join("report.json").display()),
        )
        .hint("give the folder `gearloss run` wrote, unedited; `gearloss run` again rewrites it whole"),
    )
}

fn timings_bad(dir: &Path, e: serde_json::Error) -> RunError {
    RunError::Render(
        Failure::new(
            FailureKind::NotAReport,
            format!("{} is not the timings gearloss wrote: {e}", dir.join(TIMINGS_FILE).display()),
        )
        .hint("give the folder `gearloss run` wrote, unedited; `gearloss run` again rewrites it whole"),
    )
}
