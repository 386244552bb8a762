#![warn(clippy::print_stdout, clippy::print_stderr)]
//! gearloss: gear mesh friction, efficiency and dynamics from a `.gear` scene.
//!
//! ```text
//!  scene.gear ─parse─▶ SceneAst ─lower─▶ Scene ─evaluate─▶ Evaluation ─report─▶ Report ─render─▶ report folder
//!   (text)     pest    (syntax)  units,  (uom,   cases,     (SI f64)    serde   (data)  md, json,  (written to a
//!                                names,  checked) only what                              svg        temp folder,
//!                                checks           is asked                                          then renamed)
//! ```
//!
//! One public function per stage: [`parse`], [`lower`], [`evaluate_sweep`] (the sweep streamed, its
//! summary rows to the record files, its tally returned) with [`evaluate_details`] (the detail points in
//! full), [`report()`] and [`render()`]; [`run_into`] and [`merge_into`] run them into a report folder
//! (whole or sharded). Errors of the first two stages are [`SceneErrors`]: every problem with
//! its span, reason and hints, rendered by miette. The library never prints.
//!
//! The layers, each importing only from those below it (no import circles):
//!
//! ```text
//!  cli ─ lib                      the binary's commands; one function per stage
//!  shard, folder                  shards and merge; a report folder written whole (concurrent-safe)
//!  render/ (markdown, svg/)       formats the report; never computes
//!  report/                        the serde report: numbers and series ready to draw, findings
//!  evaluate/ (plan, stream,       the run's plan (points, detail points, kept rows); the sweep streamed in
//!    records, tally, laws,        blocks: rows to the record files, a mergeable tally; friction,
//!    dynamics, cases)             efficiency and dynamics at each point, only what the scene asks for
//!  scene/                         the language: grammar, parse, units, lowering to the model
//!  model                          the lowered scene (uom quantities, what the user wrote)
//!  dynamics/                      the n-state periodic engine (PeriodicModel: propagators, Floquet,
//!                                 trajectory, integrators, numerics study) and its models (SDOF)
//!  thermal/                       the housing as one thermal node, the balance θ*, the rating, a duty
//!                                 cycle's transient (the losses come in as a function of θ)
//!  efficiency                     η(t), η̄ and power loss of a law along the mesh cycle
//!  friction/                      the law catalogue (typed LawId, one constructor each), one law a file
//!  tribology/                     lubricant and surface data in SI, film thickness
//!  geometry/ (pair, mesh,         the pair: involute geometry, the mesh cycle (contacts, switch
//!             stiffness/, teeth/) times), contact states, the mesh stiffness catalogue, the teeth as
//!                                 bodies (PEM stiffness, load sharing, relief, transmission error)
//!  numerics/ quantity diagnostics quadrature and roots; physical dimensions; spans and diagnostics
//! ```
//!
//! Where a new model goes (README, "Where a new model goes"): a friction law is one file in
//! `friction/` and one row of [`friction::catalog::LAWS`]; a mesh stiffness model one file in
//! `geometry/stiffness/` and one row of [`geometry::stiffness::MODELS`]; a dynamic model a
//! [`dynamics::PeriodicModel`] in `dynamics/` (and, today, its branch in `evaluate/dynamics.rs`).

pub mod diagnostics;
pub mod dynamics;
pub mod efficiency;
pub mod evaluate;
pub mod folder;
pub mod friction;
pub mod geometry;
pub mod losses;
pub mod model;
pub mod numerics;
pub mod progress;
pub mod quantity;
pub mod render;
pub mod report;
pub mod rerender;
pub mod run_error;
pub mod scene;
pub mod shard;
pub mod thermal;
pub mod tribology;

use std::path::{Path, PathBuf};

pub use diagnostics::{Diagnostic, DiagnosticKind, SceneErrors};
pub use evaluate::records::{RecordSink, RecordWriter};
pub use evaluate::{Evaluation, Plan, Shard, Tally};
use folder::ReportFolder;
pub use model::Scene;
pub use progress::{Progress, Quiet};
pub use render::RenderedReport;
pub use report::Report;
pub use run_error::RunError;
pub use scene::ast::SceneAst;

/// Stage 1: text → syntax tree.
pub fn parse(source_name: &str, source: &str) -> Result<SceneAst, SceneErrors> {
    scene::parse::parse_scene_text(source).map_err(|diagnostics| SceneErrors {
        source_name: source_name.into(),
        source: source.into(),
        diagnostics,
    })
}

