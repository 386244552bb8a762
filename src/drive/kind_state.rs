//! What a stage kind keeps of one pass of the drive's walk ([`KindState`]), puts into the report's
//! point of the stage ([`KindPoint`]) and into the report's inputs of the stage ([`KindInputs`]),
//! one variant a kind that has anything of its own: a parallel stage keeps nothing beyond its η
//! and its mesh forces, which every stage's point carries, and has no inputs beyond every stage's.

use serde::{Deserialize, Serialize};

use super::layout::Member;
use super::planetary::flow::PlanetaryState;
use super::planetary::inputs::PlanetaryInputs;
use super::planetary::point::PlanetaryPoint;

/// A stage as one pass of the walk evaluated it, for its point in the report.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum KindState {
    Planetary(PlanetaryState),
}

/// A stage kind's own inputs (in report.json under the kind's name), from its
/// `StageModel::inputs`.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub enum KindInputs {
    #[serde(rename = "planetary")]
    Planetary(PlanetaryInputs),
}

/// A stage kind's part of the stage's point (in report.json under the kind's name).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum KindPoint {
    #[serde(rename = "planetary")]
    Planetary(PlanetaryPoint),
}

impl KindPoint {
    /// The name of the member on place `m` when the member on `driving` drives.
    pub fn member_name(&self, m: Member, driving: Member) -> &'static str {
        match self {
            KindPoint::Planetary(p) if m == driving => p.driving_member.name(),
            KindPoint::Planetary(p) => p.driven_member.name(),
        }
    }

    /// The values of its kind's columns of drive_records.csv (`StageModel::record_columns`).
    pub fn record_values(&self) -> Vec<f64> {
        match self {
            KindPoint::Planetary(p) => p.record_values(),
        }
    }
}
