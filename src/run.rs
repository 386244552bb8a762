//! The whole run, built from the stages: a scene (at each of its oil temperatures) streamed into
//! its record files, its details evaluated, reported and rendered into a report folder written
//! whole ([`run_into`]); the same in memory ([`run_to_files`], [`report_of`]); a shard's part and
//! the merge of shards ([`merge_into`]).

use std::path::{Path, PathBuf};

use crate::evaluate::record_files::RecordFormats;
use crate::evaluate::stages::{details, stream};
use crate::evaluate::stream::Streamed;
use crate::evaluate::{self, Plan, Shard};
use crate::folder::ReportFolder;
use crate::model::Scene;
use crate::progress::{Progress, Quiet};
use crate::render::RenderedReport;
use crate::report::{self, Report};
use crate::run_error::{Failure, FailureKind, RunError};
use crate::run_pair::{finish, has_records, run_scene_to_files};
use crate::scene::check::check;
use crate::{render, shard};

/// Stages 3 and 4 in memory, the record rows dropped: the report of a checked scene (tests, benches).
pub fn report_of(scene: &Scene) -> Report {
    let scene = &*evaluate::first_balance::at_first_balance(scene);
    let plan = Plan::new(&scene.operating, None, &scene.operating.detail_points);
    let streamed = stream(scene, &plan, &mut evaluate::records::NoRecords, &Quiet)
        .expect("records that go nowhere cannot fail to be written");
    let eval = details(scene, &plan, &streamed, &Quiet);
    report::build_report(scene, &eval, &streamed.tally, &plan)
}

/// Everything `gearloss run` does, in memory: check, evaluate (records into buffers), report,
/// render; the record files are among the files returned. A scene with several oil temperatures
/// gives one report per temperature in its folder (`oil_temperature_90degC/report.md`) and their
/// comparison at the top (`report::oil_sweep`).
pub fn run_to_files(source_name: &str, source: &str) -> Result<RenderedReport, RunError> {
    let scene = check(source_name, source).map_err(RunError::Scene)?;
    let slug = report::slug(&scene.title);
    if let Some(drive) = &scene.drive {
        if scene.operating.oil_temperatures.is_some() {
            return Ok(RenderedReport { slug, files: crate::run_drive::drive_sweep_files(&scene)?.0 });
        }
        return Ok(crate::run_drive::drive_report_files(&scene, drive)?.1);
    }
    if scene.operating.oil_temperatures.is_none() {
        let (_, files) = run_scene_to_files(&scene)?;
        return Ok(RenderedReport { slug, files });
    }
    let mut files = Vec::new();
    let top = each_oil_temperature(&scene, |at, dir| {
        let (report, run_files) = run_scene_to_files(at)?;
        files.extend(run_files.into_iter().map(|(f, c)| (format!("{dir}/{f}"), c)));
        Ok(report)
    })?;
    Ok(RenderedReport { slug, files: top.into_iter().chain(files).collect() })
}

/// Runs a scene at each of its oil temperatures by `run_one(scene at θ, its folder)` and renders
/// the comparison of the runs: the files at the top of the report folder.
fn each_oil_temperature(
    scene: &Scene,
    mut run_one: impl FnMut(&Scene, &str) -> Result<Report, RunError>,
) -> Result<Vec<(String, String)>, RunError> {
    let mut runs = Vec::new();
    // The sweep's own temperatures (K): each run is at one of them.
    let kelvin: Vec<f64> =
        scene.operating.oil_temperatures.iter().flat_map(|s| s.values.iter().map(|t| t.value)).collect();
    for ((i, label), kelvin) in scene.oil_temperature_labels().into_iter().enumerate().zip(kelvin) {
        let at = scene.at_oil_temperature(i);
        let report = run_one(&at, &report::oil_sweep::run_folder(&label))?;
        runs.push((label, kelvin, report));
    }
    render::oil_sweep::render_oil_sweep(&report::oil_sweep::build_oil_sweep(&runs)).map_err(RunError::drawing)
}

