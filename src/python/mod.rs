//! The Python module `gearloss._native` (cargo feature `python`; built by maturin from
//! `pyproject.toml`). The package `gearloss` (`src/python/gearloss/`) wraps it: `Scene`, `run`,
//! `Report` with pandas tables, and `gearloss.dask`. Every function here runs the same pipeline as
//! the CLI, and every run releases the GIL. Errors become Python exceptions in one place,
//! [`error`].

// pyo3 0.22's #[pyfunction] expands to a `.into()` of PyErr into PyErr.
#![allow(clippy::useless_conversion)]

mod error;

use std::path::{Path, PathBuf};

use pyo3::prelude::*;

use crate::scene::ast::Item;
use crate::Shard;
use error::{to_py, Error, GearlossRunError, SceneError};

/// Checks a scene; returns its title.
#[pyfunction]
fn check(py: Python<'_>, name: &str, text: &str) -> PyResult<String> {
    to_py(py, crate::check(name, text).map(|s| s.title).map_err(Error::from))
}

/// The number of operating points of a scene (the product of its sweeps).
#[pyfunction]
fn operating_points(py: Python<'_>, name: &str, text: &str) -> PyResult<usize> {
    to_py(py, crate::check(name, text).map(|s| s.operating.count()).map_err(Error::from))
}

/// A scene file's text, read as the CLI reads it: a regular file of at most 16 MiB (`/dev/zero`
/// and pipes refused before reading), UTF-8 with the first bad byte located.
#[pyfunction]
fn read_scene(py: Python<'_>, path: PathBuf) -> PyResult<String> {
    let text = py.allow_threads(|| crate::scene::source::read_text(&path, crate::scene::source::MAX_SCENE_BYTES));
    text.map_err(|e| match e {
        crate::scene::source::ReadError::Io(io) => error::os_error(&format!("cannot read {}", path.display()), &io),
        other => pyo3::exceptions::PyOSError::new_err(format!("cannot read {}: {other}", path.display())),
    })
}

/// Writes a report folder `name` with `files` into `out` as `gearloss run` does: a hidden
/// temporary folder renamed into place (concurrent writers all succeed, nothing left behind).
#[pyfunction]
fn write_folder(py: Python<'_>, out: PathBuf, name: String, files: Vec<(String, Vec<u8>)>) -> PyResult<PathBuf> {
    let written = py.allow_threads(|| {
        let folder = crate::folder::ReportFolder::create(&out, &name)?;
        for (path, bytes) in &files {
            folder.write(path, bytes)?;
        }
        folder.commit()
    });
    written.map_err(|e| error::os_error("cannot write the report folder", &e))
}

/// Runs a scene (or one shard `"K/N"` of it) as `gearloss run --out out` does and returns the
/// report folder's path: nothing of it is held in memory (a sweep's records stay on disk, read
/// when a table is asked for). Ctrl-C stops it as [`run`].
#[pyfunction]
#[pyo3(signature = (name, text, out, shard=None, records=None))]
fn run_to(
    py: Python<'_>,
    name: String,
    text: String,
    out: PathBuf,
    shard: Option<String>,
    records: Option<String>,
) -> PyResult<PathBuf> {
    let formats: crate::RecordFormats = match records {
        Some(r) => r.parse().map_err(pyo3::exceptions::PyValueError::new_err)?,
        None => crate::RecordFormats::default(),
    };
    let shard: Option<Shard> = match shard {
        Some(s) => Some(s.parse().map_err(pyo3::exceptions::PyValueError::new_err)?),
        None => None,
    };
    let signals = Signals::default();
    let result = py.allow_threads(|| run_into(&name, &text, (shard, formats), &out, &signals));
    if let Some(interrupt) = signals.pending.into_inner().ok().flatten() {
        return Err(interrupt);
    }
    to_py(py, result)
}

/// A run's progress that asks Python for pending signals (Ctrl-C) and keeps the exception the
/// signal's handler raised.
#[derive(Default)]
struct Signals {
    pending: std::sync::Mutex<Option<PyErr>>,
}

impl crate::Progress for Signals {
    fn cancelled(&self) -> bool {
        let Ok(mut pending) = self.pending.lock() else { return true };
        if pending.is_none() {
            *pending = Python::with_gil(|py| py.check_signals().err());
        }
        pending.is_some()
    }
}

