//! A warning where a stage's gear churning is read beyond the speeds its model was measured at:
//! Mauz's dip churning (ISO/TR 14179-2:2001, from Mauz 1987) was tested up to a pitch-line speed of
//! 60 m/s ([`crate::losses::gear_no_load`]); above it P_VZ0 is extrapolated.
//!
//! One check for every scene, on its drive (a scene of one pair: its one-stage drive). Every shaft
//! turns in proportion to the end the speeds are given at, so a stage's v_t is largest at the
//! fastest speed the scene turns the drive at: its operating points, its efficiency map's speeds
//! and, on a drive cycle, the output's speed at each piece's ends (a piece's speed is linear in
//! time). v_t is the speed the churning is read at, ω r of the body [`crate::drive::stage_model`]'s
//! `gears_running` names (a parallel stage's pinion at its working pitch radius, a planetary
//! stage's carrier disc or sun).

use super::finding::{Finding, Severity};
use crate::drive::walk::{shaft_speeds, EndValue};
use crate::drive::{MeshForceSizes, ShaftEnd};
use crate::model::{Scene, SceneDrive};

/// The warnings of the stages whose dip churning is read above 60 m/s, each at its fastest v_t;
/// `cycle_output_speeds` (rad/s): the output's speeds a drive cycle reaches (empty without one).
pub(crate) fn churning_findings(scene: &Scene, cycle_output_speeds: &[f64]) -> Vec<Finding> {
    let Some(drive) = scene.drive.as_ref().filter(|d| d.layout.stages.iter().any(|s| s.lubrication.is_some())) else {
        return Vec::new();
    };
    let at = drive.layout.operating.speed_at;
    let map_speeds = scene.analyses.efficiency_map.iter().flat_map(|(_, s)| s.values.iter());
    let given = scene.operating.pinion_speed.values.iter().chain(map_speeds).map(|w| EndValue { at, value: w.value });
    let cycle = cycle_output_speeds.iter().map(|&value| EndValue { at: ShaftEnd::Output, value });
    // Every shaft's speed at each of those ends, found once for all stages.
    let omegas: Vec<Vec<f64>> = given.chain(cycle).map(|end| shaft_speeds(&drive.layout, end)).collect();
    let mut out = Vec::new();
    for (k, stage) in drive.layout.stages.iter().enumerate() {
        let Some(lubrication) = stage.lubrication.as_ref() else { continue };
        let v_t = fastest_pitch_line_speed(drive, k, &omegas);
        if let Some(note) = lubrication.note(v_t) {
            let message = if drive.one_pair { note } else { format!("stage `{}`: {note}", stage.name) };
            out.push(Finding { severity: Severity::Warning, message });
        }
    }
    out
}

/// The largest v_t = ω r (m/s) stage `k`'s churning is read at over the shafts' speeds `omegas`
/// (rad/s, one set a speed the scene turns the drive at).
fn fastest_pitch_line_speed(drive: &SceneDrive, k: usize, omegas: &[Vec<f64>]) -> f64 {
    let stage = &drive.layout.stages[k];
    let sizes = MeshForceSizes::of(&drive.mesh(k, None).geometry());
    omegas
        .iter()
        .map(|omega| {
            let (_, running) = stage.model().gears_running(stage, &sizes, stage.places.map(|p| omega[p.shaft]));
            running.omega[0].abs() * running.pitch_radius[0]
        })
        .fold(0.0, f64::max)
}
