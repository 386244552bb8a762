//! Parallel axes: an external pair (spur or helical) on two shafts. An external mesh reverses the
//! sense of rotation: ω_wheel = −ω_pinion z_pinion / z_wheel (ISO 21771:2007, the transmission ratio
//! u = z_2/z_1 of an external pair, with the sign of the sense).

use super::stage_kinematics::StageKinematics;

/// The teeth [z_pinion, z_wheel] of a parallel-axis stage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parallel {
    pub teeth: [u32; 2],
}

impl StageKinematics for Parallel {
    fn speeds(&self, known: usize, omega: f64) -> Vec<f64> {
        pair_speeds(self.teeth, known, omega, -1.0)
    }

    fn torque_ratio(&self, driving: usize) -> f64 {
        pair_torque_ratio(self.teeth, driving)
    }
}

/// The two gears' speeds of a pair of `teeth` from gear `known`'s ω: the other at ω z_known/z_other
/// with `sense` (−1 an external mesh, +1 an internal one).
pub(crate) fn pair_speeds(teeth: [u32; 2], known: usize, omega: f64, sense: f64) -> Vec<f64> {
    let z = teeth.map(f64::from);
    let other = sense * omega * z[known] / z[1 - known];
    if known == 0 {
        vec![omega, other]
    } else {
        vec![other, omega]
    }
}

/// The lossless torque ratio of a pair: the driven gear's torque over the driving gear's.
pub(crate) fn pair_torque_ratio(teeth: [u32; 2], driving: usize) -> f64 {
    let z = teeth.map(f64::from);
    z[1 - driving] / z[driving]
}
