//! A REXS `planetary_stage` read into gearloss's planetary stage kind: its cylindrical stages
//! (relation `assembly`, the planetary stage the assembly) are the sun–planet meshes (two
//! `cylindrical_gear`s) and the planet–ring meshes (a `ring_gear`); the gear in both kinds of mesh
//! is a planet, the other gears are the sun and the ring. The carrier is the `planet_carrier`, on
//! its `planet_carrier_shaft`s (the cheeks of a two-cheek carrier are rigidly one: their bearings
//! join on one shaft); the planets' bearings join each `planet_shaft` to its `planet_pin` (or to
//! the carrier). The member held is the one joined to the casing by a coupling (an engaged
//! `switchable_coupling`, a `coupling`, a shaft–hub connection) or a ring that is a part of the
//! casing. Refused by name: a compound set (several suns or rings, stepped planets), planets that
//! differ, no member or two held, helix angles that do not mesh.

use super::bearings::{read_bearing, sits_on_bearings, BearingData, BEARING_KINDS};
use super::error::RexsError;
use super::model::{Component, RexsModel};
pub(crate) use super::planetary_hold::Member;
use super::stage_data::GearData;
use super::units::{quantity, vector, Kind};

/// A planetary stage as the scene writes it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PlanetaryData {
    pub id: u64,
    pub name: String,
    /// The planets' gear ids (their count is the stage's `planets`).
    pub planet_ids: Vec<u64>,
    pub sun: GearData,
    /// The first planet (the others are checked equal to it).
    pub planet: GearData,
    pub ring: GearData,
    pub center_distance: Option<f64>,
    pub face_width: f64,
    /// gearloss's `direction` (deg): from the sun's axis to the first planet's, in (v, w).
    pub direction: f64,
    pub held: Member,
    /// The components that hold it, in words.
    pub held_by: String,
    pub carrier_id: u64,
    /// The carrier's shaft, the shafts joined to it (its other cheeks) and the planets' mid-plane
    /// on it (mm); None when the carrier is held.
    pub carrier: Option<(u64, Vec<u64>, f64)>,
    /// One planet's bearings (their count is the planet bearing's `count`).
    pub planet_bearings: Vec<BearingData>,
    /// The distance between a planet's two bearings (mm), where it has two.
    pub planet_bearing_spacing: Option<f64>,
    /// The cylindrical stages read as its meshes.
    pub meshes: Vec<u64>,
}

impl PlanetaryData {
    /// The turning members' places on the drive's shafts: (shaft, at mm).
    pub(crate) fn places(&self) -> Vec<(u64, f64)> {
        let mut out = Vec::new();
        if self.held != Member::Sun {
            out.push((self.sun.shaft, self.sun.at));
        }
        if self.held != Member::Ring {
            out.push((self.ring.shaft, self.ring.at));
        }
        if let Some((shaft, _, at)) = &self.carrier {
            out.push((*shaft, *at));
        }
        out
    }
}

/// The cylindrical stages that are a planetary stage's meshes.
pub(crate) fn meshes_of(model: &RexsModel, stage: u64) -> Vec<u64> {
    model
        .relations_with("assembly", "assembly", stage)
        .filter_map(|r| r.role("part"))
        .filter(|id| model.components.get(id).is_some_and(|c| c.kind == "cylindrical_stage"))
        .collect()
}

