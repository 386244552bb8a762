//! The drive point a settled pass of the power walk gives (`super::walk`): every shaft's speed,
//! torques, bearing places, gear loads and bending, every stage's driving member, torques, mesh
//! loss and forces, the ends' powers, the loss parts and the efficiency.

use super::pass::Pass;
use super::point::{DrivePoint, LossParts, PowerFlow, ShaftPoint, StagePoint};
use super::walk::{DriveModel, Supported, Walk};
use super::walk_parts::FixedLosses;

impl Walk<'_> {
    /// The drive point of the settled pass `p`.
    pub(super) fn point(&self, model: &DriveModel, p: &Pass, fixed: &FixedLosses, passes: usize) -> DrivePoint {
        let drive = model.drive;
        let Supported { places, loads, bending, .. } = self.bearing_powers(model, &p.driving_torque, true);
        let torque = |power: f64, j: usize| if self.omega[j] == 0.0 { 0.0 } else { power / self.omega[j].abs() };
        let shafts: Vec<ShaftPoint> = drive
            .shafts
            .iter()
            .enumerate()
            .zip(places.into_iter().zip(bending))
            .map(|((j, s), (bearings, bending))| ShaftPoint {
                name: s.name.clone(),
                speed: self.omega[j],
                received_torque: torque(p.received[j], j),
                passed_torque: torque(p.passed[j], j),
                received_power: p.received[j],
                passed_power: p.passed[j],
                bearings,
                gear_loads: loads.iter().filter(|l| l.shaft == j).copied().collect(),
                seals: fixed.seals(j),
                gear_no_load: fixed.gear_no_load(j),
                bending,
            })
            .collect();
        let bent: Vec<_> = shafts.iter().map(|s| s.bending.as_ref()).collect();
        let mut steps = self.steps.clone();
        steps.sort_by_key(|(k, _)| *k);
        let stages: Vec<StagePoint> = steps
            .iter()
            .map(|&(k, m)| {
                let stage = &drive.stages[k];
                let sizes = &model.sizes[k];
                let kind = stage.model();
                let t = p.driving_torque[k];
                let d = m.index();
                let bearings = kind
                    .member_bearings(stage, (m, t), self.places(k), model.oil)
                    .map_or([0.0; 2], |(_, b)| [b.no_load, b.load]);
                let parts = (bearings, fixed.stage_no_load()[k]);
                let ([f_t, f_r, f_a], kind_point) = kind.point(stage, sizes, (m, t), p.kind_state[k].as_ref(), parts);
                StagePoint {
                    name: stage.name.clone(),
                    driving: m,
                    driving_torque: t,
                    driven_torque: t * kind.kinematics(stage).torque_ratio(d) * p.efficiency[k],
                    driving_speed: self.omega[stage.places[d].shaft].abs(),
                    mesh_efficiency: p.efficiency[k],
                    mesh_loss: p.mesh_loss[k],
                    no_load: fixed.stage_no_load()[k],
                    tangential_force: f_t,
                    radial_force: f_r,
                    axial_force: f_a,
                    mesh_misalignment: super::shaft_bending::stage_misalignment(
                        &bent,
                        &loads,
                        (k, stage),
                        sizes.face_width,
                    ),
                    kind: kind_point,
                }
            })
            .collect();
        let source = *self.shafts.first().expect("a drive has shafts");
        let sink = *self.shafts.last().expect("a drive has shafts");
        let (p_source, p_sink) = (p.received[source], p.passed[sink]);
        let (input_power, output_power) = match self.flow {
            PowerFlow::Drive => (p_source, p_sink),
            PowerFlow::Coast => (-p_sink, -p_source),
        };
        let losses = LossParts { meshes: p.mesh_loss.iter().sum(), parts: fixed.point_parts(&shafts) };
        let both_ends_deliver = p_sink < 0.0 || p_source < 0.0;
        let efficiency = if both_ends_deliver || p_source == 0.0 { 0.0 } else { p_sink / p_source };
        DrivePoint {
            flow: self.flow,
            input_torque: torque(input_power, drive.input),
            input_speed: self.omega[drive.input].abs(),
            input_power,
            output_torque: torque(output_power, drive.output),
            output_speed: self.omega[drive.output].abs(),
            output_power,
            shafts,
            stages,
            losses,
            efficiency,
            both_ends_deliver,
            iterations: passes,
            diverged: false,
            books_gap: None,
            pinion_torque_missed: None,
        }
    }
}
