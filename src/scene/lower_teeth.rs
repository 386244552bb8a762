//! Lowering of what the teeth as elastic bodies need: each gear's `root_diameter`,
//! `bore_diameter` and `tip_relief { ... }`, the analysis `transmission_error(pinion_torque = ...)`,
//! and the check that the potential-energy model can be built (the rack cuts a fillet, the mate's
//! tip stays on the involute, the bore lies inside the root), each problem at the line that causes it.

use uom::si::length::meter;

use super::ast::{Block, Call};
use super::fields::{call_fields, Fields};
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::geometry::teeth::load_sharing::{ReliefShape, Reliefs, TipRelief};
use crate::geometry::teeth::outline::OutlineProblem;
use crate::geometry::teeth::pair_stiffness::{Bodies, PairStiffness, StiffnessProblem};
use crate::model::{Analyses, DynamicsSpec, Gear, GearPair, Given, Sweep, TipReliefSpec, Torque};

const RELIEF_KEYS: &[&str] = &["amount", "length", "shape"];
const SHAPES: &[&str] = &["linear", "parabolic"];
/// Most torques of one `transmission_error(...)`.
pub(crate) const MAX_STE_TORQUES: usize = 16;

/// `tip_relief { amount = 10 um  length = 1.8 mm  shape = linear }` inside a gear block.
pub(super) fn lower_tip_relief(gear: &str, blocks: &[&Block], errors: &mut Vec<Diagnostic>) -> Option<TipReliefSpec> {
    let mut found = blocks.iter().filter(|b| b.kind.text == "tip_relief");
    let block = found.next()?;
    for extra in found {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::DuplicateKey,
                extra.kind.span,
                format!("the {gear} has two `tip_relief` blocks"),
            )
            .hint("keep one `tip_relief { ... }` per gear"),
        );
    }
    let f = Fields::read(format!("the {gear}'s `tip_relief`"), block.span, &block.items, RELIEF_KEYS, &[], &[], errors);
    let amount: Option<Given<crate::model::Length>> = f.required("amount", "10 um", errors);
    let length: Option<Given<crate::model::Length>> = f.required("length", "1.8 mm", errors);
    let shape = match f.name("shape", SHAPES, errors).map(|n| n.text.as_str()) {
        Some("parabolic") => ReliefShape::Parabolic,
        _ => ReliefShape::Linear,
    };
    let amount = amount.filter(|a| {
        let ok = a.value.value >= 0.0;
        if !ok {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    a.span,
                    format!("relief `amount` = {} is negative", a.written),
                )
                .hint("a tip relief removes material: give the amount at the tip, e.g. `amount = 10 um`"),
            );
        }
        ok
    });
    let length = length.filter(|l| {
        let ok = l.value.value > 0.0;
        if !ok {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    l.span,
                    format!("relief `length` = {} must be positive", l.written),
                )
                .hint("the length runs along the line of action from the tip's contact, e.g. `length = 1.8 mm`"),
            );
        }
        ok
    });
    Some(TipReliefSpec { amount: amount?, length: length?, shape, span: block.kind.span })
}

/// `transmission_error(pinion_torque = [50, 200, 400] N*m)`.
pub(super) fn lower_transmission_error(call: &Call, errors: &mut Vec<Diagnostic>) -> Option<Sweep<Torque>> {
    let mut items = Vec::new();
    let f = call_fields(call, "`transmission_error(...)`", &["pinion_torque"], &mut items, errors);
    let t: Sweep<Torque> = f.sweep("pinion_torque", "[50, 200, 400] N*m", errors)?;
    if t.values.is_empty()
        || t.values.len() > MAX_STE_TORQUES
        || t.values.iter().any(|v| v.value.is_nan() || v.value <= 0.0)
    {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                t.span,
                format!("`transmission_error` needs 1 to {MAX_STE_TORQUES} torques above zero"),
            )
            .hint("the transmission error is the deflection under load: write `pinion_torque = [50, 200, 400] N*m`"),
        );
        return None;
    }
    Some(t)
}

impl GearPair {
    /// Whether the scene needs the teeth as bodies: the pair describes them (relief, root or bore
    /// given), an analysis asks for the transmission error, or the dynamics read their stiffness.
    pub fn wants_teeth(&self, analyses: &Analyses, dynamics: Option<&DynamicsSpec>) -> bool {
        analyses.transmission_error.is_some()
            || self.load_sharing == crate::model::LoadSharing::Stiffness
            || dynamics.is_some_and(|d| d.stiffness.is_potential_energy())
            || [&self.pinion, &self.wheel]
                .iter()
                .any(|g| g.tip_relief.is_some() || g.root_diameter.is_some() || g.bore_diameter.is_some())
    }