pub(crate) fn read_planetary(
    model: &RexsModel,
    c: &Component,
    warnings: &mut Vec<String>,
) -> Result<PlanetaryData, RexsError> {
    let meshes = meshes_of(model, c.id);
    let mut sun_meshes = Vec::new();
    let mut ring_meshes = Vec::new();
    for &m in &meshes {
        let stage = &model.components[&m];
        let r = model.relations_with("stage", "stage", m).next().ok_or_else(|| {
            RexsError::at(
                stage,
                "no `stage` relation names its two gears",
                "export the stage with its gear_1 and gear_2",
            )
        })?;
        let (Some(g1), Some(g2)) = (r.role("gear_1"), r.role("gear_2")) else {
            return Err(RexsError::at(
                stage,
                "its stage relation does not name gear_1 and gear_2",
                "a stage names two gears",
            ));
        };
        let ring = |id: u64| model.components[&id].kind == "ring_gear";
        match (ring(g1), ring(g2)) {
            (false, false) => sun_meshes.push((m, g1, g2)),
            (true, false) => ring_meshes.push((m, g2, g1)),
            (false, true) => ring_meshes.push((m, g1, g2)),
            (true, true) => {
                return Err(RexsError::at(stage, "both its gears are rings", "a mesh has at most one ring"))
            }
        }
    }
    // The planets mesh with the sun and the ring; the suns and rings are the other gears.
    let in_ring_mesh = |g: u64| ring_meshes.iter().any(|(_, p, _)| *p == g);
    let mut planets: Vec<u64> = Vec::new();
    let mut suns: Vec<u64> = Vec::new();
    for &(_, g1, g2) in &sun_meshes {
        let (planet, sun) = if in_ring_mesh(g2) { (g2, g1) } else { (g1, g2) };
        planets.push(planet);
        suns.push(sun);
    }
    let mut rings: Vec<u64> = ring_meshes.iter().map(|(_, _, r)| *r).collect();
    for v in [&mut planets, &mut suns, &mut rings] {
        v.sort_unstable();
        v.dedup();
    }
    let stepped = planets.len() != sun_meshes.len()
        || planets.len() != ring_meshes.len()
        || planets.iter().any(|p| !in_ring_mesh(*p));
    if suns.len() != 1 || rings.len() != 1 || planets.is_empty() || stepped {
        return Err(RexsError::at(
            c,
            format!(
                "a compound planetary set ({} sun(s), {} ring(s), {} planet(s) in {} sun–planet and {} planet–ring meshes) is not modelled yet",
                suns.len(),
                rings.len(),
                planets.len(),
                sun_meshes.len(),
                ring_meshes.len()
            ),
            "gearloss models a simple planetary stage: one sun, one ring, planets each meshing with both",
        ));
    }
    let sun = super::gears::read_gear(model, &model.components[&suns[0]], false, warnings)?;
    let ring = super::gears::read_gear(model, &model.components[&rings[0]], true, warnings)?;
    let mut planet_gears = Vec::new();
    for &p in &planets {
        planet_gears.push(super::gears::read_gear(model, &model.components[&p], false, warnings)?);
    }
    let planet = planet_gears[0].clone();
    same_planets(c, &planet_gears)?;
    check_hands(c, &sun, &planet, &ring)?;
    let first_mesh = &model.components
        [&sun_meshes.iter().find(|(_, a, b)| *a == planet.id || *b == planet.id).expect("a planet meshes").0];
    let center_distance = quantity(first_mesh, &["center_distance"], Kind::Length)?;
    let face_width =
        quantity(first_mesh, &["common_face_width"], Kind::Length)?.unwrap_or(sun.face_width.min(planet.face_width));
    check_ring_centre(model, &ring_meshes, center_distance)?;
    let direction = direction_of(&model.components[&sun.id], &model.components[&planet.id]).unwrap_or(0.0);
    let carrier = model
        .relations
        .iter()
        .filter(|r| r.kind == "assembly" && r.role("assembly") == Some(c.id))
        .filter_map(|r| r.role("part"))
        .find(|id| model.components[id].kind == "planet_carrier")
        .or_else(|| model.of_kind("planet_carrier").next().map(|k| k.id))
        .ok_or_else(|| RexsError::at(c, "it has no `planet_carrier`", "export the stage with its carrier"))?;
    let carrier_shafts: Vec<u64> =
        model.relations_with("planet_carrier_shaft", "planetary_stage", c.id).filter_map(|r| r.role("shaft")).collect();
    let (held, held_by) = super::planetary_hold::held_member(model, c, &sun, &ring, &carrier_shafts)?;
    let carrier_place =
        if held == Member::Carrier { None } else { Some(carrier_place(model, c, &carrier_shafts, &planet)?) };
    let planet_bearings = planet_bearings(model, planet.shaft, warnings)?;
    Ok(PlanetaryData {
        id: c.id,
        name: c.name.clone(),
        planet_ids: planets,
        sun,
        planet,
        ring,
        center_distance,
        face_width,
        direction,
        held,
        held_by,
        carrier_id: carrier,
        carrier: carrier_place,
        planet_bearing_spacing: match planet_bearings.as_slice() {
            [a, b] => Some((a.at - b.at).abs()),
            _ => None,
        },
        planet_bearings,
        meshes,
    })
}

/// A helical stage's hands: the planets' opposite to the sun's (an external mesh), the ring's the
/// planets' (an internal one), one |β|.
fn check_hands(c: &Component, sun: &GearData, planet: &GearData, ring: &GearData) -> Result<(), RexsError> {
    let (s, p, r) = (sun.helix_angle, planet.helix_angle, ring.helix_angle);
    let same_size = (s.abs() - p.abs()).abs() < 1e-9 && (p.abs() - r.abs()).abs() < 1e-9;
    let hands = s == 0.0 || (s * p < 0.0 && p * r > 0.0);
    if same_size && hands {
        return Ok(());
    }
    Err(RexsError::at(
        c,
        format!("its helix angles are {s} (sun), {p} (planet) and {r} deg (ring): the planets mesh with the sun in the other hand and with the ring in their own, at one |β|"),
        "check the signs of `helix_angle_reference_diameter` (> 0 right hand, < 0 left)",
    ))
}

