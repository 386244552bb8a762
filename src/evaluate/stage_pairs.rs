//! The analyses of one pair on a drive's stages: each analysed stage's mesh (each mesh of a
//! planetary stage) becomes the problem of one mesh ([`MeshProblem`]) at the operating state the
//! drive's power walk gives it, and runs as that pair alone runs.
//!
//! At each analysed operating point the drive is solved under its first friction law and first
//! efficiency formulation (the row drive_records.csv holds first for that point). Each mesh is then
//! the pair with its **driving member in the pinion's place**, exactly the pair whose efficiency the
//! walk charged ([`super::drive_setup`]):
//!
//! - a parallel stage: its pinion drives in drive, its wheel in coast (the pair with the roles
//!   swapped); the pinion's torque is |T| of the driving gear into the mesh, its speed the driving
//!   gear's |ω|;
//! - a planetary stage: the sun–planet pair with the sun or the planet in the pinion's place (the
//!   one that drives the meshes), and the planet–ring pair with the planet as pinion whichever
//!   drives (as the walk evaluates it); each at the pinion's torque per planet and its speed in the
//!   carrier's frame.
//!
//! The lubricant is the scene's at its oil temperature, the laws, the `dynamics` block and the
//! analyses of one pair are the scene's; the drive's efficiency formulations are the pair's. So a
//! stage's pair reports what the same pair written alone with `pinion_torque` and `pinion_speed` at
//! those values reports (tests/it/stage_pairs.rs holds the two to 1e-12).

use super::drive_setup::DriveSetup;
use crate::drive::{EndValue, Member};
use crate::mesh::MeshProblem;
use crate::model::{Analyses, GearPair, Operating, Scene, SceneDrive, Sweep};

/// One mesh of an analysed stage at one of the drive's operating points, or over the whole sweep
/// (a one-pair drive's stage).
#[derive(Debug, Clone)]
pub struct StagePair {
    /// The stage's index and name.
    pub stage: usize,
    pub stage_name: String,
    /// A planetary stage's mesh: `sun–planet` or `planet–ring`; None for a parallel stage.
    pub mesh: Option<&'static str>,
    /// The drive's operating point the mesh was analysed at and its state there; None for the stage
    /// of a scene of one pair, analysed over the scene's whole sweep (`one_pair_sweep`).
    pub at: Option<MeshAtPoint>,
    /// The gears in the pinion's and the wheel's places (`wheel`, `pinion` in coast; `planet`,
    /// `ring` for the planet–ring mesh whichever drives, as the walk evaluates it).
    pub members: [&'static str; 2],
    /// The pair alone at that state; None where no torque or no speed goes through the mesh.
    pub problem: Option<MeshProblem>,
}

/// A mesh's state at one of the drive's operating points, from the drive's walk.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshAtPoint {
    /// The drive's operating point (0-based, torque-major) and its torque and speed indices.
    pub point: usize,
    pub torque_index: usize,
    pub speed_index: usize,
    /// The pinion's torque (N·m) and speed (rad/s) from the drive's walk.
    pub pinion_torque: f64,
    pub pinion_speed: f64,
    /// The mesh's efficiency the walk charged at this point (first law and formulation).
    pub mesh_efficiency: f64,
}

/// Every analysed stage's meshes at every analysed point (`detail_points`, else the first point),
/// point-major; empty when the scene asks for no analysis of one pair. A scene of one pair's stage is
/// its pair alone over the scene's whole sweep (`one_pair_sweep`).
pub fn stage_pairs(scene: &Scene, drive: &SceneDrive) -> Vec<StagePair> {
    let a = &scene.analyses;
    if drive.one_pair {
        if let Some(p) = one_pair_sweep(scene, drive) {
            return vec![p];
        }
    }
    if !a.runs_stage_pairs(!scene.operating.detail_points.is_empty()) || scene.operating.count() == 0 {
        return Vec::new();
    }
    let setup = DriveSetup::new(scene, drive);
    let op = &scene.operating;
    let points = if op.detail_points.is_empty() { vec![0] } else { op.detail_points.clone() };
    let speeds = op.pinion_speed.values.len();
    let ends = setup.operating_ends();
    let mut out = Vec::new();
    for point in points {
        let (torque_index, speed_index) = (point / speeds, point % speeds);
        let torque = EndValue { at: ends.torque_at, value: op.pinion_torque.values[torque_index].value };
        let speed = EndValue { at: ends.speed_at, value: op.pinion_speed.values[speed_index].value };
        let solved = setup.first_law_point(a.first_formulation(), torque, speed);
        for (k, s) in solved.stages.iter().enumerate() {
            if !a.analyses_stage(&s.name) {
                continue;
            }
            for m in drive.layout.stages[k].mesh_states(s) {
                let title = format!(
                    "{}: {}{}, point {}",
                    scene.title,
                    s.name,
                    m.name.map_or_else(String::new, |name| format!(" {name}")),
                    point + 1
                );
                // The mesh's pair with the gear the walk evaluated in the pinion's place (a ring
                // driving an internal pair: the pinion, at the same power; StageModel::mesh_states).
                let pair = drive.mesh_pair(k, m.mesh);
                let pair = match m.driving {
                    Member::Pinion => pair.clone(),
                    Member::Wheel => pair.swapped(),
                };
                let alone = (m.torque > 0.0 && m.speed > 0.0)
                    .then(|| mesh_problem(scene, title, pair, Some((m.torque, m.speed))));
                out.push(StagePair {
                    stage: k,
                    stage_name: s.name.clone(),
                    mesh: m.name,
                    at: Some(MeshAtPoint {
                        point,
                        torque_index,
                        speed_index,
                        pinion_torque: m.torque,
                        pinion_speed: m.speed,
                        mesh_efficiency: m.efficiency,
                    }),
                    members: m.members,
                    problem: alone,
                });
            }
        }
    }
    out
}

