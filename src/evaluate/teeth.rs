//! The teeth as bodies, when a scene asks for them (`transmission_error`, `mesh_stiffness =
//! potential_energy`, or a pair that gives a relief, root or bore): the pair's stiffness, ISO 6336-1
//! Method B beside it, the largest single-pair stiffness located, and the transmission error at
//! each asked torque.

use serde::{Deserialize, Serialize};

use super::records::{RowKind, SummaryRow};
use crate::geometry::teeth::iso_6336_method_b::{iso_6336_method_b, IsoStiffness};
use crate::geometry::teeth::load_sharing::LoadSharing;
use crate::geometry::teeth::transmission_error::TransmissionError;
use crate::geometry::{OperatingState, PairGeometry};
use crate::model::Scene;
use crate::numerics::roots::extrema;

/// What the report's stiffness and transmission-error sections read.
#[derive(Debug, Clone)]
pub struct TeethDetails {
    pub sharing: LoadSharing,
    pub iso: IsoStiffness,
    /// (k_w, s) of the stiffest single pair, located.
    pub max_single: (f64, f64),
    pub transmission_error: Vec<TransmissionError>,
}

/// The details, when the scene asks for them (lowering has checked that they can be computed).
pub fn teeth_details(scene: &Scene, g: &PairGeometry) -> Option<TeethDetails> {
    if !scene.gears.wants_teeth(&scene.analyses, scene.dynamics.as_ref()) {
        return None;
    }
    let stiffness = scene.gears.pair_stiffness()?;
    let roots = stiffness.teeth.each_ref().map(|t| t.outline.input.root_radius);
    let iso = iso_6336_method_b(g, stiffness.teeth.each_ref().map(|t| t.young), roots);
    let xtol = 1e-13 * stiffness.path;
    let scale = stiffness.per_width(0.5 * stiffness.path);
    let (_, (k, at)) = extrema(|s| stiffness.per_width(s) / scale, &[0.0, stiffness.path], 32, xtol);
    let sharing = LoadSharing { stiffness, reliefs: scene.gears.reliefs() };
    let torques = scene.analyses.transmission_error.as_ref().map_or(&[][..], |t| &t.values[..]);
    let transmission_error =
        torques.iter().map(|t| sharing.transmission_error(t.value, g.base_radius[0])).collect::<Vec<_>>();
    Some(TeethDetails { sharing, iso, max_single: (k * scale, at), transmission_error })
}

/// The static transmission error at one torque as the record files carry it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SteRow {
    /// Peak-to-peak of δ over a mesh cycle (m), from the located extremes.
    #[serde(rename = "ste_peak_to_peak_m")]
    pub peak_to_peak: f64,
    /// Mean of δ over a mesh cycle (m), integrated, and its error estimate.
    #[serde(rename = "ste_mean_m")]
    pub mean: f64,
    #[serde(rename = "ste_mean_error_m")]
    pub mean_error: f64,
}

impl SteRow {
    /// The record files' column names, in order.
    pub const COLUMNS: [&'static str; 3] = ["ste_peak_to_peak_m", "ste_mean_m", "ste_mean_error_m"];

    pub fn of(te: &TransmissionError) -> SteRow {
        SteRow { peak_to_peak: te.peak_to_peak(), mean: te.mean, mean_error: te.mean_error }
    }

    /// The numbers in [`Self::COLUMNS`] order.
    pub fn numbers(&self) -> [f64; 3] {
        [self.peak_to_peak, self.mean, self.mean_error]
    }
}

/// One `transmission_error` record per torque of the analysis, in its order: point 0 (not an
/// operating point), the torque's index in the analysis, speed 0 (the error is static).
pub fn transmission_error_rows(details: &TeethDetails) -> Vec<SummaryRow> {
    details
        .transmission_error
        .iter()
        .enumerate()
        .map(|(i, te)| SummaryRow {
            kind: RowKind::TransmissionError,
            ste: Some(SteRow::of(te)),
            ..SummaryRow::blank(0, (i, 0), OperatingState { pinion_torque: te.pinion_torque, pinion_speed: 0.0 })
        })
        .collect()
}
