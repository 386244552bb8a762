//! A `stage` block of a drive: its kind's block (one of the catalogue's `STAGE_BLOCKS`: a `gears`
//! block, `lower_gears_stage.rs`, whose pinion and wheel also say on which `shaft` and `at` which
//! axial coordinate they sit, and may say their `hand`), its direction and its lubrication.
//!
//! ```text
//! stage "first" {
//!     direction = 0 deg
//!     gears {
//!         module = 1.5177 mm  pressure_angle = 20 deg  helix_angle = 23.4 deg  hand = right  face_width = 35.44 mm
//!         pinion { teeth = 23  shaft = motor  at = 55.72 mm  material = steel }
//!         wheel  { teeth = 68  shaft = lay    at = 55.72 mm  material = steel }
//!     }
//!     lubrication = injection(flow = 2.5 l/min, jet_speed = 0.4 m/s)
//! }
//! ```

use std::collections::BTreeMap;

use super::ast::*;
use super::fields::Fields;
use super::stage_kind_decl::{StageBlock, STAGE_BLOCKS};
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::drive::Hand;
use crate::losses::Lubrication;
use crate::model::{Angle, GearPair, Given, Material};

/// A stage as written: its pair, where its gears sit (shaft names as written), the pinion's hand.
pub(super) struct StageDecl {
    pub name: Name,
    pub pair: GearPair,
    /// [pinion, wheel]: the shaft's name and the face mid-plane on that shaft (m).
    pub places: [(Name, f64); 2],
    pub hand: Option<Hand>,
    /// φ (rad) and where it was written.
    pub direction: Option<Given<Angle>>,
    pub lubrication: Option<Lubrication>,
    /// Its kind (a planetary set: `pair` is its sun–planet pair, `places` its two turning members').
    pub kind: super::stage_kind_decl::StageDeclKind,
}

pub(super) fn lower_stage(
    block: &Block,
    materials: &BTreeMap<&str, Material>,
    errors: &mut Vec<Diagnostic>,
) -> Option<StageDecl> {
    let Some(name) = block.label.clone() else {
        errors.push(
            Diagnostic::new(DiagnosticKind::MissingKey, block.kind.span, "a stage needs a name")
                .hint("write `stage \"first\" { ... }`"),
        );
        return None;
    };
    let what = format!("stage `{}`", name.text);
    let kinds: Vec<&str> = STAGE_BLOCKS.iter().map(|k| k.block).collect();
    let f = Fields::read(&what, block.span, &block.items, &["direction", "lubrication"], &kinds, &[], errors);
    let direction: Option<Given<Angle>> = f.optional("direction", errors);
    let lubrication = f.values.get("lubrication").and_then(|(_, v)| super::lower_gearbox::lower_lubrication(v, errors));
    // The stage's kind is the block it is written with: one of the catalogue's, one only.
    let written: Vec<(&StageBlock, &Block)> =
        STAGE_BLOCKS.iter().filter_map(|k| f.blocks.iter().find(|b| b.kind.text == k.block).map(|b| (k, *b))).collect();
    let (kind, kind_block) = match written.as_slice() {
        [one] => *one,
        [] => {
            let first = &STAGE_BLOCKS[0];
            let others: Vec<String> = STAGE_BLOCKS[1..].iter().map(|k| k.example.to_string()).collect();
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::MissingKey,
                    block.kind.span,
                    format!("{what} has no `{}` block", first.block),
                )
                .hint(format!("add {}, or {}", first.example, others.join(", or "))),
            );
            return None;
        }
        [(a, first), (b, _), ..] => {
            let kinds: Vec<String> = STAGE_BLOCKS.iter().map(|k| format!("{} (`{}`)", k.is, k.block)).collect();
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::DuplicateKey,
                    first.kind.span,
                    format!("{what} has both `{}` and `{}`", a.block, b.block),
                )
                .hint(format!("a stage is {}", kinds.join(" or "))),
            );
            return None;
        }
    };
    let lowered = (kind.lower)((block, kind_block), materials, lubrication.as_ref(), errors)?;
    Some(StageDecl {
        name,
        pair: lowered.pair,
        places: lowered.places,
        hand: lowered.hand,
        direction,
        lubrication,
        kind: lowered.kind,
    })
}
