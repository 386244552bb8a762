//! A stage's `planetary` block: the sun–planet pair and the planet–ring pair (internal) lowered as
//! two `gears` blocks of the members' own keys, the members' shafts (one held by `housing`), the
//! planets' count, mass and bearings, and the assembly and neighbour conditions.
//!
//! ```text
//! planetary {
//!     planets = 3
//!     module = 2 mm  pressure_angle = 20 deg  face_width = 25 mm
//!     sun     { teeth = 25  shaft = motor  at = 40 mm  material = steel  roughness_ra = 0.4 um }
//!     planet  { teeth = 25  material = steel  roughness_ra = 0.4 um
//!               bearing(type = cylindrical_roller, bore = 15 mm, outside = 28 mm, count = 2)
//!               bearing_spacing = 14 mm }
//!     ring    { teeth = 75  tip_diameter = 147 mm  shaft = housing  material = steel }
//!     carrier { shaft = output  at = 40 mm }
//! }
//! ```

use std::collections::BTreeMap;

use uom::si::length::meter;

use super::ast::*;
use super::fields::Fields;
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::drive::kinematics::planetary::PlanetaryMember;
use crate::losses::Bearing;
use crate::model::{GearPair, Given, Length, Mass, Material};

/// The pair-level keys both meshes share.
const PAIR_KEYS: &[&str] =
    &["module", "diametral_pitch", "pressure_angle", "helix_angle", "center_distance", "face_width", "load_sharing"];
/// Steel's density for a planet's mass when the scene gives none (kg/m³).
pub(crate) const STEEL_DENSITY: f64 = 7850.0;

/// A planetary stage as written.
pub(super) struct PlanetaryDecl {
    /// The planet–ring pair (internal), at the carrier's centre distance.
    pub ring_pair: GearPair,
    pub planets: u32,
    /// The members on the stage's two places, in the order sun, ring, carrier.
    pub members: [PlanetaryMember; 2],
    pub planet_mass: f64,
    pub planet_bearing: Option<Bearing>,
    /// The distance between a planet's two bearings (m), `bearing_spacing`.
    pub planet_bearing_spacing: Option<f64>,
    /// K_γ, 1 when not given.
    pub load_sharing_factor: f64,
    /// The sun's hand (`hand`) of a helical stage; None for a spur stage.
    pub sun_hand: Option<crate::drive::Hand>,
}

/// The sun–planet pair, the members' places [(shaft, at)] on the stage's two places, and the rest.
pub(super) type Lowered = (GearPair, [(Name, f64); 2], PlanetaryDecl);

