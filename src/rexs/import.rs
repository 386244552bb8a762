//! One REXS file into a scene's text, with what the reader must know.

use super::error::RexsError;

/// What an import gives: the scene's text and what the reader must know.
#[derive(Debug, Clone, PartialEq)]
pub struct Imported {
    pub scene: String,
    pub warnings: Vec<String>,
}

/// Imports the REXS model in `bytes`, read from a file named `file_name` (its stem titles the scene).
pub fn import(file_name: &str, bytes: &[u8]) -> Result<Imported, RexsError> {
    let model = super::formats::read_model(bytes)?;
    let unit = super::gear_unit::read_gear_unit(&model)?;
    let scene = super::write_scene::write_scene(file_name, &model, &unit);
    written_scene_checks(file_name, &scene)?;
    Ok(Imported { scene, warnings: unit.warnings })
}

/// Every scene an import gives parses and checks (`gearloss check`'s own path) before anyone
/// writes it: a scene that does not is the importer's fault, refused with what the check said.
fn written_scene_checks(file_name: &str, scene: &str) -> Result<(), RexsError> {
    crate::check(&format!("{file_name} (imported)"), scene).map(|_| ()).map_err(|errors| {
        let first = errors.diagnostics.first().map(|d| {
            let (line, column) = errors.line_column(d.span.start);
            format!("line {line}, column {column}: {}", d.reason)
        });
        RexsError::new(
            format!(
                "the scene written for this model does not check ({} error(s); the first at {})",
                errors.diagnostics.len(),
                first.unwrap_or_default()
            ),
            "this is a gearloss bug: please report it with the model",
        )
    })
}

/// Imports the REXS file at `path`.
pub fn import_file(path: &std::path::Path) -> Result<Imported, RexsError> {
    let bytes = crate::scene::source::read_bytes(path, super::formats::MAX_MODEL_BYTES).map_err(|e| {
        RexsError::new(
            format!("cannot read {}: {e}", path.display()),
            "give the path of a .rexs, .rexsj or .rexsz file (a regular file of at most 64 MiB)",
        )
    })?;
    import(&path.display().to_string(), &bytes)
}
