//! The operating-point sections of the report (contact-state table, friction at the table rows) and
//! the curves the plots draw.

use serde::{Deserialize, Serialize};

use super::friction;
use super::number::{m, mps, pa, Num, Q};
use crate::evaluate::{Evaluation, PointEvaluation};
use crate::geometry::ContactPoint;
use crate::mesh::MeshProblem;

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct OperatingPointReport {
    /// The point's number in the sweep, 0-based (records.csv's `point` is this + 1).
    pub index: usize,
    pub pinion_torque: Q,
    pub pinion_speed: Q,
    /// The operating point as the user wrote its units, e.g. `239.3 N*m, 100 rpm`.
    pub label: String,
    pub wheel_speed: Q,
    pub normal_load: Q,
    pub mesh_period: Q,
    pub pitch_line_velocity: Q,
    pub contact: Vec<ContactRow>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub film: Option<Vec<friction::FilmRow>>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub friction: Vec<friction::LawReport>,
    /// The plot of μ, η and local power loss at this point, when drawn.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<String>,
}

/// The contact state at one point of the line of action.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ContactRow {
    pub point: Option<String>,
    pub distance_from_t1: Q,
    pub s: Q,
    pub radius_of_curvature_pinion: Q,
    pub radius_of_curvature_wheel: Q,
    pub reduced_radius: Q,
    pub velocity_pinion: Q,
    pub velocity_wheel: Q,
    pub sliding_velocity: Q,
    pub sum_velocity: Q,
    pub entrainment_velocity: Q,
    pub slide_to_roll: Num,
    pub pairs_in_contact: usize,
    pub load_share: Num,
    pub load_per_width: Q,
    pub hertz_pressure: Q,
    pub hertz_half_width: Q,
}

/// Curves along the line of action, for plots: x in m from T1.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct Curves {
    #[serde(with = "super::floats")]
    pub u: Vec<f64>,
    /// (label, v_s in m/s) for each plotted speed.
    #[serde(with = "super::floats")]
    pub sliding_velocity: Vec<(String, Vec<f64>)>,
    #[serde(with = "super::floats")]
    pub slide_to_roll: Vec<f64>,
    /// (label, p_H in Pa) for each plotted torque.
    #[serde(with = "super::floats")]
    pub hertz_pressure: Vec<(String, Vec<f64>)>,
    /// Load share of one contact along the line of action.
    #[serde(with = "super::floats")]
    pub load_share: Vec<f64>,
    /// A B P D E from T1 (m).
    #[serde(with = "super::floats")]
    pub marks: Vec<(String, f64)>,
    /// Per plotted operating point: μ, local power loss along the line of action, η over a cycle.
    pub points: Vec<PointCurves>,
    /// η(τ) sample times (mesh periods).
    #[serde(with = "super::floats")]
    pub tau: Vec<f64>,
}

/// Curves of one operating point.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct PointCurves {
    pub file: String,
    pub label: String,
    /// (law label, signed μ)
    #[serde(with = "super::floats")]
    pub mu: Vec<(String, Vec<f64>)>,
    /// Composite regime bands along the line of action: (from, to, regime) in m.
    #[serde(with = "super::floats")]
    pub regime_bands: Vec<(f64, f64, String)>,
    /// (law label, W)
    #[serde(with = "super::floats")]
    pub power_loss: Vec<(String, Vec<f64>)>,
    /// (law label · formulation, η)
    #[serde(with = "super::floats")]
    pub efficiency: Vec<(String, Vec<f64>)>,
}

pub(super) fn contact_row(point: Option<&'static str>, c: &ContactPoint) -> ContactRow {
    ContactRow {
        point: point.map(String::from),
        distance_from_t1: m(c.u),
        s: m(c.s),
        radius_of_curvature_pinion: m(c.radius_of_curvature[0]),
        radius_of_curvature_wheel: m(c.radius_of_curvature[1]),
        reduced_radius: m(c.reduced_radius),
        velocity_pinion: mps(c.rolling_velocity[0]),
        velocity_wheel: mps(c.rolling_velocity[1]),
        sliding_velocity: mps(c.sliding_velocity),
        sum_velocity: mps(c.sum_velocity),
        entrainment_velocity: mps(c.entrainment_velocity),
        slide_to_roll: Num(c.slide_to_roll),
        pairs_in_contact: c.pairs_in_contact,
        load_share: Num(c.load_share),
        load_per_width: Q::new(c.load_per_width, "N/m"),
        hertz_pressure: pa(c.hertz_pressure),
        hertz_half_width: m(c.hertz_half_width),
    }
}

pub(super) fn operating_point_report(
    problem: &MeshProblem,
    eval: &Evaluation,
    pe: &PointEvaluation,
) -> OperatingPointReport {
    let g = &eval.geometry;
    let label = eval.cases[pe.case].label.clone();
    OperatingPointReport {
        index: eval.cases[pe.case].index,
        pinion_torque: Q::new(pe.state.pinion_torque, "N*m"),
        pinion_speed: Q::new(pe.state.pinion_speed, "rad/s"),
        label,
        wheel_speed: Q::new(g.wheel_speed(&pe.state).abs(), "rad/s"),
        normal_load: Q::new(g.normal_load(&pe.state), "N"),
        mesh_period: Q::new(pe.mesh_period, "s"),
        pitch_line_velocity: mps(pe.state.pinion_speed * g.working_pitch_radius[0]),
        contact: pe.table.iter().map(|(n, c)| contact_row(*n, c)).collect(),
        film: friction::film_rows(pe),
        friction: problem
            .friction
            .iter()
            .zip(&pe.laws)
            .map(|(spec, law)| friction::law_report(spec, pe, law))
            .collect(),
        plot: None,
    }
}

pub(super) fn curves(problem: &MeshProblem, eval: &Evaluation) -> Curves {
    let c = &eval.contact_curves;
    Curves {
        u: c.u.clone(),
        sliding_velocity: c.sliding_velocity.clone(),
        slide_to_roll: c.slide_to_roll.clone(),
        hertz_pressure: c.hertz_pressure.clone(),
        load_share: c.load_share.clone(),
        marks: eval.geometry.named_points().into_iter().map(|(n, u)| (n.to_string(), u)).collect(),
        points: point_curves(problem, eval),
        tau: crate::evaluate::cycle_times(),
    }
}

pub(super) fn point_curves(problem: &MeshProblem, eval: &Evaluation) -> Vec<PointCurves> {
    let mut out = Vec::new();
    for pe in &eval.points {
        if !pe.has_curves || pe.laws.is_empty() {
            continue;
        }
        let mut pc = PointCurves {
            file: format!("point_{}_friction.svg", eval.cases[pe.case].index + 1),
            label: eval.cases[pe.case].label.clone(),
            ..Default::default()
        };
        for (spec, law) in problem.friction.iter().zip(&pe.laws) {
            let Some(c) = &law.curves else { continue };
            let label = friction::law_label(spec);
            pc.mu.push((label.clone(), c.mu.clone()));
            match &c.power_loss_equal {
                Some(equal) => {
                    pc.power_loss.push((format!("{label}, shared by stiffness"), c.power_loss.clone()));
                    pc.power_loss.push((format!("{label}, shared equally"), equal.clone()));
                }
                None => pc.power_loss.push((label.clone(), c.power_loss.clone())),
            }
            for (f, eta) in &c.efficiency {
                pc.efficiency.push((format!("{label} {}", f.name()), eta.clone()));
            }
            pc.regime_bands.extend(law.regime_bands.iter().map(|(a, b, r)| (*a, *b, format!("{r:?}"))));
        }
        out.push(pc);
    }
    out
}
