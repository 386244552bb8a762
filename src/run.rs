//! The whole run, one path for every scene: a scene (at each of its oil temperatures) streamed
//! into its record files, evaluated, reported and rendered into a report folder written whole
//! ([`run_into`]); the same in memory ([`run_to_files`], [`report_of`]); a shard's part and the
//! merge of shards ([`merge_into`]). Every scene runs as its drive
//! ([`crate::run_drive::DriveRun`]: a scene of one pair as its one-stage drive, its pair's own
//! report in `stages/pair/`); the meshes of its stages analysed as pairs alone go through
//! `run_pair.rs` beneath it (`run_stage_pairs.rs`).

use std::path::{Path, PathBuf};

use crate::evaluate::record_files::RecordFormats;
use crate::evaluate::stages::{details, stream};
use crate::evaluate::{self, Plan, Shard};
use crate::folder::ReportFolder;
use crate::mesh::MeshProblem;
use crate::model::Scene;
use crate::progress::{Progress, Quiet};
use crate::render::RenderedReport;
use crate::report::{self, Report};
use crate::run_drive::{DriveRun, DriveRunReports, LabelledDrives};
use crate::run_error::{Failure, FailureKind, RunError};
use crate::run_kind::OilRun;
use crate::scene::check::check;
use crate::shard;

/// Stages 3 and 4 of the per-mesh evaluation in memory, the record rows dropped: the report of a
/// checked scene's pair alone (its oil at the first balance at `oil_temperature = equilibrium`), the
/// report a drive's stage mesh gets (tests, benches).
///
/// # Panics
/// On a drive written with `stage` blocks, which has no pair alone ([`Scene::pair_alone`]: its
/// meshes are reported at the states its walk gives them, [`run_to_files`]).
pub fn report_of(scene: &Scene) -> Report {
    let problem = evaluate::first_balance::at_first_balance(scene).pair_alone();
    mesh_report(&problem.expect("report_of takes a scene of one pair, not a drive of stages"))
}

/// Stages 3 and 4 of the per-mesh evaluation in memory, the record rows dropped: the report of one
/// mesh's problem (a scene's pair alone, [`Scene::pair_alone`], or a drive's stage mesh at its
/// operating state, `evaluate::stage_pairs`).
pub fn mesh_report(problem: &MeshProblem) -> Report {
    let plan = Plan::new(&problem.operating, None, &problem.operating.detail_points);
    let streamed = stream(problem, &plan, &mut evaluate::records::NoRecords, &Quiet)
        .expect("records that go nowhere cannot fail to be written");
    let eval = details(problem, &plan, &streamed, &Quiet);
    report::build_report(problem, &eval, &streamed.tally, &plan)
}

/// The per-mesh evaluation alone, in memory: the scene's pair (`scene.gears`) alone evaluated,
/// reported and rendered as a pair — the report a drive's stage mesh gets, without the drive around
/// it (its budget, thermal balance, duty cycle and map are the drive's, [`run_to_files`]). Its record
/// files (the default formats) are among the files. `gearloss run` writes a scene as its drive;
/// this is the stage beneath it, for a library user or a test of the pair's own modules.
pub fn pair_files(scene: &Scene) -> Result<RenderedReport, RunError> {
    let scene = &evaluate::first_balance::at_first_balance(scene);
    let problem = scene.pair_alone().ok_or_else(|| {
        RunError::Render(
            Failure::new(FailureKind::NotOnePair, format!("`{}` is a drive of stages, not one pair", scene.title))
                .hint("run it whole (`gearloss::run_to_files`): each analysed stage mesh's report is in its `stages/…/` folder"),
        )
    })?;
    let (_, files) = crate::run_pair::run_mesh_to_files(&problem)?;
    Ok(RenderedReport { slug: report::slug(&scene.title), files })
}

