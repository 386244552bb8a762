//! A drive's stages and shafts put together into a checked [`Drive`]: every gear's shaft declared
//! and every shaft carrying a gear, one input and one output, no loop, one chain of stages from the
//! input to the output, its shafts on their bearing places ([`super::lower_drive_places`]: two or
//! more at distinct positions, on the sections when given, at most one that locates), and the
//! stages' centre distances agreeing with the shafts' positions where both are given.

use std::collections::BTreeMap;

use super::ast::*;
use super::fields::nearest;
use super::lower_shafts::ShaftDecl;
use super::lower_stage::StageDecl;
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::drive::kinematics::StageKind;
use crate::drive::{Drive, DriveOperating, GearPlace, Stage};

/// How far a stage's centre distance may differ from the distance of its shafts' positions (m).
const CENTRE_TOLERANCE: f64 = 1e-6;

/// The drive of `stages` on `shafts`; `all_stages` says whether every stage block lowered (else the
/// checks that need every stage, a shaft without a gear or the chain, are left to the next run).
pub(super) fn build_drive(
    stages: &[StageDecl],
    all_stages: bool,
    shafts: Vec<ShaftDecl>,
    operating: DriveOperating,
    (gearbox, one_pair): (Span, bool),
    errors: &mut Vec<Diagnostic>,
) -> Option<Drive> {
    let before = errors.len();
    let index = shaft_index(&shafts, errors);
    if !one_pair {
        check_bearings_everywhere(&shafts, errors);
    }
    let mut built = Vec::new();
    for s in stages {
        let mut at = |m: usize| -> Option<usize> {
            let name = &s.places[m].0;
            let found = index.get(name.text.as_str()).copied();
            if found.is_none() {
                let names: Vec<&str> = index.keys().copied().collect();
                let hint = match nearest(&name.text, names.iter().copied()) {
                    Some(n) => format!("did you mean `{n}`? Or declare `shaft {} {{ ... }}` in `gearbox`", name.text),
                    None => format!(
                        "the gearbox declares {}; or declare `shaft {} {{ ... }}` in it",
                        names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", "),
                        name.text
                    ),
                };
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::Undefined,
                        name.span,
                        format!("shaft `{}` is not declared", name.text),
                    )
                    .hint(hint),
                );
            }
            found
        };
        let (p, w) = (at(0), at(1));
        let (Some(p), Some(w)) = (p, w) else { continue };
        if p == w {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    s.places[1].0.span,
                    "the stage's two members are on the same shaft",
                )
                .hint("a stage joins two shafts: put its wheel (or a planetary stage's other turning member) on another shaft"),
            );
            continue;
        }
        let (kind, teeth) = s
            .kind
            .lowered(&s.pair)
            .unwrap_or((StageKind::Parallel, [s.pair.pinion.teeth.value, s.pair.wheel.teeth.value]));
        built.push(Stage {
            name: s.name.text.clone(),
            places: [GearPlace { shaft: p, at: s.places[0].1 }, GearPlace { shaft: w, at: s.places[1].1 }],
            teeth,
            hand: s.hand,
            direction: s.direction.as_ref().map_or(0.0, |d| d.value.value),
            lubrication: s.lubrication,
            kind,
        });
    }
    if errors.len() > before {
        return None;
    }
    super::lower_drive_places::check_gears_on_sections(stages, &built, &shafts, errors);
    check_loops(stages, &built, shafts.len(), errors)?;
    check_layout(stages, &built, &shafts, errors);
    let (input, output) = ends(&shafts, gearbox, errors)?;
    if !all_stages {
        return None;
    }
    for (j, shaft) in shafts.iter().enumerate() {
        if !built.iter().any(|s| s.member_on(j).is_some()) {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    shaft.name.span,
                    format!("shaft `{}` carries no gear", shaft.name.text),
                )
                .hint(
                    "put a stage's pinion or wheel on it (`shaft = ...` in the stage's gears), or leave the shaft out",
                ),
            );
        }
    }
    let chain = Drive::find_chain(&built, input, output);
    match &chain {
        None => errors.push(
            Diagnostic::new(DiagnosticKind::OutOfRange, gearbox, "no chain of stages joins the input shaft to the output shaft")
                .hint("each stage joins the shaft of its pinion to the shaft of its wheel: join the input to the output through them"),
        ),
        Some(c) => {
            for (_, s) in stages.iter().enumerate().filter(|(k, _)| !c.iter().any(|(i, _)| i == k)) {
                errors.push(
                    Diagnostic::new(DiagnosticKind::OutOfRange, s.name.span, format!("stage `{}` is not on the way from the input to the output", s.name.text))
                        .hint("this version takes one chain of stages from the input to the output; a branch (a power take-off) comes later"),
                );
            }
        }
    }
    let floating = floating_suns(&built, shafts.len());
    let shafts = shafts
        .iter()
        .enumerate()
        .filter_map(|(j, s)| super::lower_drive_places::lower_places(s, (one_pair, floating[j]), errors))
        .collect::<Vec<_>>();
    (errors.len() == before).then(|| Drive {
        shafts,
        stages: built,
        input,
        output,
        chain: chain.unwrap_or_default(),
        operating,
    })
}

