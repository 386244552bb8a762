//! A drive's shafts on their bearing places: none, or two or more at distinct positions (one for a
//! floating sun's shaft), each
//! with its `at` (a rigid beam's statics on two; more need the shaft's sections, the elastic
//! beam), every place and every gear on the sections when given, at most one place that locates.

use super::ast::Span;
use super::lower_shafts::ShaftDecl;
use super::lower_stage::StageDecl;
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::drive::{Shaft, Stage};

/// A shaft's bearing places: none, or two or more with `at` at distinct positions (a rigid beam's
/// statics on two; more need the shaft's sections, the elastic beam); each on the sections when
/// given; at most one says `locating`. A one-pair scene's shaft (`one_pair`) may instead give no
/// `at` at all, on any number of places and without sections: each bearing then carries an equal
/// share of the gear force, the pair's reading (`crate::drive::shaft_bending::shared_reactions`).
pub(super) fn lower_places(
    s: &ShaftDecl,
    (one_pair, floating): (bool, bool),
    errors: &mut Vec<Diagnostic>,
) -> Option<Shaft> {
    let bearings: Vec<_> = s.bearings.iter().map(|(b, _, _)| *b).collect();
    let unplaced = one_pair
        && s.body.is_none()
        && s.stiffness.iter().all(Option::is_none)
        && bearings.iter().all(|b| b.position.is_none());
    if !unplaced {
        check_places(s, floating, errors)?;
    }
    let locating: Vec<(usize, Span)> =
        s.bearings.iter().enumerate().filter_map(|(i, (_, l, _))| l.map(|span| (i, span))).collect();
    if let [_, (_, span), ..] = locating.as_slice() {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                *span,
                format!("two bearing places of shaft `{}` say `locating`", s.name.text),
            )
            .hint("one place takes the shaft's axial force: leave `locating` on one"),
        );
        return None;
    }
    Some(Shaft {
        name: s.name.text.clone(),
        bearings,
        locating: locating.first().map_or(0, |(i, _)| *i),
        // A one-pair scene's reading names the first place (it has no `locating`).
        locating_given: one_pair || !locating.is_empty(),
        seals: s.seals.clone(),
        body: s.body.clone(),
        stiffness: s.stiffness.iter().map(|k| k.map(|(k, _)| k)).collect(),
    })
}

/// Two or more places (one for a floating sun's shaft: its planets centre it), each with its `at`,
/// at distinct positions on the sections when given; more than two only with sections;
/// `radial_stiffness` only with sections.
fn check_places(s: &ShaftDecl, floating: bool, errors: &mut Vec<Diagnostic>) -> Option<()> {
    let fail = |errors: &mut Vec<Diagnostic>, span: Span, reason: String, hint: &str| {
        errors.push(Diagnostic::new(DiagnosticKind::OutOfRange, span, reason).hint(hint.to_string()));
        None
    };
    if let ([_], false) = (s.bearings.as_slice(), floating) {
        return fail(
            errors,
            s.name.span,
            format!("shaft `{}` has one bearing place; its statics needs two", s.name.text),
            "add the second bearing with its `at` (a place of several bearings says `count`)",
        );
    }
    if let (Some(third), None) = (s.bearings.get(2), &s.body) {
        return fail(
            errors,
            third.2,
            format!("shaft `{}` has more than two bearing places and no sections", s.name.text),
            "on three or more places the reactions depend on the shaft's bending: give its `section(from = 0 mm, to = 42 mm, diameter = 40 mm)`s (several bearings at one place are one `bearing(..., count = 2)`)",
        );
    }
    for (k, (bearing, _, span)) in s.bearings.iter().enumerate() {
        let Some(at) = bearing.position else {
            return fail(
                errors,
                *span,
                "a bearing of a drive's shaft needs its `at`".into(),
                "add `at = 30 mm` (on the shaft's own axial coordinate, as the gears' `at`)",
            );
        };
        if s.bearings[..k].iter().any(|(b, _, _)| b.position == Some(at)) {
            return fail(
                errors,
                *span,
                format!("two bearing places of shaft `{}` are at the same `at`", s.name.text),
                "a shaft rests on places at different positions (several bearings at one place are one `bearing(..., count = 2)`)",
            );
        }
        if let Some(body) = &s.body {
            if !body.covers(at) {
                return fail(
                    errors,
                    *span,
                    format!("this bearing at {} mm lies outside shaft `{}`'s sections", at * 1e3, s.name.text),
                    "extend the sections over every bearing and gear of the shaft, or move the bearing's `at`",
                );
            }
        }
    }
    if let (Some((_, span)), None) = (s.stiffness.iter().flatten().next(), &s.body) {
        return fail(
            errors,
            *span,
            format!("`radial_stiffness` bends shaft `{}`, which has no sections", s.name.text),
            "give the shaft's `section(...)`s, or leave `radial_stiffness` out (the place is rigid)",
        );
    }
    Some(())
}

/// Every gear on a shaft with sections lies on them.
pub(super) fn check_gears_on_sections(
    decls: &[StageDecl],
    stages: &[Stage],
    shafts: &[ShaftDecl],
    errors: &mut Vec<Diagnostic>,
) {
    for (s, d) in stages.iter().zip(decls) {
        for (m, place) in s.places.iter().enumerate() {
            let shaft = &shafts[place.shaft];
            if shaft.body.as_ref().is_some_and(|b| !b.covers(place.at)) {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::OutOfRange,
                        d.places[m].0.span,
                        format!(
                            "stage `{}`'s gear at {} mm lies outside shaft `{}`'s sections",
                            s.name,
                            place.at * 1e3,
                            shaft.name.text
                        ),
                    )
                    .hint("extend the shaft's sections over every gear and bearing on it, or move the gear's `at`"),
                );
            }
        }
    }
}
