//! A stage's kind as the scene writes it, one variant a kind (a `gears` block: a pair on parallel
//! shafts; a `planetary` block: a planetary set), and what lowering asks of a kind beyond the
//! stage's own pair: its further meshes' pairs, the kind the drive's physics reads, how its
//! members' shafts sit, whether the dynamic models (one pair on fixed axes) apply.

use super::lower_planetary::PlanetaryDecl;
use crate::drive::kinematics::StageKind;
use crate::model::GearPair;

/// A stage's kind as written.
pub(super) enum StageDeclKind {
    Parallel,
    /// The stage's own pair is the sun–planet pair and its places its two turning members'.
    Planetary(Box<PlanetaryDecl>),
}

impl StageDeclKind {
    /// The pairs of the stage's meshes after its own (mesh 1 on: a planetary set's planet–ring pair).
    pub(super) fn further_pairs(&self) -> Vec<&GearPair> {
        match self {
            StageDeclKind::Parallel => Vec::new(),
            StageDeclKind::Planetary(d) => vec![&d.ring_pair],
        }
    }

    /// The kind the drive's physics reads and the teeth on the stage's two places (a planetary
    /// set's sun's and ring's), from the stage's own pair; None where a pair's geometry fails
    /// (lowering reports that where it checks the pairs).
    pub(super) fn lowered(&self, pair: &GearPair) -> Option<(StageKind, [u32; 2])> {
        match self {
            StageDeclKind::Parallel => {
                let kind = if pair.internal { StageKind::Internal } else { StageKind::Parallel };
                Some((kind, [pair.pinion.teeth.value, pair.wheel.teeth.value]))
            }
            StageDeclKind::Planetary(d) => {
                let layout = d.layout(pair)?;
                let teeth = [layout.teeth[0], layout.teeth[2]];
                Some((StageKind::Planetary(Box::new(layout)), teeth))
            }
        }
    }

    /// For a kind whose members turn about one axis (their shafts coaxial, not a pair's centre
    /// distance apart), the words that name such a stage in a message.
    pub(super) fn coaxial(&self) -> Option<&'static str> {
        match self {
            StageDeclKind::Parallel => None,
            StageDeclKind::Planetary(_) => Some("planetary stage"),
        }
    }

    /// For a kind the dynamic models (one pair on fixed axes) do not apply to: the words naming
    /// such a stage and why.
    pub(super) fn off_fixed_axes(&self) -> Option<(&'static str, &'static str)> {
        match self {
            StageDeclKind::Parallel => None,
            StageDeclKind::Planetary(_) => Some(("planetary stage", "turns its planets on a moving carrier")),
        }
    }
}
