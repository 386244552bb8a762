//! The one interface a stage kind implements: the speeds of its members from the speed of one of
//! them, and the ideal torque ratio between the two members the power passes through.
//!
//! ```
//! use gearloss::drive::kinematics::{parallel::Parallel, StageKinematics};
//! // VW ID.3's first stage, 23/68: the pinion at 3000 rpm turns the wheel the other way.
//! let k = Parallel { teeth: [23, 68] };
//! let w = k.speeds(0, 3000.0);
//! assert!((w[1] + 3000.0 * 23.0 / 68.0).abs() < 1e-12);
//! // And back: from the wheel's speed, the pinion's.
//! assert!((k.speeds(1, w[1])[0] - 3000.0).abs() < 1e-9);
//! // A lossless stage: driven torque = driving torque × z_driven / z_driving.
//! assert!((k.torque_ratio(0) - 68.0 / 23.0).abs() < 1e-15);
//! ```

/// A stage kind's kinematics.
pub trait StageKinematics {
    /// The signed speeds (about +z) of every member, in member order, from member `known` at `omega`.
    fn speeds(&self, known: usize, omega: f64) -> Vec<f64>;
    /// T_driven / T_driving of a lossless stage driven by member `driving` (= |ω_driving / ω_driven|).
    fn torque_ratio(&self, driving: usize) -> f64;
}
