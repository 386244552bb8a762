//! The conditions a planetary stage must meet before its physics means anything: the planets fit
//! (assembly condition) and clear each other (neighbour condition), a helical stage names the sun's
//! hand and carries its planets' tilting on two bearings, and exactly one member is held.

use super::ast::*;
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::drive::kinematics::planetary::PlanetaryMember;
use crate::model::GearPair;

/// Assembly: n equally spaced planets mesh with both sun and ring only if (z_sun + z_ring)/n is a
/// whole number (Müller, *Die Umlaufgetriebe*, §2.4; VDI 2157). Neighbours: the planets' tip circles
/// must not touch, 2 a_w sin(π/n) > d_a,planet.
pub(super) fn check_planets(
    sun: &GearPair,
    ring: &GearPair,
    n: u32,
    span: Span,
    errors: &mut Vec<Diagnostic>,
) -> Option<()> {
    let before = errors.len();
    let (z_sun, z_ring) = (sun.pinion.teeth.value, ring.wheel.teeth.value);
    let z_planet = sun.wheel.teeth.value;
    if (z_sun + z_ring) % n != 0 {
        let fits: Vec<String> = (1..=8).filter(|k| (z_sun + z_ring) % k == 0).map(|k| k.to_string()).collect();
        errors.push(
            Diagnostic::new(
                DiagnosticKind::Geometry,
                span,
                format!(
                    "{n} planets cannot be assembled equally spaced: (z_sun + z_ring)/n = ({z_sun} + {z_ring})/{n} = {:.4} is not a whole number",
                    f64::from(z_sun + z_ring) / f64::from(n)
                ),
            )
            .hint(format!("with {z_sun} + {z_ring} teeth, {} planets fit; or change the sun's or the ring's teeth", fits.join(", "))),
        );
    }
    let g = sun.geometry().ok()?;
    let a = g.center_distance;
    let tip = 2.0 * g.tip_radius[1];
    let spacing = 2.0 * a * (std::f64::consts::PI / f64::from(n)).sin();
    if n > 1 && spacing <= tip {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::Geometry,
                span,
                format!(
                    "{n} planets of {z_planet} teeth touch their neighbours: 2 a_w sin(π/n) = {:.4} mm is not larger than the planet's tip diameter {:.4} mm",
                    spacing * 1e3,
                    tip * 1e3
                ),
            )
            .hint("take fewer planets, or larger sun and ring with smaller planets"),
        );
    }
    (errors.len() == before).then_some(())
}

/// Exactly one member is held (`shaft = housing`): two turning members on the stage's two places.
pub(super) fn one_held(
    turning: Vec<(PlanetaryMember, (Name, f64))>,
    block: &Block,
    errors: &mut Vec<Diagnostic>,
) -> Option<[(PlanetaryMember, (Name, f64)); 2]> {
    match <[_; 2]>::try_from(turning) {
        Ok(two) => Some(two),
        Err(turning) if turning.len() == 3 => {
            errors.push(
                Diagnostic::new(DiagnosticKind::OutOfRange, block.kind.span, "no member of the planetary stage is held: all three turn")
                    .hint("a power-split stage (two shafts given, the third by Willis) is not available in a drive in this version: hold one member with `shaft = housing`"),
            );
            None
        }
        Err(_) => {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    block.kind.span,
                    "two members of the planetary stage are held: nothing can turn",
                )
                .hint("hold one member (`shaft = housing`) and put the other two on shafts"),
            );
            None
        }
    }
}

/// The sun's hand of a helical stage (`hand = right`: the sun's; the planets' the other, the
/// ring's the planets'): Some(None) for a spur stage, None (an error) when a helical stage gives no
/// hand or a spur one gives one.
pub(super) fn sun_hand(
    f: &super::fields::Fields,
    helix: Option<&crate::model::Given<crate::model::Angle>>,
    block: &Block,
    errors: &mut Vec<Diagnostic>,
) -> Option<Option<crate::drive::Hand>> {
    let helical = helix.is_some_and(|b| b.value.value != 0.0);
    let hand = f.name("hand", &["left", "right"], errors);
    match (helical, hand) {
        (true, Some(h)) => {
            Some(Some(if h.text == "left" { crate::drive::Hand::Left } else { crate::drive::Hand::Right }))
        }
        (true, None) => {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::MissingKey,
                    block.kind.span,
                    "a helical planetary stage does not say the sun's `hand`",
                )
                .hint("add `hand = right` (the sun's; the planets take the other hand, the ring the planets')"),
            );
            None
        }
        (false, Some(h)) => {
            errors.push(
                Diagnostic::new(DiagnosticKind::OutOfRange, h.span, "a spur planetary stage has no hand")
                    .hint("give `helix_angle` for a helical stage, or leave out `hand`"),
            );
            None
        }
        (false, None) => Some(None),
    }
}