    /// The gear bodies in SI.
    pub fn bodies(&self) -> Bodies {
        let gears = [&self.pinion, &self.wheel];
        let half = |d: &Option<Given<crate::model::Length>>| d.as_ref().map(|d| 0.5 * d.value.get::<meter>());
        Bodies {
            young: gears.map(|g| g.material.youngs_modulus.value.value),
            poisson: gears.map(|g| g.material.poisson_ratio.value),
            root_radius: gears.map(|g| half(&g.root_diameter)),
            bore_radius: gears.map(|g| half(&g.bore_diameter)),
        }
    }

    /// The tip reliefs in SI.
    pub fn reliefs(&self) -> Reliefs {
        Reliefs([&self.pinion, &self.wheel].map(|g| {
            g.tip_relief.as_ref().map(|r| TipRelief {
                amount: r.amount.value.get::<meter>(),
                length: r.length.value.get::<meter>(),
                shape: r.shape,
            })
        }))
    }

    /// The potential-energy stiffness of the pair (after `check_teeth` passed).
    pub fn pair_stiffness(&self) -> Option<PairStiffness> {
        PairStiffness::new(&self.geometry().ok()?, &self.bodies()).ok()
    }
}

/// Checks that the potential-energy teeth can be built and the reliefs fit the path; every
/// problem at its line.
pub(crate) fn check_teeth(pair: &GearPair, errors: &mut Vec<Diagnostic>) -> Option<()> {
    let g = pair.geometry().ok()?;
    let gears = [&pair.pinion, &pair.wheel];
    let names = ["pinion", "wheel"];
    let mm = |x: f64| format!("{:.4} mm", 2e3 * x);
    let before = errors.len();
    if let Err(problems) = PairStiffness::outlines(&g, &pair.bodies()) {
        for p in problems {
            let d = match p {
                StiffnessProblem::Outline { gear, problem } => {
                    let at = gears[gear].root_diameter.as_ref().map_or(gears[gear].span, |d| d.span);
                    match problem {
                        OutlineProblem::RootTooHigh { root, limit } => Diagnostic::new(
                            DiagnosticKind::Geometry,
                            at,
                            format!("the {} root diameter {} is at or above d = {} (its form circle or tip): no fillet is left", names[gear], mm(root), mm(limit)),
                        )
                        .hint(format!("the basic rack (h_fP = 1.25 m) gives d_f = {}", mm(Bodies::default_root_radius(&g, gear)))),
                        OutlineProblem::NoClearance { dedendum, addendum } => Diagnostic::new(
                            DiagnosticKind::Geometry,
                            at,
                            format!("the {} root diameter leaves a rack dedendum of {:.4} mm, not more than its addendum {:.4} mm: the cutter has no tip rounding", names[gear], dedendum * 1e3, addendum * 1e3),
                        )
                        .hint(format!("lower the root diameter; the basic rack gives d_f = {}", mm(Bodies::default_root_radius(&g, gear)))),
                        OutlineProblem::PointedRack { dedendum, limit } => Diagnostic::new(
                            DiagnosticKind::Geometry,
                            at,
                            format!("the {} root diameter asks for a rack dedendum of {:.4} mm, at or past {:.4} mm where the rack's flanks meet: no rack cuts so deep a space", names[gear], dedendum * 1e3, limit * 1e3),
                        )
                        .hint(format!("raise the root diameter; the basic rack gives d_f = {}", mm(Bodies::default_root_radius(&g, gear)))),
                        OutlineProblem::Undercut => Diagnostic::new(
                            DiagnosticKind::Geometry,
                            gears[gear].profile_shift.span,
                            format!("the rack's tip rounding undercuts the {}: its involute does not reach down to the fillet", names[gear]),
                        )
                        .hint("raise the profile shift or the number of teeth, or raise the root diameter"),
                    }
                }
                StiffnessProblem::Interference { gear, start_of_active_profile, form_radius } => {
                    let mate = gears[1 - gear];
                    Diagnostic::new(
                        DiagnosticKind::Geometry,
                        mate.tip_diameter.as_ref().map_or(mate.span, |d| d.span),
                        format!(
                            "the {}'s tip reaches the {} at d = {}, below its form circle d_Ff = {}: the teeth would interfere with the fillet",
                            names[1 - gear], names[gear], mm(start_of_active_profile), mm(form_radius)
                        ),
                    )
                    .hint(format!("shorten the {}'s tip diameter, or raise the {}'s profile shift", names[1 - gear], names[gear]))
                }
                StiffnessProblem::BoreTooLarge { gear, bore, root } => Diagnostic::new(
                    DiagnosticKind::Geometry,
                    gears[gear].bore_diameter.as_ref().map_or(gears[gear].span, |d| d.span),
                    format!(
                        "the {} bore diameter {} is at or above its root diameter {}",
                        names[gear],
                        mm(bore),
                        mm(root)
                    ),
                )
                .hint("the bore is the body's inner boundary below the teeth: give a smaller `bore_diameter`"),
            };
            errors.push(d);
        }
    }
    let path = g.points.e - g.points.a;
    for (spec, gear) in gears.iter().zip(names).filter_map(|(g, n)| g.tip_relief.as_ref().map(|r| (r, n))) {
        let l = spec.length.value.get::<meter>();
        if l > path {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    spec.length.span,
                    format!(
                        "the {gear}'s relief length {} is longer than the path of contact g_α = {:.4} mm",
                        spec.length.written,
                        path * 1e3
                    ),
                )
                .hint("the relief runs along the line of action from the tip's contact: keep it within the path"),
            );
        }
    }
    if errors.len() == before {
        errors.extend(contact_ratio_under_relief(&g, gears));
    }
    (errors.len() == before).then_some(())
}

