//! Sharded runs: `gearloss run SCENE --shard K/N` evaluates the K-th contiguous block of the sweep's
//! operating points ([`crate::evaluate::Shard::range`]) and writes its record files and a manifest
//! (`shard.json`: the scene's text, the shard, and the tally of its points); `gearloss merge`
//! checks that the folders are the N shards of one scene, concatenates their record files in
//! shard order (byte for byte those of a single run) and folds their tallies in the same order
//! (exactly a single run's tally), then reports as a single run does.

use std::collections::BTreeMap;
use std::fs::File;
use std::io::{BufRead, BufReader, BufWriter, Write};
use std::path::PathBuf;

use serde::{Deserialize, Serialize};

use crate::evaluate::record_files::{RecordFiles, RecordFormats, RecordTable};
use crate::evaluate::records::ExtraColumns;
use crate::evaluate::{Shard, Tally};
use crate::folder::ReportFolder;
use crate::progress::Progress;
use crate::run_error::{Failure, FailureKind};

/// The manifest of a shard folder.
pub(crate) const MANIFEST: &str = "shard.json";
/// The manifest's format, checked by `merge`.
pub(crate) const FORMAT: &str = "gearloss-shard-1";

/// Opens the record files of `formats` in a folder being written.
pub(crate) fn record_files(
    folder: &ReportFolder,
    dir: &str,
    extra: &ExtraColumns,
    formats: RecordFormats,
) -> std::io::Result<RecordFiles<BufWriter<File>, crate::evaluate::pair_records::PairRecords>> {
    let at = |f: &str| crate::folder::in_dir(dir, f);
    RecordFiles::new(formats, extra, |f| Ok(BufWriter::new(folder.create_file(&at(f))?)))
}

/// What a shard folder says of itself.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub(crate) struct Manifest {
    pub format: String,
    pub gearloss_version: String,
    /// The scene as given to `run`, its path (files it names are read relative to it) and text.
    pub source_name: String,
    pub source: String,
    pub shard: Shard,
    /// Operating points of the whole sweep, and this shard's [from, to).
    pub operating_points: usize,
    pub range: (usize, usize),
    /// The tally of the shard's points, as its kind of scene keeps it ([`ShardTally`]: a pair's
    /// `Tally`, a drive's `DriveTally`).
    pub tally: serde_json::Value,
    /// The CRC-32 of the scene's text and of each record file the shard wrote
    /// ([`crate::shard_digest`]), checked by `merge`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub source_digest: Option<String>,
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub digests: BTreeMap<String, String>,
    /// A scene of one pair run as its one-stage drive: its stage's pair, analysed over the scene's
    /// whole sweep, as this shard's points tally it (its record files in [`Self::stage_pair`]'s
    /// folder, `stages/pair/`, their digests among `digests`); merged as a pair's shards are.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stage_pair: Option<(String, serde_json::Value)>,
}

/// What a kind of scene tallies over a shard's points, written in its manifest and folded at the
/// merge in shard order into exactly a single run's tally.
pub(crate) trait ShardTally: Serialize + serde::de::DeserializeOwned + Default {
    /// Folds the tally of the points that follow (the next shard's).
    fn absorb(&mut self, next: Self);
}

impl ShardTally for Tally {
    fn absorb(&mut self, next: Tally) {
        Tally::absorb(self, next);
    }
}

impl ShardTally for crate::evaluate::drive::DriveTally {
    fn absorb(&mut self, next: Self) {
        crate::evaluate::drive::DriveTally::absorb(self, next);
    }
}

