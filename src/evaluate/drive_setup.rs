//! What every point of a drive's evaluation reads: each stage's mesh from its own pair (a
//! [`crate::mesh::Mesh`], never the scene) as each member driving sees it, the forces' sizes, the
//! oil; and one point, or a block of a grid's rows, solved ([`crate::drive::solve`]).
//!
//! Where a stage's wheel drives (coast), its mesh is evaluated as the pair with the roles swapped:
//! the wheel in the pinion's place, so approach and recess exchange (Ohlendorf's H_V is symmetric
//! in ε₁, ε₂); the efficiency of a law at a driving torque T and speed ω is 1 − P_mesh/(T ω), with
//! P_mesh the mesh loss the budget of one pair charges ([`crate::efficiency::charged_mesh_loss`]).

use super::setup::law_at;
use super::stage_mesh::{LawMeshes, MeshMemo, RingMesh, StageMesh, WholeMeshes};
use crate::drive::walk::{DriveModel, Seed};
use crate::drive::{solve, DrivePoint, EndValue, Member, MeshEfficiency, MeshForceSizes, ShaftEnd};
use crate::efficiency::Formulation;
use crate::friction::LawContext;
use crate::model::{FrictionLawSpec, Scene, SceneDrive};

/// One operating point, law and formulation of a drive.
#[derive(Debug, Clone)]
pub struct DriveRow {
    pub torque_index: usize,
    pub speed_index: usize,
    pub law_index: usize,
    pub formulation: Formulation,
    pub point: DrivePoint,
    /// At `oil_temperature = equilibrium`: the row's own balance θ*, where it was evaluated (at
    /// ambient when it has none); None at a given oil temperature.
    pub balance: Option<crate::thermal::Balance>,
}

/// What every point of a drive reads.
pub(crate) struct DriveSetup<'a> {
    scene: &'a Scene,
    drive: &'a SceneDrive,
    stages: Vec<StageMesh>,
    sizes: Vec<MeshForceSizes>,
    oil: crate::losses::Oil,
    /// Each shaft's beam made ready once (a shaft with sections).
    beams: Vec<Option<crate::drive::shaft_beam::PreparedBeam>>,
}

