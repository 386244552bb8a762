//! A scene of one pair read as its one-stage drive analyses its stage's mesh as the pair alone over
//! the scene's whole sweep (`stages/pair`): that pair alone is the scene's own pair, oil, laws,
//! operating block and analyses of one pair, without what the drive evaluates itself (budget,
//! thermal balance, duty cycle, map), so its mesh sections are the pair's own report's.

use gearloss::efficiency::Formulation;
use gearloss::report::Report;

/// Every scene of one pair in specs/ and tests/specs/ok/ (not on a drive cycle).
fn pair_scenes() -> Vec<std::path::PathBuf> {
    crate::one_stage::pair_scene_files(|text| !text.contains("vehicle"))
}

/// Every pair scene that checks, with its name from the project root.
fn checked_pair_scenes() -> impl Iterator<Item = (String, gearloss::Scene)> {
    pair_scenes().into_iter().filter_map(|path| {
        let name = path.strip_prefix(crate::root()).unwrap().display().to_string();
        let source = std::fs::read_to_string(&path).unwrap();
        gearloss::check(&name, &source).ok().map(|scene| (name, scene))
    })
}

/// The same JSON but for numbers that agree to `tol` relative (of the larger magnitude); the
/// numbers compared.
fn agree(at: &str, a: &serde_json::Value, b: &serde_json::Value, tol: f64) -> usize {
    use serde_json::Value;
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => {
            let (x, y) = (x.as_f64().unwrap(), y.as_f64().unwrap());
            assert!((x - y).abs() <= tol * x.abs().max(y.abs()), "{at}: {x} vs {y}");
            1
        }
        (Value::Array(x), Value::Array(y)) => {
            assert_eq!(x.len(), y.len(), "{at}: lengths");
            x.iter().zip(y).enumerate().map(|(k, (x, y))| agree(&format!("{at}[{k}]"), x, y, tol)).sum()
        }
        (Value::Object(x), Value::Object(y)) => {
            assert_eq!(x.keys().collect::<Vec<_>>(), y.keys().collect::<Vec<_>>(), "{at}: keys");
            x.iter().map(|(k, v)| agree(&format!("{at}.{k}"), v, &y[k], tol)).sum()
        }
        _ => {
            assert_eq!(a, b, "{at}");
            0
        }
    }
}

/// The sections of a pair's report that are its mesh's: the geometry, every point in full (contact,
/// μ along the line of action, film), each law's efficiency record, the dynamics, the stiffness
/// from the teeth, the transmission error and the composite law's mean |μ|.
fn mesh_sections(r: &Report) -> serde_json::Value {
    serde_json::json!({
        "geometry": r.geometry,
        "operating_points": r.operating_points,
        "efficiency": r.efficiency,
        "dynamics": r.dynamics,
        "stiffness": r.stiffness,
        "transmission_error": r.transmission_error,
        "composite_mu": r.composite_mu,
    })
}

/// Every pair scene's one-stage drive analyses one mesh, its stage `pair`, over the whole sweep
/// (not at a point), and the pair alone's report has the pair's own geometry, points in full,
/// efficiency records, dynamics, stiffness, transmission error and composite μ: every number to
/// 1e-12 relative (the same evaluation of the same pair: they are in fact equal).
#[test]
fn a_pairs_stage_is_the_pair_alone_over_its_sweep() {
    let (mut scenes, mut numbers) = (0, 0);
    for path in pair_scenes() {
        let name = path.strip_prefix(crate::root()).unwrap().display().to_string();
        let source = std::fs::read_to_string(&path).unwrap();
        let Ok(pair) = gearloss::check(&name, &source) else { continue };
        // The checked scene carries its one-stage drive (`lower_as_one_stage_drive`'s, below).
        let pair = pair.at_oil_temperature(0);
        let stages = gearloss::evaluate::stage_pairs(&pair, pair.drive.as_ref().unwrap());
        assert_eq!(stages.len(), 1, "{name}");
        assert!(stages[0].at.is_none() && stages[0].stage_name == "pair", "{name}");
        let alone = stages[0].problem.as_ref().expect("the pair alone");
        assert_eq!(alone.operating.detail_points, pair.operating.detail_points, "{name}");
        let (a, p) = (gearloss::mesh_report(alone), gearloss::report_of(&pair));
        assert_eq!(a.efficiency.len(), p.efficiency.len(), "{name}");
        numbers += agree(&name, &mesh_sections(&a), &mesh_sections(&p), 1e-12);
        scenes += 1;
    }
    assert!(scenes >= 25, "{scenes} scenes");
    assert!(numbers > 10_000, "{numbers} numbers");
}

