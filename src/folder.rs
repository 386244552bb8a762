//! The report folder, written whole or not at all: files go into a hidden temporary folder beside
//! the target (`.<name>.tmp-<pid>-<n>`), which is renamed into place once complete. Whatever
//! happens before [`ReportFolder::commit`] (an error, a panic), dropping the folder removes the
//! temporary one; a run stopped by Ctrl-C removes it through the process's list of unfinished paths
//! (`unfinished.rs`, which the command's interrupt handler empties); a run killed otherwise (SIGKILL,
//! a power cut) leaves its temporary folder, which the next run into the same place removes. Concurrent runs writing the same folder all succeed; the last to commit wins
//! and no temporary or displaced folder is left behind.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

use crate::unfinished::Unfinished;

static UNIQUE: AtomicUsize = AtomicUsize::new(0);

/// A name beside `name` in `dir` that no other process or thread uses: `.name.what-pid-n`.
fn unique(dir: &Path, name: &str, what: &str) -> PathBuf {
    let n = UNIQUE.fetch_add(1, Ordering::Relaxed);
    dir.join(format!(".{name}.{what}-{}-{n}", std::process::id()))
}

/// A report folder being written.
#[derive(Debug)]
pub(crate) struct ReportFolder {
    dir: PathBuf,
    name: String,
    tmp: PathBuf,
    committed: bool,
    /// The temporary folder on the process's list of unfinished paths.
    unfinished: Unfinished,
}

/// The name of `file` inside the folder's subfolder `dir` (`""`: the top), as a run writes it:
/// `dir/file`.
pub(crate) fn in_dir(dir: &str, file: &str) -> String {
    if dir.is_empty() {
        file.to_string()
    } else {
        format!("{dir}/{file}")
    }
}

impl ReportFolder {
    /// Starts `out_dir/name/`, creating `out_dir` if needed. `out_dir` naming a file is an error.
    pub(crate) fn create(out_dir: &Path, name: &str) -> std::io::Result<ReportFolder> {
        if out_dir.exists() && !out_dir.is_dir() {
            return Err(std::io::Error::new(
                std::io::ErrorKind::AlreadyExists,
                format!(
                    "{} is not a folder (give --out a folder, or a path that does not exist yet)",
                    out_dir.display()
                ),
            ));
        }
        std::fs::create_dir_all(out_dir)?;
        remove_stale(out_dir, name);
        let tmp = unique(out_dir, name, "tmp");
        // Registered before it exists: an interrupt between the two removes it all the same.
        let unfinished = Unfinished::register(&tmp)?;
        std::fs::create_dir(&tmp)?;
        Ok(ReportFolder { dir: out_dir.to_path_buf(), name: name.to_string(), tmp, committed: false, unfinished })
    }

    /// The path of a file inside the folder being written.
    pub(crate) fn path(&self, file: &str) -> PathBuf {
        self.tmp.join(file)
    }

    /// Creates one file of the folder for writing (`dir/file` in a subfolder, created as needed).
    pub(crate) fn create_file(&self, file: &str) -> std::io::Result<std::fs::File> {
        Unfinished::check_open()?;
        let path = self.path(file);
        if let Some(parent) = path.parent() {
            std::fs::create_dir_all(parent)?;
        }
        std::fs::File::create(path)
    }

    /// Writes one file of the folder ([`ReportFolder::create_file`]).
    pub(crate) fn write(&self, file: &str, content: &[u8]) -> std::io::Result<()> {
        use std::io::Write;
        self.create_file(file)?.write_all(content)
    }

    /// Renames the finished folder into place, replacing a folder of the same name. Another run may
    /// put its folder there at the same time: the displaced folder is moved aside under a unique
    /// name and removed, and the rename is tried again.
    pub(crate) fn commit(mut self) -> std::io::Result<PathBuf> {
        let target = self.dir.join(&self.name);
        let mut last = None;
        for _ in 0..256 {
            match self.unfinished.finish(|| std::fs::rename(&self.tmp, &target)) {
                Ok(()) => {
                    self.committed = true;
                    return Ok(target);
                }
                // Interrupted: the temporary folder is gone, the folder in place stays as it was.
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => return Err(e),
                // Another run's folder is in the way (or was, a moment ago): move it aside and retry.
                Err(e) if target.exists() || is_in_the_way(&e) => {
                    last = Some(e);
                    let old = unique(&self.dir, &self.name, "old");
                    match std::fs::rename(&target, &old) {
                        Ok(()) => std::fs::remove_dir_all(&old)?,
                        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
                        Err(e) => return Err(e),
                    }
                }
                Err(e) => return Err(e),
            }
        }
        Err(last.unwrap_or_else(|| std::io::Error::other("the report folder could not be renamed into place")))
    }
}

/// `bytes` written whole into a new file `out` (`gearloss import`'s scene): first into a temporary
/// file of a name no other file has (`.<name>.import-<pid>-<n>`, created new beside `out`, on the
/// process's list of unfinished paths), then linked into place, which fails if `out` has appeared
/// meanwhile (a file is never overwritten: not the model, not another import's scene); the
/// temporary file is removed whatever happens, Ctrl-C included.
pub fn write_new_file(out: &Path, bytes: &[u8]) -> std::io::Result<()> {
    use std::io::Write;
    let dir = out.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let name = out.file_name().map_or_else(|| "scene".into(), |n| n.to_string_lossy().into_owned());
    let mut opened = None;
    for n in 0..1000 {
        let temp = dir.join(format!(".{name}.import-{}-{n}", std::process::id()));
        let unfinished = Unfinished::register(&temp)?;
        if let Ok(file) = std::fs::OpenOptions::new().write(true).create_new(true).open(&temp) {
            opened = Some((file, temp, unfinished));
            break;
        }
    }
    let (mut file, temp, unfinished) =
        opened.ok_or_else(|| std::io::Error::other("no temporary file could be created beside it"))?;
    let placed = file.write_all(bytes).and_then(|()| file.sync_all()).and_then(|()| {
        unfinished.finish(|| match std::fs::hard_link(&temp, out) {
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => Err(e),
            // A file system without hard links: renamed, once more checked not to be there.
            Err(_) if !out.exists() => std::fs::rename(&temp, out),
            other => other,
        })
    });
    let _ = std::fs::remove_file(&temp);
    placed
}

/// Removes the temporary and displaced folders that runs killed before they could clean up (a
/// signal, a power cut) left beside `name`: those whose process no longer exists (Linux: no
/// `/proc/<pid>`; elsewhere nothing is removed).
fn remove_stale(dir: &Path, name: &str) {
    if !Path::new("/proc/self").exists() {
        return;
    }
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let file = entry.file_name().to_string_lossy().into_owned();
        let Some(rest) = [".tmp-", ".old-"].iter().find_map(|w| file.strip_prefix(&format!(".{name}{w}"))) else {
            continue;
        };
        let Some(pid) = rest.split('-').next().and_then(|p| p.parse::<u32>().ok()) else { continue };
        if pid != std::process::id() && !Path::new(&format!("/proc/{pid}")).exists() {
            let _ = std::fs::remove_dir_all(entry.path());
        }
    }
}

/// A rename failed because the target is a non-empty folder (ENOTEMPTY, EEXIST).
fn is_in_the_way(e: &std::io::Error) -> bool {
    matches!(e.kind(), std::io::ErrorKind::DirectoryNotEmpty | std::io::ErrorKind::AlreadyExists)
}

impl Drop for ReportFolder {
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_dir_all(&self.tmp);
        }
    }
}
