//! The one interface a loss part of the budget implements: at an operating state, in an oil, the
//! powers of its columns and, for parts made of items a user audits one by one (bearings), each
//! item's loads and losses.
//!
//! ```
//! use gearloss::losses::parts::{LossColumn, LossPart, LossPartId, PartLosses, PartState};
//! use gearloss::losses::{Oil, Seal};
//!
//! /// A constant drag torque on the wheel shaft (a brake's residual drag, say).
//! struct Drag { torque: f64 }
//!
//! impl LossPart for Drag {
//!     fn id(&self) -> LossPartId { LossPartId::Seals }
//!     fn losses(&self, at: &PartState, _oil: &Oil, out: &mut PartLosses) {
//!         out.add(LossColumn::Seals, self.torque * at.omega[1]);
//!     }
//! }
//!
//! let oil = Oil { nu: Some(3.0e-5), rho: Some(870.0), eta: 0.026, mineral: true };
//! let at = PartState { pinion_torque: 100.0, omega: [150.0, 100.0], pitch_radius: [0.04, 0.06],
//!                      face_width: 0.02, transverse_force: 2660.0, pressure_angle: 0.35,
//!                      axial_force: 0.0 };
//! let mut out = PartLosses::default();
//! Drag { torque: 0.05 }.losses(&at, &oil, &mut out);
//! // A seal on a 30 mm shaft at 100 rad/s (ISO/TR 14179-2): 7.69e-6 · 30² · n.
//! let seals = [vec![], vec![Seal { diameter: 0.030, count: 1 }]];
//! gearloss::losses::parts::seals::Seals(&seals).losses(&at, &oil, &mut out);
//! let n = 100.0 * 30.0 / std::f64::consts::PI;
//! assert!((out.power(LossColumn::Seals).unwrap() - (5.0 + 7.69e-6 * 900.0 * n)).abs() < 1e-9);
//! ```

use super::loss_column::LossColumn;
use super::part_id::LossPartId;
use crate::losses::bearing_loss::BearingLoss;
use crate::losses::oil::Oil;

/// The operating state as the parts read it (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PartState {
    /// T_1 (N·m).
    pub pinion_torque: f64,
    /// [ω_1, ω_2] (rad/s).
    pub omega: [f64; 2],
    /// Working pitch radii [r_w1, r_w2] (m) and the face width (m).
    pub pitch_radius: [f64; 2],
    pub face_width: f64,
    /// The transverse mesh force F_bt = T_1 / r_b1 (N) along the line of action, the working
    /// transverse pressure angle α_wt (rad), and the axial force F_a on the pinion (N).
    pub transverse_force: f64,
    pub pressure_angle: f64,
    pub axial_force: f64,
}

/// What the parts found: the powers by column (W, added up when a column is filled twice) and
/// every bearing place's loads and losses.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PartLosses {
    pub powers: Vec<(LossColumn, f64)>,
    pub bearings: Vec<BearingLoss>,
}

impl PartLosses {
    /// Adds `power` (W) to `column`.
    pub fn add(&mut self, column: LossColumn, power: f64) {
        match self.powers.iter_mut().find(|(c, _)| *c == column) {
            Some((_, p)) => *p += power,
            None => self.powers.push((column, power)),
        }
    }

    pub fn power(&self, column: LossColumn) -> Option<f64> {
        self.powers.iter().find(|(c, _)| *c == column).map(|(_, p)| *p)
    }
}

/// A loss part of the budget.
pub trait LossPart {
    /// Its catalogue row.
    fn id(&self) -> LossPartId;
    /// Its powers (and items) at `at` in `oil`, added to `out`.
    fn losses(&self, at: &PartState, oil: &Oil, out: &mut PartLosses);
}
