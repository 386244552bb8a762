//! The contact-state plot's curves along the line of action.

use super::cases::pick;
use super::setup::Setup;
use crate::geometry::{ContactPoint, OperatingState};
use crate::mesh::MeshProblem;

/// Contact quantities along the line of action for the contact-state plot: v_s at each plotted speed
/// (first torque), p_H at each plotted torque (first speed), SR at the first operating point.
#[derive(Debug, Clone, Default)]
pub struct ContactCurves {
    /// Positions from T1 (m), [`Setup::curve_positions`].
    pub u: Vec<f64>,
    /// (speed as written, v_s in m/s).
    pub sliding_velocity: Vec<(String, Vec<f64>)>,
    pub slide_to_roll: Vec<f64>,
    /// (torque as written, p_H in Pa).
    pub hertz_pressure: Vec<(String, Vec<f64>)>,
    /// The share of the normal load on one contact, at the first operating point.
    pub load_share: Vec<f64>,
}

/// The contact curves of the contact-state plot.
pub(super) fn contact_curves(problem: &MeshProblem, eval: &Setup) -> ContactCurves {
    let u = eval.curve_positions();
    let op = &problem.operating;
    let torque0 = op.pinion_torque.values[0].value;
    let speed0 = op.pinion_speed.values[0].value;
    let at = |t: f64, n: f64| -> Vec<ContactPoint> {
        let state = OperatingState { pinion_torque: t, pinion_speed: n };
        u.iter().map(|x| eval.contact_at(*x, &state)).collect()
    };
    let sliding_velocity = pick(op.pinion_speed.values.len())
        .into_iter()
        .map(|i| {
            let label = op.pinion_speed.point_label(i);
            (label, at(torque0, op.pinion_speed.values[i].value).iter().map(|c| c.sliding_velocity).collect())
        })
        .collect();
    let hertz_pressure = pick(op.pinion_torque.values.len())
        .into_iter()
        .map(|i| {
            let label = op.pinion_torque.point_label(i);
            (label, at(op.pinion_torque.values[i].value, speed0).iter().map(|c| c.hertz_pressure).collect())
        })
        .collect();
    let first = at(torque0, speed0);
    let slide_to_roll = first.iter().map(|c| c.slide_to_roll).collect();
    let load_share = first.iter().map(|c| c.load_share).collect();
    ContactCurves { u, sliding_velocity, slide_to_roll, hertz_pressure, load_share }
}