impl<'a> DriveSetup<'a> {
    pub(crate) fn new(scene: &'a Scene, drive: &'a SceneDrive) -> DriveSetup<'a> {
        let stages: Vec<StageMesh> =
            (0..drive.pairs.len()).map(|k| StageMesh::of(drive, k, scene.lubricant.as_ref())).collect();
        let sizes = stages.iter().map(StageMesh::sizes).collect();
        let oil = drive.mesh(0, scene.lubricant.as_ref()).budget_oil(&stages[0].tribology);
        let beams = crate::drive::shaft_bending::prepared_beams(&drive.layout);
        DriveSetup { scene, drive, stages, sizes, oil, beams }
    }

    /// The same drive with its oil at `kelvin`: the lubricant moved there, each mesh's tribology
    /// and the losses' oil read again, the geometry shared.
    pub(crate) fn at_oil_temperature(&self, kelvin: f64) -> DriveSetup<'a> {
        let lubricant = self.scene.lubricant.as_ref().map(|l| l.at_kelvin(kelvin));
        let stages: Vec<StageMesh> = self
            .stages
            .iter()
            .enumerate()
            .map(|(k, s)| {
                let mesh = self.drive.mesh(k, lubricant.as_ref());
                StageMesh {
                    geometry: s.geometry.clone(),
                    positions: s.positions.clone(),
                    table: s.table.clone(),
                    h_v: s.h_v,
                    tribology: mesh.tribology(mesh.reduced_modulus()),
                    whole: s.whole,
                    stiffness: s.stiffness.clone(),
                    ring: RingMesh::of(self.drive, k, lubricant.as_ref(), s.ring.as_ref().map(|r| r.geometry.clone())),
                }
            })
            .collect();
        let oil = self.drive.mesh(0, lubricant.as_ref()).budget_oil(&stages[0].tribology);
        DriveSetup {
            scene: self.scene,
            drive: self.drive,
            stages,
            sizes: self.sizes.clone(),
            oil,
            beams: self.beams.clone(),
        }
    }

    /// This drive with its oil moved to θ (K), and its point under (law, formulation) with `torque`
    /// and `speed` at the ends its operating block names: what every P_V(θ) of a balance, a rating,
    /// a heat-balance curve and a duty cycle walks, a drive's and a pair's (its one-stage drive's).
    pub(crate) fn walked_at(
        &self,
        (law, formulation): (usize, Formulation),
        (torque, speed): (f64, f64),
        theta: f64,
    ) -> (DriveSetup<'a>, DrivePoint) {
        let setup = self.at_oil_temperature(theta);
        let ends = self.operating_ends();
        let torque = EndValue { at: ends.torque_at, value: torque };
        let speed = EndValue { at: ends.speed_at, value: speed };
        let point = setup.point(law, formulation, torque, speed);
        (setup, point)
    }

    /// The output speeds (rad/s, magnitudes) at which a bearing's model changes form on its shaft at
    /// this setup's oil ([`crate::losses::bearings::Bearing::switch_speed`]): every shaft turns in
    /// proportion to the output, by the stages' kinematics alone.
    pub(crate) fn bearing_switch_output_speeds(&self) -> Vec<f64> {
        let Some(nu) = self.oil.nu else { return Vec::new() };
        let layout = &self.drive.layout;
        let per_output = crate::drive::walk::shaft_speeds(
            layout,
            crate::drive::EndValue { at: crate::drive::ShaftEnd::Output, value: 1.0 },
        );
        layout
            .shafts
            .iter()
            .zip(&per_output)
            .filter(|(_, ratio)| ratio.abs() > 0.0)
            .flat_map(|(s, ratio)| s.bearings.iter().filter_map(move |b| b.switch_speed(nu).map(|w| w / ratio.abs())))
            .collect()
    }

    /// The drive's layout: its shafts, stages and chain.
    pub(crate) fn layout(&self) -> &'a crate::drive::Drive {
        &self.drive.layout
    }

    /// The ends the drive's operating block gives its torque and speed at.
    pub(crate) fn operating_ends(&self) -> crate::drive::DriveOperating {
        self.drive.layout.operating
    }

    /// Each stage's meshes' H_V as the walk integrates them, the pinion driving (a planetary
    /// stage's planet–ring mesh after its sun–planet mesh).
    pub(crate) fn loss_factors(&self) -> Vec<Vec<f64>> {
        self.stages.iter().map(|s| std::iter::once(s.h_v[0]).chain(s.ring.as_ref().map(|r| r.h_v)).collect()).collect()
    }

    /// The first stage with a result at `point` no gear mesh can have or whose formulas no longer
    /// hold ([`super::drive_plausibility`]).
    pub(crate) fn implausible(&self, point: &DrivePoint) -> Option<super::drive_plausibility::StageImplausible> {
        super::drive_plausibility::implausible(self.drive, &self.stages, point)
    }

    /// Where law `law` leaves its validity range on each stage's mesh at `point` (the driving
    /// member's torque and speed, the pair as that member drives it): the law's verdict at
    /// the contacts a pair alone reads it at (`super::setup::curve_positions`), by stage.
    pub(crate) fn validity(&self, law: usize, point: &DrivePoint) -> Vec<super::laws::ValiditySummary> {
        point
            .stages
            .iter()
            .enumerate()
            .map(|(k, s)| {
                let mesh = &self.stages[k];
                let spec = &self.scene.friction[law];
                let at = |m: &crate::drive::MeshState| {
                    validity_along(
                        spec,
                        &mesh.law_context(m.mesh, m.driving, m.torque.max(f64::MIN_POSITIVE), m.speed).0,
                        mesh.validity_positions(m.mesh, m.driving),
                    )
                };
                match self.drive.layout.stages[k].mesh_states(s).as_slice() {
                    [one] => at(one),
                    meshes => {
                        // A stage of several meshes: each at its pinion's load and rolling speed,
                        // its notes named by the mesh.
                        let mut all = super::laws::ValiditySummary::default();
                        for m in meshes {
                            let v = at(m);
                            all.samples += v.samples;
                            all.outside += v.outside;
                            all.intervals.extend(v.intervals);
                            let name = m.name.unwrap_or_default();
                            all.notes.extend(v.notes.into_iter().map(|n| format!("{name} mesh: {n}")));
                        }
                        all
                    }
                }
            })
            .collect()
    }

    /// The drive at `torque` and `speed` under law `law` and `formulation`.
    pub(crate) fn point(&self, law: usize, formulation: Formulation, torque: EndValue, speed: EndValue) -> DrivePoint {
        self.point_in(&MeshMemo::default(), law, formulation, torque, speed)
    }

    /// [`Self::point`] with the meshes' η read from and kept in `memo` (one memo for one law at one
    /// point: its formulations' walks share their meshes' integrals).
    pub(crate) fn point_in(
        &self,
        memo: &MeshMemo,
        law: usize,
        formulation: Formulation,
        torque: EndValue,
        speed: EndValue,
    ) -> DrivePoint {
        let meshes = LawMeshes::new(&self.stages, &self.scene.friction[law], formulation, memo);
        self.solved(&meshes, torque, speed)
    }

    /// The drive at `torque` and `speed` under its first law and `formulation`; with no law (a
    /// scene that asks only for analyses of one pair), its meshes passing their power whole.
    pub(crate) fn first_law_point(&self, formulation: Formulation, torque: EndValue, speed: EndValue) -> DrivePoint {
        match self.scene.friction.is_empty() {
            true => self.solved(&WholeMeshes, torque, speed),
            false => self.point(0, formulation, torque, speed),
        }
    }

    /// The walk at the given ends. A scene of one pair (its one-stage drive) gives its
    /// `pinion_torque` at the pinion gear, into the mesh, as the pair's budget reads it: the input's
    /// torque is that plus the pinion shaft's own losses (bearings, seals, no-load parts), which the
    /// given torque fixes (they depend on the mesh's forces): the walk starts with the input at the
    /// given torque plus those losses over the input's speed (`walk::shaft_losses_at`), and walks
    /// again with the input raised by what the mesh missed until the mesh's driving torque is the
    /// given one to [`crate::drive::walk::TOLERANCE`] (the first walk reaches it but for rounding).
    fn solved(&self, meshes: &dyn MeshEfficiency, torque: EndValue, speed: EndValue) -> DrivePoint {
        self.solved_in(meshes, (torque, speed), crate::drive::point::PINION_WALKS)
    }

    /// [`Self::solved`] in at most `walks` walks beyond the first; a one-pair point whose mesh has
    /// not its given torque by then says by how much it is short (`pinion_torque_missed`, which
    /// makes it unsettled in the report).
    fn solved_in(
        &self,
        meshes: &dyn MeshEfficiency,
        (torque, speed): (EndValue, EndValue),
        walks: usize,
    ) -> DrivePoint {
        let model = self.model();
        let given = AtGivenPinion { meshes, torque: torque.value };
        let start = self.pinion_start(&model, torque, speed);
        let at_pinion = start.is_some();
        let meshes: &dyn MeshEfficiency = if at_pinion { &given } else { meshes };
        let (mut at_input, seed) = start.map_or((torque, None), |(at, seed)| (at, Some(seed)));
        let mut point = crate::drive::walk::solve_from(&model, meshes, (at_input, speed), seed);
        let missed = |p: &DrivePoint| torque.value - p.stages[0].driving_torque;
        if !at_pinion {
            return point;
        }
        for _ in 0..walks {
            let missed = missed(&point);
            if !missed.is_finite() || settled(missed, torque.value) {
                break;
            }
            at_input.value += missed;
            point = solve(&model, meshes, at_input, speed);
        }
        let left = missed(&point);
        point.pinion_torque_missed = (!settled(left, torque.value)).then_some(left);
        point
    }

    /// The walk's model: the layout, the stages' sizes, the oil and the shafts' beams.
    fn model(&self) -> DriveModel<'_> {
        DriveModel { drive: &self.drive.layout, sizes: &self.sizes, oil: &self.oil, beams: &self.beams }
    }

    /// Where a one-pair drive's walk at a given pinion torque starts (None for any other walk): the
    /// input at that torque plus the pinion shaft's own losses over its speed, and those losses, the
    /// walk's seed. Zero torque at the pinion gear too (an idle step): the mesh carries nothing,
    /// the input gives the pinion shaft its own losses, as a pair's budget reads them.
    fn pinion_start(&self, model: &DriveModel, torque: EndValue, speed: EndValue) -> Option<(EndValue, Seed)> {
        let at_pinion = self.drive.one_pair && torque.at == ShaftEnd::Input && torque.value >= 0.0;
        if !at_pinion {
            return None;
        }
        let losses = crate::drive::walk::shaft_losses_at(model, speed, &[torque.value]);
        let input = self.drive.layout.input;
        let omega = crate::drive::walk::shaft_speeds(&self.drive.layout, speed)[input].abs();
        let mut at_input = torque;
        if omega > 0.0 {
            at_input.value += losses.own(input) / omega;
        }
        Some((at_input, losses))
    }

    /// Whether the drive is a scene of one pair's one-stage drive.
    pub(crate) fn is_one_pair(&self) -> bool {
        self.drive.one_pair
    }

    /// A one-pair drive's losses under (law, formulation), its pinion torque and speed given at the input, in this
    /// setup's oil: [the mesh's loss, every loss beside it] (W), from the walk's first pass when it settles there (the
    /// seeded walk does: the point's losses but for rounding), else from its point: P_V(θ) without building the point.
    pub(crate) fn one_pair_losses(
        &self,
        law: usize,
        formulation: Formulation,
        torque: EndValue,
        speed: EndValue,
    ) -> [f64; 2] {
        let model = self.model();
        let memo = MeshMemo::default();
        let meshes = LawMeshes::new(&self.stages, &self.scene.friction[law], formulation, &memo);
        let given = AtGivenPinion { meshes: &meshes, torque: torque.value };
        if let Some((at_input, seed)) = self.pinion_start(&model, torque, speed) {
            let pass = crate::drive::seeded_losses::seeded_losses(&model, &given, (at_input, speed), &seed);
            if pass.finite && settled(torque.value - pass.driving_torque[0], torque.value) {
                return [pass.mesh_loss[0], pass.beside_meshes];
            }
        }
        let p = self.point(law, formulation, torque, speed);
        [p.stages[0].mesh_loss, p.losses.beside_meshes()]
    }

    /// The formulations each point is evaluated in, in the scene's order.
    pub(crate) fn formulations(&self) -> Vec<Formulation> {
        self.scene.analyses.efficiency.clone().unwrap_or_default()
    }

    /// Rows (laws × formulations) per operating point.
    pub(crate) fn rows_per_point(&self) -> usize {
        self.scene.friction.len() * self.scene.analyses.efficiency.as_ref().map_or(0, Vec::len)
    }
}

