//! The gearbox loss budget beside the mesh: load-independent gear losses (churning for dip
//! lubrication, the jet's impulse and the gears' windage for injection), rolling-bearing losses
//! (Palmgren, or the SKF model where its constants are given) and radial shaft-seal
//! losses, each a small function with its source; [`parts`], the catalogue that makes each of them a
//! part of the budget (one file and one row per part), and [`budget::LossBudget`] which adds the
//! parts up beside the mesh's load-dependent loss at an operating point.
//!
//! The method is ISO/TR 14179-2:2001 (Gears — Thermal capacity — Part 2), the FZG method of
//! Niemann & Winter: P_V = P_VZP + P_VZ0 + P_VL + P_VD (mesh under load, gears without load,
//! bearings, seals).

pub(crate) mod bearing_loss;
pub(crate) mod bearing_type;
pub(crate) mod bearings;
pub(crate) mod budget;
pub mod columns;
pub(crate) mod gear_no_load;
pub(crate) mod gearbox;
pub(crate) mod oil;
pub mod pair_statics;
pub mod parts;
pub(crate) mod seals;
pub(crate) mod skf_bearing;

pub use bearings::{Bearing, BearingType};
pub use budget::{loss_budget, total_efficiency, BearingLoads, BearingLoss, BudgetParts, LossBudget};
pub use gear_no_load::Lubrication;
pub use gear_no_load::{mauz_dip_torque, windage_loss, GearsRunning};
pub use gearbox::Gearbox;
pub use oil::Oil;
pub use seals::Seal;
pub use skf_bearing::{skf_moments, SkfConstants};
