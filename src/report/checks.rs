//! Findings about the scene as a whole: notes on how it was read and warnings about its inputs.

use super::finding::{Finding, Severity};
use crate::evaluate::Evaluation;
use crate::geometry::TipSource;
use crate::model::{LoadSharing, Scene};

pub(super) fn findings(scene: &Scene, eval: &Evaluation) -> Vec<Finding> {
    let g = &eval.geometry;
    let mut out = Vec::new();
    let note = |m: String| Finding { severity: Severity::Note, message: m };
    let warn = |m: String| Finding { severity: Severity::Warning, message: m };
    out.extend(crate::scene::summary::unused_blocks(scene).into_iter().map(warn));
    out.extend(oil_temperature_finding(scene).map(warn));
    for (i, name) in [(0, "pinion"), (1, "wheel")] {
        out.push(note(match g.tip_source[i] {
            TipSource::Given => format!("{name} tip diameter as given: {:.4} mm", 2e3 * g.tip_radius[i]),
            TipSource::AddendumRule if g.is_helical() => format!(
                "{name} tip diameter from the addendum rule d_a = m_t z + 2 m_n (1 + x): {:.4} mm",
                2e3 * g.tip_radius[i]
            ),
            TipSource::AddendumRule => format!(
                "{name} tip diameter from the addendum rule d_a = m (z + 2 + 2x): {:.4} mm",
                2e3 * g.tip_radius[i]
            ),
        }));
        if g.tip_thickness[i] < 0.2 * g.module {
            out.push(warn(format!(
                "{name} tip thickness s_a = {:.4} mm is below 0.2 m = {:.4} mm: risk of a brittle tip",
                g.tip_thickness[i] * 1e3,
                0.2e3 * g.module
            )));
        }
        let start = g.involute_start_from_t1(i);
        let (contact_start, beyond) =
            if i == 0 { (g.points.a, g.points.a < start) } else { (g.points.e, g.points.e > start) };
        if beyond {
            out.push(warn(format!(
                "contact at {:.4} mm from T1 lies below the {name}'s generated involute, which starts at {:.4} mm (root interference with a rack-cut flank)",
                contact_start * 1e3,
                start * 1e3
            )));
        }
    }
    if g.center_distance_given {
        out.push(note(format!(
            "operating pressure angle from the given centre distance {:.4} mm; the zero-backlash centre distance is {:.4} mm (α_w = {:.4}°)",
            g.center_distance * 1e3,
            g.zero_backlash_center_distance * 1e3,
            g.zero_backlash_pressure_angle.to_degrees()
        )));
    } else {
        out.push(note(format!(
            "centre distance from the involute function (zero backlash): {:.4} mm",
            g.center_distance * 1e3
        )));
    }
    let by_stiffness = scene.gears.load_sharing == LoadSharing::Stiffness;
    if by_stiffness && eval.stiffness_sharing.is_none() {
        out.push(warn(
            "`load_sharing = stiffness`: the teeth's stiffness could not be computed, so the load is shared equally"
                .into(),
        ));
    }
    if g.is_helical() {
        out.extend(helical_findings(g, by_stiffness && eval.stiffness_sharing.is_some()));
        return out;
    }
    out.push(note(match scene.gears.load_sharing {
        LoadSharing::Equal => "load sharing: equal (1/n of the normal load on each of n pairs in contact)".into(),
        LoadSharing::None => "load sharing: none (every contact carries the whole normal load)".into(),
        LoadSharing::Stiffness => "load sharing: by stiffness (pair j carries k_j max(0, δ − e_j) of the potential-energy stiffness and tip relief, δ closing the balance at each torque)".into(),
    }));
    out
}

/// Helical pairs: how the load is shared, and the checks on the overlap ratio and the helix angle.
fn helical_findings(g: &crate::geometry::PairGeometry, by_stiffness: bool) -> Vec<Finding> {
    let message = if by_stiffness {
        "load sharing: by stiffness along the contact lines: at q each line carries k_w(q) max(0, δ − e(q)) per unit length, k_w the potential-energy stiffness per unit width, e the tip relief, δ closing the balance at each instant".to_string()
    } else {
        format!(
            "load sharing: constant stiffness density along the contact lines (He & Singh): w = F_bn / L(t), L̄ = ε_α b / cos β_b = {:.4} mm",
            g.mean_contact_length() * 1e3
        )
    };
    let mut out = vec![Finding { severity: Severity::Note, message }];
    if g.overlap_ratio < 1.0 {
        out.push(Finding {
            severity: Severity::Warning,
            message: format!(
                "overlap ratio ε_β = {:.4} is below 1: the contact length varies strongly over the cycle (a quiet helical mesh has ε_β ≥ 1; widen the face or raise β)",
                g.overlap_ratio
            ),
        });
    }
    if g.helix_angle.to_degrees() > 30.0 {
        out.push(Finding {
            severity: Severity::Warning,
            message: format!(
                "helix angle {:.2}° is above 30°: the axial force F_a = F_t tan β exceeds 0.58 F_t (bearings; consider a double-helical pair)",
                g.helix_angle.to_degrees()
            ),
        });
    }
    out
}

/// A warning when the oil temperature is above its base oil's typical service limit
/// ([`crate::tribology::lubricant::service_limit_celsius`]).
fn oil_temperature_finding(scene: &Scene) -> Option<String> {
    let l = scene.lubricant.as_ref()?;
    let base = l.oil.as_ref()?.base;
    let theta = scene.operating.oil_temperature.as_ref()?.value.value - 273.15;
    let limit = crate::tribology::lubricant::service_limit_celsius(base)?;
    (theta > limit).then(|| {
        format!(
            "oil temperature {theta:.0} °C is above the {limit:.0} °C a {} gear oil is typically run at continuously: it ages fast there (its life roughly halves for every 10 K above); check the oil's data sheet or the cooling",
            base.words()
        )
    })
}