impl Manifest {
    /// The manifest of `shard` of a sweep of `operating_points`, its points `range`, with their
    /// `tally` (the digests of its record files added by [`Manifest::with_digests`]).
    pub(crate) fn new(
        (source_name, source): (&str, &str),
        shard: Shard,
        (operating_points, range): (usize, std::ops::Range<usize>),
        tally: &impl ShardTally,
    ) -> Manifest {
        Manifest {
            format: FORMAT.into(),
            gearloss_version: env!("CARGO_PKG_VERSION").into(),
            source_name: source_name.into(),
            source: source.into(),
            shard,
            operating_points,
            range: (range.start, range.end),
            tally: serde_json::to_value(tally).expect("a tally serialises"),
            source_digest: Some(crate::shard_digest::of_text(source.as_bytes())),
            digests: BTreeMap::new(),
            stage_pair: None,
        }
    }

    /// The manifest with the tally of the stage's pair analysed over the sweep in folder `dir`.
    pub(crate) fn with_stage_pair(mut self, stage_pair: Option<(String, Tally)>) -> Manifest {
        self.stage_pair =
            stage_pair.map(|(dir, tally)| (dir, serde_json::to_value(tally).expect("a tally serialises")));
        self
    }

    /// The manifest with the digests of the record files `files` of the shard's folder.
    pub(crate) fn with_digests(mut self, folder: &ReportFolder, files: &[String]) -> std::io::Result<Manifest> {
        self.digests = crate::shard_digest::of_files(&folder.path(""), files)?;
        Ok(self)
    }

    pub(crate) fn to_json(&self) -> Vec<u8> {
        let mut v = serde_json::to_vec_pretty(self).expect("a manifest serialises");
        v.push(b'\n');
        v
    }
}

/// The N shards of one scene, in shard order, with their tallies folded.
#[derive(Debug)]
pub(crate) struct ShardSet {
    pub source_name: String,
    pub source: String,
    pub folders: Vec<PathBuf>,
    /// Each shard's tally as its manifest holds it, in shard order ([`ShardSet::tally`] folds them).
    tallies: Vec<serde_json::Value>,
    /// The folder and each shard's tally of a one-pair drive's stage analysed over the sweep
    /// ([`Manifest::stage_pair`]), where the first shard has one.
    stage_pair: Option<(String, Vec<serde_json::Value>)>,
}