/// A helical stage's planets tilt under their two meshes' axial forces: two bearings a known
/// distance apart carry the moment (`count = 2` with `bearing_spacing`). One bearing per planet is
/// taken as it is (the report says the moment is not on it); three or more, or two without their
/// spacing, are refused.
pub(super) fn check_tilting_support(
    helical: bool,
    count: Option<usize>,
    spacing: Option<(f64, Span)>,
    planet: Span,
    errors: &mut Vec<Diagnostic>,
) -> Option<()> {
    let problem = match (helical, count, spacing) {
        (true, Some(2), None) => Some("the planets' two bearings need their `bearing_spacing`: they carry the planet's tilting moment in a helical stage"),
        (true, Some(c), _) if c > 2 => Some("a helical stage's planet tilts under its axial forces: on more than two bearings their shares are not known"),
        _ => None,
    };
    let span = spacing.map_or(planet, |(_, s)| s);
    if let Some(reason) = problem {
        errors.push(
            Diagnostic::new(DiagnosticKind::OutOfRange, span, reason)
                .hint("give each planet `bearing(..., count = 2)` and `bearing_spacing = 30 mm` (centre to centre, the mesh midway)"),
        );
        return None;
    }
    if let (Some(c), Some((l, s))) = (count, spacing) {
        if c != 2 {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    s,
                    format!(
                        "`bearing_spacing` = {:.3} mm is the distance between two bearings, but the planet has {c}",
                        l * 1e3
                    ),
                )
                .hint("give `count = 2` in the planet's `bearing(...)`, or leave out `bearing_spacing`"),
            );
            return None;
        }
    }
    Some(())
}

/// A planet's parts must fit it. Its bearing's outer ring sits in the planet's bore, inside the
/// root circle (d_f = d − 2 m_n (1.25 − x) with ISO 53's dedendum, or the given root diameter): an
/// outer ring at or beyond the root circle is refused. A given mass is refused above 1.5 × the solid steel
/// disc of the planet's tip diameter and face width (a hub wider than the face, not a different
/// metal) and below 2 % of it (not a gear).
pub(super) fn check_planet_parts(
    sun: &GearPair,
    mass: Option<(f64, Span, f64)>,
    bearing: Option<(f64, Span)>,
    errors: &mut Vec<Diagnostic>,
) -> Option<()> {
    let before = errors.len();
    let g = sun.geometry().ok()?;
    let m = g.module;
    let root = sun.wheel.root_diameter.as_ref().map_or_else(
        || 2.0 * (g.pitch_radius[1] - (1.25 - g.profile_shift[1]) * m),
        |d| d.value.get::<uom::si::length::meter>(),
    );
    if let Some((outside, span)) = bearing {
        if outside >= root {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::Geometry,
                    span,
                    format!(
                        "the planet's bearing does not fit in the planet: its outer ring ({:.3} mm) is not inside the planet's root circle ({:.3} mm)",
                        outside * 1e3,
                        root * 1e3
                    ),
                )
                .hint("a planet bearing sits in the planet's bore: take a smaller bearing, or larger planets"),
            );
        }
    }
    if let Some((mass, span, disc)) = mass {
        if mass > 1.5 * disc || mass < 0.02 * disc {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    span,
                    format!(
                        "a planet of {mass} kg: a solid steel disc of its tip diameter and face width weighs {disc:.4} kg; a planet lies between 2 % and 1.5 × that"
                    ),
                )
                .hint("give the planet's mass in kg (with its bearing's inner parts, not the carrier's), or leave it out: the reference disc in steel is taken"),
            );
        }
    }
    (errors.len() == before).then_some(())
}

/// The ring–planet mesh's geometry errors said as the ring's: it meshes at the carrier's centre
/// distance `a` (m, the sun–planet mesh's), and where the teeth break the coaxial condition of
/// unshifted gears, z_ring = z_sun + 2 z_planet, the hint says by how many teeth (a ring one size
/// too big read as "ε_α = 0.69 outside (1, 3)", hint "more teeth").
pub(super) fn name_the_ring(sun: &GearPair, ring: &GearPair, a: f64, errors: &mut [Diagnostic]) {
    let (z_sun, z_planet, z_ring) = (sun.pinion.teeth.value, sun.wheel.teeth.value, ring.wheel.teeth.value);
    let coaxial = z_sun + 2 * z_planet;
    for d in errors {
        d.reason = format!(
            "the ring–planet mesh, at the carrier's centre distance a = {:.4} mm (the sun–planet mesh's): {}",
            a * 1e3,
            d.reason
        );
        if z_ring != coaxial {
            let (more, word) = if z_ring > coaxial { (z_ring - coaxial, "more") } else { (coaxial - z_ring, "fewer") };
            d.span = ring.wheel.teeth.span;
            d.hints = vec![format!(
                "the ring has {z_ring} teeth, {more} {word} than z_sun + 2 z_planet = {z_sun} + 2 × {z_planet} = {coaxial}: unshifted gears are coaxial only with z_ring = {coaxial}; take {coaxial} teeth, or profile shifts that bring the ring–planet centre distance to a"
            )];
        }
    }
}
