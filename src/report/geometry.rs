//! The geometry section of the report: both gears, the pair, and the named points of the line of action.

use serde::{Deserialize, Serialize};

use super::number::{m, pa, rad, Num, Q};
use crate::evaluate::Evaluation;
use crate::geometry::{PairGeometry, TipSource};
use crate::model::LoadSharing;

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct GearReport {
    pub teeth: u32,
    pub profile_shift: Num,
    pub pitch_diameter: Q,
    pub base_diameter: Q,
    pub tip_diameter: Q,
    pub tip_diameter_source: TipSource,
    pub working_pitch_diameter: Q,
    pub addendum_contact_ratio: Num,
    pub tip_thickness: Q,
    pub undercut_limit: Num,
}

/// Positions along the line of action, from T1.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct PointsReport {
    pub A: Q,
    /// B = E − p_b and D = A + p_b, the limits of single contact: only for ε_α < 2.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub B: Option<Q>,
    pub P: Q,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub D: Option<Q>,
    pub E: Q,
    /// For ε_α ≥ 2: every point where the number of pairs changes (A + k p_b, E − k p_b), in order.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub pair_changes: Vec<NamedPoint>,
}

/// A named point of the line of action.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct NamedPoint {
    pub name: String,
    pub distance_from_t1: Q,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct GeometryReport {
    /// Normal module (the module of a spur pair).
    pub module: Q,
    /// Normal pressure angle.
    pub pressure_angle: Q,
    /// β at the reference circle (0 for spur).
    pub helix_angle: Q,
    pub gear_ratio: Num,
    pub center_distance: Q,
    pub center_distance_source: String,
    pub zero_backlash_center_distance: Q,
    pub operating_pressure_angle: Q,
    pub zero_backlash_pressure_angle: Q,
    pub face_width: Q,
    pub base_pitch: Q,
    pub line_of_action_length: Q,
    pub points_from_t1: PointsReport,
    /// The transverse contact ratio ε_α (also `transverse_contact_ratio`).
    pub contact_ratio: Num,
    pub transverse_contact_ratio: Num,
    /// ε_β = b sin β / (π m_n) (0 for spur).
    pub overlap_ratio: Num,
    /// ε_γ = ε_α + ε_β.
    pub total_contact_ratio: Num,
    /// Helical pairs: transverse values, contact lines and regions of the cycle.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub helical: Option<super::helical::HelicalReport>,
    /// Ohlendorf's gear loss factor H_V.
    pub ohlendorf_loss_factor: Num,
    pub reduced_modulus: Q,
    pub load_sharing: LoadSharing,
    pub pinion: GearReport,
    pub wheel: GearReport,
    /// An internal pair (the wheel a ring; ISO 21771's signs on u, T1T2 and the ring's ρ).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub internal: bool,
}

pub(super) fn gear_report(g: &PairGeometry, i: usize) -> GearReport {
    GearReport {
        teeth: g.teeth[i],
        profile_shift: Num(g.profile_shift[i]),
        pitch_diameter: m(2.0 * g.pitch_radius[i]),
        base_diameter: m(2.0 * g.base_radius[i]),
        tip_diameter: m(2.0 * g.tip_radius[i]),
        tip_diameter_source: g.tip_source[i],
        working_pitch_diameter: m(2.0 * g.working_pitch_radius[i]),
        addendum_contact_ratio: Num(g.addendum_contact_ratio[i]),
        tip_thickness: m(g.tip_thickness[i]),
        undercut_limit: Num(g.undercut_limit[i]),
    }
}

pub(super) fn geometry_report(eval: &Evaluation) -> GeometryReport {
    let helical = super::helical::helical_report(&eval.geometry, super::helical::axial_forces(eval));
    pair_geometry_report(&eval.geometry, helical, eval.ohlendorf_loss_factor, eval.reduced_modulus, eval.sharing)
}

/// The geometry report of pair `g` (with its helical report, `helical`, for a helical pair) and
/// what its evaluation reads beside it: Ohlendorf's H_V (as
/// the pair's load sharing integrates it), E' and the load sharing. A pair's report and each stage
/// mesh of a drive's.
pub(super) fn pair_geometry_report(
    g: &PairGeometry,
    helical: Option<super::helical::HelicalReport>,
    h_v: f64,
    e_r: f64,
    sharing: LoadSharing,
) -> GeometryReport {
    let p = &g.points;
    GeometryReport {
        module: m(g.module),
        pressure_angle: rad(g.pressure_angle),
        helix_angle: rad(g.helix_angle),
        gear_ratio: Num(g.gear_ratio),
        center_distance: m(g.center_distance),
        center_distance_source: if g.center_distance_given { "given" } else { "zero_backlash" }.into(),
        zero_backlash_center_distance: m(g.zero_backlash_center_distance),
        operating_pressure_angle: rad(g.operating_pressure_angle),
        zero_backlash_pressure_angle: rad(g.zero_backlash_pressure_angle),
        face_width: m(g.face_width),
        base_pitch: m(g.base_pitch),
        line_of_action_length: m(g.line_of_action_length),
        points_from_t1: {
            let single = g.contact_ratio < 2.0;
            PointsReport {
                A: m(p.a),
                B: single.then(|| m(p.b)),
                P: m(p.p),
                D: single.then(|| m(p.d)),
                E: m(p.e),
                pair_changes: if single {
                    Vec::new()
                } else {
                    g.pair_change_points()
                        .into_iter()
                        .map(|(name, u)| NamedPoint { name: name.into(), distance_from_t1: m(u) })
                        .collect()
                },
            }
        },
        contact_ratio: Num(g.contact_ratio),
        transverse_contact_ratio: Num(g.contact_ratio),
        overlap_ratio: Num(g.overlap_ratio),
        total_contact_ratio: Num(g.total_contact_ratio),
        helical,
        ohlendorf_loss_factor: Num(h_v),
        reduced_modulus: pa(e_r),
        load_sharing: sharing,
        internal: g.internal,
        pinion: gear_report(g, 0),
        wheel: gear_report(g, 1),
    }
}
