//! A scene's own part of the one run layer (`run.rs`), every scene being a drive (one pair its
//! one-stage drive): its evaluation streamed into its record files, reported and rendered
//! (`DriveRun`), in memory or into a folder, as a shard, and merged from its shards; the meshes of
//! its stages analysed as pairs alone (`run_stage_pairs.rs`) with it.

use std::io::BufWriter;
use std::path::Path;

use crate::evaluate::drive_records::{self, DriveRecordFiles};
use crate::evaluate::record_files::RecordFormats;
use crate::evaluate::{self, Shard};
use crate::folder::ReportFolder;
use crate::model::Scene;
use crate::progress::Progress;
use crate::render::RenderedReport;
use crate::report;
use crate::report::drive::DriveReport;
use crate::report::drive_stage_pairs::StagePairReport;
use crate::run_error::RunError;
use crate::run_kind::{File, OilRun, Redrawn};
use crate::run_stage_pairs::{stage_pair_shard, stage_pairs_into, stage_pairs_merged, StagePairReports};
use crate::{render, shard};

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

/// The report of `eval` with the rows of the analyses of one pair on its stages (`stage_pairs`, run
/// by the caller), rendered.
fn reported(
    scene: &Scene,
    drive: &crate::model::SceneDrive,
    eval: &evaluate::drive::DriveEvaluation,
    stage_pairs: Vec<StagePairReport>,
) -> Result<(crate::report::drive::DriveReport, RenderedReport), RunError> {
    let mut report = report::drive::build_drive_report(scene, drive, eval);
    report.stage_pairs = stage_pairs;
    // Drawn from the report as report.json reads back, as `gearloss render` draws it (and a pair's
    // run, `run_pair::render_as_written`): a number report.json rounds is shown as it reads back.
    let json = render::drive::render_drive_json(&report);
    let read: DriveReport = serde_json::from_str(&json)
        .map_err(|e| format!("report.json does not read back: {e}"))
        .map_err(RunError::read_back)?;
    let rendered = render::drive::render_drive(&read).map_err(RunError::drawing)?;
    Ok((report, rendered))
}

/// A drive scene evaluated, reported and rendered in memory, its record files (the default
/// formats: drive_records.csv and drive_records.jsonl) among the files.
pub fn drive_report_files(
    scene: &Scene,
    drive: &crate::model::SceneDrive,
) -> Result<(crate::report::drive::DriveReport, RenderedReport), RunError> {
    report_files(scene, drive).map(|(report, rendered, _)| (report, rendered))
}

/// [`drive_report_files`] with the reports of the stage meshes analysed as pairs alone.
fn report_files(
    scene: &Scene,
    drive: &crate::model::SceneDrive,
) -> Result<(DriveReport, RenderedReport, StagePairReports), RunError> {
    let scene = &*evaluate::drive_thermal::at_first_balance(scene, drive);
    let io = RunError::io("records");
    let mut records =
        drive_records::drive_record_files(drive, RecordFormats::default(), |_| Ok(Vec::new())).map_err(&io)?;
    let eval =
        evaluate::drive::evaluate_drive_into_with(scene, drive, &mut records, &crate::progress::Quiet).map_err(&io)?;
    let ((rows, pair_files), pairs) = crate::run_stage_pairs::stage_pair_files(scene, drive)?;
    let (report, mut rendered) = reported(scene, drive, &eval, rows)?;
    rendered.files.extend(pair_files);
    let (csv, jsonl) = records.finish().map_err(&io)?;
    let text = |b: Option<Vec<u8>>| String::from_utf8(b.expect("the default formats")).expect("records are UTF-8");
    rendered.files.push((drive_records::FILE.to_string(), text(csv)));
    rendered.files.push((drive_records::JSONL_FILE.to_string(), text(jsonl)));
    Ok((report, rendered, pairs))
}

/// Drive reports with their labels (their folders at several oil temperatures, else empty).
pub type LabelledDrives = Vec<(String, crate::report::drive::DriveReport)>;

/// A drive of stages, as the one run layer runs it ([`crate::run`]).
pub(crate) struct DriveRun;

/// A drive's run at one oil temperature: its report and the reports of its stages' meshes analysed
/// as pairs alone, labelled by their folders (`stages/pair`).
#[derive(Debug, Clone)]
pub(crate) struct DriveRunReports {
    pub drive: DriveReport,
    pub pairs: StagePairReports,
}

