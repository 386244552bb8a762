//! What a kind of scene gives the one run layer ([`crate::run`]): a drive
//! ([`crate::run_drive::DriveRun`], every scene a user writes: one pair is a one-stage drive) and a
//! pair alone ([`crate::run_pair::PairRun`], a scene built without a drive) are each one
//! [`SceneRun`]. The run layer owns everything around a scene's own evaluation, the same for
//! both: the report folder written whole and renamed into place, a run at each of the scene's oil
//! temperatures (a folder each and their comparison at the top), a shard's folder with its
//! manifest and the digests of its record files, and the merge of shards into the report a single
//! run writes; and `gearloss render` reading each kind's report.json back ([`crate::rerender`]).

use std::path::Path;

use crate::evaluate::record_files::RecordFormats;
use crate::evaluate::Shard;
use crate::folder::ReportFolder;
use crate::model::Scene;
use crate::progress::Progress;
use crate::report::drive::DriveReport;
use crate::report::Report;
use crate::run_error::{FailureKind, RunError};
use crate::shard::{Manifest, ShardSet};

/// A file of a run in memory: its path in the report folder and its text.
pub(crate) type File = (String, String);

/// One run at an oil temperature, as the comparison of a sweep reads it: its label (`90 °C`), the
/// temperature (K), its folder (`oil_temperature_90degC`) and its report.
pub(crate) type OilRun<R> = (String, f64, String, R);

/// The labelled reports a run wrote (by their oil temperature's folder, else empty): a pair's, a
/// drive's (one of the two lists is empty).
pub(crate) type Labelled = (Vec<(String, Report)>, Vec<(String, DriveReport)>);

/// What a report.json read back draws: its files, and the folders inside its folder that hold
/// reports of their own.
pub(crate) type Redrawn = (Vec<File>, Vec<String>);

/// A kind of scene's evaluation, report and record files, run by the one run layer.
pub(crate) trait SceneRun {
    /// The report of one run (at one oil temperature).
    type Report: Clone;

    /// What a shard of the sweep holds in a sweep of several oil temperatures, refused: the kind
    /// of failure and what the scene is called (`the scene`, `the drive`).
    const SHARDED_SWEEP: (FailureKind, &'static str);

    /// The scene (at one oil temperature) in memory: its report and its files, the record files
    /// of the default formats among them.
    fn files(&self, scene: &Scene) -> Result<(Self::Report, Vec<File>), RunError>;

    /// The scene (at one oil temperature) into `folder` under `dir` (`""`: the top): its record
    /// files of `formats` as its sweep streams, then its report. The report and the files written.
    fn run_in_folder(
        &self,
        scene: &Scene,
        at: (&ReportFolder, &str),
        formats: RecordFormats,
        progress: &dyn Progress,
    ) -> Result<(Self::Report, Vec<String>), RunError>;

    /// The comparison of the runs at the scene's oil temperatures: the files at the top of the
    /// report folder.
    fn oil_sweep(&self, runs: &[OilRun<Self::Report>]) -> Result<Vec<File>, RunError>;

    /// The shard's part of the sweep: its record files of `formats` written into `folder` (their
    /// names) and its manifest (without the digests, which the run layer adds).
    fn shard_into(
        &self,
        scene: &Scene,
        source: (&str, &str),
        shard: Shard,
        into: (&ReportFolder, RecordFormats),
        progress: &dyn Progress,
    ) -> Result<(Vec<String>, Manifest), RunError>;

    /// The shards' record files concatenated into `folder` and the report a single run gives
    /// written there: the report and the files written.
    fn merge_into(
        &self,
        set: &ShardSet,
        scene: &Scene,
        folder: &ReportFolder,
        progress: &dyn Progress,
    ) -> Result<(Self::Report, Vec<String>), RunError>;

    /// What this kind's report.json is called (`a pair's report`) and the top-level fields only
    /// it has (a pair's `geometry`, a drive's `shafts`), read by `gearloss render`.
    const REPORT: (&'static str, &'static [&'static str]);
    /// The same of its comparison of oil temperatures (`runs`; a drive's with `rows`).
    const OIL_SWEEP: (&'static str, &'static [&'static str]);

    /// The files a report.json of this kind (`text`, in `dir`) draws again, and the folders in
    /// `dir` that hold reports of their own (a drive's stage meshes analysed as pairs alone);
    /// `bad` names what in the text is not this kind's report.
    fn redraw(dir: &Path, text: &str, bad: &dyn Fn(serde_json::Error) -> RunError) -> Result<Redrawn, RunError>;
    /// The same for its comparison of oil temperatures (the runs' folders inside it).
    fn redraw_oil_sweep(text: &str, bad: &dyn Fn(serde_json::Error) -> RunError) -> Result<Redrawn, RunError>;

    /// The reports of a run, labelled (by their oil temperature's folder, else empty), as
    /// [`crate::run::Written`] holds them.
    fn labelled(reports: Vec<(String, Self::Report)>) -> Labelled;
}
