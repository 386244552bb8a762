//! The conditions a planetary stage must meet before its physics means anything: the planets fit
//! (assembly condition) and clear each other (neighbour condition), helical planetaries wait, and
//! exactly one member is held.

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

/// A helical planetary stage is refused: its axial forces on the sun and the planets' tilting
/// moments are not modelled in this version.
pub(super) fn check_spur(
    helix: Option<&crate::model::Given<crate::model::Angle>>,
    errors: &mut Vec<Diagnostic>,
) -> Option<()> {
    match helix {
        Some(b) if b.value.value != 0.0 => {
            errors.push(
                Diagnostic::new(DiagnosticKind::OutOfRange, b.span, "a helical planetary stage is not available in this version")
                    .hint("give `helix_angle = 0 deg` (spur); the axial forces on the sun and the planets' tilting moments come later"),
            );
            None
        }
        _ => Some(()),
    }
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
