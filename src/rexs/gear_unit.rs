//! The gear unit in a REXS model: its cylindrical stages with their gears (pinion the gear with
//! fewer teeth), shafts and bearings ([`super::shafts`]), lubricant and load cases
//! ([`super::cases`]), checked; what gearloss does not use or had to choose, as warnings.

use super::error::describe;
use super::error::RexsError;
use super::model::{Component, RexsModel};
pub(crate) use super::stage_data::{GearData, StageData};
use super::units::{quantity, required, Kind};

/// Versions this reader knows.
pub(crate) const VERSIONS: &[&str] = &["1.0", "1.1", "1.2", "1.3", "1.4", "1.5", "1.6", "1.7", "2.0", "2.0.0"];
/// Component types read; any other type present is listed as not imported.
const READ: &[&str] = &[
    "gear_unit",
    "gear_casing",
    "shaft",
    "cylindrical_stage",
    "cylindrical_gear",
    "cylindrical_gear_flank",
    "flank_geometry",
    "cylindrical_stage_gear_data",
    "stage_gear_data",
    "rolling_bearing_with_catalog_geometry",
    "rolling_bearing_with_detailed_geometry",
    "concept_bearing",
    "external_load",
    "lubricant",
    "material",
];

/// Component types of stages and parts gearloss does not model, refused by name with what they are.
const UNMODELLED: &[(&str, &str)] = &[
    ("bevel_stage", "a bevel or hypoid stage"),
    ("bevel_gear", "a bevel or hypoid gear"),
    ("worm_stage", "a worm stage"),
    ("worm_gear", "a worm"),
    ("worm_wheel", "a worm wheel"),
    ("switchable_coupling", "a shiftable coupling: a unit with gears to shift"),
];

/// What the scene is written from.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct GearUnit {
    pub version: String,
    pub application: String,
    pub stages: Vec<StageData>,
    pub shafts: Vec<super::shafts::ShaftData>,
    pub lubricant: Option<super::cases::LubricantData>,
    pub cases: Vec<super::cases::CaseData>,
    /// The unit's operating time (h), when given.
    pub operating_time: Option<f64>,
    pub warnings: Vec<String>,
}

/// Reads and checks the gear unit.
pub(crate) fn read_gear_unit(model: &RexsModel) -> Result<GearUnit, RexsError> {
    if !VERSIONS.contains(&model.version.as_str()) {
        return Err(RexsError::new(
            format!("REXS version `{}` is not one this reader knows", model.version),
            format!("gearloss reads REXS {}; export the model in one of them", VERSIONS.join(", ")),
        ));
    }
    let missing: Vec<RexsError> = model
        .relations
        .iter()
        .filter_map(|r| {
            let x = r.refs.iter().find(|x| !model.components.contains_key(&x.id))?;
            Some(RexsError::new(
                format!(
                    "a `{}` relation names component {} (as `{}`), which the model does not have",
                    r.kind, x.id, x.role
                ),
                "every relation's references must name components of the model",
            ))
        })
        .collect();
    if let Some(e) = RexsError::gather(missing) {
        return Err(e);
    }
    if let Some(c) = model.components.values().find(|c| c.kind.starts_with("planet") || c.kind == "ring_gear") {
        return Err(RexsError::at(
            c,
            "planetary stages are not imported in this version",
            "import a gear unit of cylindrical stages on parallel shafts",
        ));
    }
    let unmodelled: Vec<String> = model
        .components
        .values()
        .filter_map(|c| {
            UNMODELLED.iter().find(|(k, _)| *k == c.kind).map(|(_, what)| format!("{} ({what})", describe(c)))
        })
        .collect();
    if !unmodelled.is_empty() {
        return Err(RexsError::new(
            format!("the model has what gearloss does not model yet: {}", unmodelled.join("; ")),
            "gearloss imports gear units of cylindrical stages on parallel shafts (and, later, simple planetary stages)",
        ));
    }
    let mut unit =
        GearUnit { version: model.version.clone(), application: model.application.clone(), ..Default::default() };
    let mut errors = Vec::new();
    for c in model.of_kind("cylindrical_stage") {
        match read_stage(model, c, &mut unit.warnings) {
            Ok(stage) => unit.stages.push(stage),
            Err(e) => errors.push(e),
        }
    }
    if let Some(e) = RexsError::gather(errors) {
        return Err(e);
    }
    if unit.stages.is_empty() {
        return Err(RexsError::new(
            "the model has no cylindrical stage",
            "gearloss imports gear units of cylindrical stages",
        ));
    }
    unit.shafts = super::shafts::read_shafts(model, &unit.stages, &mut unit.warnings)?;
    let lubricant = super::cases::read_lubricant(model, &mut unit.warnings);
    let cases = super::cases::read_cases(model, &unit.shafts, &mut unit.warnings);
    match (lubricant, cases) {
        (Ok(lubricant), Ok((cases, time))) => {
            (unit.lubricant, unit.cases, unit.operating_time) = (lubricant, cases, time)
        }
        (lubricant, cases) => {
            let errors = [lubricant.err(), cases.err()].into_iter().flatten().collect();
            return Err(RexsError::gather(errors).expect("one of them failed"));
        }
    }
    let mut others: Vec<String> = model
        .components
        .values()
        .filter(|c| {
            !READ.contains(&c.kind.as_str())
                && !super::shafts::HUB_CONNECTIONS.contains(&c.kind.as_str())
                && c.kind != "shaft_section"
        })
        .map(|c| c.kind.clone())
        .collect();
    others.dedup();
    if !others.is_empty() {
        unit.warnings.push(format!("not imported (gearloss has no use for them): {}", others.join(", ")));
    }
    Ok(unit)
}

