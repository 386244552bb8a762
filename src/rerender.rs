//! `gearloss render DIR`: a report folder's report.md and plots drawn again from its report.json
//! alone (and its `timing_numerics.json`, when the run wrote one): a drive's report (every scene's),
//! its comparison of oil temperatures, and a pair's report (a stage mesh's, in its folder). `run` renders the same way: the report is written as report.json and
//! read back before the other files are drawn, so the two give the same files byte for byte, and
//! report.json is shown to hold everything the files show.

use std::path::Path;

use crate::run_drive::DriveRun;
use crate::run_error::{Failure, FailureKind, RunError};
use crate::run_pair;

/// The files `render` draws for the report folder `dir` (a scene's, or a comparison of oil
/// temperatures with one such folder per temperature), as (path inside `dir`, content): the
/// report read back as its kind, the folders inside it that hold reports of their own drawn in turn.
pub fn render_folder(dir: &Path) -> Result<Vec<(String, String)>, RunError> {
    let text = read(dir, "report.json")?;
    let value: Option<serde_json::Value> = serde_json::from_str(&text).ok();
    let has = |keys: &[&str]| value.as_ref().is_some_and(|v| keys.iter().all(|k| v.get(k).is_some()));
    // Which report `text` is, by the top-level fields only its kind has; an edited or damaged
    // report is then read as its own kind, and the error names that kind's field.
    let (files, inner) = if has(&["geometry", "efficiency_map"]) {
        return Err(not_a_report(
            dir,
            "a pair's report with its own efficiency map, which gearloss no longer writes: a pair's scene runs as its one-stage drive, whose loss map holds the map",
            "run the scene again: `gearloss run` writes the drive's report with its loss map and the pair's in `stages/pair/`",
        ));
    } else if has(run_pair::REPORT.1) {
        run_pair::redraw(dir, &text, &|e| bad(dir, run_pair::REPORT.0, e))?
    } else if has(DriveRun::REPORT.1) {
        DriveRun::redraw(dir, &text, &|e| bad(dir, DriveRun::REPORT.0, e))?
    } else if has(DriveRun::OIL_SWEEP.1) {
        DriveRun::redraw_oil_sweep(&text, &|e| bad(dir, DriveRun::OIL_SWEEP.0, e))?
    } else if has(&["runs"]) {
        return Err(not_a_report(
            dir,
            "a comparison of one pair's runs at several oil temperatures, which gearloss no longer writes: a pair's scene runs as its one-stage drive, whose comparison has `rows`",
            "run the scene again: `gearloss run` writes the comparison and each temperature's folder whole",
        ));
    } else {
        return Err(not_a_report(
            dir,
            "not a report gearloss wrote: it is not JSON, or none of its kinds (a pair's, a drive's, a comparison of oil temperatures)",
            "give the folder `gearloss run` wrote, unedited; `gearloss run` again rewrites it whole",
        ));
    };
    let mut files = files;
    for folder in inner {
        let drawn = render_folder(&dir.join(&folder))?;
        files.extend(drawn.into_iter().map(|(f, c)| (format!("{folder}/{f}"), c)));
    }
    Ok(files)
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

/// `dir`'s report.json refused as `what` it is, with `hint`.
fn not_a_report(dir: &Path, what: &str, hint: &str) -> RunError {
    RunError::Render(
        Failure::new(FailureKind::NotAReport, format!("{} is {what}", dir.join("report.json").display())).hint(hint),
    )
}