pub(super) fn lower_planetary(
    block: &Block,
    materials: &BTreeMap<&str, Material>,
    errors: &mut Vec<Diagnostic>,
) -> Option<Lowered> {
    let members = ["sun", "planet", "ring", "carrier"];
    let mut keys = PAIR_KEYS.to_vec();
    keys.push("planets");
    keys.push("load_sharing_factor");
    keys.push("hand");
    let f = Fields::read("the `planetary` block", block.span, &block.items, &keys, &members, &[], errors);
    let member = |name: &str| f.blocks.iter().find(|b| b.kind.text == name).copied();
    let mut missing = false;
    for name in members {
        if member(name).is_none() {
            missing = true;
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::MissingKey,
                    block.kind.span,
                    format!("the `planetary` block has no `{name}`"),
                )
                .hint(match name {
                    "carrier" => "add `carrier { shaft = output  at = 40 mm }`".to_string(),
                    "planet" => "add `planet { teeth = 25  material = steel }`".to_string(),
                    _ => format!("add `{name} {{ teeth = 25  shaft = input  at = 40 mm  material = steel }}`"),
                }),
            );
        }
    }
    let planets = lower_planet_count(&f, block, errors);
    let helix: Option<Given<crate::model::Angle>> = f.optional("helix_angle", errors);
    let sun_hand = super::lower_planetary_checks::sun_hand(&f, helix.as_ref(), block, errors);
    if missing {
        return None;
    }
    let [sun, planet, ring, carrier] = members.map(|m| member(m).expect("checked above"));
    let pair_items: Vec<Item> = block
        .items
        .iter()
        .filter(|i| matches!(i, Item::Assignment { key, .. } if PAIR_KEYS.contains(&key.text.as_str())))
        .cloned()
        .collect();
    let place = ["shaft", "at"];
    let (sun_gear, sun_place) = split(sun, &place, &[]);
    let (planet_gear, planet_extra) = split(planet, &["shaft", "at", "mass", "bearing_spacing"], &["bearing"]);
    let (ring_gear, ring_place) = split(ring, &place, &[]);
    let sun_pair = gears_block(block, &pair_items, [sun_gear, planet_gear.clone()], false);
    let ring_block = gears_block(block, &pair_items, [planet_gear, ring_gear], true);
    let sun_pair = super::lower_gears::lower_gears_named(&sun_pair, ["sun", "planet"], materials, errors);
    let ring_pair = super::lower_gears::lower_gears_named(&ring_block, ["planet", "ring"], materials, errors);
    let (planet_mass, planet_bearing, bearing_outside, spacing) = lower_planet_parts(&planet_extra, planet, errors);
    let places = [("sun", sun, sun_place), ("ring", ring, ring_place), ("carrier", carrier, carrier.items.clone())]
        .map(|(name, b, items)| lower_member_place(name, b, &items, errors));
    let (sun_pair, mut ring_pair, planets) = (sun_pair?, ring_pair?, planets?);
    let sun_geometry = sun_pair.geometry().ok()?;
    let a = sun_geometry.center_distance;
    // The ring meshes at the carrier's centre distance, the sun–planet mesh's.
    ring_pair.center_distance = Some(Given {
        value: Length::new::<meter>(a),
        written: format!("{:.4} mm (the sun–planet mesh's)", a * 1e3),
        span: ring.kind.span,
    });
    let before = errors.len();
    let ring_fits = super::lower_gears::check_geometry(&ring_pair, errors);
    if ring_fits.is_none() {
        super::lower_planetary_checks::name_the_ring(&sun_pair, &ring_pair, a, &mut errors[before..]);
    }
    ring_fits?;
    let (planets, planets_span) = planets;
    super::lower_planetary_checks::check_planets(&sun_pair, &ring_pair, planets, planets_span, errors)?;
    let [sun_at, ring_at, carrier_at] = places;
    let turning: Vec<(PlanetaryMember, (Name, f64))> =
        [(PlanetaryMember::Sun, sun_at?), (PlanetaryMember::Ring, ring_at?), (PlanetaryMember::Carrier, carrier_at?)]
            .into_iter()
            .filter_map(|(m, p)| p.map(|p| (m, p)))
            .collect();
    let [(m0, p0), (m1, p1)] = super::lower_planetary_checks::one_held(turning, block, errors)?;
    let disc = |d: f64| STEEL_DENSITY * std::f64::consts::PI / 4.0 * d * d * sun_pair.face_width.value.get::<meter>();
    super::lower_planetary_checks::check_planet_parts(
        &sun_pair,
        planet_mass.map(|(m, span)| (m, span, disc(2.0 * sun_geometry.tip_radius[1]))),
        bearing_outside,
        errors,
    )?;
    let planet_mass = planet_mass.map_or_else(|| disc(2.0 * sun_geometry.pitch_radius[1]), |(m, _)| m);
    let load_sharing_factor = lower_load_sharing_factor(&f, planets, errors)?;
    let sun_hand = sun_hand?;
    super::lower_planetary_checks::check_tilting_support(
        sun_hand.is_some(),
        planet_bearing.as_ref().map(|b| b.count),
        spacing,
        planet.kind.span,
        errors,
    )?;
    let decl = PlanetaryDecl {
        ring_pair,
        planets,
        members: [m0, m1],
        planet_mass,
        planet_bearing,
        planet_bearing_spacing: spacing.map(|(l, _)| l),
        load_sharing_factor,
        sun_hand,
    };
    Some((sun_pair, [p0, p1], decl))
}

