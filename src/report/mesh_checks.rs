//! The warnings on one mesh's geometry, the same wherever the mesh stands: a scene of one pair
//! (its report's findings, [`super::checks`]) and every mesh of every stage of a drive (the
//! drive's findings, each naming its stage, [`super::drive_findings`]). A reader must act on each:
//! a brittle tip, contact below the generated involute, an undercut gear, a ring too close in teeth
//! to its pinion, a helical mesh of small overlap or a helix that loads its bearings axially.

use super::finding::{Finding, Severity};
use super::units::Shown;
use crate::geometry::PairGeometry;

fn warn(message: String) -> Finding {
    Finding { severity: Severity::Warning, message }
}

/// Every warning on the mesh `g` whose gears the report calls `names`, in the order a pair's
/// report lists them: each gear's tip (thickness, root interference), the undercut gears, an
/// internal pair's tooth gap, a helical pair's overlap and helix angle.
pub(super) fn mesh_warnings(g: &PairGeometry, names: [&str; 2], len: Shown) -> Vec<Finding> {
    let mut out: Vec<Finding> = (0..2).flat_map(|i| tip_warnings(g, i, names[i], len)).collect();
    out.extend(undercut_warnings(g, names, len));
    out.extend(internal_warning(g));
    if g.is_helical() {
        out.extend(helical_warnings(g));
    }
    out
}

/// Gear `i`'s tip: a tip thickness s_a below 0.2 m (a brittle tip; the usual design limit for
/// hardened gears), and contact that starts below the flank's
/// generated involute (root interference with a rack-cut flank: the path of contact's end A or E
/// lies inside the involute's start, [`PairGeometry::involute_start_from_t1`]).
pub(super) fn tip_warnings(g: &PairGeometry, i: usize, name: &str, len: Shown) -> Vec<Finding> {
    let mut out = Vec::new();
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
    out
}

/// Each undercut gear whose undercut stays below the path of contact (`geometry::undercut_radius`;
/// one that reaches it is refused while the geometry is built): the diameter the generating rack
/// cuts to, the diameter where contact starts on the flank, and x_min (DIN 3960's harmless
/// undercut), in the report's length unit.
pub(super) fn undercut_warnings(g: &PairGeometry, names: [&str; 2], len: Shown) -> Vec<Finding> {
    let start = [g.base_radius[0].hypot(g.points.a), g.base_radius[1].hypot(g.line_of_action_length - g.points.e)];
    (0..2)
        .filter_map(|i| {
            let ru = g.undercut_radius[i]?;
            Some(warn(format!(
                "the {} is undercut (x = {} below x_min = {:.4}): the generating rack cuts its involute up to d = {}, below the d = {} where contact starts on its flank, so the path of contact meets the involute only (DIN 3960's harmless undercut); its root is weakened",
                names[i],
                crate::numerics::rounding::sig(g.profile_shift[i]),
                g.undercut_limit[i],
                len.with(2.0 * ru, 4),
                len.with(2.0 * start[i], 4)
            )))
        })
        .collect()
}

/// An internal pair whose ring has fewer than 10 teeth more than its pinion: standard 20° teeth
/// risk tip fouling there (the trochoid check passed, its margin shown).
pub(super) fn internal_warning(g: &PairGeometry) -> Option<Finding> {
    let gap = g.teeth[1] as i64 - g.teeth[0] as i64;
    (g.internal && gap < 10).then(|| {
        warn(format!(
            "the ring has only {gap} teeth more than its pinion: below 10, standard 20° teeth risk tip fouling (trochoid interference passed here, with margin {:.5} rad)",
            crate::geometry::trochoid_margin(g.teeth, g.base_radius, g.tip_radius, g.center_distance, g.operating_pressure_angle)
        ))
    })
}

/// A helical pair's overlap ratio ε_β below 1 (the contact length varies strongly over the cycle)
/// and a helix angle above 30° (F_a = F_t tan β above 0.58 F_t).
pub(super) fn helical_warnings(g: &PairGeometry) -> Vec<Finding> {
    let mut out = Vec::new();
    if g.overlap_ratio < 1.0 {
        out.push(warn(format!(
            "overlap ratio ε_β = {:.4} is below 1: the contact length varies strongly over the cycle (a quiet helical mesh has ε_β ≥ 1; widen the face or raise β)",
            g.overlap_ratio
        )));
    }
    if g.helix_angle.to_degrees() > 30.0 {
        out.push(warn(format!(
            "helix angle {:.2}° is above 30°: the axial force F_a = F_t tan β exceeds 0.58 F_t (bearings; consider a double-helical pair)",
            g.helix_angle.to_degrees()
        )));
    }
    out
}
