//! The shafts that carry the stages' gears, their role (input: `defines_speed`; output: its
//! external load transmits torque it does not define), their position in the gear unit and their
//! bearings (relation `side`: the bearing's inner part is the shaft).

use super::error::describe;
use super::error::RexsError;
use super::model::{Component, RexsModel};
use super::stage_data::StageData;
use super::units::{flag, quantity, text, vector, Kind};

/// A bearing as the scene writes it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct BearingData {
    pub id: u64,
    pub designation: String,
    /// gearloss's type name.
    pub kind: &'static str,
    pub bore: f64,
    pub outside: f64,
    pub static_load_rating: Option<f64>,
    pub at: f64,
    /// `axial_force_absorption` as written.
    pub axial: String,
    pub locating: bool,
    /// Where the sizes came from, in words.
    pub sizes_from: String,
    /// C₀ was estimated (chosen).
    pub c0_estimated: bool,
}

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

/// REXS `bearing_type` → gearloss's type.
const TYPES: &[(&str, &str)] = &[
    ("radial_grooved_ball_bearing", "deep_groove_ball"),
    ("radial_grooved_ball", "deep_groove_ball"),
    ("radial_angular_contact_ball_bearing", "angular_contact_ball"),
    ("angular_contact_ball_bearing", "angular_contact_ball"),
    ("four_point_contact_ball_bearing", "angular_contact_ball"),
    ("radial_roller_bearing", "cylindrical_roller"),
    ("radial_cylindrical_roller_bearing", "cylindrical_roller"),
    ("radial_tapered_roller_bearing", "tapered_roller"),
    ("radial_spherical_roller_bearing", "spherical_roller"),
    ("radial_self_aligning_roller_bearing", "spherical_roller"),
];

/// REXS bearing types gearloss has no type of its own for: the type whose Palmgren factors stand
/// in (chosen, said).
const STAND_INS: &[(&str, &str)] = &[
    ("radial_needle_roller_bearing", "cylindrical_roller"),
    ("crossed_roller_bearing", "cylindrical_roller"),
    ("radial_self_aligning_ball_bearing", "deep_groove_ball"),
];

/// Thrust bearings (REXS `axial_*`): they take no radial load, so they are no bearing place of the
/// shaft's beam; the shaft's axial force goes to its locating place (said).
fn is_thrust(bearing_type: Option<&str>, b: &Component) -> bool {
    bearing_type.is_some_and(|t| t.starts_with("axial_")) || flag(b, &["radial_force_absorption"]) == Some(false)
}

/// Component types that are rolling bearings.
const BEARING_KINDS: &[&str] =
    &["rolling_bearing_with_catalog_geometry", "rolling_bearing_with_detailed_geometry", "concept_bearing"];