/// A one-pair drive's meshes with its pair's mesh at the given pinion torque: the torque the walk
/// of [`DriveSetup::solved`] puts on the mesh (the input raised by the pinion shaft's losses at it),
/// so the walk reads the mesh where the solution has it, and the law's mesh cycle is integrated
/// once a point (`LawMeshes` reads back a state it has met) instead of at torques that differ from
/// it in the last digits.
/// Whether a one-pair walk's mesh missed its given pinion torque `torque` (N·m) by no more than
/// the walk's tolerance.
fn settled(missed: f64, torque: f64) -> bool {
    missed.is_finite() && missed.abs() <= crate::drive::walk::TOLERANCE * torque.max(1.0)
}

struct AtGivenPinion<'a> {
    meshes: &'a dyn MeshEfficiency,
    torque: f64,
}

impl MeshEfficiency for AtGivenPinion<'_> {
    fn efficiency(&self, stage: usize, mesh: usize, driving: Member, torque: f64, speed: f64) -> f64 {
        match (stage, mesh, driving) {
            (0, 0, Member::Pinion) if self.torque > 0.0 => {
                self.meshes.efficiency(0, 0, Member::Pinion, self.torque, speed)
            }
            _ => self.meshes.efficiency(stage, mesh, driving, torque, speed),
        }
    }
}

