//! Every error of the library as the Python exception it raises, in one place (as pyca/cryptography's
//! `src/rust/src/error.rs`): a scene's diagnostics → `gearloss.SceneError` with `.diagnostics` (file,
//! line, column, message, help — what the CLI prints) and `str()` the CLI's rendering; a run that
//! fails after lowering → `gearloss.RunError` with `.kind` and `.hints`; a REXS model that cannot
//! be imported → `gearloss.RexsError` (a `ValueError`) with `.component` and `.hint`; a file system
//! error → `OSError`.

// pyo3 0.22's `create_exception!` tests a `gil-refs` feature this crate does not have.
#![allow(unexpected_cfgs)]

use pyo3::exceptions::PyOSError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::diagnostics::SceneErrors;
use crate::run_error::RunError;

pyo3::create_exception!(_native, SceneError, pyo3::exceptions::PyValueError, "A scene that does not lower.");
pyo3::create_exception!(
    _native,
    GearlossRunError,
    pyo3::exceptions::PyRuntimeError,
    "A run that failed after lowering."
);

pyo3::create_exception!(_native, RexsError, pyo3::exceptions::PyValueError, "A REXS model that cannot be imported.");

/// The error of the library, ready to become a Python exception.
pub(super) enum Error {
    Scene(SceneErrors),
    Run(RunError),
    Rexs(crate::rexs::RexsError),
}

impl From<crate::rexs::RexsError> for Error {
    fn from(e: crate::rexs::RexsError) -> Error {
        Error::Rexs(e)
    }
}

impl From<SceneErrors> for Error {
    fn from(e: SceneErrors) -> Error {
        Error::Scene(e)
    }
}

impl From<RunError> for Error {
    fn from(e: RunError) -> Error {
        match e {
            RunError::Scene(s) => Error::Scene(s),
            other => Error::Run(other),
        }
    }
}

/// One diagnostic as Python reads it.
fn diagnostic<'py>(
    py: Python<'py>,
    e: &SceneErrors,
    d: &crate::diagnostics::Diagnostic,
) -> PyResult<Bound<'py, PyDict>> {
    let (line, column) = e.line_column(d.span.start);
    let out = PyDict::new_bound(py);
    out.set_item("file", &e.source_name)?;
    out.set_item("line", line)?;
    out.set_item("column", column)?;
    out.set_item("kind", format!("{:?}", d.kind))?;
    out.set_item("message", &d.reason)?;
    out.set_item("help", d.hints.join("\n"))?;
    Ok(out)
}

impl Error {
    /// The Python exception.
    pub(super) fn into_py_err(self, py: Python<'_>) -> PyErr {
        match self {
            Error::Scene(e) => {
                let err = SceneError::new_err(e.render(false));
                let list = PyList::empty_bound(py);
                for d in &e.diagnostics {
                    match diagnostic(py, &e, d) {
                        Ok(d) => {
                            let _ = list.append(d);
                        }
                        Err(x) => return x,
                    }
                }
                if let Err(x) = err.value_bound(py).setattr("diagnostics", list) {
                    return x;
                }
                err
            }
            Error::Rexs(e) => {
                let all: Vec<String> = e.all().map(|e| format!("{e}\n  help: {}", e.hint)).collect();
                let err = RexsError::new_err(all.join("\n"));
                let value = err.value_bound(py);
                let set =
                    value.setattr("component", e.component.clone()).and_then(|_| value.setattr("hint", e.hint.clone()));
                if let Err(x) = set {
                    return x;
                }
                err
            }
            Error::Run(RunError::Io { what, source }) => os_error(&format!("cannot write {what}"), &source),
            Error::Run(e) => {
                let err = GearlossRunError::new_err(e.to_string());
                let (kind, hints) = e.failure().map_or((String::new(), Vec::new()), |f| {
                    (
                        serde_json::to_value(f.kind)
                            .ok()
                            .and_then(|v| v.as_str().map(String::from))
                            .unwrap_or_default(),
                        f.hints.clone(),
                    )
                });
                let value = err.value_bound(py);
                if let Err(x) = value.setattr("kind", kind).and_then(|_| value.setattr("hints", hints)) {
                    return x;
                }
                err
            }
        }
    }
}

/// A file system error as the `OSError` subclass Python raises for its kind (`PermissionError`,
/// `FileNotFoundError`, `FileExistsError`, `IsADirectoryError`, `NotADirectoryError`,
/// `InterruptedError`; else `OSError`), with `message` (what could not be done) and the cause.
pub(super) fn os_error(message: &str, e: &std::io::Error) -> PyErr {
    use pyo3::exceptions as x;
    use std::io::ErrorKind as K;
    let text = format!("{message}: {e}");
    match e.kind() {
        K::PermissionDenied => x::PyPermissionError::new_err(text),
        K::NotFound => x::PyFileNotFoundError::new_err(text),
        K::AlreadyExists => x::PyFileExistsError::new_err(text),
        K::IsADirectory => x::PyIsADirectoryError::new_err(text),
        K::NotADirectory => x::PyNotADirectoryError::new_err(text),
        K::Interrupted => x::PyInterruptedError::new_err(text),
        _ => PyOSError::new_err(text),
    }
}

/// `Result<T, Error>` → `PyResult<T>`.
pub(super) fn to_py<T>(py: Python<'_>, r: Result<T, Error>) -> PyResult<T> {
    r.map_err(|e| e.into_py_err(py))
}
