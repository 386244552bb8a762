//! How a run tells its progress: the library never prints, the binary draws a bar from these calls.

/// Told how a run proceeds, for a progress bar; the library never prints.
pub trait Progress: Sync {
    /// A stage begins with `total` steps.
    fn stage(&self, _label: &'static str, _total: u64) {}
    /// `n` steps of the stage are done.
    fn advance(&self, _n: u64) {}
    /// Whether the run should stop: asked between blocks of a sweep (a Python caller's Ctrl-C);
    /// a run that stops fails with an `Interrupted` I/O error and writes nothing.
    fn cancelled(&self) -> bool {
        false
    }
}

/// No progress reported.
pub struct Quiet;
impl Progress for Quiet {}