/// The plan's points streamed into the record files of `folder` under `dir` (`""`: the top), when
/// the scene writes records; returns the stream and the record files written.
fn stream_into(
    scene: &Scene,
    plan: &Plan,
    (folder, dir): (&ReportFolder, &str),
    formats: RecordFormats,
    progress: &dyn Progress,
) -> Result<(Streamed, Vec<String>), RunError> {
    let io = RunError::io("the record files");
    if !has_records(scene) {
        return Ok((stream(scene, plan, &mut evaluate::records::NoRecords, progress).map_err(io)?, Vec::new()));
    }
    let mut sink =
        shard::record_files(folder, dir, &evaluate::records::ExtraColumns::of(scene), formats).map_err(&io)?;
    let streamed = stream(scene, plan, &mut sink, progress).map_err(&io)?;
    sink.finish().map_err(&io)?;
    let path = |f: &str| if dir.is_empty() { f.to_string() } else { format!("{dir}/{f}") };
    Ok((streamed, formats.files().into_iter().map(path).collect()))
}

/// One scene (at one oil temperature) into `folder`, its files under `dir` (`""`: the top): the
/// record files as the sweep runs, then the report. Returns the report and the files written.
fn run_scene_into(
    scene: &Scene,
    (folder, dir): (&ReportFolder, &str),
    formats: RecordFormats,
    progress: &dyn Progress,
) -> Result<(Report, Vec<String>), RunError> {
    let scene = &*evaluate::first_balance::at_first_balance(scene);
    let plan = Plan::new(&scene.operating, None, &scene.operating.detail_points);
    let path = |f: &str| if dir.is_empty() { f.to_string() } else { format!("{dir}/{f}") };
    let (streamed, mut files) = stream_into(scene, &plan, (folder, dir), formats, progress)?;
    let (report, rendered) = finish(scene, &plan, &streamed.tally, &streamed, progress)?;
    progress.stage("write", rendered.files.len() as u64);
    for (file, content) in &rendered.files {
        folder.write(&path(file), content.as_bytes()).map_err(RunError::io("the report folder"))?;
        files.push(path(file));
        progress.advance(1);
    }
    Ok((report, files))
}

/// What a run wrote: the report folder, its files, and the report of each run it holds (one; one
/// per oil temperature, labelled; none for a shard's part).
#[derive(Debug)]
pub struct Written {
    pub folder: PathBuf,
    pub files: Vec<String>,
    pub reports: Vec<(String, Report)>,
    /// The reports of a drive of several stages, labelled as `reports` are (then `reports` is empty).
    pub drives: crate::run_drive::LabelledDrives,
}

impl Written {
    /// What a drive's run wrote.
    fn of(w: crate::run_drive::DriveWritten) -> Written {
        Written { folder: w.folder, files: w.files, reports: Vec::new(), drives: w.drives }
    }
}

/// `gearloss run`: evaluates a checked scene into `out_dir/<slug>/` (or, with a shard, into
/// `out_dir/<slug>.shard-K-of-N/` with the shard's records and tally for `gearloss merge`),
/// written into a temporary folder and renamed into place.
pub fn run_into(
    source_name: &str,
    source: &str,
    scene: &Scene,
    out_dir: &Path,
    shard: Option<Shard>,
    progress: &dyn Progress,
) -> Result<Written, RunError> {
    run_into_with(source_name, source, scene, (out_dir, shard), RecordFormats::default(), progress)
}

