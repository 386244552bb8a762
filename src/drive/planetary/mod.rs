//! A planetary stage in the drive: the stage at one operating point from its two meshes'
//! efficiencies ([`flow`]), the forces on its members and planet bearings ([`loads`]) and what the
//! report reads ([`point`]). Its kinematics and layout are the catalogue's
//! [`super::kinematics::planetary`] entry; what the walk reads of it is its `StageModel`
//! (`super::planetary_stage`).

pub(crate) mod flow;
pub(crate) mod inputs;
pub(crate) mod loads;
pub(crate) mod point;

pub(crate) use crate::drive::kinematics::planetary::PlanetaryLayout;

impl crate::drive::layout::Stage {
    /// A planetary stage's layout; None for a stage of another kind.
    pub fn planetary(&self) -> Option<&PlanetaryLayout> {
        match &self.kind {
            crate::drive::kinematics::StageKind::Planetary(layout) => Some(layout.as_ref()),
            _ => None,
        }
    }
}