/// A stage from its `stage` relation (gear_1, gear_2).
fn read_stage(model: &RexsModel, c: &Component, warnings: &mut Vec<String>) -> Result<StageData, RexsError> {
    let relation = model.relations_with("stage", "stage", c.id).next().ok_or_else(|| {
        RexsError::at(c, "no `stage` relation names its two gears", "export the stage with its gear_1 and gear_2")
    })?;
    let mut gear = |role: &str| -> Result<GearData, RexsError> {
        let id = relation.role(role).ok_or_else(|| {
            RexsError::at(c, format!("its stage relation has no `{role}`"), "a stage names gear_1 and gear_2")
        })?;
        read_gear(model, &model.components[&id], warnings)
    };
    let (g1, g2) = (gear("gear_1")?, gear("gear_2")?);
    if g1.shaft == g2.shaft {
        return Err(RexsError::at(
            c,
            format!("its gears {} and {} sit on the same shaft ({})", g1.id, g2.id, g1.shaft),
            "a stage's two gears sit on two different shafts",
        ));
    }
    if (g1.module - g2.module).abs() > 1e-9 * g1.module {
        return Err(RexsError::at(
            c,
            format!("its gears' normal modules differ ({} and {} mm)", g1.module, g2.module),
            "mating gears have one normal module",
        ));
    }
    if g1.helix_angle * g2.helix_angle > 0.0 || (g1.helix_angle.abs() - g2.helix_angle.abs()).abs() > 1e-9 {
        return Err(RexsError::at(
            c,
            format!(
                "its gears' helix angles are {} and {} deg: mating external gears have one |β| and opposite hands",
                g1.helix_angle, g2.helix_angle
            ),
            "check the sign of `helix_angle_reference_diameter` (> 0 right hand, < 0 left)",
        ));
    }
    if (g1.pressure_angle - g2.pressure_angle).abs() > 1e-9 {
        warnings.push(format!(
            "{}: the gears' normal pressure angles differ ({} and {} deg); the pinion's is used",
            describe(c),
            g1.pressure_angle,
            g2.pressure_angle
        ));
    }
    let common = quantity(c, &["common_face_width"], Kind::Length)?;
    let face_width = common.unwrap_or(g1.face_width.min(g2.face_width));
    if common.is_none() && g1.face_width != g2.face_width {
        warnings.push(format!(
            "{}: the gears' face widths differ ({} and {} mm); the smaller is the stage's",
            describe(c),
            g1.face_width,
            g2.face_width
        ));
    }
    let phi = quantity(c, &["rotating_angle_around_neg_u_axis"], Kind::Angle)?.unwrap_or(0.0);
    let pinion_first = g1.teeth <= g2.teeth;
    // gear_2's axis lies at a (sin φ, cos φ) in (v, w) from gear_1's; gearloss's direction runs from
    // the pinion's shaft to the wheel's, measured from +v towards +w.
    let from_first = 90.0 - phi;
    let direction = normalise(if pinion_first { from_first } else { from_first + 180.0 });
    let mut gears = if pinion_first { [g1, g2] } else { [g2, g1] };
    let center_distance = quantity(c, &["center_distance"], Kind::Length)?;
    super::profile_shift::derive_missing(c, &mut gears, center_distance, warnings);
    Ok(StageData { id: c.id, name: c.name.clone(), gears, center_distance, direction, face_width })
}

