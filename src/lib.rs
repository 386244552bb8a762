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
//! One public function per stage: [`parse`], [`lower`], [`evaluate()`], [`report()`], [`render()`], and
//! [`write_report_folder`]. Errors of the first two stages are [`SceneErrors`]: every problem with
//! its span, reason and hints, rendered by miette. The library never prints.
//!
//! The layers, each importing only from those below it (no import circles):
//!
//! ```text
//!  cli ─ lib                      the binary's commands; one function per stage
//!  render/ (markdown, svg/)       formats the report; never computes
//!  report/                        the serde report: numbers and series ready to draw, findings
//!  evaluate/ (cases, laws,        expands the sweeps into cases once; friction, efficiency and the
//!             dynamics)           dynamics at each case, only what the scene asks for
//!  scene/                         the language: grammar, parse, units, lowering to the model
//!  model                          the lowered scene (uom quantities, what the user wrote)
//!  dynamics/                      the n-state periodic engine (PeriodicModel: propagators, Floquet,
//!                                 trajectory, integrators, numerics study) and its models (SDOF)
//!  efficiency                     η(t), η̄ and power loss of a law along the mesh cycle
//!  friction/                      the law catalogue (typed LawId, one constructor each), one law a file
//!  tribology/                     lubricant and surface data in SI, film thickness
//!  geometry/ (spur, mesh,         the pair: involute geometry, the mesh cycle (contacts, switch
//!             stiffness)          times), contact states, mesh stiffness
//!  numerics/ quantity diagnostics quadrature and roots; physical dimensions; spans and diagnostics
//! ```

pub mod diagnostics;
pub mod dynamics;
pub mod efficiency;
pub mod evaluate;
pub mod friction;
pub mod geometry;
pub mod model;
pub mod numerics;
pub mod quantity;
pub mod render;
pub mod report;
pub mod scene;
pub mod tribology;

use std::path::{Path, PathBuf};

pub use diagnostics::{Diagnostic, DiagnosticKind, SceneErrors};
pub use evaluate::Evaluation;
pub use model::Scene;
pub use render::RenderedReport;
pub use report::Report;
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

/// Stage 3: computes what the scene asks for.
pub fn evaluate(scene: &Scene) -> Evaluation {
    evaluate::evaluate_scene(scene)
}

/// Stage 3 with a callback once per operating point evaluated (from any worker thread), for progress bars.
pub fn evaluate_with_progress(scene: &Scene, tick: &(dyn Fn() + Sync)) -> Evaluation {
    evaluate::evaluate_scene_with_progress(scene, tick)
}

/// Stage 4: the serde report data.
pub fn report(scene: &Scene, evaluation: &Evaluation) -> Report {
    report::build_report(scene, evaluation)
}

/// Stage 5: the files of the report folder.
pub fn render(report: &Report) -> Result<RenderedReport, String> {
    render::render_report(report)
}

/// Writes `DIR/<slug>/` atomically: into a temporary folder beside it, then renamed into place.
/// An existing report folder of the same name is replaced only once the new one is complete.
pub fn write_report_folder(rendered: &RenderedReport, out_dir: &Path) -> std::io::Result<PathBuf> {
    std::fs::create_dir_all(out_dir)?;
    let target = out_dir.join(&rendered.slug);
    let tmp = out_dir.join(format!(".{}.tmp-{}", rendered.slug, std::process::id()));
    if tmp.exists() {
        std::fs::remove_dir_all(&tmp)?;
    }
    std::fs::create_dir(&tmp)?;
    let written = (|| {
        for (name, content) in &rendered.files {
            std::fs::write(tmp.join(name), content)?;
        }
        Ok::<(), std::io::Error>(())
    })();
    if let Err(e) = written {
        let _ = std::fs::remove_dir_all(&tmp);
        return Err(e);
    }
    let old = out_dir.join(format!(".{}.old-{}", rendered.slug, std::process::id()));
    let had_old = target.exists();
    if had_old {
        std::fs::rename(&target, &old)?;
    }
    if let Err(e) = std::fs::rename(&tmp, &target) {
        if had_old {
            let _ = std::fs::rename(&old, &target);
        }
        let _ = std::fs::remove_dir_all(&tmp);
        return Err(e);
    }
    if had_old {
        std::fs::remove_dir_all(&old)?;
    }
    Ok(target)
}

/// Everything `gearloss run` does short of writing: check, evaluate, report, render.
pub fn run_to_files(source_name: &str, source: &str) -> Result<RenderedReport, RunError> {
    let scene = check(source_name, source).map_err(RunError::Scene)?;
    let evaluation = evaluate(&scene);
    let report = report(&scene, &evaluation);
    render(&report).map_err(RunError::Render)
}

/// Why a run failed.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    #[error("{0}")]
    Scene(SceneErrors),
    #[error("rendering the report failed: {0}")]
    Render(String),
}
