//! Which member of a planetary stage the casing holds: the one whose shaft a `side` relation joins
//! to the `gear_casing` through a coupling, a shaft–hub connection or an engaged
//! `switchable_coupling` (its `is_engaged`, one per gear), or a ring that is a part of the casing.

use super::bearings::BEARING_KINDS;
use super::error::{describe, RexsError};
use super::model::{AttributeValue, Component, RexsModel};
use super::stage_data::GearData;
use super::units::{quantity, Kind};

/// A planetary stage's member.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Member {
    Sun,
    Ring,
    Carrier,
}

impl Member {
    pub(crate) fn name(self) -> &'static str {
        match self {
            Member::Sun => "sun",
            Member::Ring => "ring",
            Member::Carrier => "carrier",
        }
    }
}

/// The member the casing holds and how, in words.
pub(super) fn held_member(
    model: &RexsModel,
    c: &Component,
    sun: &GearData,
    ring: &GearData,
    carrier_shafts: &[u64],
) -> Result<(Member, String), RexsError> {
    let casing = |id: Option<u64>| is_casing(model, id);
    let mut held = Vec::new();
    let mut loose = Vec::new();
    if casing(Some(ring.shaft)) {
        held.push((Member::Ring, format!("the casing itself (ring_gear {} is a part of it)", ring.id)));
    }
    let members: Vec<(Member, u64)> = [(Member::Sun, sun.shaft), (Member::Ring, ring.shaft)]
        .into_iter()
        .chain(carrier_shafts.iter().map(|s| (Member::Carrier, *s)))
        .filter(|(_, s)| !casing(Some(*s)))
        .collect();
    for (member, shaft) in members {
        for r in model.relations.iter().filter(|r| r.kind == "side") {
            let (inner, outer) = (r.role("inner_part"), r.role("outer_part"));
            let joins = (inner == Some(shaft) && casing(outer)) || (outer == Some(shaft) && casing(inner));
            let Some(joint) = r.role("assembly").and_then(|id| model.components.get(&id)) else { continue };
            if !joins || BEARING_KINDS.contains(&joint.kind.as_str()) {
                continue;
            }
            if engaged(model, joint) {
                if !held.iter().any(|(m, _)| *m == member) {
                    held.push((member, format!("{} to the casing", describe(joint))));
                }
            } else {
                loose.push(describe(joint));
            }
        }
    }
    match held.as_slice() {
        [(m, how)] => Ok((*m, how.clone())),
        [] => Err(RexsError::at(
            c,
            format!(
                "none of its members is held by the casing{}: a power-split stage (all three turning) is not modelled yet",
                if loose.is_empty() { String::new() } else { format!(" ({} join a member to it but are not engaged)", loose.join(", ")) }
            ),
            "hold the sun, the ring or the carrier by the casing (an engaged coupling), as the unit runs",
        )),
        many => Err(RexsError::at(
            c,
            format!(
                "{} of its members are held by the casing ({}): nothing can turn",
                many.len(),
                many.iter().map(|(m, how)| format!("the {} by {how}", m.name())).collect::<Vec<_>>().join("; ")
            ),
            "hold one member; the other two turn on the unit's shafts",
        )),
    }
}

/// A coupling holds while engaged: a `switchable_coupling`'s `is_engaged` (one per gear shift
/// index: the gear unit's `gear_shift_index`, else the first), any other joint always.
fn engaged(model: &RexsModel, joint: &Component) -> bool {
    if joint.kind != "switchable_coupling" {
        return true;
    }
    let index = model
        .of_kind("gear_unit")
        .next()
        .and_then(|u| quantity(u, &["gear_shift_index"], Kind::Number).ok().flatten())
        .map_or(0, |i| (i.max(1.0) as usize) - 1);
    match joint.attribute(&["is_engaged"]).map(|a| &a.value) {
        Some(AttributeValue::Bool(b)) => *b,
        Some(AttributeValue::Bools(v)) => v.get(index).or(v.first()).copied().unwrap_or(true),
        _ => true,
    }
}

/// The joints (couplings, not bearings) between the casing and a planetary stage's member shafts
/// (its `central_shaft`s and `planet_carrier_shaft`s, and a ring's shaft): they hold or free a
/// member, so they are the stage's to read, not a shiftable unit's.
pub(crate) fn member_joints(model: &RexsModel) -> Vec<u64> {
    let mut shafts: Vec<u64> = model
        .relations
        .iter()
        .filter(|r| r.kind == "central_shaft" || r.kind == "planet_carrier_shaft")
        .filter_map(|r| r.role("shaft"))
        .collect();
    shafts.extend(
        model
            .relations
            .iter()
            .filter(|r| r.kind == "assembly")
            .filter(|r| r.role("part").and_then(|id| model.components.get(&id)).is_some_and(|c| c.kind == "ring_gear"))
            .filter_map(|r| r.role("assembly")),
    );
    let casing = |id: Option<u64>| is_casing(model, id);
    model
        .relations
        .iter()
        .filter(|r| r.kind == "side")
        .filter(|r| {
            let (inner, outer) = (r.role("inner_part"), r.role("outer_part"));
            (inner.is_some_and(|s| shafts.contains(&s)) && casing(outer))
                || (outer.is_some_and(|s| shafts.contains(&s)) && casing(inner))
        })
        .filter_map(|r| r.role("assembly"))
        .filter(|id| model.components.get(id).is_some_and(|c| !BEARING_KINDS.contains(&c.kind.as_str())))
        .collect()
}

/// Whether `id` names the gear casing.
fn is_casing(model: &RexsModel, id: Option<u64>) -> bool {
    id.and_then(|id| model.components.get(&id)).is_some_and(|k| k.kind == "gear_casing")
}