/// A member's block without `keys` and `calls` (the place keys `shaft`, `at`; a planet's parts
/// `mass`, `bearing`), and the items taken out.
fn split(b: &Block, keys: &[&str], calls: &[&str]) -> (Block, Vec<Item>) {
    let mut gear = b.clone();
    let (keep, take): (Vec<Item>, Vec<Item>) = gear.items.drain(..).partition(|i| match i {
        Item::Assignment { key, .. } => !keys.contains(&key.text.as_str()),
        Item::Call(c) => !calls.contains(&c.name.text.as_str()),
        Item::Block(_) => true,
    });
    gear.items = keep;
    (gear, take)
}

/// A `gears` block of the shared pair keys and two gear blocks (`mesh = internal` for the ring).
fn gears_block(planetary: &Block, pair_items: &[Item], gears: [Block; 2], internal: bool) -> Block {
    let mut items = pair_items.to_vec();
    if internal {
        let mut key = planetary.kind.clone();
        key.text = "mesh".into();
        let mut value_name = planetary.kind.clone();
        value_name.text = "internal".into();
        items.push(Item::Assignment {
            key,
            value: Value {
                kind: ValueKind::Call(Call { name: value_name, arguments: Vec::new(), span: planetary.kind.span }),
                span: planetary.kind.span,
            },
        });
    }
    items.extend(gears.into_iter().map(Item::Block));
    let mut kind = planetary.kind.clone();
    kind.text = "gears".into();
    Block { kind, label: None, items, span: planetary.span }
}

/// `planets = n`: a whole number of at least 1, with where it was written.
fn lower_planet_count(f: &Fields, block: &Block, errors: &mut Vec<Diagnostic>) -> Option<(u32, Span)> {
    let Some((_, v)) = f.values.get("planets") else {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::MissingKey,
                block.kind.span,
                "the `planetary` block does not say its `planets`",
            )
            .hint("add `planets = 3`: how many planets the carrier holds"),
        );
        return None;
    };
    let (n, _) = super::fields::scalar("planets", v, super::units::Dimension::NONE, errors)?;
    if n.fract() != 0.0 || !(1.0..=32.0).contains(&n) {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                v.span,
                format!("planets = {n} is not a whole number from 1 to 32"),
            )
            .hint("a planetary stage has at least one planet; three to seven are usual"),
        );
        return None;
    }
    Some((n as u32, v.span))
}

/// The planet's `mass` (optional, with its span), `bearing(...)` (optional) with the diameter
/// its outer ring needs in the planet (m: `outside`, else its mean diameter, which D exceeds) and
/// the call's span, and `bearing_spacing` (m, with its span).
#[allow(clippy::type_complexity)]
fn lower_planet_parts(
    items: &[Item],
    planet: &Block,
    errors: &mut Vec<Diagnostic>,
) -> (Option<(f64, Span)>, Option<Bearing>, Option<(f64, Span)>, Option<(f64, Span)>) {
    let f =
        Fields::read("the `planet` block", planet.span, items, &["mass", "bearing_spacing"], &[], &["bearing"], errors);
    let mass: Option<Given<Mass>> = super::fields::positive(f.optional("mass", errors), "mass", errors);
    let spacing: Option<Given<Length>> =
        super::fields::positive(f.optional("bearing_spacing", errors), "bearing_spacing", errors);
    let bearings: Vec<&&Call> = f.calls.iter().filter(|c| c.name.text == "bearing").collect();
    if let [_, second, ..] = bearings.as_slice() {
        errors.push(
            Diagnostic::new(DiagnosticKind::DuplicateKey, second.name.span, "a planet takes one `bearing(...)`")
                .hint("several bearings on each planet are one `bearing(..., count = 2)`"),
        );
    }
    let bearing = bearings.first().and_then(|c| super::lower_gearbox::lower_bearing(c, errors));
    // The outer ring's diameter, read again quietly (lower_bearing said what is wrong with it).
    let outside = bearings.first().and_then(|c| {
        let (mut scratch_items, mut scratch) = (Vec::new(), Vec::new());
        let args = super::fields::call_fields(c, "", super::lower_gearbox::BEARING, &mut scratch_items, &mut scratch);
        let d: Option<Given<Length>> = args.optional("outside", &mut scratch);
        let d = d.map(|d| d.value.get::<meter>()).or(bearing.as_ref().map(|b| b.mean_diameter))?;
        Some((d, c.span))
    });
    (mass.map(|m| (m.value.value, m.span)), bearing, outside, spacing.map(|l| (l.value.get::<meter>(), l.span)))
}

