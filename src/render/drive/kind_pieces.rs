//! Each stage kind's piece of a drive's report.md, one row a kind: its words in the stages' table,
//! its notes and inputs after that table, its part of each operating point. A parallel stage has
//! none of its own; the internal stage a note; the planetary stage all of them (`planetary.rs`).
//! The rest of the drive's report.md never asks a stage's kind.

use crate::drive::DrivePoint;
use crate::render::markup::md;
use crate::report::drive_inputs::StageInputs;
use crate::report::units::Units;

use super::shown_units::Shown;

/// A kind's words for the stages' table (what it joins, its teeth, its ratio); None for a pair's.
pub(super) fn stage_words(s: &StageInputs) -> Option<(String, String, String)> {
    super::planetary::stage_words(s)
}

/// The kinds' notes on their stages, after the stages' table.
pub(super) fn notes(out: &mut String, stages: &[StageInputs]) {
    for s in stages.iter().filter(|s| s.internal) {
        md!(out, "\nStage `{}` is internal: its wheel is a ring gear with the pinion inside it, both turning the same way (a and u in size; the teeth push the pinion toward its own axis and the ring outward).", s.name);
    }
}

/// The kinds' own inputs, after the stages' notes.
pub(super) fn inputs(out: &mut String, stages: &[StageInputs], units: Units) {
    super::planetary::inputs(out, stages, units);
}

/// The kinds' part of one operating point, after the stages' table of the point.
pub(super) fn point(out: &mut String, d: &DrivePoint, u: Shown) {
    super::planetary::point(out, d, u);
}
