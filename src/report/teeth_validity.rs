//! Where the linear model of the teeth stops meaning anything: a warning for each torque of
//! `transmission_error` whose static deflection or Hertzian pressure leaves the range in which the
//! potential-energy stiffness (linear elastic tooth, linearised Hertz contact) holds.

use super::finding::{Finding, Severity};
use super::scene::units;
use super::teeth::TransmissionErrorReport;
use crate::evaluate::Evaluation;
use crate::geometry::contact::Sharing;
use crate::geometry::OperatingState;
use crate::mesh::MeshProblem;

/// The largest static transmission error the linear model is read at, as a fraction of the normal
/// module: the potential-energy method treats the tooth as a beam under small deflections (Yang &
/// Sun 1985; Tian 2004), and gear STEs are a few µm, 0.1 % of the module; at 1 % the deflection is
/// a tenth of the tip's thickness over a tooth's height and the geometry it was computed on has
/// moved.
pub(crate) const MAX_DEFLECTION_PER_MODULE: f64 = 0.01;

/// The largest Hertzian pressure the linear contact stiffness is read at (Pa): ISO 6336-5's highest
/// allowable contact stress σ_H,lim is 1.65 GPa (case-hardened, grade MQ); past 2 GPa the subsurface
/// of hardened steel reaches first yield (p₀ = 1.67 Y for a line contact, Tresca; Johnson, Contact
/// Mechanics, 1985, §6.2; Y ≈ 1.2–2 GPa when case-hardened), and the elastic Hertz term of the
/// compliance no longer describes the contact.
pub(crate) const MAX_HERTZ_PRESSURE: f64 = 2.0e9;

/// The warnings for every asked torque whose STE peak or single-pair Hertzian pressure at the
/// pitch point (the whole normal load on one pair: F_bn / b) leaves the linear range.
pub(super) fn linear_range_findings(
    problem: &MeshProblem,
    eval: &Evaluation,
    reports: &[TransmissionErrorReport],
) -> Vec<Finding> {
    let (g, e_r) = (&eval.geometry, eval.reduced_modulus);
    let u = units(problem);
    let m_n = problem.gears.module.value.value;
    let mut out = Vec::new();
    for te in reports {
        let torque = te.pinion_torque.si();
        let state = OperatingState { pinion_torque: torque, pinion_speed: 1.0 };
        let pitch = g.contact_at(g.points.p, &state, e_r, Sharing::Whole);
        let peak = te.max.value.si().abs().max(te.min.value.si().abs());
        let mut why = Vec::new();
        if peak > MAX_DEFLECTION_PER_MODULE * m_n {
            why.push(format!(
                "its static transmission error reaches {} ({:.1} % of the module; the linear tooth model holds to {} %)",
                u.micro().with(peak, 1),
                100.0 * peak / m_n,
                100.0 * MAX_DEFLECTION_PER_MODULE
            ));
        }
        if pitch.hertz_pressure > MAX_HERTZ_PRESSURE {
            why.push(format!(
                "the Hertzian pressure of one pair at the pitch point is {} (above {}, where hardened flanks yield)",
                u.pressure().with(pitch.hertz_pressure, 0),
                u.pressure().with(MAX_HERTZ_PRESSURE, 0)
            ));
        }
        if !why.is_empty() {
            out.push(Finding {
                severity: Severity::Warning,
                message: format!(
                    "transmission error at {}: {}; the linear stiffness model does not hold there and its numbers mean nothing",
                    u.torque().with(torque, 1),
                    why.join("; ")
                ),
            });
        }
    }
    out
}
