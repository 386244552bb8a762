//! The checked drive as lowering builds it: shafts with their bearing places and seals, stages
//! joining two shafts, the input and the output shaft, and the chain of stages the power runs
//! through. Plain SI; the stages' gear pairs themselves stay with the scene
//! ([`crate::model::SceneDrive`]), the drive keeps what its physics reads.

use super::kinematics::StageKind;
use crate::losses::{Bearing, Lubrication, Seal};

/// A stage's member: the pinion (index 0) or the wheel (index 1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Member {
    Pinion,
    Wheel,
}

impl Member {
    pub fn index(self) -> usize {
        self as usize
    }

    pub fn other(self) -> Member {
        match self {
            Member::Pinion => Member::Wheel,
            Member::Wheel => Member::Pinion,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Member::Pinion => "pinion",
            Member::Wheel => "wheel",
        }
    }
}

/// The hand of a helix; a spur gear has none.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum Hand {
    Right,
    Left,
}

impl Hand {
    /// +1 for a right hand, −1 for a left.
    pub fn sign(self) -> f64 {
        match self {
            Hand::Right => 1.0,
            Hand::Left => -1.0,
        }
    }
}

/// Where a stage's gear sits: its shaft (index into [`Drive::shafts`]) and the axial coordinate of
/// its face mid-plane on that shaft (m).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct GearPlace {
    pub shaft: usize,
    pub at: f64,
}

/// One shaft: its name, its bearing places (each with `position`, m on the shaft's own axial
/// coordinate), which place locates (takes the whole axial force), and its seals.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Shaft {
    pub name: String,
    pub bearings: Vec<Bearing>,
    /// Index into `bearings` of the place that takes the axial force.
    pub locating: usize,
    /// Whether a place said `locating` (else the first takes the axial force, and the report says so).
    pub locating_given: bool,
    pub seals: Vec<Seal>,
    /// The shaft's body for the elastic beam (sections, material); None: a rigid beam on two places.
    pub body: Option<super::shaft_beam::ShaftBody>,
    /// Per bearing place: its radial stiffness (N/m); None (or an empty list) is rigid.
    pub stiffness: Vec<Option<f64>>,
}

/// One stage: its kind with the kind's own data (the catalogue; what the walk reads of it is the
/// kind's `StageModel`), its two gears' places, the teeth and the pinion's hand, its direction φ
/// (rad; the line from the pinion shaft's centre to the wheel shaft's, seen from +z; for a kind of
/// several meshes, its first), its lubrication (the no-load parts: churning and jet impulse charged
/// on the pinion's shaft, each gear's windage on its own; a kind may charge another body).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Stage {
    pub name: String,
    pub kind: StageKind,
    /// [pinion, wheel].
    pub places: [GearPlace; 2],
    pub teeth: [u32; 2],
    /// The pinion's hand (the wheel's is the other); None for a spur stage.
    pub hand: Option<Hand>,
    pub direction: f64,
    pub lubrication: Option<Lubrication>,
}

impl Stage {
    /// The member on `shaft`, if the stage has a gear there.
    pub fn member_on(&self, shaft: usize) -> Option<Member> {
        [Member::Pinion, Member::Wheel].into_iter().find(|m| self.places[m.index()].shaft == shaft)
    }
}

/// Which end of the drive a value is given at.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ShaftEnd {
    Input,
    Output,
}

impl ShaftEnd {
    pub fn name(self) -> &'static str {
        match self {
            ShaftEnd::Input => "input",
            ShaftEnd::Output => "output",
        }
    }
}

/// At which ends the operating sweeps are given (the values are the scene's sweeps).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub struct DriveOperating {
    pub torque_at: ShaftEnd,
    pub speed_at: ShaftEnd,
}

/// The checked drive.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Drive {
    pub shafts: Vec<Shaft>,
    pub stages: Vec<Stage>,
    pub input: usize,
    pub output: usize,
    /// The chain from the input shaft to the output: the stages in the order the power meets them in
    /// drive, each with the member on the side of the input.
    pub chain: Vec<(usize, Member)>,
    pub operating: DriveOperating,
}

impl Drive {
    /// The shafts in the order of the chain, input first.
    pub fn shaft_order(&self) -> Vec<usize> {
        let mut out = vec![self.input];
        for &(k, m) in &self.chain {
            out.push(self.stages[k].places[m.other().index()].shaft);
        }
        out
    }

    /// The chain from the input to the output through the stages, or None when no chain joins them
    /// (lowering refuses such a drive). Stages must join distinct shafts and form no loop.
    pub fn find_chain(stages: &[Stage], input: usize, output: usize) -> Option<Vec<(usize, Member)>> {
        let mut chain = Vec::new();
        let mut at = input;
        let mut used = vec![false; stages.len()];
        while at != output {
            let (k, m) = stages
                .iter()
                .enumerate()
                .filter(|(k, _)| !used[*k])
                .find_map(|(k, s)| s.member_on(at).map(|m| (k, m)))?;
            used[k] = true;
            chain.push((k, m));
            at = stages[k].places[m.other().index()].shaft;
        }
        Some(chain)
    }
}
