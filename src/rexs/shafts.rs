//! The shafts that carry the stages' gears, their role (input: `defines_speed`; output: its
//! external load transmits torque it does not define), their position in the gear unit and their
//! bearings (relation `side`: the bearing's inner part is the shaft).

use super::bearings::{is_thrust, read_bearing, BearingData, BEARING_KINDS};
use super::error::describe;
use super::error::RexsError;
use super::model::{Component, RexsModel};
use super::stage_data::StageData;
use super::units::{flag, quantity, text, vector, Kind};

/// A shaft of the drive.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ShaftData {
    pub id: u64,
    pub name: String,
    /// Its origin (support vector, mm) in the gear unit's (u, v, w).
    pub origin: [f64; 3],
    pub input: bool,
    pub output: bool,
    pub bearings: Vec<BearingData>,
    /// Its sections when they make a beam over its gears and bearings (empty: the rigid beam).
    pub sections: Vec<super::shaft_sections::SectionData>,
}

/// Shaft–hub connections: a gear sits on its shaft through one (a `side` relation).
pub(crate) const HUB_CONNECTIONS: &[&str] = &[
    "feather_key_connection",
    "cylindrical_interference_fit",
    "tapered_interference_fit",
    "involute_spline_connection",
];

/// The shafts of `stages`' gears and of the planetary members' `places` (shaft, at mm); `joined`
/// names shafts rigidly one with another (a carrier's cheeks: their bearings join the first's).
pub(crate) fn read_shafts(
    model: &RexsModel,
    stages: &[StageData],
    places: &[(u64, f64)],
    joined: &[(u64, Vec<u64>)],
    floating: &[u64],
    warnings: &mut Vec<String>,
) -> Result<Vec<ShaftData>, RexsError> {
    let mut ids: Vec<u64> = stages.iter().flat_map(|s| s.gears.iter().map(|g| g.shaft)).collect();
    ids.extend(places.iter().map(|(s, _)| *s));
    ids.sort_unstable();
    ids.dedup();
    let loads = |shaft: u64| {
        model
            .relations
            .iter()
            .filter(move |r| r.kind == "assembly" && r.role("assembly") == Some(shaft))
            .filter_map(|r| r.role("part"))
            .map(|id| &model.components[&id])
            .filter(|c| c.kind == "external_load")
    };
    let mut out = Vec::new();
    let mut errors = Vec::new();
    for id in ids {
        let others = joined.iter().find(|(s, _)| *s == id).map_or(&[][..], |(_, o)| o.as_slice());
        match read_shaft(model, id, (stages, places), others, floating.contains(&id), &loads, warnings) {
            Ok(shaft) => out.push(shaft),
            Err(e) => errors.push(e),
        }
    }
    if let Some(e) = RexsError::gather(errors) {
        return Err(e);
    }
    let flagged = (out.iter().filter(|s| s.input).count(), out.iter().filter(|s| s.output).count());
    if flagged != (1, 1) {
        ends_from_torque_loads(model, stages, &mut out, warnings);
    }
    for (what, count) in [
        ("input (`defines_speed`)", out.iter().filter(|s| s.input).count()),
        ("output (a load that transmits torque)", out.iter().filter(|s| s.output).count()),
    ] {
        if count != 1 {
            return Err(RexsError::new(
                format!("{count} of the gear unit's shafts are its {what}"),
                "gearloss imports a chain of stages with one input shaft and one output shaft",
            ));
        }
    }
    Ok(out)
}

