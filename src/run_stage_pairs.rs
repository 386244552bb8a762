//! The analyses of one pair on a drive's stages, run: each analysed mesh's scene of one pair
//! ([`crate::evaluate::stage_pairs`]) run as a pair alone runs ([`crate::run_pair`]), its files
//! under `stages/…` in the drive's report folder, and the drive report's rows that say what each
//! ran at and where its report is. In memory ([`stage_pair_files`]) or into the run's folder
//! ([`stage_pairs_into`]: each pair's record files streamed in the run's formats as its sweep runs,
//! so a one-pair drive's whole sweep is never held in memory).

use crate::efficiency::charges_iso_mesh_loss;
use crate::evaluate::record_files::RecordFormats;
use crate::evaluate::stage_pairs::{one_pair_sweep, stage_pairs};
use crate::evaluate::{Shard, Tally};
use crate::folder::ReportFolder;
use crate::mesh::MeshProblem;
use crate::model::{Scene, SceneDrive};
use crate::progress::Progress;
use crate::report::drive_stage_pairs::{folder as folder_of, StagePairReport};
use crate::report::Report;
use crate::run_error::RunError;
use crate::scene::lower_stage_analyses::check_pair_at_state;
use crate::shard::ShardSet;

/// The rows for the drive's report and the files of every analysed mesh's report (paths under the
/// drive's folder).
pub(crate) type StagePairFiles = (Vec<StagePairReport>, Vec<(String, String)>);

/// The analysed meshes' reports, labelled by their folders (`stages/pair`).
pub(crate) type StagePairReports = Vec<(String, Report)>;

/// Every analysed mesh run as a pair alone, in memory: the rows and the files.
pub(crate) fn stage_pair_files(
    scene: &Scene,
    drive: &SceneDrive,
) -> Result<(StagePairFiles, StagePairReports), RunError> {
    let mut files = Vec::new();
    let (rows, reports) = stage_pair_rows(scene, drive, |alone, dir| {
        let (report, _, run_files) = crate::run_pair::run_mesh_exact(alone)?;
        files.extend(run_files.into_iter().map(|(f, c)| (format!("{dir}/{f}"), c)));
        Ok(report)
    })?;
    Ok(((rows, files), reports))
}

/// Every analysed mesh run as a pair alone into `folder` under the run's `dir` (`""`: the top),
/// its record files of `formats` streamed: the rows, the files written and the reports.
pub(crate) fn stage_pairs_into(
    scene: &Scene,
    drive: &SceneDrive,
    (folder, dir): (&ReportFolder, &str),
    formats: RecordFormats,
    progress: &dyn Progress,
) -> Result<(Vec<StagePairReport>, Vec<String>, StagePairReports), RunError> {
    let mut files = Vec::new();
    let (rows, reports) = stage_pair_rows(scene, drive, |alone, pair_dir| {
        let at = crate::folder::in_dir(dir, pair_dir);
        let (report, _, written) = crate::run_pair::run_in_folder_exact(alone, (folder, &at), formats, progress)?;
        files.extend(written);
        Ok(report)
    })?;
    Ok((rows, files, reports))
}

/// A shard's part of a one-pair drive's stage analysed over the sweep: its folder and tally (None
/// where there is none) and its record files.
pub(crate) type ShardedStage = (Option<(String, Tally)>, Vec<String>);

/// A scene of one pair run as its one-stage drive, sharded: its stage's pair, analysed over the
/// scene's whole sweep, run as a pair's shard into the shard's folder. Its folder and tally (for
/// the manifest) and its record files; none where the stage is not analysed so (another stage
/// analysis runs at the merge, on the drive's points).
pub(crate) fn stage_pair_shard(
    scene: &Scene,
    drive: &SceneDrive,
    shard: Shard,
    (folder, formats): (&ReportFolder, RecordFormats),
    progress: &dyn Progress,
) -> Result<ShardedStage, RunError> {
    let Some(p) = one_pair_sweep(scene, drive) else { return Ok((None, Vec::new())) };
    let Some(alone) = p.problem.as_ref().filter(|a| check_pair_at_state(a).is_empty()) else {
        return Ok((None, Vec::new()));
    };
    let dir = folder_of(&p.stage_name, p.mesh, None);
    let (tally, files) = crate::run_pair::shard_in_folder(alone, shard, (folder, &dir), formats, progress)?;
    Ok((Some((dir, tally)), files))
}