/// A member's `shaft` (a shaft's name, or `housing`: held) and `at` (needed where it turns):
/// Some(None) when held. `items` are the carrier's whole block, the sun's and ring's place keys.
fn lower_member_place(
    name: &str,
    b: &Block,
    items: &[Item],
    errors: &mut Vec<Diagnostic>,
) -> Option<Option<(Name, f64)>> {
    let f = Fields::read(format!("the `{name}` block"), b.span, items, &["shaft", "at"], &[], &[], errors);
    let Some(shaft) = f.name("shaft", &[], errors).cloned() else {
        if !f.has("shaft") {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::MissingKey,
                    b.kind.span,
                    format!("the `{name}` does not say its `shaft`"),
                )
                .hint(format!("add `shaft = output` (a shaft of the gearbox) or `shaft = housing` (the {name} held)")),
            );
        }
        return None;
    };
    if shaft.text == "housing" {
        return Some(None);
    }
    let at: Option<Given<Length>> = f.required("at", "40 mm", errors);
    Some(Some((shaft, at?.value.value)))
}

/// `load_sharing_factor = K_γ` (ISO 6336-1's mesh load factor of a planetary stage): from 1 (equal
/// sharing, the default) to n (one planet carrying everything).
fn lower_load_sharing_factor(f: &Fields, planets: u32, errors: &mut Vec<Diagnostic>) -> Option<f64> {
    let Some((_, v)) = f.values.get("load_sharing_factor") else { return Some(1.0) };
    let (k, _) = super::fields::scalar("load_sharing_factor", v, super::units::Dimension::NONE, errors)?;
    if !(1.0..=f64::from(planets)).contains(&k) {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                v.span,
                format!("load_sharing_factor = {k} is outside 1 … {planets} (the planets' count)"),
            )
            .hint("K_γ is the most loaded planet's load over the mean: 1 for equal sharing, n if one planet carried it all"),
        );
        return None;
    }
    Some(k)
}

impl PlanetaryDecl {
    /// The stage's layout (what the drive's physics reads) from its sun–planet pair and this
    /// declaration; None where a pair's geometry fails (lowering reports that).
    pub(super) fn layout(&self, sun_pair: &GearPair) -> Option<crate::drive::planetary::PlanetaryLayout> {
        let d = self;
        let (sp, pr) = (sun_pair.geometry().ok()?, d.ring_pair.geometry().ok()?);
        Some(crate::drive::planetary::PlanetaryLayout {
            planets: d.planets,
            teeth: [sp.teeth[0], sp.teeth[1], pr.teeth[1]],
            members: d.members,
            center_distance: sp.center_distance,
            working_pitch_radius: [
                sp.working_pitch_radius[0],
                sp.working_pitch_radius[1],
                pr.working_pitch_radius[0],
                pr.working_pitch_radius[1],
            ],
            working_pressure_angle: [sp.operating_pressure_angle, pr.operating_pressure_angle],
            planet_tip_radius: sp.tip_radius[1],
            face_width: sp.face_width,
            planet_mass: d.planet_mass,
            planet_bearing: d.planet_bearing,
            load_sharing_factor: d.load_sharing_factor,
            helix: d.sun_hand.filter(|_| sp.helix_angle != 0.0).map(|h| {
                crate::drive::kinematics::planetary::PlanetaryHelix {
                    helix_angle: sp.helix_angle,
                    sun_hand: h.sign(),
                    sun_reference_radius: sp.pitch_radius[0],
                }
            }),
            planet_bearing_spacing: d.planet_bearing_spacing,
        })
    }
}