/// Stage 2: syntax tree → checked scene (units, names, ranges, geometry).
/// Files the scene names are read relative to the folder of `source_name`.
pub fn lower(source_name: &str, source: &str, ast: &SceneAst) -> Result<Scene, SceneErrors> {
    let base = Path::new(source_name).parent();
    scene::lower::lower_scene_in(ast, base).map_err(|diagnostics| SceneErrors {
        source_name: source_name.into(),
        source: source.into(),
        diagnostics,
    })
}

/// Stages 1 and 2: what `gearloss check` runs.
pub fn check(source_name: &str, source: &str) -> Result<Scene, SceneErrors> {
    let ast = parse(source_name, source)?;
    lower(source_name, source, &ast)
}

/// Stage 3's detail points in memory: every point of a sweep of up to 100 points in full (tests and
/// benches); a larger sweep's detail points only — its every point goes through [`evaluate_sweep`].
pub fn evaluate(scene: &Scene) -> Evaluation {
    evaluate::evaluate_scene(scene)
}

/// Stage 3, the sweep: the plan's points streamed, their summary rows written to `sink` in sweep
/// order, their tally returned. Memory does not grow with the sweep.
pub fn evaluate_sweep(
    scene: &Scene,
    plan: &Plan,
    sink: &mut dyn RecordSink,
    progress: &dyn Progress,
) -> std::io::Result<Tally> {
    Ok(stream(scene, plan, sink, progress)?.tally)
}

fn stream(
    scene: &Scene,
    plan: &Plan,
    sink: &mut dyn RecordSink,
    progress: &dyn Progress,
) -> std::io::Result<evaluate::stream::Streamed> {
    let eval = evaluate::prepare(scene, plan);
    progress.stage("evaluate", plan.range.len() as u64);
    evaluate::stream::evaluate_records(scene, &eval, plan, sink, &|n| progress.advance(n as u64))
}

/// Stage 3, the details: the plan's detail points in full, the contact curves and the dynamics.
pub fn evaluate_details(scene: &Scene, plan: &Plan, progress: &dyn Progress) -> Evaluation {
    details(scene, plan, &[], progress)
}

fn details(
    scene: &Scene,
    plan: &Plan,
    known: &[(usize, evaluate::dynamics::DynamicsPoint)],
    progress: &dyn Progress,
) -> Evaluation {
    let mut eval = evaluate::prepare(scene, plan);
    progress.stage("details", plan.detail.len() as u64);
    evaluate::evaluate_details(scene, &mut eval, plan, known, &|| progress.advance(1));
    eval
}

/// Stage 4: the serde report data, from the detail points and the tally of every point.
pub fn report(scene: &Scene, evaluation: &Evaluation, tally: &Tally, plan: &Plan) -> Report {
    report::build_report(scene, evaluation, tally, plan)
}

/// Stage 5: the files of the report folder (the record files are written as the sweep runs).
pub fn render(report: &Report) -> Result<RenderedReport, String> {
    render::render_report(report, None)
}

/// Stages 3 and 4 in memory, the record rows dropped: the report of a checked scene (tests, benches).
pub fn report_of(scene: &Scene) -> Report {
    let scene = &*evaluate::thermal::at_first_balance(scene);
    let plan = Plan::new(&scene.operating, None, &scene.operating.detail_points);
    let streamed = stream(scene, &plan, &mut evaluate::records::NoRecords, &Quiet)
        .expect("records that go nowhere cannot fail to be written");
    let eval = details(scene, &plan, &streamed.detail_dynamics, &Quiet);
    report(scene, &eval, &streamed.tally, &plan)
}

/// Whether the scene's run writes record files (it asks for friction or per-point dynamics).
pub fn has_records(scene: &Scene) -> bool {
    let a = &scene.analyses;
    a.friction_along_loa || a.efficiency.is_some() || (a.dynamics && scene.dynamics.is_some())
}

