//! A stage kind's own inputs in a drive's report, one variant a kind that has them (a parallel
//! stage's are every stage's): the report's part of the stage-kind catalogue.

use serde::{Deserialize, Serialize};

use super::planetary_inputs::PlanetaryInputs;
use crate::drive::kinematics::StageKind;
use crate::drive::{Drive, Stage};
use crate::model::GearPair;

/// A stage kind's own inputs (in report.json under the kind's name).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub enum KindInputs {
    #[serde(rename = "planetary")]
    Planetary(PlanetaryInputs),
}

/// The inputs of `stage`'s kind; `further` are the pairs of its meshes beyond its own pair.
pub(super) fn kind_inputs(layout: &Drive, stage: &Stage, further: &[GearPair]) -> Option<Box<KindInputs>> {
    match &stage.kind {
        StageKind::Parallel | StageKind::Internal => None,
        StageKind::Planetary(p) => super::planetary_inputs::planetary_inputs(layout, stage, p, further.first())
            .map(|i| Box::new(KindInputs::Planetary(i))),
    }
}
