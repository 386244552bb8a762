//! A duty cycle: steps of pinion torque and speed held for a duration, in order.

/// One step of a duty cycle, in SI.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DutyStep {
    /// Δt (s).
    pub duration: f64,
    /// Pinion torque (N·m) and speed (rad/s); either may be zero.
    pub pinion_torque: f64,
    pub pinion_speed: f64,
    /// `10 min, 120 N*m, 2500 rpm`, as written.
    pub label: String,
}

/// A named duty cycle.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DutyCycle {
    pub name: String,
    pub steps: Vec<DutyStep>,
}

impl DutyCycle {
    /// E_in = Σ T ω Δt (J).
    pub fn energy_in(&self) -> f64 {
        self.steps.iter().map(|s| s.pinion_torque * s.pinion_speed * s.duration).sum()
    }
}