/// The drive of a drive's scene (at any of its oil temperatures).
fn drive_of(scene: &Scene) -> &crate::model::SceneDrive {
    scene.drive.as_ref().expect("a drive's run is of a drive scene, at every oil temperature")
}

/// The reports of one pair a run wrote (the stage meshes'), labelled by their folders, and its
/// drives' reports, labelled by theirs.
pub(crate) type Labelled = (Vec<(String, crate::report::Report)>, LabelledDrives);

impl DriveRun {
    /// The scene (at one oil temperature) in memory: its reports and its files, the record files
    /// of the default formats among them.
    pub(crate) fn files(&self, scene: &Scene) -> Result<(DriveRunReports, Vec<File>), RunError> {
        let (drive, rendered, pairs) = report_files(scene, drive_of(scene))?;
        Ok((DriveRunReports { drive, pairs }, rendered.files))
    }

    /// The scene (at one oil temperature) into `folder` under `dir` (`""`: the top): its record
    /// files of `formats` as its sweep streams, then its report. The reports and the files written.
    pub(crate) fn run_in_folder(
        &self,
        scene: &Scene,
        at: (&ReportFolder, &str),
        formats: RecordFormats,
        progress: &dyn Progress,
    ) -> Result<(DriveRunReports, Vec<String>), RunError> {
        run_one_into(scene, drive_of(scene), at, formats, progress)
    }

    /// The comparison of the runs at the scene's oil temperatures: the files at the top of the
    /// report folder.
    pub(crate) fn oil_sweep(&self, runs: &[OilRun<DriveRunReports>]) -> Result<Vec<File>, RunError> {
        let runs: Vec<OilRun<DriveReport>> =
            runs.iter().map(|(l, k, f, r)| (l.clone(), *k, f.clone(), r.drive.clone())).collect();
        let sweep = report::drive_oil_sweep::build_drive_oil_sweep(&runs);
        render::drive::oil_sweep::render_drive_oil_sweep(&sweep).map_err(RunError::drawing)
    }

    /// The shard's part of the sweep: its record files of `formats` written into `folder` (their
    /// names) and its manifest (without the digests, which the run layer adds).
    pub(crate) fn shard_into(
        &self,
        scene: &Scene,
        (source_name, source): (&str, &str),
        shard: Shard,
        (folder, formats): (&ReportFolder, RecordFormats),
        progress: &dyn Progress,
    ) -> Result<(Vec<String>, shard::Manifest), RunError> {
        let drive = drive_of(scene);
        let io = RunError::io("the record files");
        let (mut records, mut files) = record_files((folder, ""), drive, formats)?;
        let tally =
            evaluate::drive::evaluate_drive_shard_with(scene, drive, shard, &mut records, progress).map_err(&io)?;
        records.finish().map_err(&io)?;
        let (stage_pair, pair_files) = stage_pair_shard(scene, drive, shard, (folder, formats), progress)?;
        files.extend(pair_files);
        let points = (scene.operating.count(), shard.range(scene.operating.count()));
        Ok((files, shard::Manifest::new((source_name, source), shard, points, &tally).with_stage_pair(stage_pair)))
    }

    /// drive_records.csv concatenated in shard order (a single run's, byte for byte), the
    /// tallies folded, the report's rows, map, thermal balance and duty cycle evaluated again; a
    /// one-pair drive's stage analysed over the sweep merged from the shards' as a pair's shards
    /// merge, the stages analysed at the drive's points run again.
    pub(crate) fn merge_into(
        &self,
        set: &shard::ShardSet,
        scene: &Scene,
        folder: &ReportFolder,
        progress: &dyn Progress,
    ) -> Result<(DriveRunReports, Vec<String>), RunError> {
        let drive = drive_of(scene);
        let scene = &*evaluate::drive_thermal::at_first_balance(scene, drive);
        progress.stage("merge", set.folders.len() as u64);
        let mut files = set
            .concatenate::<drive_records::DriveRecords>(folder, progress)
            .map_err(RunError::io("the record files"))?;
        let tally = set.tally().map_err(RunError::Shards)?;
        let eval = evaluate::drive::evaluate_drive_merged(scene, drive, tally);
        let (rows, pair_files, pairs) = stage_pairs_merged(scene, drive, set, folder, progress)?;
        let (report, rendered) = reported(scene, drive, &eval, rows)?;
        files.extend(write_all(folder, &rendered.files, progress)?);
        files.extend(pair_files);
        Ok((DriveRunReports { drive: report, pairs }, files))
    }