/// Shaft names to indices; a name declared twice is an error.
fn shaft_index<'a>(shafts: &'a [ShaftDecl], errors: &mut Vec<Diagnostic>) -> BTreeMap<&'a str, usize> {
    let mut index = BTreeMap::new();
    for (j, s) in shafts.iter().enumerate() {
        if index.insert(s.name.text.as_str(), j).is_some() {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::DuplicateKey,
                    s.name.span,
                    format!("shaft `{}` is declared twice", s.name.text),
                )
                .hint("give each shaft a name of its own"),
            );
        }
    }
    index
}

/// Stages must not close a loop of shafts (each stage joins two shafts not yet joined).
fn check_loops(decls: &[StageDecl], stages: &[Stage], n: usize, errors: &mut Vec<Diagnostic>) -> Option<()> {
    let mut root: Vec<usize> = (0..n).collect();
    fn find(root: &mut [usize], mut i: usize) -> usize {
        while root[i] != i {
            root[i] = root[root[i]];
            i = root[i];
        }
        i
    }
    for (s, d) in stages.iter().zip(decls) {
        let (a, b) = (find(&mut root, s.places[0].shaft), find(&mut root, s.places[1].shaft));
        if a == b {
            errors.push(
                Diagnostic::new(DiagnosticKind::OutOfRange, d.name.span, format!("stage `{}` closes a loop: its shafts are already joined through other stages", s.name))
                    .hint("the kinematics of a loop of stages is over-determined; a drive here is a chain from the input to the output"),
            );
            return None;
        }
        root[a] = b;
    }
    Some(())
}

/// The input and the output shaft: exactly one of each, and not the same.
fn ends(shafts: &[ShaftDecl], gearbox: Span, errors: &mut Vec<Diagnostic>) -> Option<(usize, usize)> {
    let mut found = [None, None];
    for (e, word) in ["input", "output"].iter().enumerate() {
        let with: Vec<(usize, Span)> = shafts
            .iter()
            .enumerate()
            .filter_map(|(j, s)| if e == 0 { s.input } else { s.output }.map(|span| (j, span)))
            .collect();
        match with.as_slice() {
            [] => errors.push(
                Diagnostic::new(DiagnosticKind::MissingKey, gearbox, format!("no shaft is the drive's `{word}`")).hint(
                    format!(
                        "write `{word}` in the block of the shaft where the {} is",
                        if e == 0 { "motor" } else { "load" }
                    ),
                ),
            ),
            [(j, _)] => found[e] = Some(*j),
            [_, (_, span), ..] => errors.push(
                Diagnostic::new(DiagnosticKind::DuplicateKey, *span, format!("two shafts say `{word}`"))
                    .hint(format!("a drive has one {word} shaft")),
            ),
        }
    }
    let (i, o) = (found[0]?, found[1]?);
    if i == o {
        errors.push(
            Diagnostic::new(
                DiagnosticKind::OutOfRange,
                shafts[i].name.span,
                "the input and the output are the same shaft",
            )
            .hint("the output is the shaft at the other end of the stages"),
        );
        return None;
    }
    Some((i, o))
}