impl ShardSet {
    /// Reads and checks the manifests: one scene, one shard count, every shard exactly once; the
    /// error says which folder is wrong and why.
    pub(crate) fn read(folders: &[PathBuf]) -> Result<ShardSet, Failure> {
        let not_a_shard = |reason: String| {
            Failure::new(FailureKind::NotAShard, reason)
                .hint("give the folders `gearloss run --shard K/N` wrote, named <scene>.shard-K-of-N")
        };
        let mismatch = |reason: String| Failure::new(FailureKind::ShardsDoNotMatch, reason);
        let mut manifests = Vec::new();
        for dir in folders {
            let path = dir.join(MANIFEST);
            let text = std::fs::read_to_string(&path)
                .map_err(|e| not_a_shard(format!("{}: cannot read the shard manifest: {e}", path.display())))?;
            let m: Manifest = serde_json::from_str(&text)
                .map_err(|e| not_a_shard(format!("{}: not a gearloss shard manifest: {e}", path.display())))?;
            if m.format != FORMAT {
                return Err(not_a_shard(format!("{}: shard format {} is not {FORMAT}", path.display(), m.format))
                    .hint("shard and merge with the same version of gearloss"));
            }
            if m.source_digest.as_ref().is_some_and(|d| *d != crate::shard_digest::of_text(m.source.as_bytes())) {
                return Err(mismatch(format!(
                    "{}: the scene in the manifest was edited after the shard's run (its text no longer matches its CRC-32)",
                    path.display()
                ))
                .hint("run the shard again from the scene file; a shard's records belong to the scene it was run with"));
            }
            manifests.push((dir.clone(), m));
        }
        if let Some((_, first)) = manifests.first() {
            let first = first.digests.clone();
            for (dir, m) in manifests.iter().filter(|(_, m)| !m.digests.is_empty()) {
                if let Some(problem) = crate::shard_digest::problem(dir, &m.digests, &first) {
                    return Err(mismatch(problem)
                        .hint("run that shard again (`gearloss run --shard K/N`) and merge its new folder"));
                }
            }
        }
        let Some((_, first)) = manifests.first() else {
            return Err(not_a_shard("no shard folders given".to_string()));
        };
        let (count, source, source_name) = (first.shard.count, first.source.clone(), first.source_name.clone());
        for (dir, m) in &manifests {
            if m.source != source || m.source_name != source_name {
                return Err(mismatch(format!("{} holds a shard of another scene than {source_name}", dir.display()))
                    .hint("merge the shards of one scene (same text) together"));
            }
            if m.shard.count != count {
                return Err(mismatch(format!(
                    "{} is a shard of {}, the others of {count}",
                    dir.display(),
                    m.shard.count
                ))
                .hint("merge shards cut with one count N (`--shard K/N`)"));
            }
        }
        manifests.sort_by_key(|(_, m)| m.shard.index);
        let have: Vec<usize> = manifests.iter().map(|(_, m)| m.shard.index).collect();
        if have != (1..=count).collect::<Vec<_>>() {
            let missing: Vec<String> =
                (1..=count).filter(|k| !have.contains(k)).map(|k| format!("{k}/{count}")).collect();
            let got = mismatch(format!(
                "merge needs each of the {count} shards exactly once; got {:?}{}",
                have,
                if missing.is_empty() { String::new() } else { format!(", missing {}", missing.join(", ")) }
            ));
            return Err(if missing.is_empty() {
                got.hint("give each shard folder once")
            } else {
                got.hint(format!("run `gearloss run --shard {}` and give its folder too", missing[0]))
            });
        }
        let stage_pair = match manifests[0].1.stage_pair.as_ref() {
            Some((dir, _)) => {
                let tallies = manifests.iter().map(|(shard, m)| match &m.stage_pair {
                    Some((d, t)) if d == dir => Ok(t.clone()),
                    _ => Err(mismatch(format!("{} holds no records of the stage's pair in {dir}", shard.display()))
                        .hint("run that shard again (`gearloss run --shard K/N`) and merge its new folder")),
                });
                Some((dir.clone(), tallies.collect::<Result<Vec<_>, _>>()?))
            }
            None => None,
        };
        let (folders, tallies) = manifests.into_iter().map(|(dir, m)| (dir, m.tally)).unzip();
        Ok(ShardSet { source_name, source, folders, tallies, stage_pair })
    }

    /// The shards of a one-pair drive's stage analysed over the sweep, as a pair's shards: its
    /// folder in each shard's and their tallies, and the folder's name; None where the shards hold
    /// none.
    pub(crate) fn stage_pair(&self) -> Option<(ShardSet, &str)> {
        let (dir, tallies) = self.stage_pair.as_ref()?;
        let set = ShardSet {
            source_name: self.source_name.clone(),
            source: self.source.clone(),
            folders: self.folders.iter().map(|f| f.join(dir)).collect(),
            tallies: tallies.clone(),
            stage_pair: None,
        };
        Some((set, dir))
    }

    /// The shards' tallies folded in shard order: exactly a single run's. A tally that is not the
    /// scene's kind's (a manifest edited by hand) is refused, its shard named.
    pub(crate) fn tally<T: ShardTally>(&self) -> Result<T, Failure> {
        let mut tally = T::default();
        for (dir, value) in self.folders.iter().zip(&self.tallies) {
            let next = T::deserialize(value).map_err(|e| {
                Failure::new(
                    FailureKind::NotAShard,
                    format!("{}: the tally is not one this scene's run writes: {e}", dir.join(MANIFEST).display()),
                )
                .hint("run that shard again (`gearloss run --shard K/N`) and merge its new folder")
            })?;
            tally.absorb(next);
        }
        Ok(tally)
    }

