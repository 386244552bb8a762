#![warn(clippy::print_stdout, clippy::print_stderr)]
//! gearloss: gear mesh friction, efficiency and dynamics from a `.gear` scene.
//!
//! ```text
//!  scene.gear ─parse─▶ SceneAst ─lower─▶ Scene ─────▶ MeshProblem ─evaluate─▶ Evaluation ─report─▶ Report ─render─▶ report folder
//!   (text)     pest    (syntax)  units,  (uom,        each mesh at  cases,     (SI f64)    serde   (data)  md, json,  (written to a
//!                                names,  checked,     its state:    only what                              svg        temp folder,
//!                                checks  its drive)   pair_alone,   is asked                                          then renamed)
//!                                          │          stage_pairs
//!                                          └─evaluate_drive─▶ DriveEvaluation ─report─▶ DriveReport ─render─▶ (the folder's top)
//! ```
//!
//! Every scene runs as its drive (a scene of one pair as its one-stage drive): the power walk over
//! its stages, shafts and bearings gives the drive's report at the top of the folder. Each mesh it
//! analyses goes through the stage functions below as a [`MeshProblem`] (the pair at the state the
//! walk gives it, its oil, laws, dynamics and analyses; a scene's own pair: [`Scene::pair_alone`]):
//! the per-mesh evaluation never reads the scene.
//!
//! One public function per stage: [`parse`], [`lower`] (its output printed by [`lowered`]), [`evaluate_sweep`] (the sweep streamed, its
//! summary rows to the record files, its tally returned) with [`evaluate_details`] (the detail points in
//! full), [`report()`] and [`render()`]; [`run_into`] and [`merge_into`] (in `run`) run them into a
//! report folder (whole or sharded). Errors of the first two stages are [`SceneErrors`]: every problem with
//! its span, reason and hints, rendered by miette. The library never prints.
//!
//! The layers, each importing only from those below it (no import circles):
//!
//! ```text
//!  cli ─ lib                      the binary's commands; one function per stage
//!  run, rerender                  the one run layer (folder, oil temperatures, shards, merge) for every
//!                                 scene; a folder redrawn from its json
//!  run_drive, run_pair,           a scene's run (every scene a drive: run_drive), the stage meshes run
//!    run_stage_pairs, run_kind    as pairs alone beneath it (run_stage_pairs → run_pair); run_kind the
//!                                 shapes they pass
//!  shard, folder                  shards and merge; a report folder written whole (concurrent-safe)
//!  render/ (markdown, svg/)       formats the report; never computes
//!  report/                        the serde report: numbers and series ready to draw, findings
//!  evaluate/ (plan, stream,       the run's plan (points, detail points, kept rows); the sweep streamed in
//!    records, tally, laws,        blocks: rows to the record files, a mergeable tally; friction,
//!    dynamics, cases)             efficiency and dynamics at each point, only what the scene asks for
//!  scene/                         the language: grammar, parse, units, lowering to the model
//!  model, mesh                    the lowered scene (uom quantities, what the user wrote); a checked
//!                                 mesh (one pair and its lubricant) and a MeshProblem (the mesh over
//!                                 its states, laws, dynamics, analyses), what a mesh's evaluation reads
//!  rexs/                          REXS gear-unit models (XML, JSON, zip) read into a commented scene
//!  vehicle/                       a vehicle over a drive cycle: the speed trace, the road load, the
//!                                 cycle's pieces with exact wheel energies (the box's losses over them
//!                                 come in from evaluate/drive_cycle)
//!  drive/                         a gearbox of several stages: its layout, the stage-kind catalogue
//!                                 (kinematics/: each kind's data and kinematics; a kind's physics in
//!                                 the walk one StageModel: parallel_stage, planetary_stage), the
//!                                 power walk and its fixed point (never asking a stage's kind), mesh
//!                                 forces, shaft statics, a planetary stage's meshes, planets and
//!                                 forces (planetary/; the mesh efficiency comes in from evaluate/drive)
//!  dynamics/                      the n-state periodic engine (PeriodicModel: propagators, Floquet,
//!                                 trajectory, integrators, numerics study) and the model catalogue
//!                                 (models/: SDOF, 6-DOF behind GearDynamics; generic analysis data)
//!  thermal/                       the housing as one thermal node, the balance θ*, the rating, a duty
//!                                 cycle's transient (the losses come in as a function of θ)
//!  efficiency                     η(t), η̄ and power loss of a law along the mesh cycle
//!  friction/                      the law catalogue (typed LawId, one constructor each), one law a file
//!  losses/                        the budget beside the mesh: gear no-load, bearings, seals as a part
//!                                 catalogue (parts/: LossPart, one file and one row a part)
//!  tribology/                     lubricant and surface data in SI, film thickness
//!  geometry/ (pair, mesh,         the pair: involute geometry, the mesh cycle (contacts, switch
//!             stiffness/, teeth/) times), contact states, the mesh stiffness catalogue, the teeth as
//!                                 bodies (PEM stiffness, load sharing, relief, transmission error)
//!  numerics/ quantity diagnostics quadrature and roots; physical dimensions; spans and diagnostics
//! ```
//!
//! Where a new model goes (ARCHITECTURE.md, "Where a new model goes"): a friction law is one file in
//! `friction/` and one row of [`friction::catalog::LAWS`]; a mesh stiffness model one file in
//! `geometry/stiffness/` and one row of [`geometry::stiffness::MODELS`]; a stage kind of a drive one
//! file in `drive/kinematics/` and one row of [`drive::kinematics::STAGE_KINDS`] with its `StageModel` in
//! `drive/<name>_stage.rs` (README, "Adding a stage kind"); a dynamic model one file in
//! `dynamics/models/` (a [`dynamics::models::GearDynamics`], usually over a
//! [`dynamics::PeriodicModel`] of its own) and one row of [`dynamics::models::MODELS`]; a loss part
//! one file in `losses/parts/` and one row of [`losses::parts::PARTS`] (a new column, a row of
//! [`losses::parts::COLUMNS`]). A model with parameters a scene must give adds their keys to the
//! lowering of its block.

