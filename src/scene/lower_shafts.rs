//! The `gearbox` block of a drive: one `shaft NAME { ... }` block a shaft, saying whether it is the
//! `input` or the `output`, its bearing places (`bearing(..., at = 30 mm, locating)`) and seals,
//! and optionally its centre `position = [x, y] mm` in the drive's transverse frame; beside them
//! the `housing` (the thermal node, as for one pair).
//!
//! ```text
//! gearbox {
//!     shaft motor { input
//!                   bearing(type = deep_groove_ball, bore = 30 mm, outside = 55 mm, static_load_rating = 7.35 kN, at = 30 mm, locating)
//!                   bearing(type = deep_groove_ball, bore = 30 mm, outside = 55 mm, static_load_rating = 7.35 kN, at = 81.44 mm)
//!                   seal(diameter = 27.2 mm) }
//!     shaft output { output ... }
//! }
//! ```

use super::ast::*;
use super::fields::Fields;
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::losses::{Bearing, Seal};
use crate::model::{Length, Material};
use std::collections::BTreeMap;

/// A shaft as written.
pub(super) struct ShaftDecl {
    pub name: Name,
    pub input: Option<Span>,
    pub output: Option<Span>,
    /// Each bearing place with whether it says `locating`, and where it was written.
    pub bearings: Vec<(Bearing, Option<Span>, Span)>,
    pub seals: Vec<Seal>,
    /// The shaft's centre (m) and where it was written.
    pub position: Option<([f64; 2], Span)>,
    /// Per bearing place: its radial stiffness (N/m) and where it was written; None rigid.
    pub stiffness: Vec<Option<(f64, Span)>>,
    /// Its sections, material and beam theory, when it gives sections (the elastic beam).
    pub body: Option<crate::drive::shaft_beam::ShaftBody>,
}

pub(super) fn lower_shafts(
    block: &Block,
    materials: &BTreeMap<&str, Material>,
    errors: &mut Vec<Diagnostic>,
) -> Option<Vec<ShaftDecl>> {
    if let Some(key) = block.items.iter().find_map(|i| match i {
        Item::Assignment { key, .. } if key.text == "lubrication" => Some(key),
        _ => None,
    }) {
        errors.push(
            Diagnostic::new(DiagnosticKind::UnknownName, key.span, "in a drive each stage says its own `lubrication`")
                .hint("move `lubrication = ...` into each `stage` block"),
        );
    }
    let f = Fields::read(
        "the `gearbox` block",
        block.span,
        &block.items,
        &["lubrication"],
        &["shaft", "housing"],
        &[],
        errors,
    );
    let before = errors.len();
    let shafts: Vec<ShaftDecl> =
        f.blocks.iter().filter(|b| b.kind.text == "shaft").filter_map(|b| lower_shaft(b, materials, errors)).collect();
    (errors.len() == before).then_some(shafts)
}

fn lower_shaft(block: &Block, materials: &BTreeMap<&str, Material>, errors: &mut Vec<Diagnostic>) -> Option<ShaftDecl> {
    let Some(name) = block.label.clone() else {
        errors.push(
            Diagnostic::new(DiagnosticKind::MissingKey, block.kind.span, "a shaft needs a name")
                .hint("write `shaft motor { input ... }`: stages name their gears' shafts by it"),
        );
        return None;
    };
    if name.text == "housing" {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::UnknownName,
                name.span,
                "`housing` is the casing's name (a member it holds says `shaft = housing`): a shaft cannot take it",
            )
            .hint(
                "name the shaft after what it carries, e.g. `shaft carrier { ... }`, and put its members on that name",
            ),
        );
        return None;
    }
    let what = format!("shaft `{}`", name.text);
    let f = Fields::read(
        &what,
        block.span,
        &block.items,
        &["position", "material", "beam"],
        &[],
        &["input", "output", "bearing", "seal", "section"],
        errors,
    );
    let mut shaft = ShaftDecl {
        name,
        input: None,
        output: None,
        bearings: Vec::new(),
        seals: Vec::new(),
        position: None,
        stiffness: Vec::new(),
        body: None,
    };
    let mut sections = Vec::new();
    for call in &f.calls {
        match call.name.text.as_str() {
            "input" => shaft.input = Some(call.span),
            "output" => shaft.output = Some(call.span),
            "seal" => shaft.seals.extend(super::lower_gearbox::lower_seal(call, errors)),
            "section" => sections.extend(super::lower_shaft_body::lower_section(call, errors)),
            _ => {
                let locating = call.arguments.iter().find(|(k, _)| k.text == "locating").map(|(k, _)| k.span);
                let stiffness = super::lower_shaft_body::lower_radial_stiffness(call, errors);
                let mut bare = (*call).clone();
                bare.arguments.retain(|(k, _)| k.text != "locating" && k.text != "radial_stiffness");
                if let Some(b) = super::lower_gearbox::lower_bearing(&bare, errors) {
                    shaft.bearings.push((b, locating, call.span));
                    shaft.stiffness.push(stiffness);
                }
            }
        }
    }
    if f.has("position") {
        let p: Option<crate::model::Sweep<Length>> = f.sweep("position", "[0, 120] mm", errors);
        match p {
            Some(p) if p.values.len() == 2 => shaft.position = Some(([p.values[0].value, p.values[1].value], p.span)),
            Some(p) => errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    p.span,
                    "`position` is the shaft centre's two coordinates [x, y]",
                )
                .hint("write `position = [0, 120] mm`"),
            ),
            None => {}
        }
    }
    let decl = super::lower_shaft_body::BodyDecl {
        sections,
        material: f.name("material", &[], errors),
        theory: f.name("beam", &["euler_bernoulli", "timoshenko"], errors),
    };
    shaft.body = super::lower_shaft_body::shaft_body(&shaft.name, &decl, materials, errors);
    Some(shaft)
}