/// An angle in (−180°, 180°], −0 written as 0.
fn normalise(deg: f64) -> f64 {
    let mut a = deg % 360.0;
    if a <= -180.0 {
        a += 360.0;
    } else if a > 180.0 {
        a -= 360.0;
    }
    a + 0.0
}

fn read_gear(model: &RexsModel, g: &Component, warnings: &mut Vec<String>) -> Result<GearData, RexsError> {
    let teeth = required(g, &["number_of_teeth"], Kind::Number)?;
    let module = required(g, &["normal_module"], Kind::Length)?;
    let helix_angle = quantity(g, &["helix_angle_reference_diameter", "helix_angle"], Kind::Angle)?.unwrap_or(0.0);
    let face_width = required(g, &["face_width"], Kind::Length)?;
    let flank = model
        .relations_with("flank", "gear", g.id)
        .next()
        .and_then(|r| r.role("left").or(r.role("right")))
        .map(|id| &model.components[&id]);
    let on_flank = |ids: &[&str], kind| -> Result<Option<f64>, RexsError> {
        match flank {
            Some(f) => Ok(quantity(f, ids, kind)?.or(quantity(g, ids, kind)?)),
            None => quantity(g, ids, kind),
        }
    };
    let pressure_angle = on_flank(&["normal_pressure_angle"], Kind::Angle)?.ok_or_else(|| {
        RexsError::at(
            g,
            "`normal_pressure_angle` is missing (on the gear and its flanks)",
            "export the gear's flank geometry",
        )
    })?;
    let given_shift = on_flank(&["addendum_modification_coefficient"], Kind::Number)?;
    let profile_shift = given_shift.unwrap_or(0.0);
    let is_shaft = |id: Option<u64>| id.and_then(|id| model.components.get(&id)).is_some_and(|c| c.kind == "shaft");
    // A gear is a part of its shaft (`assembly`), or sits on it through a shaft–hub connection (a
    // `side` relation: the connection the assembly, the shaft its inner part, the gear its outer).
    let shaft = model
        .relations
        .iter()
        .find(|r| r.kind == "assembly" && r.role("part") == Some(g.id) && is_shaft(r.role("assembly")))
        .and_then(|r| r.role("assembly"))
        .or_else(|| {
            model
                .relations
                .iter()
                .find(|r| r.kind == "side" && r.role("outer_part") == Some(g.id) && is_shaft(r.role("inner_part")))
                .and_then(|r| r.role("inner_part"))
        })
        .ok_or_else(|| {
            RexsError::at(
                g,
                "no `assembly` relation, and no shaft–hub connection (`side`), puts it on a shaft",
                "every gear is a part of its shaft, or sits on it through a connection",
            )
        })?;
    // REXS 1.0 gives a gear's `u_coordinate_on_shaft` at its face start; later versions at its
    // mid-plane, which gearloss's `at` is.
    let face_start = model.version == "1.0";
    let at =
        quantity(g, &["u_coordinate_on_shaft"], Kind::Length)?
            .map(|u| if face_start { u + 0.5 * face_width } else { u });
    let from_vectors = match (
        super::units::vector(g, "support_vector"),
        super::units::vector(&model.components[&shaft], "support_vector"),
    ) {
        (Some(a), Some(b)) => Some(a[0] - b[0]),
        _ => None,
    };
    let at = match (at, from_vectors) {
        (Some(u), Some(v)) if (u - v).abs() > 1e-6 => {
            warnings.push(format!("{}: `u_coordinate_on_shaft` {u} mm differs from its support vector's {v} mm; the support vector is used", describe(g)));
            v
        }
        (Some(u), _) => u,
        (None, Some(v)) => v,
        (None, None) => {
            return Err(RexsError::at(
                g,
                "`u_coordinate_on_shaft` is missing",
                "export the gear's position on its shaft",
            ))
        }
    };
    let reference = module * teeth / helix_angle.to_radians().cos();
    let tip = quantity(g, &["tip_diameter"], Kind::Length)?;
    let tip_diameter = match tip {
        Some(da) if da > reference && da < reference + 4.0 * module => Some(da),
        Some(da) => {
            warnings.push(format!("{}: `tip_diameter` {da} mm is not plausible (d = {:.3} mm, m_n = {module} mm); left out, the tip follows from the profile shift", describe(g), reference));
            None
        }
        None => None,
    };
    Ok(GearData {
        id: g.id,
        teeth: teeth.round() as u32,
        module,
        helix_angle,
        face_width,
        pressure_angle,
        profile_shift,
        profile_shift_given: given_shift.is_some(),
        profile_shift_note: None,
        tip_diameter,
        shaft,
        at,
    })
}