/// Everything `gearloss run` does, in memory: check, evaluate (records into buffers), report,
/// render; the record files are among the files returned. A scene with several oil temperatures
/// gives one report per temperature in its folder (`oil_temperature_90degC/report.md`) and their
/// comparison at the top (`report::drive_oil_sweep`).
pub fn run_to_files(source_name: &str, source: &str) -> Result<RenderedReport, RunError> {
    let scene = check(source_name, source).map_err(RunError::Scene)?;
    let slug = report::slug(&scene.title);
    let files = in_memory(&scene)?;
    Ok(RenderedReport { slug, files })
}

/// A scene's files in memory, at each of its oil temperatures when it has several (the
/// comparison's files first, then each run's under its folder).
fn in_memory(scene: &Scene) -> Result<Vec<(String, String)>, RunError> {
    if scene.operating.oil_temperatures.is_none() {
        return Ok(DriveRun.files(scene)?.1);
    }
    let mut files = Vec::new();
    let (top, _) = each_oil_temperature(scene, |at, dir| {
        let (report, run_files) = DriveRun.files(at)?;
        files.extend(run_files.into_iter().map(|(f, c)| (format!("{dir}/{f}"), c)));
        Ok(report)
    })?;
    Ok(top.into_iter().chain(files).collect())
}

/// The comparison's files of a sweep of oil temperatures and the runs' reports, labelled.
type Swept<R> = (Vec<(String, String)>, Vec<(String, R)>);

/// Runs a scene at each of its oil temperatures by `run_one(scene at θ, its folder)` and renders
/// the comparison of the runs: the files at the top of the report folder, and the runs' reports
/// labelled by their folders.
fn each_oil_temperature(
    scene: &Scene,
    mut run_one: impl FnMut(&Scene, &str) -> Result<DriveRunReports, RunError>,
) -> Result<Swept<DriveRunReports>, RunError> {
    let mut runs: Vec<OilRun<DriveRunReports>> = Vec::new();
    // The sweep's own temperatures (K): each run is at one of them.
    let kelvin: Vec<f64> =
        scene.operating.oil_temperatures.iter().flat_map(|s| s.values.iter().map(|t| t.value)).collect();
    for ((i, label), kelvin) in scene.oil_temperature_labels().into_iter().enumerate().zip(kelvin) {
        let at = scene.at_oil_temperature(i);
        let dir = report::drive_oil_sweep::run_folder(&label);
        let report = run_one(&at, &dir)?;
        runs.push((label, kelvin, dir, report));
    }
    let top = DriveRun.oil_sweep(&runs)?;
    Ok((top, runs.into_iter().map(|(_, _, dir, r)| (dir, r)).collect()))
}

/// What a run wrote: the report folder, its files, the report of each drive it holds (one; one per
/// oil temperature, labelled by its folder; none for a shard's part) and the reports of the stage
/// meshes analysed as pairs alone (labelled by their folders: `stages/pair`,
/// `oil_temperature_90degC/stages/pair`).
#[derive(Debug)]
pub struct Written {
    pub folder: PathBuf,
    pub files: Vec<String>,
    /// The reports of one pair: the stage meshes' (a scene built without a drive: its own).
    pub reports: Vec<(String, Report)>,
    pub drives: LabelledDrives,
}

