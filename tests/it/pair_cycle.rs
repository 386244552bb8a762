//! One pair over a drive cycle: the scene of one `gears` block with a vehicle is the one-stage drive
//! it describes. Its cycle loses what the same box written with a `stage` loses, and at its operating
//! points every bearing, seal, no-load and mesh loss is the pair's own budget (bearings written
//! without `at` included).

use gearloss::evaluate::drive_cycle::{evaluate_cycle, PARTS};

const PAIR: &str = "tests/specs/ok/cycle_pair_udds.gear";
const STAGE: &str = "tests/specs/ok/cycle_udds_final_drive.gear";

/// The pair fixture's text with `edits` made, lowered as if it were the fixture's own file (its
/// trace is found beside it).
fn pair_scene(edits: &[(&str, &str)]) -> gearloss::Scene {
    let path = crate::root().join(PAIR);
    let mut text = std::fs::read_to_string(&path).unwrap();
    for (a, b) in edits {
        assert!(text.contains(a), "{a}");
        text = text.replacen(a, b, 1);
    }
    gearloss::check(&path.display().to_string(), &text).unwrap_or_else(|e| panic!("{}", e.render(false)))
}

/// Each piece's integrals of the box's loss parts over the cycle (J).
fn cycle_parts(scene: &gearloss::Scene) -> Vec<[f64; PARTS]> {
    let drive = scene.drive.as_ref().expect("a pair on a drive cycle is a one-stage drive");
    let e = evaluate_cycle(scene, drive, drive.cycle.as_ref().unwrap());
    e.integrals.iter().map(|r| std::array::from_fn(|k| r.value[k])).collect()
}

/// The pair with its wheel's bearings where the stage fixture puts them (30 and 136.24 mm on its
/// lay shaft, the gear at 55.72 mm: −25.72 and 80.52 mm from the mesh mid-plane) loses, piece by
/// piece and part by part, what the stage fixture loses, to 1e-12 of the largest part (the
/// positions differ by a rounding of 55.72 mm).
#[test]
fn a_pair_on_a_cycle_loses_what_its_one_stage_drive_loses() {
    let placed = "bearing(type = deep_groove_ball, bore = 40 mm, outside = 68 mm, static_load_rating = 10.2 kN, at = -25.72 mm)
            bearing(type = deep_groove_ball, bore = 40 mm, outside = 68 mm, static_load_rating = 10.2 kN, at = 80.52 mm)";
    let pair = pair_scene(&[(
        "bearing(type = deep_groove_ball, bore = 40 mm, outside = 68 mm, static_load_rating = 10.2 kN, count = 2)",
        placed,
    )]);
    let stage = crate::scene(&crate::root().join(STAGE));
    let (a, b) = (cycle_parts(&pair), cycle_parts(&stage));
    assert_eq!(a.len(), b.len());
    let scale = b.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    assert!(scale > 1.0, "the cycle loses {scale} J at most in a part");
    for (k, (x, y)) in a.iter().zip(&b).enumerate() {
        for (p, (u, v)) in x.iter().zip(y).enumerate() {
            assert!((u - v).abs() <= 1e-12 * scale, "piece {k}, part {p}: {u} vs {v}");
        }
    }
}

/// At the fixture's four operating points (its wheel's two bearings without `at`: each carries
/// F_bt/2, the axial force on the first), the one-stage drive's bearing loads and losses, seals,
/// no-load and mesh losses are the pair's budget (the same scene without its vehicle), 1e-12.
#[test]
fn a_pair_on_a_cycle_keeps_the_pair_budget() {
    let drive = pair_scene(&[]);
    let mut text = std::fs::read_to_string(crate::root().join(PAIR)).unwrap();
    let (from, to) = (text.find("    vehicle \"").unwrap(), text.find("    friction {").unwrap());
    text.replace_range(from..to, "");
    text = text.replacen("        drive_cycle\n", "", 1);
    let pair = crate::scene_from_text(&text);
    assert!(pair.drive.as_ref().unwrap().cycle.is_none() && drive.drive.as_ref().unwrap().cycle.is_some());
    crate::drive::assert_the_pair_budget(&pair, &drive);
}
