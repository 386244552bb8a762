//! A drive of several stages run into its report folder: whole (its records streamed), at several
//! oil temperatures (a report each and their comparison), as a shard, and merged from its shards.

use std::path::{Path, PathBuf};

use std::fs::File;
use std::io::BufWriter;

use crate::evaluate::drive_records::{self, DriveRecordFiles};
use crate::evaluate::record_files::RecordFormats;
use crate::evaluate::{self, Shard};
use crate::folder::ReportFolder;
use crate::model::Scene;
use crate::progress::Progress;
use crate::render::RenderedReport;
use crate::report;
use crate::report::drive::DriveReport;
use crate::run_error::RunError;
use crate::{render, shard};

/// What a drive's run wrote: its folder, files and reports.
pub(crate) struct DriveWritten {
    pub folder: PathBuf,
    pub files: Vec<String>,
    pub drives: LabelledDrives,
}

/// Writes `files` into `folder`; their names.
fn write_all(
    folder: &ReportFolder,
    files: &[(String, String)],
    progress: &dyn Progress,
) -> Result<Vec<String>, RunError> {
    progress.stage("write", files.len() as u64);
    let mut out = Vec::new();
    for (file, content) in files {
        folder.write(file, content.as_bytes()).map_err(RunError::io("the report folder"))?;
        out.push(file.clone());
        progress.advance(1);
    }
    Ok(out)
}

/// The report of `eval` with the analyses of one pair on its stages, rendered; the stages' pair
/// reports among the files.
fn reported(
    scene: &Scene,
    drive: &crate::model::SceneDrive,
    eval: &evaluate::drive::DriveEvaluation,
) -> Result<(crate::report::drive::DriveReport, RenderedReport), RunError> {
    let mut report = report::drive::build_drive_report(scene, drive, eval);
    let (rows, files) = crate::run_stage_pairs::stage_pair_files(scene, drive)?;
    report.stage_pairs = rows;
    let mut rendered = render::drive::render_drive(&report).map_err(RunError::drawing)?;
    rendered.files.extend(files);
    Ok((report, rendered))
}

/// A drive scene evaluated, reported and rendered in memory, its record files (the default
/// formats: drive_records.csv and drive_records.jsonl) among the files.
pub fn drive_report_files(
    scene: &Scene,
    drive: &crate::model::SceneDrive,
) -> Result<(crate::report::drive::DriveReport, RenderedReport), RunError> {
    let io = RunError::io("records");
    let mut records = DriveRecordFiles::new(drive, RecordFormats::default(), |_| Ok(Vec::new())).map_err(&io)?;
    let eval =
        evaluate::drive::evaluate_drive_into_with(scene, drive, &mut records, &crate::progress::Quiet).map_err(&io)?;
    let (report, mut rendered) = reported(scene, drive, &eval)?;
    let (csv, jsonl) = records.finish().map_err(&io)?;
    let text = |b: Option<Vec<u8>>| String::from_utf8(b.expect("the default formats")).expect("records are UTF-8");
    rendered.files.push((drive_records::FILE.to_string(), text(csv)));
    rendered.files.push((drive_records::JSONL_FILE.to_string(), text(jsonl)));
    Ok((report, rendered))
}

/// Drive reports with their labels (their folders at several oil temperatures, else empty).
pub type LabelledDrives = Vec<(String, crate::report::drive::DriveReport)>;

/// A drive scene at several oil temperatures in memory: each run's files under its folder, then the
/// comparison's files at the top; with the runs' reports.
pub(crate) fn drive_sweep_files(scene: &Scene) -> Result<(Vec<(String, String)>, LabelledDrives), RunError> {
    let mut files = Vec::new();
    let (top, reports) = each_oil_temperature(scene, |at, drive, dir| {
        let (report, rendered) = drive_report_files(at, drive)?;
        files.extend(rendered.files.into_iter().map(|(f, c)| (format!("{dir}/{f}"), c)));
        Ok(report)
    })?;
    Ok((top.into_iter().chain(files).collect(), reports))
}

