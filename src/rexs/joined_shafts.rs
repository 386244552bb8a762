//! Shafts rigidly joined into one: a sleeve or stub shaft on another through a shaft–hub
//! connection (a `side` relation between two shafts whose assembly is a feather key, an
//! interference fit or a spline). gearloss reads each group as one shaft: the first of them that
//! sits on bearings (else the first), its origin theirs; the others' gears and bearings move onto
//! it at their places along u (said). A `coupling` between shafts is no such joint (it passes the
//! torque, not the bending), and neither is a bearing.

use super::bearings::sits_on_bearings;
use super::error::RexsError;
use super::model::RexsModel;
use super::units::vector;

/// The groups of joined shafts: (the shaft gearloss keeps, the others joined to it).
pub(crate) fn groups(model: &RexsModel) -> Result<Vec<(u64, Vec<u64>)>, RexsError> {
    let is_shaft = |id: Option<u64>| id.and_then(|id| model.components.get(&id)).is_some_and(|c| c.kind == "shaft");
    let mut pairs: Vec<(u64, u64)> = Vec::new();
    for r in model.relations.iter().filter(|r| r.kind == "side") {
        let (inner, outer) = (r.role("inner_part"), r.role("outer_part"));
        let joint = r.role("assembly").and_then(|id| model.components.get(&id));
        if is_shaft(inner)
            && is_shaft(outer)
            && joint.is_some_and(|j| super::shafts::HUB_CONNECTIONS.contains(&j.kind.as_str()))
        {
            pairs.push((inner.expect("a shaft"), outer.expect("a shaft")));
        }
    }
    // Union of the joined pairs, smallest id first.
    let mut sets: Vec<Vec<u64>> = Vec::new();
    for (a, b) in pairs {
        let found: Vec<usize> = (0..sets.len()).filter(|&i| sets[i].contains(&a) || sets[i].contains(&b)).collect();
        let mut merged = vec![a, b];
        for &i in found.iter().rev() {
            merged.extend(sets.remove(i));
        }
        merged.sort_unstable();
        merged.dedup();
        sets.push(merged);
    }
    let mut out = Vec::new();
    for set in sets {
        let main = set.iter().copied().find(|s| sits_on_bearings(model, *s)).unwrap_or(set[0]);
        for &s in &set {
            if vector(&model.components[&s], "support_vector").is_none() {
                return Err(RexsError::at(
                    &model.components[&s],
                    "it is joined to another shaft by a shaft–hub connection but has no `support_vector`: where it sits on that shaft is unknown",
                    "export the joined shafts with their support vectors",
                ));
            }
        }
        out.push((main, set.into_iter().filter(|s| *s != main).collect()));
    }
    Ok(out)
}

/// Moves every gear of `gears` on a joined shaft onto the shaft it joins, at its place along u from
/// that shaft's origin, and says so (`joint`: how they are joined, in words).
pub(crate) fn onto_the_kept_shaft<'a>(
    model: &RexsModel,
    groups: &[(u64, Vec<u64>)],
    joint: &str,
    gears: impl Iterator<Item = &'a mut super::stage_data::GearData>,
    warnings: &mut Vec<String>,
) {
    let origin = |id: u64| vector(&model.components[&id], "support_vector").map_or(0.0, |v| v[0]);
    for g in gears {
        let Some((main, _)) = groups.iter().find(|(_, others)| others.contains(&g.shaft)) else { continue };
        warnings.push(format!(
            "gear {}: on shaft {}, joined to shaft {main} ({joint}); it sits on shaft {main} at its place along u",
            g.id, g.shaft
        ));
        g.at += origin(g.shaft) - origin(*main);
        g.shaft = *main;
    }
}