    /// What its report.json is called and the top-level fields only it has, read by `gearloss render`.
    pub(crate) const REPORT: (&'static str, &'static [&'static str]) = ("a drive's report", &["shafts"]);
    /// The same of its comparison of oil temperatures.
    pub(crate) const OIL_SWEEP: (&'static str, &'static [&'static str]) =
        ("a drive's comparison of oil temperatures", &["runs", "rows"]);

    /// Each stage mesh analysed as a pair alone has its report of one pair in its folder.
    pub(crate) fn redraw(
        _: &Path,
        text: &str,
        bad: &dyn Fn(serde_json::Error) -> RunError,
    ) -> Result<Redrawn, RunError> {
        let drive: DriveReport = serde_json::from_str(text).map_err(bad)?;
        let files = render::drive::render_drive(&drive).map_err(RunError::drawing)?.files;
        Ok((files, drive.stage_pairs.iter().filter_map(|p| p.folder.clone()).collect()))
    }

    pub(crate) fn redraw_oil_sweep(
        text: &str,
        bad: &dyn Fn(serde_json::Error) -> RunError,
    ) -> Result<Redrawn, RunError> {
        let sweep: report::drive_oil_sweep::DriveOilSweepReport = serde_json::from_str(text).map_err(bad)?;
        let files = render::drive::oil_sweep::render_drive_oil_sweep(&sweep).map_err(RunError::drawing)?;
        Ok((files, sweep.runs.iter().map(|r| r.folder.clone()).collect()))
    }

    /// The stage meshes' reports labelled by their folders in the report folder
    /// (`oil_temperature_90degC/stages/pair`), the drives' by theirs.
    pub(crate) fn labelled(reports: Vec<(String, DriveRunReports)>) -> Labelled {
        let mut pairs = Vec::new();
        let mut drives = Vec::new();
        for (label, r) in reports {
            pairs.extend(r.pairs.into_iter().map(|(dir, p)| (crate::folder::in_dir(&label, &dir), p)));
            drives.push((label, r.drive));
        }
        (pairs, drives)
    }
}

/// A drive scene (at one oil temperature) into `folder` under `dir` (`""`: the top): its record
/// files of `formats` as the rows stream, then its report; the reports and the files written.
fn run_one_into(
    scene: &Scene,
    drive: &crate::model::SceneDrive,
    (folder, dir): (&ReportFolder, &str),
    formats: RecordFormats,
    progress: &dyn Progress,
) -> Result<(DriveRunReports, Vec<String>), RunError> {
    let io = RunError::io("the record files");
    let scene = &*evaluate::drive_thermal::at_first_balance(scene, drive);
    let (mut records, mut files) = record_files((folder, dir), drive, formats)?;
    let eval = evaluate::drive::evaluate_drive_into_with(scene, drive, &mut records, progress).map_err(&io)?;
    records.finish().map_err(&io)?;
    let (rows, pair_files, pairs) = stage_pairs_into(scene, drive, (folder, dir), formats, progress)?;
    let (report, rendered) = reported(scene, drive, &eval, rows)?;
    let path = |f: &str| crate::folder::in_dir(dir, f);
    let named: Vec<(String, String)> = rendered.files.into_iter().map(|(f, c)| (path(&f), c)).collect();
    files.extend(write_all(folder, &named, progress)?);
    files.extend(pair_files);
    Ok((DriveRunReports { drive: report, pairs }, files))
}

/// A drive's record files in a folder as they are written.
type DriveFiles = DriveRecordFiles<BufWriter<std::fs::File>>;

/// The record files `formats` ask for in `folder` (drive_records.csv, .jsonl, .parquet) and their
/// names.
fn record_files(
    (folder, dir): (&ReportFolder, &str),
    drive: &crate::model::SceneDrive,
    formats: RecordFormats,
) -> Result<(DriveFiles, Vec<String>), RunError> {
    let io = RunError::io("the record files");
    let mut files = Vec::new();
    let records = drive_records::drive_record_files(drive, formats, |file| {
        let file = crate::folder::in_dir(dir, file);
        let opened = folder.create_file(&file).map(BufWriter::new);
        files.push(file);
        opened
    })
    .map_err(&io)?;
    Ok((records, files))
}
