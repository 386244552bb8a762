//! A shaft's body for the elastic beam: its `section(from, to, diameter, bore)` cylinders, its
//! `material` (default the scene's `steel`, or its only material), its `beam` theory, and the
//! `radial_stiffness` of a bearing place (README, "Elastic shafts").
//!
//! ```text
//! shaft lay {
//!     section(from = 0 mm, to = 42 mm, diameter = 40 mm)
//!     section(from = 42 mm, to = 150 mm, diameter = 48 mm, bore = 12 mm)
//!     bearing(type = cylindrical_roller, bore = 45 mm, outside = 75 mm, at = 80 mm, radial_stiffness = 4e8 N/m)
//!     ...
//! }
//! ```
//! Sections are written in order along the shaft and join end to end (each `from` the previous
//! `to`); every gear and bearing place of the shaft lies on them (checked where the stages are known).

use std::collections::BTreeMap;

use super::ast::*;
use super::fields::{call_fields, positive, Fields};
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::drive::shaft_beam::{BeamTheory, ShaftBody, ShaftSection};
use crate::model::{Length, Material, Stiffness};

/// Sections whose ends are nearer than this join (m).
const JOIN: f64 = 1e-9;
/// The largest section diameter (m).
const LARGEST_DIAMETER: f64 = 10.0;

/// `section(from = 0 mm, to = 42 mm, diameter = 40 mm, bore = 12 mm)`.
pub(super) fn lower_section(call: &Call, errors: &mut Vec<Diagnostic>) -> Option<(ShaftSection, Span)> {
    let mut items = Vec::new();
    let f = call_fields(call, "`section(...)`", &["from", "to", "diameter", "bore"], &mut items, errors);
    let from: Option<crate::model::Given<Length>> = f.required("from", "0 mm", errors);
    let to: Option<crate::model::Given<Length>> = f.required("to", "42 mm", errors);
    let diameter: Option<crate::model::Given<Length>> = f.required("diameter", "40 mm", errors);
    let diameter = positive(diameter, "diameter", errors);
    let bore: Option<crate::model::Given<Length>> = f.optional("bore", errors);
    let (from, to, diameter) = (from?.value.value, to?.value.value, diameter?);
    let bore = bore.as_ref().map_or(0.0, |b| b.value.value);
    let fail = |errors: &mut Vec<Diagnostic>, reason: String, hint: &str| {
        errors.push(Diagnostic::new(DiagnosticKind::OutOfRange, call.span, reason).hint(hint.to_string()));
        None
    };
    if to <= from {
        return fail(
            errors,
            "a section's `to` must lie beyond its `from`".into(),
            "write `section(from = 0 mm, to = 42 mm, diameter = 40 mm)`",
        );
    }
    let d = diameter.value.value;
    if d > LARGEST_DIAMETER {
        return fail(
            errors,
            format!("a section of {} is not a shaft", diameter.written),
            "a shaft's diameter is at most 10 m: check the unit",
        );
    }
    if !(0.0..d).contains(&bore) {
        return fail(
            errors,
            "a section's `bore` must be at least 0 and below its `diameter`".into(),
            "give the bore of a hollow shaft, or leave it out for a solid one",
        );
    }
    Some((ShaftSection { from, to, outer_diameter: d, bore }, call.span))
}

/// A bearing place's `radial_stiffness = 4e8 N/m` (N/m), read off the call; None without one.
pub(super) fn lower_radial_stiffness(call: &Call, errors: &mut Vec<Diagnostic>) -> Option<(f64, Span)> {
    let (k, v) = call.arguments.iter().find(|(k, _)| k.text == "radial_stiffness")?;
    let items = vec![Item::Assignment { key: k.clone(), value: v.clone() }];
    let f = Fields::read("`bearing(...)`", call.span, &items, &["radial_stiffness"], &[], &[], errors);
    let k: Option<crate::model::Given<Stiffness>> =
        positive(f.optional("radial_stiffness", errors), "radial_stiffness", errors);
    k.map(|k| (k.value.value, k.span))
}

/// What a shaft block says of its body, as written.
pub(super) struct BodyDecl<'a> {
    pub sections: Vec<(ShaftSection, Span)>,
    pub material: Option<&'a Name>,
    pub theory: Option<&'a Name>,
}

/// The shaft's body from its sections, material and theory; None without sections (after an error
/// when `material` or `beam` is given without them, or the sections do not join).
pub(super) fn shaft_body(
    shaft: &Name,
    decl: &BodyDecl,
    materials: &BTreeMap<&str, Material>,
    errors: &mut Vec<Diagnostic>,
) -> Option<ShaftBody> {
    if decl.sections.is_empty() {
        if let Some(key) = decl.material.or(decl.theory) {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::MissingKey,
                    key.span,
                    format!("shaft `{}` has no sections to bend", shaft.text),
                )
                .hint(
                    "add its `section(from = 0 mm, to = 42 mm, diameter = 40 mm)`s, or leave `material` and `beam` out",
                ),
            );
        }
        return None;
    }
    for pair in decl.sections.windows(2) {
        let ((a, _), (b, span)) = (&pair[0], &pair[1]);
        if (b.from - a.to).abs() > JOIN {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    *span,
                    format!("this section starts at {} mm, the one before it ends at {} mm", b.from * 1e3, a.to * 1e3),
                )
                .hint("write a shaft's sections in order along it, each `from` the previous `to`"),
            );
            return None;
        }
    }
    // `beam` was checked against its two names as it was read.
    let theory = match decl.theory.map(|n| n.text.as_str()) {
        Some("timoshenko") => BeamTheory::Timoshenko,
        _ => BeamTheory::EulerBernoulli,
    };
    let material = match decl.material {
        Some(n) => super::lower_gears::named_material(n, materials, errors)?,
        None => match (materials.get("steel"), materials.len()) {
            (Some(m), _) => m,
            (None, 1) => materials.values().next().expect("one material"),
            _ => {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::MissingKey,
                        shaft.span,
                        format!("shaft `{}` needs its `material` to bend", shaft.text),
                    )
                    .hint("add `material = steel` (a `material` block of the scene) to the shaft"),
                );
                return None;
            }
        },
    };
    Some(ShaftBody {
        sections: decl.sections.iter().map(|(s, _)| *s).collect(),
        material: material.name.clone(),
        youngs_modulus: material.youngs_modulus.value.value,
        poisson_ratio: material.poisson_ratio.value,
        theory,
    })
}