/// Run as a drive, the one-pair scene writes its stage's report into `stages/pair/`, and that
/// report.md is the pair's own from its Scene table on, but for what the drive evaluates itself:
/// a scene with no gearbox, housing or map (specs/fzg_type_c.gear) byte for byte, and so are its
/// plots but for their titles (`FZG type C: pair`).
#[test]
fn a_pairs_stage_report_is_the_pairs_own() {
    let path = crate::root().join("specs/fzg_type_c.gear");
    let source = std::fs::read_to_string(&path).unwrap();
    let ast = gearloss::parse("fzg_type_c.gear", &source).unwrap();
    let drive = gearloss::scene::lower::lower_as_one_stage_drive(&ast, path.parent()).unwrap();
    let (report, rendered) = gearloss::run_drive::drive_report_files(&drive, drive.drive.as_ref().unwrap()).unwrap();
    assert_eq!(report.stage_pairs.len(), 1);
    let row = &report.stage_pairs[0];
    assert_eq!((row.point, row.folder.as_deref()), (None, Some("stages/pair")));
    let file = |files: &[(String, String)], name: &str| files.iter().find(|(f, _)| f == name).unwrap().1.clone();
    let stage = file(&rendered.files, "stages/pair/report.md");
    let alone = gearloss::pair_files(&gearloss::check("fzg_type_c.gear", &source).unwrap()).unwrap();
    let own = file(&alone.files, "report.md");
    let from_scene = |md: &str| md[md.find("## Scene").unwrap()..].to_string();
    assert_eq!(from_scene(&stage), from_scene(&own));
    assert!(stage.starts_with("# FZG type C: pair\n"), "{}", &stage[..40]);
    let top = file(&rendered.files, "report.md");
    assert!(top.contains("[stages/pair/report.md](stages/pair/report.md)"));
    for plot in ["sweep_mu.svg", "sweep_speed.svg", "point_6_friction.svg"] {
        let stage = file(&rendered.files, &format!("stages/pair/{plot}")).replace("FZG type C: pair", "FZG type C");
        assert!(stage == file(&alone.files, plot), "{plot} differs from the pair's own but for its title");
    }
}

/// The lowered form of every scene of one pair carries its one-stage drive beside its blocks: the
/// drive `lower_as_one_stage_drive` gives (the same lowered JSON), with `one_pair` set, and the
/// drive walked on the scene as checked writes the same drive records byte for byte (the pair's
/// own blocks beside it change nothing the walk reads). A scene of one pair runs as that drive.
#[test]
fn a_pairs_lowered_form_carries_its_one_stage_drive() {
    let mut scenes = 0;
    for path in pair_scenes() {
        let name = path.strip_prefix(crate::root()).unwrap().display().to_string();
        let source = std::fs::read_to_string(&path).unwrap();
        let Ok(checked) = gearloss::check(&name, &source) else { continue };
        let ast = gearloss::parse(&name, &source).unwrap();
        let alone = gearloss::scene::lower::lower_as_one_stage_drive(&ast, path.parent()).unwrap();
        let drive = checked.drive.as_ref().expect("a pair's lowered form has its drive");
        assert!(drive.one_pair, "{name}");
        let json = |s: &gearloss::Scene| serde_json::from_str::<serde_json::Value>(&gearloss::lowered(s)).unwrap();
        assert_eq!(json(&checked)["drive"], json(&alone)["drive"], "{name}");
        assert_eq!(json(&checked)["gears"], json(&checked)["drive"]["pairs"][0], "{name}");
        if checked.analyses.efficiency.is_some() {
            let walk = |s: &gearloss::Scene| {
                let s = s.at_oil_temperature(0);
                let mut csv = Vec::new();
                gearloss::evaluate::evaluate_drive_into(&s, s.drive.as_ref().unwrap(), &mut csv).unwrap();
                csv
            };
            assert!(walk(&checked) == walk(&alone), "{name}: the drive records differ");
        }
        scenes += 1;
    }
    assert!(scenes >= 25, "{scenes} scenes");
}

