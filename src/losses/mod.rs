//! The gearbox loss budget beside the mesh: load-independent gear losses (churning for dip
//! lubrication, the jet's impulse and the gears' windage for injection), rolling-bearing losses
//! (Palmgren, or the SKF model where its constants are given) and radial shaft-seal
//! losses, each a small function with its source, and [`budget::LossBudget`] which adds them up
//! with the mesh's load-dependent loss at an operating point.
//!
//! The method is ISO/TR 14179-2:2001 (Gears — Thermal capacity — Part 2), the FZG method of
//! Niemann & Winter: P_V = P_VZP + P_VZ0 + P_VL + P_VD (mesh under load, gears without load,
//! bearings, seals).

pub mod bearings;
pub mod budget;
pub mod columns;
pub mod gear_no_load;
pub mod seals;
pub mod skf_bearing;

pub use bearings::{Bearing, BearingType};
pub use budget::{loss_budget, BearingLoads, BearingLoss, BudgetParts, LossBudget};
pub use gear_no_load::Lubrication;
pub use seals::Seal;

/// The oil at the oil temperature, as the losses beside the mesh read it (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oil {
    /// Kinematic viscosity ν (m²/s), density ρ (kg/m³), dynamic viscosity η (Pa·s).
    pub nu: f64,
    pub rho: f64,
    pub eta: f64,
    /// A mineral oil (SKF's μ_EHL of ball bearings depends on it).
    pub mineral: bool,
}

/// The housing, shafts, bearings and seals of a single-stage gearbox, in SI.
#[derive(Debug, Clone, PartialEq)]
pub struct Gearbox {
    pub lubrication: Option<Lubrication>,
    /// [pinion shaft, wheel shaft].
    pub bearings: [Vec<Bearing>; 2],
    pub seals: [Vec<Seal>; 2],
}

impl Gearbox {
    /// Whether the scene gives anything beyond the mesh.
    pub fn is_empty(&self) -> bool {
        self.lubrication.is_none() && self.bearings.iter().all(Vec::is_empty) && self.seals.iter().all(Vec::is_empty)
    }
}