pub(crate) mod diagnostics;
pub mod drive;
pub mod dynamics;
pub mod efficiency;
pub mod evaluate;
pub(crate) mod folder;
pub mod friction;
pub mod geometry;
pub mod listing;
pub mod losses;
pub(crate) mod mesh;
pub mod model;
pub mod numerics;
pub(crate) mod oil_temperature;
pub(crate) mod progress;
#[cfg(feature = "python")]
mod python;
pub(crate) mod quantity;
pub mod render;
pub mod report;
pub mod rerender;
pub mod rexs;
pub(crate) mod run;
pub mod run_drive;
pub(crate) mod run_error;
pub(crate) mod run_kind;
pub(crate) mod run_pair;
pub(crate) mod run_stage_pairs;
pub mod scene;
pub(crate) mod shard;
pub(crate) mod shard_digest;
pub mod thermal;
pub mod tribology;
pub(crate) mod unfinished;
pub mod vehicle;

pub use diagnostics::{Diagnostic, DiagnosticKind, SceneErrors};
pub use evaluate::record_files::RecordFiles;
pub use evaluate::record_files::RecordFormats;
pub use evaluate::records::RecordSink;
pub use evaluate::{Evaluation, Plan, Shard, Tally};
pub use folder::write_new_file;
pub use mesh::MeshProblem;
pub use model::Scene;
pub use progress::{Progress, Quiet};
pub use render::RenderedReport;
pub use report::Report;
pub use run::{merge_into, mesh_report, pair_files, report_of, run_into, run_into_with, run_to_files, Written};
pub use run_error::{Failure, FailureKind, RunError};
pub use run_pair::has_records;
pub use scene::ast::SceneAst;
pub use unfinished::remove_unfinished;

/// Stage 1: text → syntax tree.
pub fn parse(source_name: &str, source: &str) -> Result<SceneAst, SceneErrors> {
    scene::check::parse(source_name, source)
}

/// Stage 2: syntax tree → checked scene (units, names, ranges, geometry).
/// Files the scene names are read relative to the folder of `source_name`.
pub fn lower(source_name: &str, source: &str, ast: &SceneAst) -> Result<Scene, SceneErrors> {
    scene::check::lower(source_name, source, ast)
}

/// Stage 2's output as text: the checked scene as JSON in SI (`gearloss check --emit lowered`).
pub fn lowered(scene: &Scene) -> String {
    scene::lowered::lowered(scene)
}

/// Stages 1 and 2: what `gearloss check` runs.
pub fn check(source_name: &str, source: &str) -> Result<Scene, SceneErrors> {
    scene::check::check(source_name, source)
}

/// Stage 3's detail points in memory: every point of a sweep of up to 100 points in full (tests and
/// benches); a larger sweep's detail points only — its every point goes through [`evaluate_sweep`].
pub fn evaluate(problem: &MeshProblem) -> Evaluation {
    evaluate::evaluate_mesh(problem)
}

/// Stage 3, the sweep: the plan's points streamed, their summary rows written to `sink` in sweep
/// order, their tally returned. Memory does not grow with the sweep.
pub fn evaluate_sweep(
    problem: &MeshProblem,
    plan: &Plan,
    sink: &mut dyn RecordSink,
    progress: &dyn Progress,
) -> std::io::Result<Tally> {
    Ok(evaluate::stages::stream(problem, plan, sink, progress)?.tally)
}

/// Stage 3, the details: the plan's detail points in full, the contact curves and the dynamics.
pub fn evaluate_details(problem: &MeshProblem, plan: &Plan, progress: &dyn Progress) -> Evaluation {
    evaluate::stages::details(problem, plan, &Default::default(), progress)
}

/// Stage 4: the serde report data, from the detail points and the tally of every point.
pub fn report(problem: &MeshProblem, evaluation: &Evaluation, tally: &Tally, plan: &Plan) -> Report {
    report::build_report(problem, evaluation, tally, plan)
}

/// Stage 5: the files of the report folder (the record files are written as the sweep runs).
pub fn render(report: &Report) -> Result<RenderedReport, String> {
    render::render_report(report, None)
}