/// Runs a drive scene at each of its oil temperatures by `run_one(scene at θ, its drive, its
/// folder)`; the comparison's files (the top of the report folder) and the runs' reports.
fn each_oil_temperature(
    scene: &Scene,
    mut run_one: impl FnMut(&Scene, &crate::model::SceneDrive, &str) -> Result<DriveReport, RunError>,
) -> Result<(Vec<(String, String)>, LabelledDrives), RunError> {
    let mut runs = Vec::new();
    let kelvin: Vec<f64> =
        scene.operating.oil_temperatures.iter().flat_map(|s| s.values.iter().map(|t| t.value)).collect();
    for ((i, label), kelvin) in scene.oil_temperature_labels().into_iter().enumerate().zip(kelvin) {
        let at = scene.at_oil_temperature(i);
        let drive = at.drive.as_ref().expect("a drive scene at another temperature is a drive scene");
        let dir = report::oil_sweep::run_folder(&label);
        let report = run_one(&at, drive, &dir)?;
        runs.push((label, kelvin, dir, report));
    }
    let top = render::drive::oil_sweep::render_drive_oil_sweep(&report::drive_oil_sweep::build_drive_oil_sweep(&runs));
    Ok((top, runs.into_iter().map(|(_, _, dir, r)| (dir, r)).collect()))
}

/// One shard of a drive into `out_dir/<slug>.shard-K-of-N/`: its rows of drive_records.csv and the
/// manifest with their tally.
pub(crate) fn run_drive_shard_into(
    source_name: &str,
    source: &str,
    scene: &Scene,
    drive: &crate::model::SceneDrive,
    (shard, out_dir, formats): (Shard, &Path, RecordFormats),
    progress: &dyn Progress,
) -> Result<DriveWritten, RunError> {
    let name = format!("{}.shard-{}-of-{}", report::slug(&scene.title), shard.index, shard.count);
    let folder = ReportFolder::create(out_dir, &name).map_err(RunError::io("the report folder"))?;
    let io = RunError::io("the record files");
    let (mut records, mut files) = record_files((&folder, ""), drive, formats)?;
    let tally = evaluate::drive::evaluate_drive_shard_with(scene, drive, shard, &mut records, progress).map_err(&io)?;
    records.finish().map_err(&io)?;
    let manifest = shard::Manifest::of_drive(source_name, source, shard, scene.operating.count(), tally)
        .with_digests(&folder, &files)
        .map_err(&io)?;
    folder.write(shard::MANIFEST, &manifest.to_json()).map_err(RunError::io("the shard manifest"))?;
    files.push(shard::MANIFEST.to_string());
    let folder = folder.commit().map_err(RunError::io("the report folder"))?;
    Ok(DriveWritten { folder, files, drives: Vec::new() })
}

/// `gearloss merge` of a drive's shards: drive_records.csv concatenated in shard order (a single
/// run's, byte for byte), the tallies folded, the report's rows, map, thermal balance and duty
/// cycle evaluated again: the report a single run writes.
pub(crate) fn merge_drive_into(
    set: &shard::ShardSet,
    scene: &Scene,
    drive: &crate::model::SceneDrive,
    out_dir: &Path,
    progress: &dyn Progress,
) -> Result<DriveWritten, RunError> {
    let folder =
        ReportFolder::create(out_dir, &report::slug(&scene.title)).map_err(RunError::io("the report folder"))?;
    progress.stage("merge", set.folders.len() as u64);
    let files = set.concatenate_drive_records(&folder, progress).map_err(RunError::io("the record files"))?;
    let tally = set.drive_tally.unwrap_or_default();
    let eval = evaluate::drive::evaluate_drive_merged(scene, drive, tally);
    report_into((folder, files), scene, drive, &eval, progress)
}

