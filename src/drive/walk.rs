//! The power walk through the drive and its fixed point (README, "Several stages").
//!
//! Walking from the source to the sink, a shaft passes on the power it receives less its own
//! losses (its bearings, its seals, the churning and jet impulse of the stages whose pinion it
//! carries, each gear's windage); a stage passes on η_mesh times what its driving gear puts in
//! (driven torque = driving torque × z_driven/z_driving × η_mesh). Bearing losses depend on the bearing loads, which depend on every
//! mesh force on the shaft, which depend on the torques: the walk is repeated, the loads taken from
//! the previous pass, until no torque moves by more than [`TOLERANCE`] relative. Given the sink's
//! torque (a vehicle's wheel in drive, the motor's brake torque in coast), the walk runs back from
//! the sink: a stage's driving gear must put in what its driven gear passes on over η_mesh, η read
//! at the previous pass's driving torque.

use super::forces::{GearLoad, MeshForceSizes};
use super::layout::{Drive, Member, ShaftEnd};
use super::mesh_efficiency::MeshEfficiency;
use super::pass::Pass;
use super::point::{BearingPoint, DrivePoint, PowerFlow};
use super::shaft_bending::{support_reactions, ShaftBending};
pub use super::speeds::{overall_ratio, shaft_speeds, EndValue};
use super::walk_parts::{shaft_parts, FixedLosses, Statics};
use crate::losses::parts::catalog::add_parts;
use crate::losses::parts::{PartLosses, PartState, StageGears};
use crate::losses::Oil;

/// The fixed point stops when no torque moves by more than this, relative to the largest.
pub const TOLERANCE: f64 = 1e-12;
/// Passes before the walk gives up (the report then says how far it got).
use super::point::MAX_PASSES;
/// A pass whose largest driving torque exceeds the first pass's this many times diverges.
const DIVERGED: f64 = 1e3;

/// What the supports of every shaft carry at one pass: each shaft's bearing losses (W), its
/// places, every gear's load and each shaft's bending (when asked and it has sections).
pub(super) struct Supported {
    pub(super) powers: Vec<f64>,
    pub(super) places: Vec<Vec<BearingPoint>>,
    pub(super) loads: Vec<GearLoad>,
    pub(super) bending: Vec<Option<ShaftBending>>,
}

/// The drive with what its walk reads: the stages' sizes (in stage order) and the oil.
pub struct DriveModel<'a> {
    pub drive: &'a Drive,
    pub sizes: &'a [MeshForceSizes],
    pub oil: &'a Oil,
    /// Each shaft's beam made ready ([`super::shaft_bending::shaft_beam_of`]; None: a rigid beam,
    /// or made at each pass).
    pub beams: &'a [Option<super::shaft_beam::PreparedBeam>],
}

/// The drive at one operating point: speeds by the kinematics, the power walked through until the
/// bearing loads settle.
pub fn solve(model: &DriveModel, meshes: &dyn MeshEfficiency, torque: EndValue, speed: EndValue) -> DrivePoint {
    solve_from(model, meshes, (torque, speed), None)
}

/// [`solve`] with the first pass's bearing losses (W, per shaft) `seed` where they are known (else
/// none): a one-pair drive at a given pinion torque knows them (`shaft_losses_at` at that torque,
/// the input raised by the pinion shaft's own losses), and its first pass, which puts that torque
/// on the mesh but for rounding, is then its fixed point: the bearings' loads are the mesh's forces
/// at that torque, which the pass does not move. The point says it took one pass.
pub(crate) fn solve_from(
    model: &DriveModel,
    meshes: &dyn MeshEfficiency,
    (torque, speed): (EndValue, EndValue),
    seed: Option<Seed>,
) -> DrivePoint {
    let omega = shaft_speeds(model.drive, speed);
    let (walk, from_source, given_power) = Walk::given(model, &omega, torque);
    let seeded = seed.is_some();
    let (fixed, mut loads) = match seed {
        Some(Seed { fixed, bearings, .. }) => (fixed, bearings),
        None => (walk.fixed_losses(model), vec![0.0; model.drive.shafts.len()]),
    };
    let mut state = walk.pass(meshes, from_source, given_power, &fixed, &loads, None);
    let first = state.largest_torque();
    let mut passes = 1;
    let mut diverged = false;
    while !(seeded && state.is_finite()) {
        loads = walk.bearing_powers(model, &state.driving_torque, false).powers;
        let next = walk.pass(meshes, from_source, given_power, &fixed, &loads, Some(&state.driving_torque));
        passes += 1;
        if !next.is_finite() || next.largest_torque() > DIVERGED * first {
            // The walk diverges: the bearing losses grow faster than the torque that loads them (a
            // gear far outside its bearings' span). Keep the last pass before, reported unsettled.
            passes = MAX_PASSES;
            diverged = true;
            break;
        }
        let moved = state.moved(&next);
        state = next;
        if moved <= TOLERANCE || passes >= MAX_PASSES {
            break;
        }
    }
    let mut point = walk.point(model, &state, &fixed, passes);
    point.diverged = diverged;
    point.books_gap = point.books_gap_of();
    point
}

