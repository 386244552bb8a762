//! The speeds of a drive's shafts: the chain walked from the input by each stage's kinematics.

use super::layout::{Drive, ShaftEnd};

/// A value given at one end of the drive: a torque (N·m; positive: the input drives) or a speed
/// (rad/s; at the input signed about +z, at the output a magnitude, the input then turning
/// counter-clockwise).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EndValue {
    pub at: ShaftEnd,
    pub value: f64,
}

/// ω_in/ω_out of the chain (signed: negative when the output turns the other way).
pub fn overall_ratio(drive: &Drive) -> f64 {
    1.0 / shaft_speeds(drive, EndValue { at: ShaftEnd::Input, value: 1.0 })[drive.output]
}

/// The signed speed of every shaft (rad/s): the input's given, or found from the output's
/// magnitude, then passed along the chain by each stage's kinematics.
pub fn shaft_speeds(drive: &Drive, speed: EndValue) -> Vec<f64> {
    let along = |input: f64| {
        let mut omega = vec![0.0; drive.shafts.len()];
        omega[drive.input] = input;
        for &(k, m) in &drive.chain {
            let stage = &drive.stages[k];
            let kinematics = stage.model().kinematics(stage);
            let s = kinematics.speeds(m.index(), omega[stage.places[m.index()].shaft]);
            omega[stage.places[m.other().index()].shaft] = s[m.other().index()];
        }
        omega
    };
    match speed.at {
        ShaftEnd::Input => along(speed.value),
        ShaftEnd::Output => {
            let ratio = along(1.0)[drive.output].abs();
            along(speed.value.abs() / ratio)
        }
    }
}
