//! A gear unit's planetary stages together, as the unit's reading ([`super::gear_unit`]) and its
//! scene ([`super::write_scene`]) need them: read from the model's `planetary_stage`s, the
//! cylindrical stages that are their meshes (not read as stages of their own), the components
//! that hold a member, the shafts a carrier's cheeks join, the members' places on shafts and the
//! suns that float among their planets. The gear unit's reading asks these questions of every
//! unit and never names a planetary member itself.

use super::error::RexsError;
use super::model::RexsModel;
use super::planetary::{Member, PlanetaryData};
use super::stage_data::{GearData, StageData};

/// Component types the planetary stages' reading reads (`ring_gear` is any internal gear's).
pub(crate) const READ: &[&str] = &["planetary_stage", "planet_carrier"];

/// Every planetary stage of a gear unit.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct PlanetaryStages(pub(crate) Vec<PlanetaryData>);

impl PlanetaryStages {
    /// Every `planetary_stage` of the model; each one that fails joins `errors`.
    pub(crate) fn read(model: &RexsModel, warnings: &mut Vec<String>, errors: &mut Vec<RexsError>) -> Self {
        let mut out = Vec::new();
        for c in model.of_kind("planetary_stage") {
            match super::planetary::read_planetary(model, c, warnings) {
                Ok(stage) => out.push(stage),
                Err(e) => errors.push(e),
            }
        }
        PlanetaryStages(out)
    }

    /// The cylindrical stages of the model that are a planetary stage's meshes.
    pub(crate) fn meshes_in(model: &RexsModel) -> Vec<u64> {
        model.of_kind("planetary_stage").flat_map(|p| super::planetary::meshes_of(model, p.id)).collect()
    }

    /// The components that hold a planetary stage's member to the casing (a coupling that would
    /// otherwise be refused as a shift).
    pub(crate) fn holds(model: &RexsModel) -> Vec<u64> {
        super::planetary_hold::member_joints(model)
    }

    pub(crate) fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// Each turning carrier's shaft and the shafts of its other cheeks, which are rigidly one with it.
    pub(crate) fn carrier_cheeks(&self) -> Vec<(u64, Vec<u64>)> {
        self.0.iter().filter_map(|p| p.carrier.as_ref().map(|(s, others, _)| (*s, others.clone()))).collect()
    }

    /// The gears that sit on the drive's shafts (suns and rings; planets turn on the carrier).
    pub(crate) fn gears_on_shafts(&mut self) -> impl Iterator<Item = &mut GearData> {
        self.0.iter_mut().flat_map(|p| [&mut p.sun, &mut p.ring])
    }

    /// The turning members' places on the drive's shafts: (shaft, at mm).
    pub(crate) fn places(&self) -> Vec<(u64, f64)> {
        self.0.iter().flat_map(|p| p.places()).collect()
    }

    /// The shafts of suns that float: a turning sun among two planets or more, alone on its shaft
    /// (no gear of `stages` on it), which one bearing place carries.
    pub(crate) fn floating_suns(&self, stages: &[StageData]) -> Vec<u64> {
        self.0
            .iter()
            .filter(|p| p.planet_ids.len() >= 2 && p.held != Member::Sun)
            .map(|p| p.sun.shaft)
            .filter(|s| !stages.iter().any(|st| st.gears.iter().any(|g| g.shaft == *s)))
            .collect()
    }

    /// Each stage as the scene writes it.
    pub(crate) fn write(&self, w: &mut String) {
        for p in &self.0 {
            super::write_planetary::planetary_stage(w, p);
        }
    }
}