/// A scene of one pair run as its drive keeps the total efficiency its own report has always
/// given: each headline row's "η at the pinion", 1 − P_V/(T_1 ω_1), is the pair's own total
/// efficiency at the same point, law and formulation — its law's charged mesh loss and its
/// gearbox's budget on its own two shafts (`pair_alone`) over the power at the pinion gear — to
/// 1e-12, for every pair spec with a gearbox whose points the drive's report keeps; the drive's own
/// η (P_out/P_in at the box's ends) differs where the pinion shaft loses power.
#[test]
fn a_pairs_drive_report_keeps_its_total_efficiency() {
    let (mut compared, mut differs) = (0, 0);
    for (name, scene) in checked_pair_scenes() {
        if scene.gearbox.is_none() || scene.analyses.efficiency.is_none() || scene.operating.oil_temperatures.is_some()
        {
            continue;
        }
        let alone = crate::pair_alone::PairAlone::new(&scene);
        let (drive, _) = gearloss::run_drive::drive_report_files(&scene, scene.drive.as_ref().unwrap()).unwrap();
        assert!(drive.one_pair, "{name}");
        for p in &drive.points {
            let Some(eta) = p.pinion_efficiency() else { continue };
            let s = &p.point.stages[0];
            let law = scene.friction.iter().position(|l| l.label() == p.law).unwrap();
            let f =
                [Formulation::External, Formulation::Internal].into_iter().find(|f| f.name() == p.formulation).unwrap();
            let (t, w) = (s.driving_torque, s.driving_speed);
            let [mesh, beside] = alone.losses((law, f), (t, w));
            let want = 1.0 - (mesh + beside) / (t * w);
            assert!((eta - want).abs() <= 1e-12, "{name} {}: {eta} vs {want}", p.label);
            differs += usize::from((p.point.efficiency - want).abs() > 1e-9);
            compared += 1;
        }
    }
    assert!(compared >= 20 && differs > 0, "{compared} rows compared, {differs} where the drive's η differs");
}

/// A drive written with `stage` blocks has no pair alone (its operating block is at the drive's
/// ends; its meshes are analysed at the states its walk gives them): `Scene::pair_alone` is None
/// and `gearloss::pair_files` refuses it, `FailureKind::NotOnePair` with a hint; a scene of one pair
/// (lowered with its one-stage drive) has its pair alone.
#[test]
fn a_drive_of_stages_has_no_pair_alone() {
    let drive = crate::scene(&crate::root().join("specs/ev_two_stage_reducer.gear"));
    assert!(drive.pair_alone().is_none());
    let e = gearloss::pair_files(&drive).expect_err("a drive of stages is refused");
    let f = e.failure().expect("a failure with its kind");
    assert_eq!(f.kind, gearloss::FailureKind::NotOnePair);
    assert!(f.reason.contains("drive of stages") && !f.hints.is_empty(), "{f:?}");
    let pair = crate::scene(&crate::root().join("specs/fzg_type_c.gear"));
    assert!(pair.drive.as_ref().is_some_and(|d| d.one_pair) && pair.pair_alone().is_some());
}