/// Stages 3 to 5 after the sweep: details (reusing the dynamics the stream computed), report, render.
fn finish(
    scene: &Scene,
    plan: &Plan,
    tally: &Tally,
    known: &[(usize, evaluate::dynamics::DynamicsPoint)],
    progress: &dyn Progress,
) -> Result<(Report, RenderedReport), RunError> {
    let eval = details(scene, plan, known, progress);
    progress.stage("report", 1);
    let report = report(scene, &eval, tally, plan);
    let timings = eval.dynamics.as_ref().and_then(report::dynamics::timings);
    progress.stage("render", 1);
    let (report, mut rendered) = rerender::render_as_written(&report, timings.as_ref())?;
    // The map's cells are data of the run, as the record files are: written beside the report.
    if let (Some(map), Some(m)) = (&eval.efficiency_map, &report.efficiency_map) {
        let labels: Vec<String> = scene.friction.iter().map(|l| l.label()).collect();
        rendered.files.push((m.csv.clone(), map.csv(&labels)));
    }
    Ok((report, rendered))
}

/// One scene (at one oil temperature) run in memory: its report and files, the record files included.
fn run_scene_to_files(scene: &Scene) -> Result<(Report, Vec<(String, String)>), RunError> {
    let scene = &*evaluate::thermal::at_first_balance(scene);
    let plan = Plan::new(&scene.operating, None, &scene.operating.detail_points);
    let budget = evaluate::records::budget_columns(scene);
    let mut sink = RecordWriter::new(Vec::new(), Vec::new(), &budget, true).map_err(RunError::io("records"))?;
    let streamed = stream(scene, &plan, &mut sink, &Quiet).map_err(RunError::io("records"))?;
    let (report, mut rendered) = finish(scene, &plan, &streamed.tally, &streamed.detail_dynamics, &Quiet)?;
    if has_records(scene) {
        let (csv, jsonl) = sink.finish().map_err(RunError::io("records"))?;
        let text = |b: Vec<u8>| String::from_utf8(b).expect("records are UTF-8");
        rendered.files.push((report::sweep::RECORDS_CSV.into(), text(csv)));
        rendered.files.push((report::sweep::RECORDS_JSONL.into(), text(jsonl)));
    }
    Ok((report, rendered.files))
}

/// Everything `gearloss run` does, in memory: check, evaluate (records into buffers), report,
/// render; the record files are among the files returned. A scene with several oil temperatures
/// gives one report per temperature in its folder (`oil_temperature_90degC/report.md`) and their
/// comparison at the top ([`report::oil_sweep`]).
pub fn run_to_files(source_name: &str, source: &str) -> Result<RenderedReport, RunError> {
    let scene = check(source_name, source).map_err(RunError::Scene)?;
    let slug = report::slug(&scene.title);
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
    for (i, label) in scene.oil_temperature_labels().into_iter().enumerate() {
        let at = scene.at_oil_temperature(i);
        let report = run_one(&at, &report::oil_sweep::run_folder(&label))?;
        let kelvin = at.operating.oil_temperature.as_ref().map_or(f64::NAN, |t| t.value.value);
        runs.push((label, kelvin, report));
    }
    render::oil_sweep::render_oil_sweep(&report::oil_sweep::build_oil_sweep(&runs)).map_err(RunError::Render)
}

/// One scene (at one oil temperature) into `folder`, its files under `dir` (`""`: the top): the
/// record files as the sweep runs, then the report. Returns the report and the files written.
fn run_scene_into(
    scene: &Scene,
    folder: &ReportFolder,
    dir: &str,
    progress: &dyn Progress,
) -> Result<(Report, Vec<String>), RunError> {
    let scene = &*evaluate::thermal::at_first_balance(scene);
    let plan = Plan::new(&scene.operating, None, &scene.operating.detail_points);
    let path = |f: &str| if dir.is_empty() { f.to_string() } else { format!("{dir}/{f}") };
    let mut files = Vec::new();
    let streamed = if has_records(scene) {
        let mut sink = shard::record_files(folder, dir, &evaluate::records::budget_columns(scene))
            .map_err(RunError::io("the record files"))?;
        let streamed = stream(scene, &plan, &mut sink, progress).map_err(RunError::io("the record files"))?;
        sink.finish().map_err(RunError::io("the record files"))?;
        files.extend([path(report::sweep::RECORDS_CSV), path(report::sweep::RECORDS_JSONL)]);
        streamed
    } else {
        stream(scene, &plan, &mut evaluate::records::NoRecords, progress).map_err(RunError::io("the record files"))?
    };
    let (report, rendered) = finish(scene, &plan, &streamed.tally, &streamed.detail_dynamics, progress)?;
    progress.stage("write", rendered.files.len() as u64);
    for (file, content) in &rendered.files {
        folder.write(&path(file), content.as_bytes()).map_err(RunError::io("the report folder"))?;
        files.push(path(file));
        progress.advance(1);
    }
    Ok((report, files))
}

