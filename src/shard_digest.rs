//! What a shard wrote, held against what `merge` reads: the CRC-32 of each record file and of the
//! scene's text, written into the shard's manifest and checked before the shards are merged, so
//! that a record file cut short, edited or replaced, a manifest whose scene was edited, or shards
//! written with different `--records` are refused, naming the folder and the file, instead of
//! merging into a report that contradicts its numbers. (A CRC finds accidents, not forgery.)

use std::collections::BTreeMap;
use std::io::Read;
use std::path::Path;

/// The CRC-32 of `bytes` as eight hex digits.
pub(crate) fn of_text(bytes: &[u8]) -> String {
    format!("{:08x}", crc32fast::hash(bytes))
}

/// The CRC-32 of a file, read in blocks (a big sweep's records are not held whole).
pub(crate) fn of_file(path: &Path) -> std::io::Result<String> {
    let mut file = std::fs::File::open(path)?;
    let mut hasher = crc32fast::Hasher::new();
    let mut block = vec![0u8; 1 << 20];
    loop {
        let n = file.read(&mut block)?;
        if n == 0 {
            break;
        }
        hasher.update(&block[..n]);
    }
    Ok(format!("{:08x}", hasher.finalize()))
}

/// The digests of `files` in the folder `dir`.
pub(crate) fn of_files(dir: &Path, files: &[String]) -> std::io::Result<BTreeMap<String, String>> {
    files.iter().map(|f| Ok((f.clone(), of_file(&dir.join(f))?))).collect()
}

/// What is wrong with a shard folder's files against its manifest's digests and the first shard's
/// files, in words naming the file; None when they hold what the shard wrote.
pub(crate) fn problem(
    dir: &Path,
    digests: &BTreeMap<String, String>,
    first: &BTreeMap<String, String>,
) -> Option<String> {
    let (mine, theirs): (Vec<&String>, Vec<&String>) = (digests.keys().collect(), first.keys().collect());
    if mine != theirs {
        return Some(format!(
            "{} holds the record files {mine:?}, the first shard {theirs:?}: the shards were run with different `--records`",
            dir.display()
        ));
    }
    for (file, want) in digests {
        let path = dir.join(file);
        match of_file(&path) {
            Err(e) => return Some(format!("{}: {e}", path.display())),
            Ok(got) if &got != want => {
                return Some(format!(
                    "{} is not the file its shard wrote (CRC-32 {got}, the manifest says {want}): cut short, edited or replaced after the run",
                    path.display()
                ))
            }
            Ok(_) => {}
        }
    }
    None
}