/// Merges shard folders as `gearloss merge --out out` does; returns the merged folder's path.
#[pyfunction]
fn merge_to(py: Python<'_>, folders: Vec<PathBuf>, out: PathBuf) -> PyResult<PathBuf> {
    let result = py.allow_threads(|| Ok(crate::merge_into(&folders, &out, &crate::Quiet)?.folder));
    to_py(py, result)
}

/// The scene text with operating values replaced (`pinion_speed = "100..3000 rpm count 30"`), checked.
#[pyfunction]
fn replace(py: Python<'_>, name: &str, text: &str, values: Vec<(String, String)>) -> PyResult<String> {
    to_py(py, replaced(name, text, &values))
}

fn run_into(
    name: &str,
    text: &str,
    (shard, formats): (Option<Shard>, crate::RecordFormats),
    out: &Path,
    progress: &dyn crate::Progress,
) -> Result<PathBuf, Error> {
    let scene = crate::check(name, text)?;
    Ok(crate::run_into_with(name, text, &scene, (out, shard), formats, progress)?.folder)
}

/// Replaces (or adds) `key = value` in the scene's `operating` block, then checks the new text.
fn replaced(name: &str, text: &str, values: &[(String, String)]) -> Result<String, Error> {
    let ast = crate::parse(name, text)?;
    let operating = ast.items.iter().find_map(|i| match i {
        Item::Block(b) if b.kind.text == "operating" => Some(b),
        _ => None,
    });
    let Some(block) = operating else {
        let span = crate::diagnostics::Span::new(ast.title_span.start, ast.title_span.end);
        let d = crate::diagnostics::Diagnostic::new(
            crate::diagnostics::DiagnosticKind::MissingKey,
            span,
            "the scene has no `operating` block whose values could be replaced",
        )
        .hint("add `operating { pinion_torque = ...  pinion_speed = ... }`");
        return Err(crate::SceneErrors { source_name: name.into(), source: text.into(), diagnostics: vec![d] }.into());
    };
    let mut edits: Vec<(usize, usize, String)> = Vec::new();
    for (key, value) in values {
        let found = block.items.iter().find_map(|i| match i {
            Item::Assignment { key: k, value: v } if k.text == *key => Some(v.span),
            _ => None,
        });
        match found {
            Some(span) => edits.push((span.start, span.end, value.clone())),
            None => {
                let end = block.span.end.saturating_sub(1);
                edits.push((end, end, format!("    {key} = {value}\n")));
            }
        }
    }
    edits.sort_by_key(|e| std::cmp::Reverse(e.0));
    let mut out = text.to_string();
    for (start, end, new) in edits {
        out.replace_range(start..end, &new);
    }
    // Errors are located in the edited text, so they name it: the file's name with the keys replaced
    // (the folder stays the file's, for the tables a scene names).
    let keys: Vec<&str> = values.iter().map(|(k, _)| k.as_str()).collect();
    crate::check(&format!("{name} (with {} replaced)", keys.join(", ")), &out)?;
    Ok(out)
}

/// A REXS model's scene text and the import's warnings.
#[pyfunction]
fn import_rexs(py: Python<'_>, path: PathBuf) -> PyResult<(String, Vec<String>)> {
    let imported = py.allow_threads(|| crate::rexs::import_file(&path));
    to_py(py, imported.map(|i| (i.scene, i.warnings)).map_err(Error::from))
}

/// The native module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(run_to, m)?)?;
    m.add_function(wrap_pyfunction!(merge_to, m)?)?;
    m.add_function(wrap_pyfunction!(replace, m)?)?;
    m.add_function(wrap_pyfunction!(operating_points, m)?)?;
    m.add_function(wrap_pyfunction!(read_scene, m)?)?;
    m.add_function(wrap_pyfunction!(write_folder, m)?)?;
    m.add("SceneError", m.py().get_type_bound::<SceneError>())?;
    m.add("RunError", m.py().get_type_bound::<GearlossRunError>())?;
    m.add("RexsError", m.py().get_type_bound::<error::RexsError>())?;
    m.add_function(wrap_pyfunction!(import_rexs, m)?)?;
    Ok(())
}
