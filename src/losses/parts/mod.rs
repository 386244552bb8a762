//! The loss parts of the budget beside the mesh, as a catalogue: each part is one file
//! implementing [`LossPart`] and one row of [`catalog::PARTS`] naming the columns it fills
//! ([`LossColumn`], one row of [`loss_column::COLUMNS`] each). The budget, the record files, the
//! report and the plots iterate the catalogue, so a new loss model adds rows, not fields.
//!
//! A part reads a drive's shafts and stages ([`PartState`]: a one-pair gearbox is two shafts and one
//! stage) and fills each shaft's columns; the power walk of a drive charges the parts that read no
//! loads once a point and those that read the bearing places' loads (from the shafts' statics,
//! outside the parts) at every pass. Today: the gears without load (churning, or jet impulse and
//! windage: `gear_no_load`), the rolling bearings under the loads their shaft's statics put on them
//! (`bearings`) and the shaft seals ([`seals`]).

pub(crate) mod bearings;
pub(crate) mod catalog;
pub(crate) mod gear_no_load;
pub(crate) mod loss_column;
pub(crate) mod loss_part;
pub(crate) mod part_id;
pub mod seals;

pub use catalog::{LossPartEntry, LossPartId, PARTS};
pub use loss_column::{ColumnEntry, LossColumn, COLUMNS};
pub use loss_part::{LossPart, PartLosses, PartState, ShaftParts, StageGears, COLUMN_COUNT};
