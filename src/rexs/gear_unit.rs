//! The gear unit in a REXS model: its cylindrical stages with their gears (pinion the gear with
//! fewer teeth), shafts and bearings ([`super::shafts`]), lubricant and load cases
//! ([`super::cases`]), checked; what gearloss does not use or had to choose, as warnings.

use super::error::describe;
use super::error::RexsError;
use super::model::{Component, RexsModel};
use super::planetary_stages::PlanetaryStages;
pub(crate) use super::stage_data::{GearData, StageData};
use super::units::{quantity, Kind};

/// Versions this reader knows.
pub(crate) const VERSIONS: &[&str] = &["1.0", "1.1", "1.2", "1.3", "1.4", "1.5", "1.6", "1.7", "2.0", "2.0.0"];
/// Component types read; any other type present is listed as not imported.
const READ: &[&str] = &[
    "gear_unit",
    "gear_casing",
    "shaft",
    "cylindrical_stage",
    "ring_gear",
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
    /// Its planetary stages (their meshes are not among `stages`).
    pub planetary: PlanetaryStages,
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
    let mut unit =
        GearUnit { version: model.version.clone(), application: model.application.clone(), ..Default::default() };
    let mut errors = Vec::new();
    unit.planetary = PlanetaryStages::read(model, &mut unit.warnings, &mut errors);
    let holds = PlanetaryStages::holds(model);
    let unmodelled: Vec<String> = model
        .components
        .values()
        .filter(|c| !holds.contains(&c.id))
        .filter_map(|c| {
            UNMODELLED.iter().find(|(k, _)| *k == c.kind).map(|(_, what)| format!("{} ({what})", describe(c)))
        })
        .collect();
    if !unmodelled.is_empty() {
        errors.push(RexsError::new(
            format!("the model has what gearloss does not model yet: {}", unmodelled.join("; ")),
            "gearloss imports gear units of cylindrical stages on parallel shafts and simple planetary stages",
        ));
    }
    let in_planetary = PlanetaryStages::meshes_in(model);
    for c in model.of_kind("cylindrical_stage").filter(|c| !in_planetary.contains(&c.id)) {
        match read_stage(model, c, &mut unit.warnings) {
            Ok(stage) => unit.stages.push(stage),
            Err(e) => errors.push(e),
        }
    }
    if let Some(e) = RexsError::gather(errors) {
        return Err(e);
    }
    if unit.stages.is_empty() && unit.planetary.is_empty() {
        return Err(RexsError::new(
            "the model has no cylindrical or planetary stage",
            "gearloss imports gear units of cylindrical stages and simple planetary stages",
        ));
    }
    let cheeks = unit.planetary.carrier_cheeks();
    let sleeves = super::joined_shafts::groups(model)?;
    for (groups, joint) in [(&cheeks, "the carrier's other cheek"), (&sleeves, "a shaft–hub connection")] {
        let gears = unit.stages.iter_mut().flat_map(|s| s.gears.iter_mut()).chain(unit.planetary.gears_on_shafts());
        super::joined_shafts::onto_the_kept_shaft(model, groups, joint, gears, &mut unit.warnings);
    }
    let places = unit.planetary.places();
    let joined: Vec<(u64, Vec<u64>)> = cheeks.into_iter().chain(sleeves).collect();
    let floating = unit.planetary.floating_suns(&unit.stages);
    unit.shafts = super::shafts::read_shafts(model, &unit.stages, &places, &joined, &floating, &mut unit.warnings)?;
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
                && !super::planetary_stages::READ.contains(&c.kind.as_str())
                && !super::shafts::HUB_CONNECTIONS.contains(&c.kind.as_str())
                && c.kind != "shaft_section"
                && !holds.contains(&c.id)
        })
        .map(|c| c.kind.clone())
        .collect();
    let mut seen = std::collections::BTreeSet::new();
    others.retain(|k| seen.insert(k.clone()));
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
        super::gears::read_gear(model, &model.components[&id], false, warnings)
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