/// The report of `eval` rendered into `folder` (which holds its record files `files`), committed.
fn report_into(
    (folder, mut files): (ReportFolder, Vec<String>),
    scene: &Scene,
    drive: &crate::model::SceneDrive,
    eval: &evaluate::drive::DriveEvaluation,
    progress: &dyn Progress,
) -> Result<DriveWritten, RunError> {
    let (report, rendered) = reported(scene, drive, eval)?;
    files.extend(write_all(&folder, &rendered.files, progress)?);
    let folder = folder.commit().map_err(RunError::io("the report folder"))?;
    Ok(DriveWritten { folder, files, drives: vec![(String::new(), report)] })
}

/// A drive scene into its report folder, written whole.
pub(crate) fn run_drive_into(
    scene: &Scene,
    drive: &crate::model::SceneDrive,
    (out_dir, formats): (&Path, RecordFormats),
    progress: &dyn Progress,
) -> Result<DriveWritten, RunError> {
    let folder =
        ReportFolder::create(out_dir, &report::slug(&scene.title)).map_err(RunError::io("the report folder"))?;
    if scene.operating.oil_temperatures.is_some() {
        let mut files = Vec::new();
        let (top, drives) = each_oil_temperature(scene, |at, drive, dir| {
            let (report, written) = run_one_into(at, drive, (&folder, dir), formats, progress)?;
            files.extend(written);
            Ok(report)
        })?;
        let files = write_all(&folder, &top, progress)?.into_iter().chain(files).collect();
        let folder = folder.commit().map_err(RunError::io("the report folder"))?;
        return Ok(DriveWritten { folder, files, drives });
    }
    let (report, files) = run_one_into(scene, drive, (&folder, ""), formats, progress)?;
    let folder = folder.commit().map_err(RunError::io("the report folder"))?;
    Ok(DriveWritten { folder, files, drives: vec![(String::new(), report)] })
}

/// A drive scene (at one oil temperature) into `folder` under `dir` (`""`: the top): its record
/// files of `formats` as the rows stream, then its report; the report and the files written.
fn run_one_into(
    scene: &Scene,
    drive: &crate::model::SceneDrive,
    (folder, dir): (&ReportFolder, &str),
    formats: RecordFormats,
    progress: &dyn Progress,
) -> Result<(DriveReport, Vec<String>), RunError> {
    let io = RunError::io("the record files");
    let (mut records, mut files) = record_files((folder, dir), drive, formats)?;
    let eval = evaluate::drive::evaluate_drive_into_with(scene, drive, &mut records, progress).map_err(&io)?;
    records.finish().map_err(&io)?;
    let (report, rendered) = reported(scene, drive, &eval)?;
    let path = |f: &str| if dir.is_empty() { f.to_string() } else { format!("{dir}/{f}") };
    let named: Vec<(String, String)> = rendered.files.into_iter().map(|(f, c)| (path(&f), c)).collect();
    files.extend(write_all(folder, &named, progress)?);
    Ok((report, files))
}

/// A drive's record files in a folder as they are written.
type DriveFiles = DriveRecordFiles<BufWriter<File>>;

/// The record files `formats` ask for in `folder` (drive_records.csv, .jsonl, .parquet) and their
/// names.
fn record_files(
    (folder, dir): (&ReportFolder, &str),
    drive: &crate::model::SceneDrive,
    formats: RecordFormats,
) -> Result<(DriveFiles, Vec<String>), RunError> {
    let io = RunError::io("the record files");
    let mut files = Vec::new();
    let records = DriveRecordFiles::new(drive, formats, |file| {
        let file = if dir.is_empty() { file.to_string() } else { format!("{dir}/{file}") };
        let opened = folder.create_file(&file).map(BufWriter::new);
        files.push(file);
        opened
    })
    .map_err(&io)?;
    Ok((records, files))
}