/// Every analysed mesh run as a pair alone into the merged `folder`: the stage the shards analysed
/// ([`stage_pair_shard`]) merged from theirs, every other run here in the formats the shards wrote
/// the drive's records in. The rows, the files written and the reports.
pub(crate) fn stage_pairs_merged(
    scene: &Scene,
    drive: &SceneDrive,
    set: &ShardSet,
    folder: &ReportFolder,
    progress: &dyn Progress,
) -> Result<(Vec<StagePairReport>, Vec<String>, StagePairReports), RunError> {
    let sharded = set.stage_pair();
    let formats = set.formats::<crate::evaluate::drive_records::DriveRecords>();
    let mut files = Vec::new();
    let (rows, reports) = stage_pair_rows(scene, drive, |alone, dir| {
        let (report, _, written) = match &sharded {
            Some((shards, d)) if *d == dir => crate::run_pair::merge_in_folder(shards, alone, (folder, dir), progress)?,
            _ => crate::run_pair::run_in_folder_exact(alone, (folder, dir), formats, progress)?,
        };
        files.extend(written);
        Ok(report)
    })?;
    Ok((rows, files, reports))
}

/// The drive report's rows of every analysed mesh, each mesh's pair run by `run(its scene, its
/// folder)`, which gives its report as built; a mesh whose pair a scene of one pair would refuse at
/// that state (dynamics at too low a speed, too many record rows) is listed with the reason, not run.
/// The rows and the reports run, labelled by their folders.
fn stage_pair_rows(
    scene: &Scene,
    drive: &SceneDrive,
    mut run: impl FnMut(&MeshProblem, &str) -> Result<Report, RunError>,
) -> Result<(Vec<StagePairReport>, StagePairReports), RunError> {
    let formulation = scene.analyses.first_formulation();
    let law = scene.friction.first().map_or_else(String::new, |l| l.label());
    let (mut rows, mut reports) = (Vec::new(), Vec::new());
    for p in stage_pairs(scene, drive) {
        let mut row = StagePairReport {
            stage: p.stage_name.clone(),
            mesh: p.mesh.map(str::to_string),
            point: p.at.map(|at| at.point + 1),
            point_words: p.at.map_or_else(
                || "every operating point (the scene's own sweep)".to_string(),
                |at| crate::report::drive::point_words(scene, drive, at.torque_index, at.speed_index),
            ),
            law: law.clone(),
            formulation: formulation.name().to_string(),
            pinion: p.members[0].to_string(),
            wheel: p.members[1].to_string(),
            pinion_torque: p.at.map(|at| at.pinion_torque),
            pinion_speed_rpm: p.at.map(|at| at.pinion_speed * 30.0 / std::f64::consts::PI),
            mesh_efficiency: p.at.map(|at| at.mesh_efficiency),
            pair_mean_efficiency: None,
            pair_charged_efficiency: None,
            folder: None,
            not_run: None,
        };
        if let Some(alone) = &p.problem {
            let refused = check_pair_at_state(alone);
            if let Some(d) = refused.first() {
                row.not_run = Some(d.reason.clone());
            } else {
                let dir = folder_of(&p.stage_name, p.mesh, p.at.map(|at| at.point));
                let report = run(alone, &dir)?;
                let one_point = p.at.is_some();
                if let Some(r) = report.efficiency.iter().find(|r| one_point && r.formulation == formulation) {
                    let charged = match &r.ohlendorf {
                        Some(o) if charges_iso_mesh_loss(r.law, &alone.mesh().geometry()) => o.power_loss.value.0,
                        _ => r.power_loss.value.0,
                    };
                    row.pair_mean_efficiency = Some(r.mean_efficiency.0);
                    row.pair_charged_efficiency =
                        Some(1.0 - charged / (r.pinion_torque.value.0 * r.pinion_speed.value.0));
                }
                row.folder = Some(dir.clone());
                reports.push((dir, report));
            }
        }
        rows.push(row);
    }
    Ok((rows, reports))
}