/// [`run_into`] writing the record files of `formats` (a drive's: drive_records.csv and
/// drive_records.parquet; JSON Lines alone gives the CSV).
pub fn run_into_with(
    source_name: &str,
    source: &str,
    scene: &Scene,
    (out_dir, shard): (&Path, Option<Shard>),
    formats: RecordFormats,
    progress: &dyn Progress,
) -> Result<Written, RunError> {
    let slug = report::slug(&scene.title);
    let labels = scene.oil_temperature_labels();
    if let (Some(drive), None) = (&scene.drive, shard) {
        return crate::run_drive::run_drive_into(scene, drive, (out_dir, formats), progress).map(Written::of);
    }
    if let (Some(drive), Some(shard)) = (&scene.drive, shard) {
        if !labels.is_empty() {
            return Err(RunError::Shards(
                Failure::new(
                    FailureKind::ShardedDrive,
                    format!(
                        "the drive runs at {} oil temperatures, and a shard holds one scene's points",
                        labels.len()
                    ),
                )
                .hint("run it whole, or write one scene per oil temperature and shard each"),
            ));
        }
        return crate::run_drive::run_drive_shard_into(
            source_name,
            source,
            scene,
            drive,
            (shard, out_dir, formats),
            progress,
        )
        .map(Written::of);
    }
    let Some(shard) = shard else {
        let folder = ReportFolder::create(out_dir, &slug).map_err(RunError::io("the report folder"))?;
        if labels.is_empty() {
            let (report, files) = run_scene_into(scene, (&folder, ""), formats, progress)?;
            let folder = folder.commit().map_err(RunError::io("the report folder"))?;
            return Ok(Written { folder, files, reports: vec![(String::new(), report)], drives: Vec::new() });
        }
        let mut files = Vec::new();
        let mut reports = Vec::new();
        let top = each_oil_temperature(scene, |at, dir| {
            let (report, written) = run_scene_into(at, (&folder, dir), formats, progress)?;
            files.extend(written);
            reports.push((dir.to_string(), report.clone()));
            Ok(report)
        })?;
        for (k, (file, content)) in top.into_iter().enumerate() {
            folder.write(&file, content.as_bytes()).map_err(RunError::io("the report folder"))?;
            files.insert(k, file);
        }
        let folder = folder.commit().map_err(RunError::io("the report folder"))?;
        return Ok(Written { folder, files, reports, drives: Vec::new() });
    };
    if !labels.is_empty() {
        return Err(RunError::Shards(
            Failure::new(
                FailureKind::ShardedOilSweep,
                format!("the scene runs at {} oil temperatures, and a shard holds one scene's points", labels.len()),
            )
            .hint("run it whole, or write one scene per oil temperature and shard each"),
        ));
    }
    let plan = Plan::new(&scene.operating, Some(shard), &scene.operating.detail_points);
    let name = format!("{slug}.shard-{}-of-{}", shard.index, shard.count);
    let folder = ReportFolder::create(out_dir, &name).map_err(RunError::io("the report folder"))?;
    let (streamed, mut files) = stream_into(scene, &plan, (&folder, ""), formats, progress)?;
    let manifest = shard::Manifest::new(source_name, source, shard, &plan, streamed.tally)
        .with_digests(&folder, &files)
        .map_err(RunError::io("the record files"))?;
    folder.write(shard::MANIFEST, &manifest.to_json()).map_err(RunError::io("the shard manifest"))?;
    files.push(shard::MANIFEST.into());
    let folder = folder.commit().map_err(RunError::io("the report folder"))?;
    Ok(Written { folder, files, reports: Vec::new(), drives: Vec::new() })
}

/// `gearloss merge`: combines the shard folders of one scene into the report a single run gives
/// (record files concatenated in shard order, tallies folded in shard order).
pub fn merge_into(shards: &[PathBuf], out_dir: &Path, progress: &dyn Progress) -> Result<Written, RunError> {
    let set = shard::ShardSet::read(shards).map_err(RunError::Shards)?;
    let scene = check(&set.source_name, &set.source).map_err(RunError::Scene)?;
    if let Some(drive) = &scene.drive {
        return crate::run_drive::merge_drive_into(&set, &scene, drive, out_dir, progress).map(Written::of);
    }
    let plan = Plan::new(&scene.operating, None, &scene.operating.detail_points);
    let folder =
        ReportFolder::create(out_dir, &report::slug(&scene.title)).map_err(RunError::io("the report folder"))?;
    let mut files = Vec::new();
    if has_records(&scene) {
        progress.stage("merge", set.folders.len() as u64);
        files.extend(set.concatenate(&folder, progress).map_err(RunError::io("the record files"))?);
    }
    let (report, rendered) = finish(&scene, &plan, &set.tally, &Default::default(), progress)?;
    for (file, content) in &rendered.files {
        folder.write(file, content.as_bytes()).map_err(RunError::io("the report folder"))?;
        files.push(file.clone());
    }
    let folder = folder.commit().map_err(RunError::io("the report folder"))?;
    Ok(Written { folder, files, reports: vec![(String::new(), report)], drives: Vec::new() })
}