/// The contact ratio under relief: the path of contact less both reliefs (the wheel's from A, the
/// pinion's up to E) is where teeth meet unrelieved; shorter than a base pitch (for a helical pair,
/// its ratio and the overlap ratio together below 1) and there are instants when every pair in
/// contact is inside a relief, where no pair carries until the relief closes: the static
/// transmission error is not defined there. Said with where.
fn contact_ratio_under_relief(g: &crate::geometry::PairGeometry, gears: [&Gear; 2]) -> Option<Diagnostic> {
    let length = |gear: &Gear| gear.tip_relief.as_ref().map_or(0.0, |r| r.length.value.get::<meter>());
    let (pinion, wheel) = (length(gears[0]), length(gears[1]));
    let path = g.points.e - g.points.a;
    let unrelieved = path - pinion - wheel;
    let ratio = unrelieved / g.base_pitch;
    let overlap = if g.is_helical() { g.overlap_ratio } else { 0.0 };
    if ratio + overlap >= 1.0 {
        return None;
    }
    let spec = gears
        .iter()
        .filter_map(|gear| gear.tip_relief.as_ref())
        .max_by(|a, b| a.length.value.get::<meter>().total_cmp(&b.length.value.get::<meter>()))?;
    let mm = |x: f64| format!("{:.4} mm", x * 1e3);
    Some(
        Diagnostic::new(
            DiagnosticKind::Geometry,
            spec.length.span,
            format!(
                "the reliefs leave {} of the path of contact g_α = {} unrelieved, less than {} = {} (contact ratio under relief {:.3}{}): while a pair{} runs from s = {} to {} from A, every pair in contact is inside a relief and none carries until its relief closes, so the transmission error is not defined there",
                mm(unrelieved.max(0.0)),
                mm(path),
                if g.is_helical() { "(1 − ε_β) p_b" } else { "a base pitch p_b" },
                mm((1.0 - overlap) * g.base_pitch),
                ratio.max(0.0),
                if g.is_helical() { format!(" + overlap {:.3}", overlap) } else { String::new() },
                if g.is_helical() { "'s mid-face section" } else { "" },
                // No line meets the unrelieved stretch [L_w, g_α − L_p] while the reference pair's
                // line (extent ε_β p_b, 0 for spur) has left it and the next one has not reached it.
                mm(path - pinion + 0.5 * overlap * g.base_pitch),
                mm(wheel + g.base_pitch - 0.5 * overlap * g.base_pitch),
            ),
        )
        .hint(format!(
            "shorten the reliefs: together at most {} = {} (pinion {} + wheel {} now)",
            if g.is_helical() { "g_α − (1 − ε_β) p_b" } else { "g_α − p_b" },
            mm(path - (1.0 - overlap) * g.base_pitch),
            mm(pinion),
            mm(wheel)
        )),
    )
}