/// One shaft carrying a stage's gear: its axis, ends, bearings and sections.
fn read_shaft<'m, L: Iterator<Item = &'m Component>>(
    model: &'m RexsModel,
    id: u64,
    (stages, places): (&[StageData], &[(u64, f64)]),
    joined: &[u64],
    floating: bool,
    loads: &impl Fn(u64) -> L,
    warnings: &mut Vec<String>,
) -> Result<ShaftData, RexsError> {
    let c = &model.components[&id];
    if vector(c, "u_axis_vector").is_some_and(|u| u[0] <= 0.0 || u[1].abs() + u[2].abs() > 1e-9) {
        return Err(RexsError::at(
            c,
            "its axis is not the gear unit's +u axis",
            "gearloss reads parallel shafts along the gear unit's u axis",
        ));
    }
    let one = || std::iter::once(id).chain(joined.iter().copied());
    let input = one().any(|s| flag(&model.components[&s], &["defines_speed"]) == Some(true));
    let output = !input
        && one()
            .flat_map(loads)
            .any(|l| flag(l, &["transmits_torque"]) == Some(true) && flag(l, &["defines_torque"]) != Some(true));
    let origin = vector(c, "support_vector").unwrap_or([0.0; 3]);
    let mut bearings = read_bearings(model, c, 0.0, warnings)?;
    for &other in joined {
        let o = &model.components[&other];
        let shift = vector(o, "support_vector").map_or(0.0, |v| v[0] - origin[0]);
        let theirs = read_bearings(model, o, shift, warnings)?;
        if !theirs.is_empty() {
            warnings.push(format!(
                "{}: rigidly one with shaft {id} (the carrier's other cheek); its {} bearing(s) are shaft {id}'s",
                describe(o),
                theirs.len()
            ));
        }
        bearings.extend(theirs);
    }
    bearings.sort_by(|a, b| a.at.total_cmp(&b.at));
    check_places(c, &mut bearings, floating, warnings)?;
    let mut points: Vec<f64> = bearings.iter().map(|b| b.at).collect();
    points.extend(stages.iter().flat_map(|s| &s.gears).filter(|g| g.shaft == id).map(|g| g.at));
    points.extend(places.iter().filter(|(s, _)| *s == id).map(|(_, at)| *at));
    let sections = match super::shaft_sections::read_sections(model, c, &points, warnings)? {
        Ok(s) => s,
        Err(why) if bearings.len() > 2 => {
            return Err(RexsError::at(
                c,
                format!("it sits on {} bearing places, and its sections do not make a beam: {why}", bearings.len()),
                "on three or more places the shaft is an elastic beam: export its shaft sections, joined end to end over every gear and bearing",
            ))
        }
        Err(why) => {
            warnings.push(format!("{}: its sections are not imported ({why}); the shaft is a rigid beam on its two places", describe(c)));
            Vec::new()
        }
    };
    Ok(ShaftData { id, name: c.name.clone(), origin, input, output, bearings, sections })
}

/// The input and output when the model does not flag exactly one of each: the two shafts that
/// carry a torque load (`transmits_torque` or `defines_torque`) are the ends; the input is the one
/// whose speed the model gives (`rotational_speed`, in the model or a load case), else the one
/// carrying its stage's pinion (a reducer; chosen). Said either way; left as it is when the ends
/// are not two.
fn ends_from_torque_loads(model: &RexsModel, stages: &[StageData], out: &mut [ShaftData], warnings: &mut Vec<String>) {
    let torque_load = |shaft: u64| {
        model
            .relations
            .iter()
            .filter(|r| r.kind == "assembly" && r.role("assembly") == Some(shaft))
            .filter_map(|r| r.role("part").and_then(|id| model.components.get(&id)))
            .any(|l| {
                l.kind == "external_load"
                    && (flag(l, &["transmits_torque"]) == Some(true) || flag(l, &["defines_torque"]) == Some(true))
            })
    };
    let ends: Vec<usize> = (0..out.len()).filter(|&j| torque_load(out[j].id)).collect();
    let [a, b] = ends[..] else { return };
    let has_speed = |id: u64| {
        let c = &model.components[&id];
        c.attribute(&["rotational_speed"]).is_some()
            || model
                .load_cases
                .iter()
                .any(|k| k.components.get(&id).is_some_and(|x| x.iter().any(|at| at.id == "rotational_speed")))
    };
    let carries_pinion = |id: u64| stages.iter().any(|s| s.gears[0].shaft == id);
    let (input, why) = match (has_speed(out[a].id), has_speed(out[b].id)) {
        (true, false) => (a, "the model gives its speed"),
        (false, true) => (b, "the model gives its speed"),
        _ => match (carries_pinion(out[a].id), carries_pinion(out[b].id)) {
            (true, false) => (a, "it carries its stage's pinion (a reducer; chosen)"),
            (false, true) => (b, "it carries its stage's pinion (a reducer; chosen)"),
            _ => return,
        },
    };
    let output = if input == a { b } else { a };
    for (j, s) in out.iter_mut().enumerate() {
        s.input = j == input;
        s.output = j == output;
    }
    warnings.push(format!(
        "the model does not flag one input and one output shaft: shafts {} and {} carry its torque loads; shaft {} is the input ({why}), shaft {} the output",
        out[a].id, out[b].id, out[input].id, out[output].id
    ));
}