/// `gearloss run`: evaluates a checked scene into `out_dir/<slug>/` (or, with a shard, into
/// `out_dir/<slug>.shard-K-of-N/` with the shard's records and tally for `gearloss merge`),
/// written into a temporary folder and renamed into place. Returns the folder and its files.
pub fn run_into(
    source_name: &str,
    source: &str,
    scene: &Scene,
    out_dir: &Path,
    shard: Option<Shard>,
    progress: &dyn Progress,
) -> Result<(PathBuf, Vec<String>), RunError> {
    let slug = report::slug(&scene.title);
    let labels = scene.oil_temperature_labels();
    let Some(shard) = shard else {
        let folder = ReportFolder::create(out_dir, &slug).map_err(RunError::io("the report folder"))?;
        if labels.is_empty() {
            let (_, files) = run_scene_into(scene, &folder, "", progress)?;
            return Ok((folder.commit().map_err(RunError::io("the report folder"))?, files));
        }
        let mut files = Vec::new();
        let top = each_oil_temperature(scene, |at, dir| {
            let (report, written) = run_scene_into(at, &folder, dir, progress)?;
            files.extend(written);
            Ok(report)
        })?;
        for (k, (file, content)) in top.into_iter().enumerate() {
            folder.write(&file, content.as_bytes()).map_err(RunError::io("the report folder"))?;
            files.insert(k, file);
        }
        return Ok((folder.commit().map_err(RunError::io("the report folder"))?, files));
    };
    if !labels.is_empty() {
        return Err(RunError::Shards(format!(
            "the scene runs at {} oil temperatures: run it whole, or shard one scene per temperature",
            labels.len()
        )));
    }
    let plan = Plan::new(&scene.operating, Some(shard), &scene.operating.detail_points);
    let name = format!("{slug}.shard-{}-of-{}", shard.index, shard.count);
    let folder = ReportFolder::create(out_dir, &name).map_err(RunError::io("the report folder"))?;
    let mut files = Vec::new();
    let streamed = if has_records(scene) {
        let mut sink = shard::record_files(&folder, "", &evaluate::records::budget_columns(scene))
            .map_err(RunError::io("the record files"))?;
        let streamed = stream(scene, &plan, &mut sink, progress).map_err(RunError::io("the record files"))?;
        sink.finish().map_err(RunError::io("the record files"))?;
        files.extend([report::sweep::RECORDS_CSV.to_string(), report::sweep::RECORDS_JSONL.to_string()]);
        streamed
    } else {
        stream(scene, &plan, &mut evaluate::records::NoRecords, progress).map_err(RunError::io("the record files"))?
    };
    let manifest = shard::Manifest::new(source_name, source, shard, &plan, streamed.tally);
    folder.write(shard::MANIFEST, &manifest.to_json()).map_err(RunError::io("the shard manifest"))?;
    files.push(shard::MANIFEST.into());
    let dir = folder.commit().map_err(RunError::io("the report folder"))?;
    Ok((dir, files))
}

/// `gearloss merge`: combines the shard folders of one scene into the report a single run gives
/// (record files concatenated in shard order, tallies folded in shard order).
pub fn merge_into(
    shards: &[PathBuf],
    out_dir: &Path,
    progress: &dyn Progress,
) -> Result<(PathBuf, Vec<String>), RunError> {
    let set = shard::ShardSet::read(shards).map_err(RunError::Shards)?;
    let scene = check(&set.source_name, &set.source).map_err(RunError::Scene)?;
    let plan = Plan::new(&scene.operating, None, &scene.operating.detail_points);
    let folder =
        ReportFolder::create(out_dir, &report::slug(&scene.title)).map_err(RunError::io("the report folder"))?;
    let mut files = Vec::new();
    if has_records(&scene) {
        progress.stage("merge", set.folders.len() as u64);
        set.concatenate(&folder, progress).map_err(RunError::io("the record files"))?;
        files.extend([report::sweep::RECORDS_CSV.to_string(), report::sweep::RECORDS_JSONL.to_string()]);
    }
    let (_, rendered) = finish(&scene, &plan, &set.tally, &[], progress)?;
    for (file, content) in &rendered.files {
        folder.write(file, content.as_bytes()).map_err(RunError::io("the report folder"))?;
        files.push(file.clone());
    }
    let dir = folder.commit().map_err(RunError::io("the report folder"))?;
    Ok((dir, files))
}
