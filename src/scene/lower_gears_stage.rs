//! A stage's `gears` block (the parallel and the internal stage kinds): its pair, whose pinion and
//! wheel also say on which `shaft` and `at` which axial coordinate they sit and may say their
//! `hand`; an internal pair's refusals (a ring's churning); the teeth built both ways where the
//! stage shares its load by stiffness.

use std::collections::BTreeMap;

use super::ast::*;
use super::fields::Fields;
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::drive::Hand;
use crate::losses::Lubrication;
use crate::model::{GearPair, Given, Length, Material};

/// The keys a stage's pinion and wheel take beyond a pair's gear.
const PLACE_KEYS: &[&str] = &["shaft", "at", "hand"];

/// The stage's pair, its gears' places [(shaft, at)] and the pinion's hand.
pub(super) type GearsStage = (GearPair, [(Name, f64); 2], Option<Hand>);

/// The `gears` block `gears` of the stage block `block` (whose `lubrication` is `lubrication`).
pub(super) fn lower_gears_stage(
    (block, gears): (&Block, &Block),
    materials: &BTreeMap<&str, Material>,
    lubrication: Option<&Lubrication>,
    errors: &mut Vec<Diagnostic>,
) -> Option<GearsStage> {
    let (pair_block, placed) = split_places(gears);
    let pair = super::lower_gears::lower_gears(&pair_block, materials, errors);
    let pinion = lower_place(&placed[0], "pinion", gears, errors);
    let wheel = lower_place(&placed[1], "wheel", gears, errors);
    let (pair, (p_shaft, p_at, p_hand), (w_shaft, w_at, w_hand)) = (pair?, pinion?, wheel?);
    let hand = stage_hand(&pair, &pair_block, p_hand, w_hand, errors)?;
    super::lower_gearbox::check_immersion(lubrication, &pair, super::lower_gearbox::lubrication_span(block), errors);
    if pair.internal {
        // A ring gear on its own shaft is an internal stage: the walk, forces and statics of
        // `drive/internal_stage.rs`. Its churning and its teeth's stiffness are not modelled.
        let before = errors.len();
        if lubrication.is_some() {
            let span = super::lower_gearbox::lubrication_span(block);
            errors.push(
                Diagnostic::new(DiagnosticKind::OutOfRange, span, "an internal stage's churning (a ring's oil) is not modelled")
                    .hint("leave out the stage's `lubrication`: its mesh, bearings and seals are charged; a ring in oil is a planetary stage's (`planetary { ... ring { ... } }`)"),
            );
        }
        let wants = super::lower_gears::InternalPairWants {
            teeth: pair.load_sharing == crate::model::LoadSharing::Stiffness,
            dynamics: None,
            gearbox: None,
        };
        super::lower_gears::check_internal_pair(&pair, &wants, errors);
        if errors.len() > before {
            return None;
        }
    }
    if pair.load_sharing == crate::model::LoadSharing::Stiffness {
        // The walk shares each mesh's load by the teeth's stiffness as either member drives: the
        // teeth must be built with the pinion driving and with the wheel driving (coast).
        super::lower_teeth::check_teeth(&pair, errors)?;
        super::lower_teeth::check_teeth(&pair.swapped(), errors)?;
    }
    Some((pair, [(p_shaft, p_at), (w_shaft, w_at)], hand))
}

/// The `gears` block without the place keys of its pinion and wheel, and those keys of each.
fn split_places(gears: &Block) -> (Block, [Vec<Item>; 2]) {
    let mut placed = [Vec::new(), Vec::new()];
    let mut block = gears.clone();
    for item in &mut block.items {
        if let Item::Block(b) = item {
            let Some(m) = ["pinion", "wheel"].iter().position(|n| *n == b.kind.text) else { continue };
            let (keep, take): (Vec<Item>, Vec<Item>) = b
                .items
                .drain(..)
                .partition(|i| !matches!(i, Item::Assignment { key, .. } if PLACE_KEYS.contains(&key.text.as_str())));
            b.items = keep;
            placed[m].extend(take);
        }
    }
    (block, placed)
}

/// A hand as written, with where.
type HandWritten = (Hand, Span);

/// A gear's shaft name, `at` (m) and hand.
fn lower_place(
    items: &[Item],
    member: &str,
    gears: &Block,
    errors: &mut Vec<Diagnostic>,
) -> Option<(Name, f64, Option<HandWritten>)> {
    let span = gears
        .items
        .iter()
        .find_map(|i| match i {
            Item::Block(b) if b.kind.text == member => Some(b.kind.span),
            _ => None,
        })
        .unwrap_or(gears.kind.span);
    let f = Fields::read(format!("the stage's `{member}`"), span, items, PLACE_KEYS, &[], &[], errors);
    if !f.has("shaft") {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::MissingKey,
                span,
                format!("the stage's `{member}` does not say its `shaft`"),
            )
            .hint(format!("add `shaft = motor` to `{member}`: the name of a shaft declared in `gearbox`")),
        );
    }
    let shaft = f.name("shaft", &[], errors).cloned();
    let at: Option<Given<Length>> = f.required("at", "55.72 mm", errors);
    let hand = f
        .name("hand", &["left", "right"], errors)
        .map(|n| (if n.text == "left" { Hand::Left } else { Hand::Right }, n.span));
    Some((shaft?, at?.value.value, hand))
}

/// The pinion's hand from the pair's `hand` (the pinion's) or the gears' own; mating gears of an
/// external pair have opposite hands. None for a spur stage.
fn stage_hand(
    pair: &GearPair,
    pair_block: &Block,
    pinion: Option<(Hand, Span)>,
    wheel: Option<(Hand, Span)>,
    errors: &mut Vec<Diagnostic>,
) -> Option<Option<Hand>> {
    let helical = pair.helix_angle.as_ref().is_some_and(|b| b.value.value != 0.0);
    let given = pair.hand.as_deref().map(|h| if h == "left" { Hand::Left } else { Hand::Right });
    let other = |h: Hand| if h == Hand::Left { Hand::Right } else { Hand::Left };
    if let (Some((w, span)), Some(p)) = (wheel, pinion.map(|p| p.0).or(given)) {
        if w == p {
            errors.push(
                Diagnostic::new(DiagnosticKind::OutOfRange, span, "the pinion and the wheel of this stage have the same hand")
                    .hint("mating gears on parallel shafts have opposite hands: a right-hand pinion meshes with a left-hand wheel"),
            );
            return None;
        }
    }
    if let (Some((p, span)), Some(g)) = (pinion, given) {
        if p != g {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::DuplicateKey,
                    span,
                    "the pinion's `hand` contradicts the pair's `hand`",
                )
                .hint("the pair's `hand` is the pinion's: give it once"),
            );
            return None;
        }
    }
    let hand = pinion.map(|p| p.0).or(given).or(wheel.map(|w| other(w.0)));
    if helical && hand.is_none() {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::MissingKey,
                pair_block.kind.span,
                "a helical stage needs its `hand`: the axial forces on the shafts follow it",
            )
            .hint("add `hand = right` (the pinion's hand) to the stage's `gears` block"),
        );
        return None;
    }
    Some(hand.filter(|_| helical))
}
