//! What the budget shows of each bearing place: its loads and its losses, for a user to audit.

use serde::Serialize;

/// The loads and losses of one bearing place.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BearingLoss {
    /// "pinion" or "wheel".
    pub shaft: &'static str,
    pub kind: &'static str,
    /// "palmgren" or "skf".
    pub model: &'static str,
    pub count: usize,
    /// Axial position `at` (m), when the scene gives one.
    pub position: Option<f64>,
    /// The numbers: loads of one bearing, losses of all `count`.
    pub loads: BearingLoads,
}

/// What one bearing place carries and loses at an operating point.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BearingLoads {
    /// Radial and axial load of one bearing (N).
    pub radial_load: f64,
    pub axial_load: f64,
    /// Power loss of all `count` bearings (W): no-load and load-dependent.
    pub no_load: f64,
    /// `None` when the bearing's f_1 needs a static load rating it lacks (lowering refuses such a
    /// scene; a bearing built in code without one adds no load-dependent loss).
    pub load: Option<f64>,
}