pub(crate) fn read_shafts(
    model: &RexsModel,
    stages: &[StageData],
    warnings: &mut Vec<String>,
) -> Result<Vec<ShaftData>, RexsError> {
    let mut ids: Vec<u64> = stages.iter().flat_map(|s| s.gears.iter().map(|g| g.shaft)).collect();
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
        match read_shaft(model, id, stages, &loads, warnings) {
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
    stages: &[StageData],
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
    let input = flag(c, &["defines_speed"]) == Some(true);
    let output = !input
        && loads(id)
            .any(|l| flag(l, &["transmits_torque"]) == Some(true) && flag(l, &["defines_torque"]) != Some(true));
    let bearings = read_bearings(model, c, warnings)?;
    let mut points: Vec<f64> = bearings.iter().map(|b| b.at).collect();
    points.extend(stages.iter().flat_map(|s| &s.gears).filter(|g| g.shaft == id).map(|g| g.at));
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
    Ok(ShaftData {
        id,
        name: c.name.clone(),
        origin: vector(c, "support_vector").unwrap_or([0.0; 3]),
        input,
        output,
        bearings,
        sections,
    })
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

/// The designation of a bearing: its `catalogue_designation` (`name` in REXS 1.0), or a concept
/// bearing's from its component name (`not a catalogue bearing: 33016 (Rolling bearing [35])`).
fn designation(b: &Component) -> String {
    if let Some(t) = text(b, &["catalogue_designation", "name"]) {
        return t.to_string();
    }
    let name = b.name.split(": ").nth(1).unwrap_or(&b.name);
    name.split(" (").next().unwrap_or(name).trim().to_string()
}

fn read_bearings(
    model: &RexsModel,
    shaft: &Component,
    warnings: &mut Vec<String>,
) -> Result<Vec<BearingData>, RexsError> {
    let mut out = Vec::new();
    for r in model.relations_with("side", "inner_part", shaft.id) {
        let Some(b) = r.role("assembly").map(|id| &model.components[&id]) else { continue };
        if HUB_CONNECTIONS.contains(&b.kind.as_str()) {
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
        let designation = designation(b);
        let kind = match text(b, &["bearing_type"]) {
            Some(t) => match (TYPES.iter().find(|(r, _)| *r == t), STAND_INS.iter().find(|(r, _)| *r == t)) {
                (Some((_, g)), _) => *g,
                (None, Some((_, g))) => {
                    warnings.push(format!("{}: a `{t}` is modelled as a {g} bearing (its Palmgren factors; chosen)", describe(b)));
                    *g
                }
                (None, None) => {
                    return Err(RexsError::at(b, format!("its `bearing_type` `{t}` has no gearloss type"), "gearloss's types: deep groove ball, angular contact ball, cylindrical, tapered and spherical roller (needle, crossed roller and self-aligning ball bearings stand in as one of them)"))
                }
            },
            None => match super::bearing_sizes::type_of(&designation) {
                Some(t) => t,
                None => {
                    warnings.push(format!(
                        "{}: it gives no `bearing_type` and its designation `{designation}` names none: a deep groove ball bearing (chosen)",
                        describe(b)
                    ));
                    "deep_groove_ball"
                }
            },
        };
        let table = super::bearing_sizes::sizes(&designation);
        let given = (quantity(b, &["inner_diameter"], Kind::Length)?, quantity(b, &["outer_diameter"], Kind::Length)?);
        let (bore, outside, sizes_from) = match (given, &table) {
            ((Some(d), Some(big)), _) => (d, big, "the model".to_string()),
            (_, Some(s)) => (s.bore, s.outside, format!("derived from the designation `{designation}` (ISO bore code and dimension series)")),
            _ => {
                return Err(RexsError::at(
                    b,
                    format!("`inner_diameter` and `outer_diameter` are missing, and its designation `{designation}` gives no sizes"),
                    "export the bearing with its diameters, or use a catalogue designation gearloss knows",
                ))
            }
        };
        if sizes_from != "the model" {
            warnings.push(format!("{}: d = {bore} mm, D = {outside} mm {sizes_from}", describe(b)));
        }
        let mut c0 = quantity(b, &["radial_static_load_rating", "static_capacity"], Kind::Force)?
            .or(table.as_ref().and_then(|s| s.static_load_rating));
        let needs_c0 = matches!(kind, "deep_groove_ball" | "angular_contact_ball" | "spherical_roller");
        let c0_estimated = needs_c0 && c0.is_none();
        if c0_estimated {
            let e = (super::bearing_sizes::estimated_static_rating(kind, bore, outside) * 10.0).round() / 10.0;
            warnings.push(format!(
                "{}: no `radial_static_load_rating`: C_0 = {} kN estimated from d and D (ISO 76's f_0 Z D_w² with the balls' size and count estimated; chosen)",
                describe(b),
                crate::numerics::rounding::sig(e)
            ));
            c0 = Some(e);
        }
        let at = quantity(b, &["u_coordinate_on_shaft_inner_side", "u_coordinate_on_shaft"], Kind::Length)?
            .ok_or_else(|| {
                RexsError::at(
                    b,
                    "`u_coordinate_on_shaft_inner_side` is missing",
                    "export the bearing's position on its shaft",
                )
            })?;
        let axial = text(b, &["axial_force_absorption"]).unwrap_or("no_direction").to_string();
        out.push(BearingData {
            id: b.id,
            designation,
            kind,
            bore,
            outside,
            static_load_rating: c0,
            at,
            locating: axial == "both_directions",
            axial,
            sizes_from,
            c0_estimated,
        });
    }
    out.sort_by(|a, b| a.at.total_cmp(&b.at));
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
    Ok(out)
}