/// What a walk that reached given driving torques charges each shaft, found without walking (the
/// losses depend on the mesh forces, which the driving torques fix): its bearings' losses, its
/// seals' and its gears' no-load parts ([`shaft_losses_at`]); [`solve_from`] starts from it.
pub(crate) struct Seed {
    pub(super) fixed: FixedLosses,
    pub(super) bearings: Vec<f64>,
}

impl Seed {
    /// Shaft `j`'s own losses (W): its bearings, its seals, its gears' no-load parts.
    pub(crate) fn own(&self, j: usize) -> f64 {
        self.fixed.own(j, self.bearings[j])
    }
}

/// Each shaft's losses when the stages' driving members (in drive, from the input) put
/// `driving_torques` (N·m, in stage order) into their meshes at `speed`.
pub(crate) fn shaft_losses_at(model: &DriveModel, speed: EndValue, driving_torques: &[f64]) -> Seed {
    let omega = shaft_speeds(model.drive, speed);
    let walk = Walk::new(model, &omega, PowerFlow::Drive);
    let fixed = walk.fixed_losses(model);
    let bearings = walk.bearing_powers(model, driving_torques, false).powers;
    Seed { fixed, bearings }
}

/// The order of the power flow: shafts from source to sink, and between each two the stage with
/// its driving member.
pub(super) struct Walk<'a> {
    pub(super) drive: &'a Drive,
    pub(super) omega: &'a [f64],
    pub(super) flow: PowerFlow,
    pub(super) shafts: Vec<usize>,
    pub(super) steps: Vec<(usize, Member)>,
}

impl<'a> Walk<'a> {
    /// The walk with `torque` given at an end, at the shafts' speeds `omega`: its direction
    /// (coast when the torque is negative), whether it starts from the source, and the power given
    /// (W).
    pub(super) fn given(model: &DriveModel<'a>, omega: &'a [f64], torque: EndValue) -> (Walk<'a>, bool, f64) {
        let drive = model.drive;
        let flow = if torque.value < 0.0 { PowerFlow::Coast } else { PowerFlow::Drive };
        let from_source = (flow == PowerFlow::Drive) == (torque.at == ShaftEnd::Input);
        let given_shaft = if torque.at == ShaftEnd::Input { drive.input } else { drive.output };
        let given_power = torque.value.abs() * omega[given_shaft].abs();
        (Walk::new(model, omega, flow), from_source, given_power)
    }