/// The stage of a scene of one pair (its one-stage drive, `pinion_torque` at the pinion gear) over the
/// scene's whole sweep: at every operating point the stage's pinion drives at the scene's own torque
/// and speed (the walk raises only the input's torque by the pinion shaft's losses,
/// [`super::drive_setup`]), so the states of its mesh are the scene's own grid and its pair alone
/// is one mesh problem over that grid: the scene's pair, oil, laws, operating block (its points in full
/// and its detail points as written) and analyses of one pair and of efficiency, without what the
/// drive evaluates itself (the gearbox's loss budget, the housing's thermal balance, the duty cycle,
/// the efficiency map, the oil at its balance, a sweep of oil temperatures). It is run whatever the
/// scene asks for, as a pair always reports its geometry and contact. None where the stage is not
/// analysed (`stages = [...]`), the scene has no operating point, or a point's pinion does not
/// drive (a torque or speed that is not positive: the stage is then analysed point by point).
pub(crate) fn one_pair_sweep(scene: &Scene, drive: &SceneDrive) -> Option<StagePair> {
    let op = &scene.operating;
    let name = &drive.layout.stages.first()?.name;
    let positive =
        op.pinion_torque.values.iter().all(|t| t.value > 0.0) && op.pinion_speed.values.iter().all(|w| w.value > 0.0);
    if drive.layout.stages.len() != 1 || !scene.analyses.analyses_stage(name) || op.count() == 0 || !positive {
        return None;
    }
    let alone = mesh_problem(scene, format!("{}: {name}", scene.title), drive.mesh_pair(0, 0).clone(), None);
    Some(StagePair {
        stage: 0,
        stage_name: name.clone(),
        mesh: None,
        at: None,
        members: ["pinion", "wheel"],
        problem: Some(alone),
    })
}

/// The problem of `pair` alone at the pinion's torque (N·m) and speed (rad/s), shown in the units the
/// drive's operating block writes its speeds in; None: over the scene's own operating block.
fn mesh_problem(scene: &Scene, title: String, pair: GearPair, state: Option<(f64, f64)>) -> MeshProblem {
    let op = &scene.operating;
    let (pinion_torque, pinion_speed, detail_points) = match state {
        Some(state) => {
            let (torque, speed) = at_state(op, state);
            (torque, speed, Vec::new())
        }
        None => (op.pinion_torque.clone(), op.pinion_speed.clone(), op.detail_points.clone()),
    };
    let a = &scene.analyses;
    MeshProblem {
        title,
        gears: pair,
        lubricant: scene.lubricant.clone(),
        operating: Operating {
            pinion_torque,
            pinion_speed,
            oil_temperature: op.oil_temperature.clone(),
            oil_temperatures: None,
            detail_points,
            equilibrium: None,
        },
        friction: scene.friction.clone(),
        dynamics: scene.dynamics.clone(),
        analyses: Analyses {
            efficiency: a.efficiency.clone(),
            friction_along_loa: a.friction_along_loa,
            film: a.film,
            film_span: a.film_span,
            dynamics: a.dynamics,
            stability_map: a.stability_map.clone(),
            numerics: a.numerics,
            dynamics_span: a.dynamics_span,
            friction_span: a.friction_span,
            transmission_error: a.transmission_error.clone(),
            ..Analyses::default()
        },
    }
}

/// One torque (N·m) and one speed (rad/s) as the operating block's sweeps, the speed in its unit.
fn at_state(
    op: &Operating,
    (torque, speed): (f64, f64),
) -> (Sweep<crate::model::Torque>, Sweep<crate::model::AngularVelocity>) {
    let torque_sweep = Sweep {
        values: vec![crate::model::Torque::new::<uom::si::torque::newton_meter>(torque)],
        unit: "N*m".to_string(),
        factor: 1.0,
        written_values: vec![shown(torque)],
        span: op.pinion_torque.span,
    };
    let speeds = &op.pinion_speed;
    let speed_sweep = Sweep {
        values: vec![crate::model::AngularVelocity::new::<uom::si::angular_velocity::radian_per_second>(speed)],
        unit: speeds.unit.clone(),
        factor: speeds.factor,
        written_values: vec![shown(speed / speeds.factor)],
        span: speeds.span,
    };
    (torque_sweep, speed_sweep)
}

/// A value as the pair's report shows it "as written": to 12 significant digits where that is the
/// value but for the last bits of a unit's conversion (3900 rpm, not 3899.9999999999995), else in
/// full. The scene's SI value is the walk's, untouched.
fn shown(x: f64) -> f64 {
    let rounded: f64 = format!("{x:.11e}").parse().unwrap_or(x);
    if (rounded - x).abs() <= 1e-14 * x.abs() {
        rounded
    } else {
        x
    }
}
