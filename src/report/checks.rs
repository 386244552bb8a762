//! Findings about the scene as a whole: notes on how it was read and warnings about its inputs.

use super::finding::{Finding, Severity};
use super::mesh_checks::{self, tip_warnings};
use crate::evaluate::Evaluation;
use crate::geometry::TipSource;
use crate::mesh::MeshProblem;
use crate::model::LoadSharing;

pub(super) fn findings(problem: &MeshProblem, eval: &Evaluation) -> Vec<Finding> {
    let g = &eval.geometry;
    let units = super::scene::units(problem);
    let len = units.length();
    let mut out = Vec::new();
    let note = |m: String| Finding { severity: Severity::Note, message: m };
    let warn = |m: String| Finding { severity: Severity::Warning, message: m };
    out.extend(
        crate::scene::summary::unused_mesh_blocks(
            &problem.analyses,
            problem.dynamics.is_some(),
            !problem.friction.is_empty(),
        )
        .into_iter()
        .map(warn),
    );
    out.extend(super::oil_checks::oil_warnings(problem.lubricant.as_ref(), &problem.operating, units));
    for (i, name) in [(0, "pinion"), (1, "wheel")] {
        out.push(note(match g.tip_source[i] {
            TipSource::Given => format!("{name} tip diameter as given: {}", len.with(2.0 * g.tip_radius[i], 4)),
            TipSource::AddendumRule if i == 1 && g.internal => format!(
                "ring tip diameter from the addendum rule with ISO 21771's signs, |d_a| = |d| − 2 m_n (1 + x) (inside the reference circle): {}",
                len.with(2.0 * g.tip_radius[i], 4)
            ),
            TipSource::AddendumRule if g.is_helical() => format!(
                "{name} tip diameter from the addendum rule d_a = m_t z + 2 m_n (1 + x): {}",
                len.with(2.0 * g.tip_radius[i], 4)
            ),
            TipSource::AddendumRule => format!(
                "{name} tip diameter from the addendum rule d_a = m (z + 2 + 2x): {}",
                len.with(2.0 * g.tip_radius[i], 4)
            ),
        }));
        out.extend(tip_warnings(g, i, name, len));
    }
    out.extend(mesh_checks::undercut_warnings(g, ["pinion", "wheel"], len));
    if !crate::geometry::loss_factor::closed_form_holds(g) {
        let [e1, e2] = g.addendum_contact_ratio;
        out.push(note(format!(
            "Ohlendorf's closed form H_V = π(u+1)/(z1 u cos β_b)(1 − ε_α + ε_1² + ε_2²) assumes the pitch point in single contact (ε_1, ε_2 ≤ 1); here ε_1 = {e1:.4}, ε_2 = {e2:.4}, where it would give {:.5}. H_V = {:.5} is the path integral it closes (equal sharing, n pairs in contact each 1/n of the load), the factor the mean efficiency follows and every P_in μ H_V charges",
            crate::geometry::loss_factor::ohlendorf_closed_form(g),
            eval.ohlendorf_loss_factor
        )));
    }
    if g.internal {
        out.push(note(
            "internal pair (ISO 21771's signs): u = z2/z1 < 0, T1T2 = a sin α_w < 0 (T2 beyond T1), the ring's radius of curvature ρ2 = T1T2 − T1C < 0 (concave), R = ρ1ρ2/(ρ1 + ρ2), v_s = ω1 (1 + 1/u) |s|".into(),
        ));
        out.extend(mesh_checks::internal_warning(g));
    }
    if g.center_distance_given {
        out.push(note(format!(
            "operating pressure angle from the given centre distance {}; the zero-backlash centre distance is {} (α_w = {:.4}°)",
            len.with(g.center_distance, 4),
            len.with(g.zero_backlash_center_distance, 4),
            g.zero_backlash_pressure_angle.to_degrees()
        )));
    } else {
        out.push(note(format!(
            "centre distance from the involute function (zero backlash): {}",
            len.with(g.center_distance, 4)
        )));
    }
    let by_stiffness = problem.gears.load_sharing == LoadSharing::Stiffness;
    if by_stiffness && eval.stiffness_sharing.is_none() {
        out.push(warn(
            "`load_sharing = stiffness`: the teeth's stiffness could not be computed, so the load is shared equally"
                .into(),
        ));
    }
    if g.is_helical() {
        out.extend(helical_findings(g, by_stiffness && eval.stiffness_sharing.is_some(), len));
        return out;
    }
    out.push(note(match problem.gears.load_sharing {
        LoadSharing::Equal => "load sharing: equal (1/n of the normal load on each of n pairs in contact)".into(),
        LoadSharing::None => "load sharing: none (every contact carries the whole normal load)".into(),
        LoadSharing::Stiffness => "load sharing: by stiffness (pair j carries k_j max(0, δ − e_j) of the potential-energy stiffness and tip relief, δ closing the balance at each torque)".into(),
    }));
    out
}

/// Helical pairs: how the load is shared, and the checks on the overlap ratio and the helix angle.
fn helical_findings(g: &crate::geometry::PairGeometry, by_stiffness: bool, len: super::units::Shown) -> Vec<Finding> {
    let message = if by_stiffness {
        "load sharing: by stiffness along the contact lines: at q each line carries k_w(q) max(0, δ − e(q)) per unit length, k_w the potential-energy stiffness per unit width, e the tip relief, δ closing the balance at each instant".to_string()
    } else {
        format!(
            "load sharing: constant stiffness density along the contact lines (He & Singh): w = F_bn / L(t), L̄ = ε_α b / cos β_b = {}",
            len.with(g.mean_contact_length(), 4)
        )
    };
    let mut out = vec![Finding { severity: Severity::Note, message }];
    out.extend(mesh_checks::helical_warnings(g));
    out
}