impl Written {
    /// What a run wrote.
    fn of(folder: PathBuf, files: Vec<String>, reports: Vec<(String, DriveRunReports)>) -> Written {
        let (reports, drives) = DriveRun::labelled(reports);
        Written { folder, files, reports, drives }
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

/// [`run_into`] writing the record files of `formats` (records.csv, .jsonl, .parquet; a drive's
/// drive_records.csv, .jsonl, .parquet).
pub fn run_into_with(
    source_name: &str,
    source: &str,
    scene: &Scene,
    (out_dir, shard): (&Path, Option<Shard>),
    formats: RecordFormats,
    progress: &dyn Progress,
) -> Result<Written, RunError> {
    if scene.drive.is_none() {
        return Err(RunError::Render(
            Failure::new(FailureKind::NotLowered, format!("`{}` has no drive: it was not built by lowering", scene.title))
                .hint("give `run` the scene `gearloss::check` lowers from its text (a pair is lowered as its one-stage drive)"),
        ));
    }
    match shard {
        None => whole_into(scene, out_dir, formats, progress),
        Some(shard) => shard_into((source_name, source), scene, (out_dir, shard), formats, progress),
    }
}

/// A scene into its report folder, whole: at each of its oil temperatures when it has several.
fn whole_into(
    scene: &Scene,
    out_dir: &Path,
    formats: RecordFormats,
    progress: &dyn Progress,
) -> Result<Written, RunError> {
    let folder =
        ReportFolder::create(out_dir, &report::slug(&scene.title)).map_err(RunError::io("the report folder"))?;
    if scene.operating.oil_temperatures.is_none() {
        let (report, files) = DriveRun.run_in_folder(scene, (&folder, ""), formats, progress)?;
        let folder = folder.commit().map_err(RunError::io("the report folder"))?;
        return Ok(Written::of(folder, files, vec![(String::new(), report)]));
    }
    let mut files = Vec::new();
    let (top, reports) = each_oil_temperature(scene, |at, dir| {
        let (report, written) = DriveRun.run_in_folder(at, (&folder, dir), formats, progress)?;
        files.extend(written);
        Ok(report)
    })?;
    progress.stage("write", top.len() as u64);
    for (k, (file, content)) in top.into_iter().enumerate() {
        folder.write(&file, content.as_bytes()).map_err(RunError::io("the report folder"))?;
        files.insert(k, file);
        progress.advance(1);
    }
    let folder = folder.commit().map_err(RunError::io("the report folder"))?;
    Ok(Written::of(folder, files, reports))
}

/// One shard of a scene's sweep into `out_dir/<slug>.shard-K-of-N/`: its record files and the
/// manifest with their tally and digests. A scene of several oil temperatures is refused.
fn shard_into(
    source: (&str, &str),
    scene: &Scene,
    (out_dir, shard): (&Path, Shard),
    formats: RecordFormats,
    progress: &dyn Progress,
) -> Result<Written, RunError> {
    let labels = scene.oil_temperature_labels();
    if !labels.is_empty() {
        return Err(RunError::Shards(
            Failure::new(
                FailureKind::ShardedDrive,
                format!("the drive runs at {} oil temperatures, and a shard holds one scene's points", labels.len()),
            )
            .hint("run it whole, or write one scene per oil temperature and shard each"),
        ));
    }
    let name = format!("{}.shard-{}-of-{}", report::slug(&scene.title), shard.index, shard.count);
    let folder = ReportFolder::create(out_dir, &name).map_err(RunError::io("the report folder"))?;
    let (mut files, manifest) = DriveRun.shard_into(scene, source, shard, (&folder, formats), progress)?;
    let manifest = manifest.with_digests(&folder, &files).map_err(RunError::io("the record files"))?;
    folder.write(shard::MANIFEST, &manifest.to_json()).map_err(RunError::io("the shard manifest"))?;
    files.push(shard::MANIFEST.into());
    let folder = folder.commit().map_err(RunError::io("the report folder"))?;
    Ok(Written::of(folder, files, Vec::new()))
}

/// `gearloss merge`: combines the shard folders of one scene into the report a single run gives
/// (record files concatenated in shard order, tallies folded in shard order).
pub fn merge_into(shards: &[PathBuf], out_dir: &Path, progress: &dyn Progress) -> Result<Written, RunError> {
    let set = shard::ShardSet::read(shards).map_err(RunError::Shards)?;
    let scene = check(&set.source_name, &set.source).map_err(RunError::Scene)?;
    let folder =
        ReportFolder::create(out_dir, &report::slug(&scene.title)).map_err(RunError::io("the report folder"))?;
    let (report, files) = DriveRun.merge_into(&set, &scene, &folder, progress)?;
    let folder = folder.commit().map_err(RunError::io("the report folder"))?;
    Ok(Written::of(folder, files, vec![(String::new(), report)]))
}