/// A law's validity along A–E of a mesh at `positions`: the contacts a pair alone reads it at (241
/// evenly, the pitch point, and both sides of B and D: `super::setup::curve_positions` of the
/// mesh's geometry, [`StageMesh::validity_positions`]).
fn validity_along(spec: &FrictionLawSpec, ctx: &LawContext, positions: &[f64]) -> super::laws::ValiditySummary {
    let built = law_at(spec, ctx);
    let contacts: Vec<_> = positions.iter().map(|u| ctx.contact_at(*u)).collect();
    super::laws::validity_summary(&*built, &contacts)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// FZG C14 in its gearbox as its one-stage drive at 94.1 N·m, 500 rpm: a walk with the input at
    /// the given torque leaves the mesh short of `pinion_torque` by the pinion shaft's own losses
    /// (between 0.01 % and 2 % of it); the walk started with the input raised by those losses
    /// (`walk::shaft_losses_at`) puts the given torque on the mesh in its first walk (1e-12), and a
    /// point still short says so (unsettled, in words).
    #[test]
    fn a_pinion_torque_not_reached_is_flagged() {
        let source =
            std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/specs/fzg_c14_gearbox.gear")).unwrap();
        let ast = crate::parse("fzg_c14_gearbox.gear", &source).unwrap();
        let scene = crate::scene::lower::lower_as_one_stage_drive(&ast, None).unwrap();
        let setup = DriveSetup::new(&scene, scene.drive.as_ref().unwrap());
        let memo = MeshMemo::default();
        let meshes = LawMeshes::new(&setup.stages, &scene.friction[0], Formulation::External, &memo);
        let ends = (
            EndValue { at: ShaftEnd::Input, value: 94.1 },
            EndValue { at: ShaftEnd::Input, value: 500.0 * std::f64::consts::PI / 30.0 },
        );
        let model =
            DriveModel { drive: &setup.drive.layout, sizes: &setup.sizes, oil: &setup.oil, beams: &setup.beams };
        let unraised = solve(&model, &AtGivenPinion { meshes: &meshes, torque: 94.1 }, ends.0, ends.1);
        let short = 94.1 - unraised.stages[0].driving_torque;
        assert!(short > 1e-4 * 94.1 && short < 0.02 * 94.1, "{short}");
        let first = setup.solved_in(&meshes, ends, 0);
        assert_eq!(first.pinion_torque_missed, None);
        assert!(first.settled());
        assert!((first.stages[0].driving_torque - 94.1).abs() <= 1e-12 * 94.1);
        let still_short = DrivePoint { pinion_torque_missed: Some(short), ..first.clone() };
        assert!(
            !still_short.settled() && still_short.unsettled_words().contains("did not reach the given pinion_torque")
        );
        let walked = setup.solved_in(&meshes, ends, crate::drive::point::PINION_WALKS);
        assert_eq!(walked.pinion_torque_missed, None);
        assert!(walked.settled());
        assert!((walked.stages[0].driving_torque - 94.1).abs() <= 1e-12 * 94.1);
    }
}
