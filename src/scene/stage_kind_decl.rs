//! A stage's kind as the scene writes it, one variant a kind (a `gears` block: a pair on parallel
//! shafts; a `planetary` block: a planetary set), and what lowering asks of a kind beyond the
//! stage's own pair: its further meshes' pairs, the kind the drive's physics reads, how its
//! members' shafts sit, whether the dynamic models (one pair on fixed axes) apply.

use std::collections::BTreeMap;

use super::ast::{Block, Name};
use super::lower_planetary::PlanetaryDecl;
use crate::diagnostics::Diagnostic;
use crate::drive::kinematics::StageKind;
use crate::drive::Hand;
use crate::losses::Lubrication;
use crate::model::{GearPair, Material};

/// A stage kind as the scene writes it: the block inside `stage` that makes a stage of this kind,
/// what such a stage is (in words and as an example), and its lowering.
pub(super) struct StageBlock {
    pub block: &'static str,
    pub is: &'static str,
    pub example: &'static str,
    /// Lowers the kind's block (the stage block, the kind's block) given the stage's lubrication.
    pub lower: LowerKind,
}

/// A kind's lowering: of (the stage block, the kind's block), given the stage's lubrication.
pub(super) type LowerKind =
    fn((&Block, &Block), &BTreeMap<&str, Material>, Option<&Lubrication>, &mut Vec<Diagnostic>) -> Option<KindLowered>;

/// What a kind's block lowers to: the stage's own pair, its two places [(shaft, at)], the pinion's
/// (a planetary set's sun's) hand, and the kind.
pub(super) struct KindLowered {
    pub pair: GearPair,
    pub places: [(Name, f64); 2],
    pub hand: Option<Hand>,
    pub kind: StageDeclKind,
}

/// The blocks a stage is written with, one row a kind (the parallel and the internal stage share
/// `gears`: an internal pair's stage is internal).
pub(super) const STAGE_BLOCKS: &[StageBlock] = &[
    StageBlock {
        block: "gears",
        is: "one pair on parallel shafts",
        example: "`gears { module = 2 mm ... pinion { teeth = 23  shaft = motor  at = 50 mm } wheel { ... } }`",
        lower: |blocks, materials, lubrication, errors| {
            let (pair, places, hand) =
                super::lower_gears_stage::lower_gears_stage(blocks, materials, lubrication, errors)?;
            Some(KindLowered { pair, places, hand, kind: StageDeclKind::Parallel })
        },
    },
    StageBlock {
        block: "planetary",
        is: "one planetary set",
        example: "a `planetary { ... }` block",
        lower: |(_, block), materials, _, errors| {
            let (pair, places, decl) = super::lower_planetary::lower_planetary(block, materials, errors)?;
            Some(KindLowered { pair, places, hand: decl.sun_hand, kind: StageDeclKind::Planetary(Box::new(decl)) })
        },
    },
];

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