    /// Writes the merged record files of a kind of record `T` into `folder` (those of
    /// `T::FILES` the first shard holds; every shard must hold them): the CSV and JSON Lines each
    /// shard's in shard order, the CSV's header once (every shard's file has it); Parquet the
    /// shards' rows in shard order into one file (a shard's file that cannot be read is refused,
    /// named). Returns the files written.
    pub(crate) fn concatenate<T: RecordTable>(
        &self,
        folder: &ReportFolder,
        progress: &dyn Progress,
    ) -> std::io::Result<Vec<String>> {
        self.concatenate_into::<T>((folder, ""), progress)
    }

    /// The formats the first shard wrote its records of kind `T` in (a merge writes what else it
    /// runs in the same).
    pub(crate) fn formats<T: RecordTable>(&self) -> RecordFormats {
        let [csv, jsonl, parquet] = T::FILES.map(|f| self.folders[0].join(f).exists());
        RecordFormats { csv, jsonl, parquet }
    }

    /// [`Self::concatenate`] into `folder` under `dir` (`""`: the top).
    pub(crate) fn concatenate_into<T: RecordTable>(
        &self,
        (folder, dir): (&ReportFolder, &str),
        progress: &dyn Progress,
    ) -> std::io::Result<Vec<String>> {
        let [csv, jsonl, parquet] = T::FILES;
        let first = &self.folders[0];
        let text: Vec<(&str, bool)> =
            [(csv, true), (jsonl, false)].into_iter().filter(|(f, _)| first.join(f).exists()).collect();
        let path = |f: &str| crate::folder::in_dir(dir, f);
        self.concatenate_files((folder, dir), &text, progress)?;
        let mut files: Vec<String> = text.iter().map(|(f, _)| path(f)).collect();
        if first.join(parquet).exists() {
            self.merge_parquet(folder, parquet, &path(parquet))?;
            files.push(path(parquet));
        }
        Ok(files)
    }

    /// The shards' Parquet record files `file`, rows in shard order, into one file of the first
    /// shard's columns.
    fn merge_parquet(&self, folder: &ReportFolder, file: &str, into: &str) -> std::io::Result<()> {
        use crate::evaluate::record_parquet::ParquetRecords;
        use crate::evaluate::record_parquet_read::read_parquet_records;
        let mut out: Option<ParquetRecords<BufWriter<File>>> = None;
        for dir in &self.folders {
            let path = dir.join(file);
            let what = path.display().to_string();
            let (columns, rows) = read_parquet_records(File::open(&path)?, &what)?;
            let writer = match &mut out {
                Some(w) => w,
                None => out
                    .insert(ParquetRecords::with_columns(BufWriter::new(folder.create_file(into)?), columns.clone())?),
            };
            if writer.columns() != columns.as_slice() {
                return Err(std::io::Error::new(
                    std::io::ErrorKind::InvalidData,
                    format!("{what} has other columns than the first shard's"),
                ));
            }
            writer.write_cells(rows)?;
        }
        if let Some(w) = out {
            w.finish()?;
        }
        Ok(())
    }

    /// Writes the merged `files` (name, whether it has a header line) into `folder` under `dir`
    /// (`""`: the top), each shard's in shard order (a header, where a shard's file has one, kept
    /// from the first shard only).
    pub(crate) fn concatenate_files(
        &self,
        (folder, dir): (&ReportFolder, &str),
        files: &[(&str, bool)],
        progress: &dyn Progress,
    ) -> std::io::Result<()> {
        for &(file, header) in files {
            let into = crate::folder::in_dir(dir, file);
            let mut out = BufWriter::new(folder.create_file(&into)?);
            for (k, dir) in self.folders.iter().enumerate() {
                let mut input = BufReader::new(File::open(dir.join(file))?);
                if header && k > 0 {
                    let mut skipped = Vec::new();
                    input.read_until(b'\n', &mut skipped)?;
                }
                std::io::copy(&mut input, &mut out)?;
                if header {
                    progress.advance(1);
                }
            }
            out.flush()?;
        }
        Ok(())
    }
}
