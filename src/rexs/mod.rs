//! REXS import: a gear unit exported by KISSsoft, FVA Workbench, MASTA or Bearinx as REXS (the
//! FVA's Reusable Engineering EXchange Standard, rexs.info; versions 1.0–1.7 and 2.0) read into a
//! commented `.gear` scene (README, "From other tools (REXS)").
//!
//! ```text
//!  .rexs / .rexsj / .rexsz ─formats─▶ RexsModel ─gear_unit─▶ GearUnit ─write_scene─▶ .gear text
//!   (XML, JSON, zip)                   (components,            (stages, shafts,          (each item names
//!                                       relations, cases)       bearings, cases)           its REXS id)
//! ```
//! What the model has and gearloss does not use, and every value gearloss had to choose, are
//! warnings (and comments in the scene); a value it needs and cannot find is an error naming the
//! component and the attribute.

pub(crate) mod bearing_sizes;
pub(crate) mod bearings;
pub(crate) mod cases;
pub(crate) mod formats;
pub(crate) mod gear_unit;
pub(crate) mod gears;
pub(crate) mod joined_shafts;
pub(crate) mod model;
pub(crate) mod planetary;
pub(crate) mod planetary_hold;
pub(crate) mod planetary_stages;
pub(crate) mod profile_shift;
pub(crate) mod scene_text;
pub(crate) mod shaft_sections;
pub(crate) mod shafts;
pub(crate) mod stage_data;
pub(crate) mod units;
pub(crate) mod write_planetary;
pub(crate) mod write_scene;
pub(crate) mod xml_depth;

mod error;
mod import;

pub use error::RexsError;
pub use import::{import, import_file, Imported};