/// Every planet has the first one's teeth, module, helix, face width and flank.
fn same_planets(c: &Component, planets: &[GearData]) -> Result<(), RexsError> {
    let first = &planets[0];
    let key = |g: &GearData| (g.teeth, g.module, g.helix_angle, g.face_width, g.pressure_angle, g.profile_shift);
    match planets.iter().find(|g| key(g) != key(first)) {
        Some(g) => Err(RexsError::at(
            c,
            format!("its planets differ (gear {} and gear {}): gearloss models equal planets", first.id, g.id),
            "give every planet the same teeth, module, helix, face width and flank",
        )),
        None => Ok(()),
    }
}

/// The ring meshes at the carrier's centre distance: the planet–ring stages' own must agree.
fn check_ring_centre(model: &RexsModel, ring_meshes: &[(u64, u64, u64)], a: Option<f64>) -> Result<(), RexsError> {
    let Some(a) = a else { return Ok(()) };
    for (m, _, _) in ring_meshes {
        let stage = &model.components[m];
        if let Some(ring_a) = quantity(stage, &["center_distance"], Kind::Length)? {
            if (ring_a.abs() - a).abs() > 1e-6 * a {
                return Err(RexsError::at(
                    stage,
                    format!("its centre distance {ring_a} mm is not the sun–planet mesh's {a} mm"),
                    "the sun–planet and planet–ring meshes share the carrier's centre distance",
                ));
            }
        }
    }
    Ok(())
}

/// The angle (deg) from the sun's axis to the planet's, in (v, w), from their support vectors.
fn direction_of(sun: &Component, planet: &Component) -> Option<f64> {
    let (s, p) = (vector(sun, "support_vector")?, vector(planet, "support_vector")?);
    let a = (p[2] - s[2]).atan2(p[1] - s[1]).to_degrees();
    Some((a * 1e9).round() / 1e9 + 0.0)
}

/// The carrier's shaft (the first of its shafts that sits on bearings, else the first), the
/// others joined to it, and the planets' mid-plane on it: the planet's place along the unit's u
/// less the shaft's origin.
fn carrier_place(
    model: &RexsModel,
    c: &Component,
    shafts: &[u64],
    planet: &GearData,
) -> Result<(u64, Vec<u64>, f64), RexsError> {
    let main =
        shafts.iter().copied().find(|s| sits_on_bearings(model, *s)).or(shafts.first().copied()).ok_or_else(|| {
            RexsError::at(
                c,
                "no `planet_carrier_shaft` relation names the carrier's shaft",
                "export the carrier with its shaft",
            )
        })?;
    let others: Vec<u64> = shafts.iter().copied().filter(|s| *s != main).collect();
    let origin = vector(&model.components[&main], "support_vector");
    let planet_u = vector(&model.components[&planet.id], "support_vector");
    let at = match (origin, planet_u) {
        (Some(o), Some(p)) => p[0] - o[0],
        _ => {
            return Err(RexsError::at(
                &model.components[&main],
                "the carrier's shaft or the planet has no `support_vector`: the planets' place on the carrier's shaft is unknown",
                "export the shafts and gears with their support vectors",
            ))
        }
    };
    Ok((main, others, at))
}

/// The bearings of one planet: those joining its planet shaft to its pin or to the carrier.
fn planet_bearings(model: &RexsModel, shaft: u64, warnings: &mut Vec<String>) -> Result<Vec<BearingData>, RexsError> {
    let mut out = Vec::new();
    for r in model.relations.iter().filter(|r| r.kind == "side") {
        if r.role("outer_part") != Some(shaft) && r.role("inner_part") != Some(shaft) {
            continue;
        }
        let Some(b) = r.role("assembly").and_then(|id| model.components.get(&id)) else { continue };
        if !BEARING_KINDS.contains(&b.kind.as_str()) {
            continue;
        }
        let at =
            quantity(b, &["u_coordinate_on_shaft_inner_side", "u_coordinate_on_shaft"], Kind::Length)?.unwrap_or(0.0);
        out.push(read_bearing(model, r, b, at, "cylindrical_roller", warnings)?);
    }
    if out.is_empty() {
        warnings.push(format!("planet shaft {shaft}: the model gives the planets no bearings; their loss is left out"));
    } else if out.windows(2).any(|w| (w[0].kind, w[0].bore, w[0].outside) != (w[1].kind, w[1].bore, w[1].outside)) {
        warnings.push(format!(
            "planet shaft {shaft}: its {} bearings differ; each planet is written with {} of the first, bearing {} (chosen)",
            out.len(),
            out.len(),
            out[0].id
        ));
    }
    Ok(out)
}