    fn new(model: &DriveModel<'a>, omega: &'a [f64], flow: PowerFlow) -> Walk<'a> {
        let drive = model.drive;
        let mut shafts = drive.shaft_order();
        let mut steps: Vec<(usize, Member)> = drive.chain.clone();
        if flow == PowerFlow::Coast {
            shafts.reverse();
            steps = steps.into_iter().rev().map(|(k, m)| (k, m.other())).collect();
        }
        Walk { drive, omega, flow, shafts, steps }
    }

    /// The speeds of stage `k`'s two places (rad/s, signed).
    pub(super) fn places(&self, k: usize) -> [f64; 2] {
        self.drive.stages[k].places.map(|p| self.omega[p.shaft])
    }

    fn fixed_losses(&self, model: &DriveModel) -> FixedLosses {
        let drive = model.drive;
        let shafts = shaft_parts(drive, self.omega, &[]);
        let stages: Vec<StageGears> = drive
            .stages
            .iter()
            .zip(model.sizes)
            .enumerate()
            .map(|(k, (stage, sizes))| {
                let (place, running) = stage.model().gears_running(stage, sizes, self.places(k));
                let shafts = [stage.places[place].shaft, stage.places[1 - place].shaft];
                StageGears { lubrication: stage.lubrication.as_ref(), running, shafts }
            })
            .collect();
        let mut out = PartLosses::new(shafts.len(), stages.len(), false);
        add_parts(&PartState { shafts: &shafts, stages: &stages }, model.oil, false, &mut out);
        FixedLosses(out)
    }

    /// One walk with the shafts' bearing losses `bearings` (W): from the source when the source's
    /// power is given, else back from the sink (η at `previous` driving torques when known).
    pub(super) fn pass(
        &self,
        meshes: &dyn MeshEfficiency,
        from_source: bool,
        given: f64,
        fixed: &FixedLosses,
        bearings: &[f64],
        previous: Option<&[f64]>,
    ) -> Pass {
        let n = self.omega.len();
        let stages = fixed.stage_no_load().len();
        let mut p = Pass {
            received: vec![0.0; n],
            passed: vec![0.0; n],
            driving_torque: vec![0.0; stages],
            efficiency: vec![1.0; stages],
            mesh_loss: vec![0.0; stages],
            kind_state: vec![None; stages],
        };
        let own = |j: usize| fixed.own(j, bearings[j]);
        // What the stage's kind keeps of the pass is kept for the report's point.
        let mut eta = |k: usize, m: Member, torque: f64, speed: f64| {
            let stage = &self.drive.stages[k];
            let (efficiency, state) = stage.model().efficiency((k, stage), meshes, (m, torque, speed), self.places(k));
            p.kind_state[k] = state;
            efficiency
        };
        if from_source {
            let mut power = given;
            for (i, &j) in self.shafts.iter().enumerate() {
                p.received[j] = power;
                p.passed[j] = power - own(j);
                power = p.passed[j];
                if let Some(&(k, m)) = self.steps.get(i) {
                    let speed = self.omega[j].abs();
                    p.driving_torque[k] = power / speed;
                    p.efficiency[k] = eta(k, m, p.driving_torque[k], speed);
                    p.mesh_loss[k] = power.abs() * (1.0 - p.efficiency[k]);
                    power -= p.mesh_loss[k];
                }
            }
        } else {
            let mut power = given;
            for (i, &j) in self.shafts.iter().enumerate().rev() {
                p.passed[j] = power;
                p.received[j] = power + own(j);
                power = p.received[j];
                if i > 0 {
                    let (k, m) = self.steps[i - 1];
                    let from = self.shafts[i - 1];
                    let speed = self.omega[from].abs();
                    let guess = previous.map_or(power / speed, |t| t[k]);
                    p.efficiency[k] = eta(k, m, guess, speed);
                    let put_in = power / p.efficiency[k];
                    p.mesh_loss[k] = put_in - power;
                    p.driving_torque[k] = put_in / speed;
                    power = put_in;
                }
            }
        }
        p
    }

    /// The mesh forces of every stage at the driving torques `torques`.
    fn gear_loads(&self, model: &DriveModel, torques: &[f64]) -> Vec<GearLoad> {
        self.steps
            .iter()
            .flat_map(|&(k, m)| {
                let stage = &model.drive.stages[k];
                stage.model().member_loads((k, stage), &model.sizes[k], (m, torques[k]), self.places(k))
            })
            .collect()
    }

    /// Each shaft's bearing losses (W), its gears' loads and, for the point (`point`), its places
    /// and its bending at the driving torques `torques` (a pass needs the powers alone).
    pub(super) fn bearing_powers(&self, model: &DriveModel, torques: &[f64], point: bool) -> Supported {
        let drive = model.drive;
        let n = drive.shafts.len();
        let (out, Statics { reactions, bending, loads }) = self.loaded_parts(model, torques, (point, point));
        let mut powers: Vec<f64> = (0..n).map(|j| out.shaft_total(j)).collect();
        let mut places: Vec<Vec<BearingPoint>> = match out.places {
            Some(kept) => drive
                .shafts
                .iter()
                .zip(kept.into_iter().zip(reactions))
                .map(|(shaft, (kept, reactions))| {
                    (shaft.bearings.iter().enumerate().zip(kept.into_iter().zip(reactions)))
                        .map(|((i, bearing), (l, reaction))| BearingPoint {
                            kind: bearing.kind.name().to_string(),
                            count: bearing.count,
                            position: bearing.position,
                            locating: i == shaft.locating,
                            reaction,
                            radial_load: l.radial_load,
                            axial_load: l.axial_load,
                            no_load: l.no_load,
                            load: l.load.unwrap_or(0.0),
                            of_stage_members: false,
                        })
                        .collect()
                })
                .collect(),
            None => vec![Vec::new(); n],
        };
        for &(k, m) in &self.steps {
            let stage = &model.drive.stages[k];
            if let Some((j, b)) = stage.model().member_bearings(stage, (m, torques[k]), self.places(k), model.oil) {
                powers[j] += b.no_load + b.load;
                if point {
                    places[j].push(b);
                }
            }
        }
        Supported { powers, places, loads, bending }
    }

    /// The catalogue's parts that read loads on every shaft at the driving torques `torques`, each
    /// bearing place kept (`keep`) or not, with the statics they rest on (each shaft's bending
    /// with them: `bent`).
    fn loaded_parts(&self, model: &DriveModel, torques: &[f64], (keep, bent): (bool, bool)) -> (PartLosses, Statics) {
        let drive = model.drive;
        let loads = self.gear_loads(model, torques);
        let n = drive.shafts.len();
        let mut reactions = vec![Vec::new(); n];
        let mut bending = vec![None; n];
        let mut place_loads = vec![Vec::new(); n];
        for (j, shaft) in drive.shafts.iter().enumerate().filter(|(_, s)| !s.bearings.is_empty()) {
            let on: Vec<GearLoad> = loads.iter().filter(|l| l.shaft == j).copied().collect();
            let beam = model.beams.get(j).and_then(Option::as_ref);
            let (r, bent_shaft) = support_reactions(shaft, &on, bent, beam);
            place_loads[j] = shaft
                .bearings
                .iter()
                .zip(&r)
                .map(|(b, r)| [r[0].hypot(r[1]) / b.count as f64, r[2].abs() / b.count as f64])
                .collect();
            reactions[j] = r;
            bending[j] = bent_shaft;
        }
        let shafts = shaft_parts(drive, self.omega, &place_loads);
        let mut out = PartLosses::new(n, 0, keep);
        add_parts(&PartState { shafts: &shafts, stages: &[] }, model.oil, true, &mut out);
        (out, Statics { reactions, bending, loads })
    }
}
