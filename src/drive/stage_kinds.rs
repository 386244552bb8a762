//! The stage kinds as the drive's walk reads them: one row a kind, from the kind's data in the
//! stage ([`crate::drive::kinematics::StageKind`]) to its [`StageModel`].

use super::internal_stage::INTERNAL_STAGE;
use super::kinematics::StageKind;
use super::layout::{Member, Stage};
use super::parallel_stage::PARALLEL_STAGE;
use super::stage_model::StageModel;

impl Stage {
    /// The stage's kind as the walk reads it: one row a kind.
    pub(crate) fn model(&self) -> &dyn StageModel {
        match &self.kind {
            StageKind::Parallel => &PARALLEL_STAGE,
            StageKind::Planetary(layout) => layout.as_ref(),
            StageKind::Internal => &INTERNAL_STAGE,
        }
    }

    /// The name of the member on place `m`: pinion or wheel, or the kind's own name of it.
    pub fn member_name(&self, m: Member) -> &'static str {
        self.model().member_name(m)
    }

    /// The stage's meshes at `point` as the walk evaluated them (its kind's
    /// `StageModel::mesh_states`).
    pub fn mesh_states(&self, point: &super::point::StagePoint) -> Vec<super::mesh_state::MeshState> {
        self.model().mesh_states(self, point)
    }
}