/// The bearings whose inner part is `shaft`, at their place on it plus `shift` (mm).
fn read_bearings(
    model: &RexsModel,
    shaft: &Component,
    shift: f64,
    warnings: &mut Vec<String>,
) -> Result<Vec<BearingData>, RexsError> {
    let mut out = Vec::new();
    for r in model.relations_with("side", "inner_part", shaft.id) {
        let Some(b) = r.role("assembly").map(|id| &model.components[&id]) else { continue };
        if HUB_CONNECTIONS.contains(&b.kind.as_str()) {
            continue;
        }
        if b.kind.ends_with("coupling") {
            continue;
        }
        if !BEARING_KINDS.contains(&b.kind.as_str()) {
            warnings.push(format!("{}: a bearing of this type is not imported", describe(b)));
            continue;
        }
        if is_thrust(text(b, &["bearing_type"]), b) {
            warnings.push(format!(
                "{}: a thrust bearing takes no radial load: it is no bearing place of shaft {}; the shaft's axial force goes to its locating place, and the thrust bearing's own loss is not counted",
                describe(b), shaft.id
            ));
            continue;
        }
        if let Some(other) = r.role("outer_part").map(|id| &model.components[&id]).filter(|o| o.kind == "shaft") {
            warnings.push(format!(
                "{}: it joins shaft {} to shaft {}; imported on shaft {} as a support to the housing (its load on shaft {} and its speed difference are not modelled)",
                describe(b), shaft.id, other.id, shaft.id, other.id
            ));
        }
        let at = quantity(b, &["u_coordinate_on_shaft_inner_side", "u_coordinate_on_shaft"], Kind::Length)?
            .ok_or_else(|| {
                RexsError::at(
                    b,
                    "`u_coordinate_on_shaft_inner_side` is missing",
                    "export the bearing's position on its shaft",
                )
            })?;
        let mut bearing = read_bearing(model, r, b, at, "deep_groove_ball", warnings)?;
        bearing.at += shift;
        out.push(bearing);
    }
    Ok(out)
}

/// A shaft sits on two bearing places or more (a floating sun's on one, which locates); where none
/// locates and each takes one axial direction, the first locates (chosen, said).
fn check_places(
    shaft: &Component,
    out: &mut [BearingData],
    floating: bool,
    warnings: &mut Vec<String>,
) -> Result<(), RexsError> {
    if floating && out.len() == 1 {
        warnings.push(format!(
            "{}: a floating sun's shaft on one bearing place: its planets centre the sun",
            describe(shaft)
        ));
        out[0].locating = true;
        return Ok(());
    }
    if out.len() < 2 {
        return Err(RexsError::at(
            shaft,
            format!("it sits on {} bearings; a shaft needs two bearing places or more", out.len()),
            "export every bearing of the shaft (a `side` relation with the shaft as its inner part)",
        ));
    }
    if !out.iter().any(|b| b.locating) {
        if let Some(first) = out.iter_mut().find(|b| b.axial == "positive" || b.axial == "negative") {
            first.locating = true;
            warnings.push(format!(
                "shaft {}: its bearings each take one axial direction; gearloss gives the whole axial force to one place: the one at {} mm (chosen)",
                shaft.id, first.at
            ));
        }
    }
    Ok(())
}
