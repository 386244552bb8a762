//! Stages 1 and 2 on a source text: parse and lower, their diagnostics gathered with the text
//! they point into ([`SceneErrors`]).

use std::path::Path;

use super::ast::SceneAst;
use crate::diagnostics::{Diagnostic, DiagnosticKind, SceneErrors, Span};
use crate::model::Scene;

/// Stage 1: text → syntax tree.
pub(crate) fn parse(source_name: &str, source: &str) -> Result<SceneAst, SceneErrors> {
    super::parse::parse_scene_text(source).map_err(|diagnostics| SceneErrors {
        source_name: source_name.into(),
        source: source.into(),
        diagnostics,
    })
}

/// Stage 2: syntax tree → checked scene (units, names, ranges, geometry).
/// Files the scene names are read relative to the folder of `source_name`.
pub(crate) fn lower(source_name: &str, source: &str, ast: &SceneAst) -> Result<Scene, SceneErrors> {
    let base = Path::new(source_name).parent();
    super::lower::lower_scene_in(ast, base).map_err(|diagnostics| SceneErrors {
        source_name: source_name.into(),
        source: source.into(),
        diagnostics: without_cascades(diagnostics),
    })
}

/// The diagnostics without those a misspelling caused: "… has no `module`" when the same block
/// (or, for a missing block, the scene) has an unknown name answered by "did you mean `module`?".
/// The misspelling's own diagnostic says what to write; the missing key would only repeat it.
pub(crate) fn without_cascades(diagnostics: Vec<Diagnostic>) -> Vec<Diagnostic> {
    let misspelt: Vec<(Span, String)> = diagnostics
        .iter()
        .filter(|d| d.kind == DiagnosticKind::UnknownName)
        .flat_map(|d| d.hints.iter().filter_map(move |h| meant(h).map(|n| (d.span, n.to_string()))))
        .collect();
    let caused = |d: &Diagnostic| {
        let Some(key) = missing_name(&d.reason) else { return false };
        let scene_wide = d.reason.starts_with("the scene has no");
        misspelt
            .iter()
            .any(|(span, name)| name == key && (scene_wide || (span.start >= d.span.start && span.end <= d.span.end)))
    };
    let keep: Vec<bool> = diagnostics.iter().map(|d| !(d.kind == DiagnosticKind::MissingKey && caused(d))).collect();
    diagnostics.into_iter().zip(keep).filter_map(|(d, k)| k.then_some(d)).collect()
}

/// `name` of a hint "did you mean `name`?".
fn meant(hint: &str) -> Option<&str> {
    hint.strip_prefix("did you mean `")?.strip_suffix("`?")
}

/// `name` of a reason "… has no `name` …".
fn missing_name(reason: &str) -> Option<&str> {
    let rest = &reason[reason.find("has no `")? + "has no `".len()..];
    rest.split('`').next()
}

/// Stages 1 and 2.
pub(crate) fn check(source_name: &str, source: &str) -> Result<Scene, SceneErrors> {
    let ast = parse(source_name, source)?;
    lower(source_name, source, &ast)
}
