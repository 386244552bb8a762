//! The report's word on an undercut gear whose undercut stays below its path of contact
//! (`geometry::undercut_radius`; one that reaches it is refused while the geometry is built).

/// What the report says of each undercut gear of a pair whose undercut stays below the path of
/// contact (one that reaches it is refused while the geometry is built): the radius it reaches,
/// where contact starts, and x_min. `names` are the gears' names in the report.
pub(super) fn undercut_notes(g: &crate::geometry::PairGeometry, names: [&str; 2]) -> Vec<String> {
    let start = [g.base_radius[0].hypot(g.points.a), g.base_radius[1].hypot(g.line_of_action_length - g.points.e)];
    (0..2)
        .filter_map(|i| {
            let ru = g.undercut_radius[i]?;
            Some(format!(
                "the {} is undercut (x = {} below x_min = {:.4}): the generating rack cuts its involute up to d = {:.4} mm, below the d = {:.4} mm where contact starts on its flank, so the path of contact meets the involute only (DIN 3960's harmless undercut); its root is weakened",
                names[i],
                crate::numerics::rounding::sig(g.profile_shift[i]),
                g.undercut_limit[i],
                2e3 * ru,
                2e3 * start[i]
            ))
        })
        .collect()
}