/// Where both shafts of a stage give a `position`, their distance is the stage's centre distance
/// and their direction the stage's `direction` (when it gives one).
fn check_layout(decls: &[StageDecl], stages: &[Stage], shafts: &[ShaftDecl], errors: &mut Vec<Diagnostic>) {
    for (s, d) in stages.iter().zip(decls) {
        let (Some((p, _)), Some((w, span))) = (shafts[s.places[0].shaft].position, shafts[s.places[1].shaft].position)
        else {
            continue;
        };
        let Ok(g) = d.pair.geometry() else { continue };
        let (dx, dy) = (w[0] - p[0], w[1] - p[1]);
        let distance = dx.hypot(dy);
        if let Some(what) = d.kind.coaxial() {
            if distance > CENTRE_TOLERANCE {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::Geometry,
                        span,
                        format!(
                            "the shafts of {what} `{}` are {:.4} mm apart: its members turn about one axis",
                            s.name,
                            distance * 1e3
                        ),
                    )
                    .hint(format!("give the shafts of a {what}'s members the same `position`")),
                );
            }
            continue;
        }
        if (distance - g.center_distance).abs() > CENTRE_TOLERANCE {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::Geometry,
                    span,
                    format!(
                        "the shafts of stage `{}` are {:.4} mm apart, its centre distance is {:.4} mm",
                        s.name,
                        distance * 1e3,
                        g.center_distance * 1e3
                    ),
                )
                .hint("move a shaft's `position`, or give the stage's `center_distance` (and profile shifts) that fit"),
            );
        }
        if let Some(dir) = &d.direction {
            let off = (dy.atan2(dx) - dir.value.value).rem_euclid(std::f64::consts::TAU);
            if off.min(std::f64::consts::TAU - off) > 1e-6 {
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::Geometry,
                        dir.span,
                        format!(
                            "stage `{}`'s `direction` is not the direction from its pinion's shaft to its wheel's",
                            s.name
                        ),
                    )
                    .hint(format!(
                        "the shafts' positions give {:.4} deg; leave `direction` out to take it from them",
                        dy.atan2(dx).to_degrees()
                    )),
                );
            }
        }
    }
}

/// Every shaft of a drive with bearings needs them when any shaft has them (the statics).
fn check_bearings_everywhere(shafts: &[ShaftDecl], errors: &mut Vec<Diagnostic>) {
    if shafts.iter().all(|s| s.bearings.is_empty()) {
        return;
    }
    for s in shafts.iter().filter(|s| s.bearings.is_empty()) {
        errors.push(
            Diagnostic::new(DiagnosticKind::MissingKey, s.name.span, format!("shaft `{}` has gears but no bearings", s.name.text))
                .hint("its statics (and so the other shafts' bearing losses) needs its two bearing places: add them with their `at`"),
        );
    }
}

/// Per shaft: whether its one gear is a member its stage's kind centres by its own bodies (a
/// floating sun among two planets or more), so that one bearing place may carry its shaft.
fn floating_suns(stages: &[crate::drive::Stage], shafts: usize) -> Vec<bool> {
    (0..shafts)
        .map(|j| {
            let on: Vec<(&crate::drive::Stage, crate::drive::Member)> = stages
                .iter()
                .flat_map(|st| {
                    [crate::drive::Member::Pinion, crate::drive::Member::Wheel]
                        .into_iter()
                        .filter(move |m| st.places[m.index()].shaft == j)
                        .map(move |m| (st, m))
                })
                .collect();
            matches!(on.as_slice(), [(st, m)] if st.model().centred_member(*m))
        })
        .collect()
}
