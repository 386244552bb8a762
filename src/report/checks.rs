//! Findings about the scene as a whole: notes on how it was read and warnings about its inputs.

use super::finding::{Finding, Severity};
use crate::evaluate::Evaluation;
use crate::geometry::TipSource;
use crate::model::{LoadSharing, Scene};

pub(super) fn findings(scene: &Scene, eval: &Evaluation) -> Vec<Finding> {
    let g = &eval.geometry;
    let units = super::scene::units(scene);
    let len = units.length();
    let mut out = Vec::new();
    let note = |m: String| Finding { severity: Severity::Note, message: m };
    let warn = |m: String| Finding { severity: Severity::Warning, message: m };
    out.extend(crate::scene::summary::unused_blocks(scene).into_iter().map(warn));
    out.extend(oil_temperature_finding(scene, units).map(warn));
    out.extend(implied_density_finding(scene, eval, units).map(warn));
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
        if g.tip_thickness[i] < 0.2 * g.module {
            out.push(warn(format!(
                "{name} tip thickness s_a = {} is below 0.2 m = {}: risk of a brittle tip",
                len.with(g.tip_thickness[i], 4),
                len.with(0.2 * g.module, 4)
            )));
        }
        let start = g.involute_start_from_t1(i);
        let (contact_start, beyond) =
            if i == 0 { (g.points.a, g.points.a < start) } else { (g.points.e, g.points.e > start) };
        if beyond {
            out.push(warn(format!(
                "contact at {} from T1 lies below the {name}'s generated involute, which starts at {} (root interference with a rack-cut flank)",
                len.with(contact_start, 4),
                len.with(start, 4)
            )));
        }
    }
    out.extend(super::undercut_notes::undercut_notes(g, ["pinion", "wheel"]).into_iter().map(warn));
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
        let gap = g.teeth[1] as i64 - g.teeth[0] as i64;
        if gap < 10 {
            out.push(warn(format!(
                "the ring has only {gap} teeth more than its pinion: below 10, standard 20° teeth risk tip fouling (trochoid interference passed here, with margin {:.5} rad)",
                crate::geometry::trochoid_margin(g.teeth, g.base_radius, g.tip_radius, g.center_distance, g.operating_pressure_angle)
            )));
        }
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
    let by_stiffness = scene.gears.load_sharing == LoadSharing::Stiffness;
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
    out.push(note(match scene.gears.load_sharing {
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
fn oil_temperature_finding(scene: &Scene, u: super::units::Units) -> Option<String> {
    let l = scene.lubricant.as_ref()?;
    let base = l.oil.as_ref()?.base;
    let kelvin = scene.operating.oil_temperature.as_ref()?.value.value;
    let limit = crate::tribology::lubricant::service_limit_celsius(base)?;
    let deg = u.temperature();
    (kelvin - 273.15 > limit).then(|| {
        format!(
            "oil temperature {:.0} {} is above the {:.0} {} a {} gear oil is typically run at continuously: it ages fast there (its life roughly halves for every 10 K above); check the oil's data sheet or the cooling",
            deg.value(kelvin),
            deg.unit,
            deg.from_celsius(limit),
            deg.unit,
            base.words()
        )
    })
}

/// Densities of oils (kg/m³): gear oils are 800–1100 (mineral ≈ 885, PAO ≈ 850, PAG ≈ 1000–1060 at
/// 15 °C); outside this band the η and ν a scene gives cannot both be one oil's at one temperature.
pub(crate) const OIL_DENSITY_RANGE: [f64; 2] = [700.0, 1200.0];

/// A warning when the density a given lubricant's η and ν imply (ρ = η/ν) is not an oil's: the
/// two viscosities are then most likely at different temperatures or one is in a mistaken unit,
/// and every film thickness and law that reads η is off by that factor.
fn implied_density_finding(scene: &Scene, eval: &Evaluation, u: super::units::Units) -> Option<String> {
    let l = scene.lubricant.as_ref()?;
    if l.oil.is_some() {
        return None;
    }
    let rho = eval.tribology.density()?;
    let [lo, hi] = OIL_DENSITY_RANGE;
    let d = u.density();
    (!(lo..=hi).contains(&rho)).then(|| {
        format!(
            "the lubricant's dynamic and kinematic viscosity imply a density ρ = η/ν = {}, outside the {}–{} of any gear oil: η and ν are not one oil's at one temperature (or one is in a mistaken unit); every film thickness and law that reads η uses the dynamic viscosity as given",
            d.with(rho, 1),
            d.cell(lo, 0),
            d.with(hi, 0)
        )
    })
}
