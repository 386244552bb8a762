//! The helical part of the geometry report: helix angles, overlap and total contact ratios, the
//! contact lines' total length L(t) (located extremes: L is piecewise linear, so they lie at break
//! times), the regions of the mesh cycle with the state of each line, and the axial force.

use serde::{Deserialize, Serialize};

use super::number::{m, rad, Num, Q};
use crate::evaluate::Evaluation;
use crate::geometry::regions::Region;

/// A value of L(τ) and where in the cycle it occurs (τ in mesh periods).
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
pub struct LengthAt {
    pub value: Q,
    pub tau: Num,
}

/// The two ends (u, z) of a contact line (m).
pub(crate) type LineEnds = [(f64, f64); 2];

/// The axial force at one reported operating point.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct AxialForce {
    pub operating_point: String,
    pub value: Q,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct HelicalReport {
    pub base_helix_angle: Q,
    pub transverse_module: Q,
    pub transverse_pressure_angle: Q,
    /// b tan β_b: how far apart along the transverse line of action a line's two ends lie.
    pub line_lead: Q,
    /// L̄ = ε_α b / cos β_b.
    pub mean_contact_length: Q,
    pub contact_length_min: LengthAt,
    pub contact_length_max: LengthAt,
    /// Fewest and most lines in contact over the cycle.
    pub lines_in_contact: [usize; 2],
    pub regions: Vec<Region>,
    /// F_a = F_t tan β, F_t = T_p / r_1, at each reported operating point.
    pub axial_force: Vec<AxialForce>,
    /// For the plot: the path of contact (T1A, T1P, T1E, b/2 in m) and the contact lines at a few
    /// instants, (τ, [(u, z) at both ends]).
    #[serde(with = "super::floats")]
    pub path: [f64; 4],
    #[serde(with = "super::floats")]
    pub lines_at: Vec<(f64, Vec<LineEnds>)>,
    /// For the plot: τ, L, L on the approach side, L on the recess side (m), over one cycle.
    #[serde(with = "super::floats")]
    pub length_curve: [Vec<f64>; 4],
}

/// Instants at which the plot draws the contact lines.
pub(crate) const PLOTTED_INSTANTS: [f64; 4] = [0.0, 0.25, 0.5, 0.75];

/// F_a = F_t tan β of pair `g` at each of a pair's operating points.
pub(super) fn axial_forces(eval: &Evaluation) -> Vec<AxialForce> {
    let g = &eval.geometry;
    eval.cases
        .iter()
        .map(|c| AxialForce {
            operating_point: c.label.clone(),
            value: Q::new(g.axial_force(c.state.pinion_torque), "N"),
        })
        .collect()
}

pub(super) fn helical_report(g: &crate::geometry::PairGeometry, axial_force: Vec<AxialForce>) -> Option<HelicalReport> {
    if !g.is_helical() {
        return None;
    }
    let breaks = g.cycle_break_times(&[]);
    // L is continuous and linear between breaks: its extremes are at the breaks.
    let at: Vec<(f64, f64)> = breaks.iter().map(|t| (*t, g.contact_length(t.min(1.0 - 1e-15)))).collect();
    // (The breaks hold τ = 0 at least.)
    let min = at.iter().copied().min_by(|a, b| a.1.total_cmp(&b.1))?;
    let max = at.iter().copied().max_by(|a, b| a.1.total_cmp(&b.1))?;
    let regions = g.cycle_regions();
    let lines_at = PLOTTED_INSTANTS
        .iter()
        .map(|t| (*t, g.contact_lines(*t).iter().map(|l| [(l.u[0], l.z[0]), (l.u[1], l.z[1])]).collect()))
        .collect();
    let mut taus: Vec<f64> = (0..=200).map(|i| i as f64 / 200.0).collect();
    taus.extend(breaks.iter().copied());
    taus.sort_by(f64::total_cmp);
    taus.dedup();
    let mut length_curve: [Vec<f64>; 4] = Default::default();
    for t in taus {
        let tt = t.min(1.0 - 1e-15);
        let [a, r] = g.contact_length_by_side(tt);
        length_curve[0].push(t);
        length_curve[1].push(g.contact_length(tt));
        length_curve[2].push(a);
        length_curve[3].push(r);
    }
    let counts = regions.iter().map(|r| r.lines.len());
    Some(HelicalReport {
        base_helix_angle: rad(g.base_helix_angle),
        transverse_module: m(g.transverse_module),
        transverse_pressure_angle: rad(g.transverse_pressure_angle),
        line_lead: m(g.line_lead()),
        mean_contact_length: m(g.mean_contact_length()),
        contact_length_min: LengthAt { value: m(min.1), tau: Num(min.0) },
        contact_length_max: LengthAt { value: m(max.1), tau: Num(max.0) },
        lines_in_contact: [counts.clone().min().unwrap_or(0), counts.max().unwrap_or(0)],
        regions,
        axial_force,
        path: [g.points.a, g.points.p, g.points.e, 0.5 * g.face_width],
        lines_at,
        length_curve,
    })
}
