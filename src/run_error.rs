//! Why a run failed.

use crate::diagnostics::SceneErrors;

/// Why a run failed.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    #[error("{0}")]
    Scene(SceneErrors),
    #[error("rendering the report failed: {0}")]
    Render(String),
    #[error("cannot write {what}: {source}")]
    Io { what: &'static str, source: std::io::Error },
    #[error("{0}")]
    Shards(String),
}

impl RunError {
    pub(crate) fn io(what: &'static str) -> impl Fn(std::io::Error) -> RunError {
        move |source| RunError::Io { what, source }
    }
}
