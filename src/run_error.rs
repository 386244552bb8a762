//! Why a run failed: before lowering, the scene's diagnostics; after it, a [`Failure`] with a kind,
//! a reason and hints, as a diagnostic has (a file system error keeps its `std::io::Error`).

use crate::diagnostics::SceneErrors;

/// Why a run failed.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    #[error("{0}")]
    Scene(SceneErrors),
    /// Drawing or reading back a report.
    #[error("{0}")]
    Render(Failure),
    #[error("cannot write {what}: {source}")]
    Io { what: &'static str, source: std::io::Error },
    /// Sharding a scene or merging shard folders.
    #[error("{0}")]
    Shards(Failure),
}

/// What went wrong after the scene was lowered.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FailureKind {
    /// A plot or report.md could not be drawn (a defect of gearloss).
    Drawing,
    /// report.json does not read back as the report it was written from (a defect of gearloss).
    ReadBack,
    /// A folder given to `render` holds no report gearloss wrote.
    NotAReport,
    /// A folder given to `merge` holds no shard manifest gearloss wrote.
    NotAShard,
    /// The shard folders given to `merge` do not belong together or do not cover the scene.
    ShardsDoNotMatch,
    /// `--shard` on a scene (a drive, one pair a one-stage drive) at several oil temperatures.
    ShardedDrive,
    /// A scene given to `run` that lowering did not build: it has no drive.
    NotLowered,
    /// A drive written with `stage` blocks given where a scene of one pair is asked for
    /// (`gearloss::pair_files`).
    NotOnePair,
}

/// A failure after lowering: its kind, the reason (one line) and what to do about it.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{reason}")]
pub struct Failure {
    pub kind: FailureKind,
    pub reason: String,
    pub hints: Vec<String>,
}

/// What a defect of gearloss asks the user to do.
const REPORT_IT: &str = "this is a defect of gearloss: please report it with the scene that shows it";

impl Failure {
    pub fn new(kind: FailureKind, reason: impl Into<String>) -> Failure {
        Failure { kind, reason: reason.into(), hints: Vec::new() }
    }

    pub fn hint(mut self, hint: impl Into<String>) -> Failure {
        self.hints.push(hint.into());
        self
    }
}

impl RunError {
    pub(crate) fn io(what: &'static str) -> impl Fn(std::io::Error) -> RunError {
        move |source| RunError::Io { what, source }
    }

    /// A plot the renderer could not draw.
    pub(crate) fn drawing(reason: String) -> RunError {
        RunError::Render(
            Failure::new(FailureKind::Drawing, format!("drawing the report failed: {reason}")).hint(REPORT_IT),
        )
    }

    /// report.json that does not read back.
    pub(crate) fn read_back(reason: String) -> RunError {
        RunError::Render(Failure::new(FailureKind::ReadBack, reason).hint(REPORT_IT))
    }

    /// The failure, for errors after lowering.
    pub fn failure(&self) -> Option<&Failure> {
        match self {
            RunError::Render(f) | RunError::Shards(f) => Some(f),
            RunError::Scene(_) | RunError::Io { .. } => None,
        }
    }
}
