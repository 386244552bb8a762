//! The one interface a loss part of the budget implements: on the shafts and stages of a drive at
//! one operating state, in an oil, each shaft's powers in the part's columns (and each stage's, for
//! the parts a stage's gears cause) and, for parts made of items a user audits one by one
//! (bearings), each item's loads and losses. The loads on a shaft's bearing places come from its
//! statics, outside the parts (`crate::drive::statics`, an elastic shaft's beam): a part reads them.
//!
//! ```
//! use gearloss::losses::parts::{LossColumn, LossPart, LossPartId, PartLosses, PartState, ShaftParts};
//! use gearloss::losses::{Oil, Seal};
//!
//! /// A constant drag torque on every shaft (a brake's residual drag, say).
//! struct Drag { torque: f64 }
//!
//! impl LossPart for Drag {
//!     fn id(&self) -> LossPartId { LossPartId::Seals }
//!     fn present(&self, _on: &PartState) -> bool { true }
//!     fn reads_loads(&self) -> bool { false }
//!     fn losses(&self, on: &PartState, _oil: &Oil, out: &mut PartLosses) {
//!         for (j, s) in on.shafts.iter().enumerate() {
//!             out.add(j, LossColumn::Seals, self.torque * s.speed);
//!         }
//!     }
//! }
//!
//! let oil = Oil { nu: Some(3.0e-5), rho: Some(870.0), eta: 0.026, mineral: true };
//! let seals = [Seal { diameter: 0.030, count: 1 }];
//! // A pinion shaft at 150 rad/s without seals, a wheel shaft at 100 rad/s with one.
//! let shafts = [
//!     ShaftParts { speed: 150.0, bearings: &[], loads: &[], seals: &[] },
//!     ShaftParts { speed: 100.0, bearings: &[], loads: &[], seals: &seals },
//! ];
//! let on = PartState { shafts: &shafts, stages: &[] };
//! let mut out = PartLosses::new(2, 0, false);
//! Drag { torque: 0.05 }.losses(&on, &oil, &mut out);
//! gearloss::losses::parts::seals::Seals.losses(&on, &oil, &mut out);
//! // A seal on a 30 mm shaft at 100 rad/s (ISO/TR 14179-2): 7.69e-6 · 30² · n.
//! let n = 100.0 * 30.0 / std::f64::consts::PI;
//! assert!((out.shaft(1)[LossColumn::Seals as usize] - (5.0 + 7.69e-6 * 900.0 * n)).abs() < 1e-9);
//! assert!((out.column(LossColumn::Seals) - (7.5 + 5.0 + 7.69e-6 * 900.0 * n)).abs() < 1e-9);
//! ```

use super::loss_column::{LossColumn, COLUMNS};
use super::part_id::LossPartId;
use crate::losses::bearing_loss::BearingLoads;
use crate::losses::bearings::Bearing;
use crate::losses::gear_no_load::{GearsRunning, Lubrication};
use crate::losses::oil::Oil;
use crate::losses::seals::Seal;

/// The number of the budget's columns.
pub const COLUMN_COUNT: usize = COLUMNS.len();

/// One shaft as the parts read it (SI).
#[derive(Debug, Clone, Copy)]
pub struct ShaftParts<'a> {
    /// |ω| (rad/s).
    pub speed: f64,
    /// Its bearing places, as written.
    pub bearings: &'a [Bearing],
    /// The [radial, axial] load on one bearing of each place (N), from the shaft's statics; empty
    /// where the parts that read loads are not asked.
    pub loads: &'a [[f64; 2]],
    pub seals: &'a [Seal],
}

/// One stage's gears as the parts read them: its lubrication, the gears it sets running (their
/// speeds, radii and face width) and the shafts its no-load parts are charged on, [the mesh's parts
/// and the first gear's windage, the second gear's windage].
#[derive(Debug, Clone, Copy)]
pub struct StageGears<'a> {
    pub lubrication: Option<&'a Lubrication>,
    pub running: GearsRunning,
    pub shafts: [usize; 2],
}

/// The drive at one operating state as the parts read it.
#[derive(Debug, Clone, Copy)]
pub struct PartState<'a> {
    pub shafts: &'a [ShaftParts<'a>],
    pub stages: &'a [StageGears<'a>],
}

/// What the parts found: each shaft's power by column and each stage's no-load power (W, added up
/// when a column is filled twice) and, when asked for, every bearing place's loads and losses by
/// shaft, as written.
#[derive(Debug, Clone, PartialEq)]
pub struct PartLosses {
    shafts: Vec<[f64; COLUMN_COUNT]>,
    /// Each stage's no-load parts (W).
    pub stages: Vec<f64>,
    /// Each shaft's bearing places (when kept).
    pub places: Option<Vec<Vec<BearingLoads>>>,
}

impl PartLosses {
    /// Nothing yet on `shafts` shafts and `stages` stages; `keep_places`: keep each bearing place.
    pub fn new(shafts: usize, stages: usize, keep_places: bool) -> PartLosses {
        PartLosses {
            shafts: vec![[0.0; COLUMN_COUNT]; shafts],
            stages: vec![0.0; stages],
            places: keep_places.then(|| vec![Vec::new(); shafts]),
        }
    }

    /// Adds `power` (W) to `column` of shaft `j`.
    pub fn add(&mut self, j: usize, column: LossColumn, power: f64) {
        self.shafts[j][column as usize] += power;
    }

    /// Shaft `j`'s powers by column (W).
    pub fn shaft(&self, j: usize) -> &[f64; COLUMN_COUNT] {
        &self.shafts[j]
    }

    /// Shaft `j`'s losses (W): its columns added in column order.
    pub fn shaft_total(&self, j: usize) -> f64 {
        self.shafts[j].iter().sum()
    }

    /// One column's power over every shaft (W), shaft by shaft.
    pub fn column(&self, column: LossColumn) -> f64 {
        self.shafts.iter().map(|s| s[column as usize]).sum()
    }
}

/// A loss part of the budget.
pub trait LossPart {
    /// Its catalogue row.
    fn id(&self) -> LossPartId;
    /// Whether the drive has any of it (a column of the budget then).
    fn present(&self, on: &PartState) -> bool;
    /// Whether it reads the loads on the bearing places (so the power walk charges it again at
    /// every pass, the loads following the torques) or not (charged once a point).
    fn reads_loads(&self) -> bool;
    /// Its powers (and items) on `on` in `oil`, added to `out`.
    fn losses(&self, on: &PartState, oil: &Oil, out: &mut PartLosses);
}
