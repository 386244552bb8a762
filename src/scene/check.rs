//! Stages 1 and 2 on a source text: parse and lower, their diagnostics gathered with the text
//! they point into ([`SceneErrors`]).

use std::path::Path;

use super::ast::SceneAst;
use crate::diagnostics::SceneErrors;
use crate::model::Scene;

/// Stage 1: text → syntax tree.
pub fn parse(source_name: &str, source: &str) -> Result<SceneAst, SceneErrors> {
    super::parse::parse_scene_text(source).map_err(|diagnostics| SceneErrors {
        source_name: source_name.into(),
        source: source.into(),
        diagnostics,
    })
}

/// Stage 2: syntax tree → checked scene (units, names, ranges, geometry).
/// Files the scene names are read relative to the folder of `source_name`.
pub fn lower(source_name: &str, source: &str, ast: &SceneAst) -> Result<Scene, SceneErrors> {
    let base = Path::new(source_name).parent();
    super::lower::lower_scene_in(ast, base).map_err(|diagnostics| SceneErrors {
        source_name: source_name.into(),
        source: source.into(),
        diagnostics,
    })
}

/// Stages 1 and 2.
pub fn check(source_name: &str, source: &str) -> Result<Scene, SceneErrors> {
    let ast = parse(source_name, source)?;
    lower(source_name, source, &ast)
}
