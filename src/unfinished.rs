//! What the process is writing and has not finished: the temporary report folders and import files
//! that are renamed into place once whole. A run stopped by an error or a panic removes its own (the
//! writers' `Drop`); a run stopped by Ctrl-C removes them through [`remove_unfinished`], which the
//! command's interrupt handler calls before it exits. After that call nothing more is registered
//! or renamed into place, and [`Unfinished::check_open`] fails every later write.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, MutexGuard, PoisonError};

/// The temporary paths being written and whether the process is stopping.
#[derive(Debug)]
pub(crate) struct Registry {
    paths: Mutex<Vec<PathBuf>>,
    stopping: AtomicBool,
}

/// The process's registry.
static REGISTRY: Registry = Registry::new();

impl Registry {
    const fn new() -> Registry {
        Registry { paths: Mutex::new(Vec::new()), stopping: AtomicBool::new(false) }
    }

    fn lock(&self) -> MutexGuard<'_, Vec<PathBuf>> {
        // A writer that panicked holding the lock left the list as it was: still right.
        self.paths.lock().unwrap_or_else(PoisonError::into_inner)
    }

    fn check_open(&self) -> std::io::Result<()> {
        if self.stopping.load(Ordering::SeqCst) {
            return Err(std::io::Error::new(std::io::ErrorKind::Interrupted, "the run was interrupted"));
        }
        Ok(())
    }

    fn register(&'static self, path: &Path) -> std::io::Result<Unfinished> {
        let mut paths = self.lock();
        self.check_open()?;
        paths.push(path.to_path_buf());
        Ok(Unfinished { registry: self, path: path.to_path_buf() })
    }

    fn remove_all(&self) -> usize {
        let mut paths = self.lock();
        self.stopping.store(true, Ordering::SeqCst);
        let mut removed = 0;
        for path in paths.drain(..) {
            let gone = if path.is_dir() { std::fs::remove_dir_all(&path) } else { std::fs::remove_file(&path) };
            removed += usize::from(gone.is_ok());
        }
        removed
    }
}

/// A temporary path (a folder or a file) registered while it is written; dropping it unregisters
/// the path (its writer has renamed or removed it by then).
#[derive(Debug)]
pub(crate) struct Unfinished {
    registry: &'static Registry,
    path: PathBuf,
}

impl Unfinished {
    /// Registers `path` with the process; refused once the process is stopping.
    pub(crate) fn register(path: &Path) -> std::io::Result<Unfinished> {
        REGISTRY.register(path)
    }

    /// An error once the process is stopping (after [`remove_unfinished`]): nothing more is written.
    pub(crate) fn check_open() -> std::io::Result<()> {
        REGISTRY.check_open()
    }

    /// Runs `step` (the rename into place) while no interrupt can remove the path under it; refused
    /// once the process is stopping.
    pub(crate) fn finish<T>(&self, step: impl FnOnce() -> std::io::Result<T>) -> std::io::Result<T> {
        let _paths = self.registry.lock();
        self.registry.check_open()?;
        step()
    }
}

impl Drop for Unfinished {
    fn drop(&mut self) {
        let mut paths = self.registry.lock();
        if let Some(k) = paths.iter().position(|p| *p == self.path) {
            paths.swap_remove(k);
        }
    }
}

/// Removes every temporary folder and file the process is writing and stops it writing more (each
/// later write fails as interrupted); returns how many were removed. For an interrupt handler: call
/// it, then exit.
pub fn remove_unfinished() -> usize {
    REGISTRY.remove_all()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A registry of its own (the process's stays open for the other tests): a folder registered is
    /// removed by the interrupt with what it holds, one finished is not, and nothing registers or
    /// finishes after.
    #[test]
    fn an_interrupt_removes_what_is_unfinished_and_stops_the_rest() {
        static R: Registry = Registry::new();
        let base = std::env::temp_dir().join(format!("gearloss-unfinished-{}", std::process::id()));
        let (open, done) = (base.join("open"), base.join("done"));
        std::fs::create_dir_all(open.join("sub")).unwrap();
        std::fs::write(open.join("sub/file"), b"x").unwrap();
        std::fs::create_dir_all(&done).unwrap();
        let still_open = R.register(&open).unwrap();
        drop(R.register(&done).unwrap());
        assert_eq!(R.remove_all(), 1);
        assert!(!open.exists() && done.exists());
        assert_eq!(R.register(&done).unwrap_err().kind(), std::io::ErrorKind::Interrupted);
        let renamed = still_open.finish(|| Ok(())).unwrap_err();
        assert_eq!(renamed.kind(), std::io::ErrorKind::Interrupted);
        std::fs::remove_dir_all(&base).unwrap();
    }
}
