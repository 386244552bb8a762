//! Gearboxes with several stages: the drive's physics against its own balances (every shaft's
//! statics, the power balance), the kinematics, drive against coast, the fixed point, and a
//! one-stage drive against the loss budget of one pair.

use gearloss::drive::statics::residuals;
use gearloss::drive::{DrivePoint, PowerFlow};
use gearloss::evaluate::evaluate_drive;

fn ev_reducer() -> gearloss::Scene {
    crate::scene(&crate::root().join("specs/ev_two_stage_reducer.gear"))
}

/// Every row's point of a drive scene's evaluation.
pub(crate) fn points(scene: &gearloss::Scene) -> Vec<DrivePoint> {
    evaluate_drive(scene, scene.drive.as_ref().unwrap()).rows.into_iter().map(|r| r.point).collect()
}

/// Every shaft balances forces and moments (five equations from its bearing reactions, the sixth,
/// about its axis, from the torques the walk passes through it) to 1e-12 of the largest force.
#[test]
fn every_shaft_balances_forces_and_moments() {
    for p in points(&ev_reducer()) {
        for s in &p.shafts {
            assert!(s.gear_loads.iter().flat_map(|l| l.force).any(|f| f != 0.0));
            assert_shaft_balances(s);
        }
    }
}

/// A shaft's five equations from its two bearing places' reactions hold to 1e-12 of its largest
/// gear force, and about its axis received − passed = its own loss moments (powers over |ω|).
pub(crate) fn assert_shaft_balances(s: &gearloss::drive::ShaftPoint) {
    let largest = s.gear_loads.iter().flat_map(|l| l.force).fold(0.0f64, |m, f| m.max(f.abs()));
    let positions = [0, 1].map(|i| s.bearings[i].position.expect("a place of a drive's shaft has its `at`"));
    let reactions = [s.bearings[0].reaction, s.bearings[1].reaction];
    for r in residuals(&s.gear_loads, positions, &reactions) {
        assert!(r.abs() <= 1e-12 * largest, "{}: residual {r} of {largest} N", s.name);
    }
    let own = s.losses() / s.speed.abs();
    let torque = s.received_torque - s.passed_torque - own;
    assert!(torque.abs() <= 1e-12 * s.received_torque.abs().max(1.0), "{}: {torque}", s.name);
}

/// P_source − P_sink = Σ parts, to 1e-9 of the source's power, drive and coast.
#[test]
fn power_lost_is_the_sum_of_the_parts() {
    let all = points(&ev_reducer());
    assert!(all.iter().any(|p| p.flow == PowerFlow::Coast) && all.iter().any(|p| p.flow == PowerFlow::Drive));
    for p in all {
        let parts = p.losses.total();
        let source = p.input_power.abs().max(p.output_power.abs());
        assert!((p.power_lost() - parts).abs() <= 1e-9 * source, "{} vs {parts}", p.power_lost());
        let stages: f64 = p.stages.iter().map(|s| s.mesh_loss + s.no_load).sum();
        let shafts: f64 = p.shafts.iter().map(|s| s.losses()).sum();
        let no_load: f64 = p.stages.iter().map(|s| s.no_load).sum();
        assert!((stages + shafts - no_load - parts).abs() <= 1e-9 * source);
    }
}

/// Speeds by the ratios: ω_lay = −ω_motor 23/68, ω_out = ω_motor (23/68)(20/78), to 1e-14.
#[test]
fn speeds_follow_the_ratios() {
    for p in points(&ev_reducer()) {
        let w = |n: &str| p.shafts.iter().find(|s| s.name == n).unwrap().speed;
        let (motor, lay, out) = (w("motor"), w("lay"), w("output"));
        assert!(motor > 0.0, "the input turns counter-clockwise");
        assert!((lay / motor + 23.0 / 68.0).abs() < 1e-14);
        assert!((out / motor - 23.0 / 68.0 * 20.0 / 78.0).abs() < 1e-14);
        assert!((p.output_speed - out.abs()).abs() <= 1e-14 * p.output_speed);
    }
}

/// The fixed point settles in a few passes (3–8), every point.
#[test]
fn the_fixed_point_settles_in_a_few_passes() {
    for p in points(&ev_reducer()) {
        assert!((3..=8).contains(&p.iterations), "{} passes", p.iterations);
    }
}

/// Every point of every drive spec settles and balances its books (P_source − P_sink = Σ parts to
/// 1e-9 of the larger); bearing places 1 µm apart make the fixed point run away: every point is
/// then reported unsettled with its gap (the books off by more than 1e6 W), and the report warns
/// on each point shown and counts the rows, none of them passed off as settled.
#[test]
fn a_point_is_settled_only_when_its_books_balance() {
    for spec in ["ev_two_stage_reducer", "planetary_two_stage", "ev_reducer_three_bearing_lay_shaft"] {
        let scene = crate::scene(&crate::root().join(format!("specs/{spec}.gear")));
        for p in points(&scene) {
            assert!(p.settled() && p.books_gap.is_none(), "{spec}: {}", p.unsettled_words());
        }
        // report.json's total loss is P_in − P_out and the parts' sum (1e-9 of the source).
        let drive = scene.drive.as_ref().unwrap();
        let report = gearloss::report::drive::build_drive_report(&scene, drive, &evaluate_drive(&scene, drive));
        for p in &report.points {
            let source = p.point.input_power.abs().max(p.point.output_power.abs());
            assert_eq!(p.total_loss, p.point.input_power - p.point.output_power);
            assert!((p.total_loss - p.point.losses.total()).abs() <= 1e-9 * source, "{spec}: {}", p.total_loss);
        }
    }
    let scene =
        ev_with(&[("static_load_rating = 10.2 kN, at = 136.24 mm)", "static_load_rating = 10.2 kN, at = 30.001 mm)")]);
    let drive = scene.drive.as_ref().unwrap();
    let eval = evaluate_drive(&scene, drive);
    for r in &eval.rows {
        let p = &r.point;
        assert!(!p.settled() && p.diverged, "a row passed off as settled");
        let gap = p.books_gap.expect("the books cannot balance");
        assert!(gap.abs() > 1e6 && (gap + p.losses.total() - p.power_lost()).abs() <= 1e-6 * gap.abs(), "{gap}");
    }
    assert_eq!(eval.tally.unsettled_rows, eval.tally.rows);
    let report = gearloss::report::drive::build_drive_report(&scene, drive, &eval);
    let warned =
        report.findings.iter().filter(|f| f.message.contains("diverged") && f.message.contains("books")).count();
    assert_eq!(warned, report.points.len());
}

/// A drive with no bearings anywhere runs (meshes, seals and no-load parts) and says so.
#[test]
fn a_drive_without_bearings_says_so() {
    let text = std::fs::read_to_string(crate::root().join("specs/ev_two_stage_reducer.gear")).unwrap();
    let mut kept = String::new();
    let mut rest = text.as_str();
    while let Some(at) = rest.find("bearing(") {
        kept.push_str(&rest[..at]);
        rest = &rest[at + rest[at..].find(')').unwrap() + 1..];
    }
    kept.push_str(rest);
    let scene = gearloss::check("nobearings.gear", &kept).unwrap_or_else(|e| panic!("{e}"));
    let drive = scene.drive.as_ref().unwrap();
    let report = gearloss::report::drive::build_drive_report(&scene, drive, &evaluate_drive(&scene, drive));
    assert!(report.findings.iter().any(|f| f.message.starts_with("no shaft of the drive has bearings")));
    assert!(report
        .points
        .iter()
        .all(|p| p.point.losses.part(gearloss::losses::parts::LossColumn::BearingsLoad) == 0.0 && p.point.settled()));
}

/// The EV reducer's text with `edits` (find, replace) applied.
fn ev_with(edits: &[(&str, &str)]) -> gearloss::Scene {
    let mut text = std::fs::read_to_string(crate::root().join("specs/ev_two_stage_reducer.gear")).unwrap();
    for (a, b) in edits {
        assert!(text.contains(a), "{a}");
        text = text.replacen(a, b, 1);
    }
    gearloss::check("ev.gear", &text).unwrap_or_else(|e| panic!("{}", e.render(false)))
}

/// Drive and coast at the same |T| (±500 N·m at the output): coast has every stage driven by its
/// wheel, drive by its pinion; the tangential forces reverse (the axial ones with them), so the
/// bearing loads differ (some place by more than 10 %), and so do the totals; each balances.
#[test]
fn drive_and_coast_at_the_same_torque() {
    let both = points(&ev_with(&[("output_torque = [-500, 150, 1000] N*m", "output_torque = [-500, 500] N*m")]));
    let (coast, drive) = (&both[0], &both[2]);
    assert_eq!((coast.flow, drive.flow), (PowerFlow::Coast, PowerFlow::Drive));
    assert!(coast.stages.iter().all(|s| s.driving == gearloss::drive::Member::Wheel));
    assert!(drive.stages.iter().all(|s| s.driving == gearloss::drive::Member::Pinion));
    let radial =
        |p: &DrivePoint| p.shafts.iter().flat_map(|s| s.bearings.iter().map(|b| b.radial_load)).collect::<Vec<_>>();
    let most = radial(coast).iter().zip(radial(drive)).map(|(c, d)| (c - d).abs() / d).fold(0.0, f64::max);
    assert!(most > 0.10, "bearing loads differ by at most {most}");
    // H_V is symmetric in ε₁, ε₂ and the law's μ reads the load and speed: the efficiencies are
    // close, not equal (the bearing losses differ).
    let gap = (coast.efficiency - drive.efficiency).abs();
    assert!(gap > 0.0 && gap < 0.01, "{gap}");
    assert!((coast.output_torque + drive.output_torque).abs() < 1e-9);
}

/// With no bearings, seals, lubrication or friction at all, drive and coast at the same |T| give
/// η = 1 and P_in = P_out to 1e-12.
#[test]
fn a_box_without_losses_passes_all_its_power_both_ways() {
    let text = std::fs::read_to_string(crate::root().join("specs/ev_two_stage_reducer.gear")).unwrap();
    let start = text.find("    gearbox {").unwrap();
    let end = text.find("    operating {").unwrap();
    // (Without a housing, no thermal balance or duty cycle either.)
    let (duty, friction) = (text.find("    # A stretch of driving").unwrap(), text.find("    friction {").unwrap());
    let text = format!(
        "{}    gearbox {{ shaft motor {{ input }} shaft lay {{ }} shaft output {{ output }} }}\n{}{}",
        &text[..start],
        &text[end..duty],
        &text[friction..]
    )
    .replace("        thermal_balance\n", "")
    .replace("        duty_cycle\n", "")
    .replace("friction { iso_14179_2(x_l = 0.75) }", "friction { coulomb(mu = 0) }")
    .replace("        lubrication = injection(flow = 2.5 l/min, jet_speed = 0.4 m/s)\n", "")
    .replace("output_torque = [-500, 150, 1000] N*m", "output_torque = [-500, 500] N*m")
    .replace("efficiency_map(output_torque = -1000..1000 N*m count 41, output_speed = 10..1500 rpm count 30)", "");
    let scene = gearloss::check("lossless.gear", &text).unwrap_or_else(|e| panic!("{}", e.render(false)));
    let p = points(&scene);
    assert_eq!(p.len(), 4);
    for d in &p {
        assert!((d.efficiency - 1.0).abs() < 1e-12, "{}", d.efficiency);
        assert!((d.input_power - d.output_power).abs() <= 1e-12 * d.input_power.abs());
        assert!((d.output_torque.abs() - 500.0).abs() < 1e-9);
        assert_eq!(d.iterations, 2, "nothing moves after the first pass");
    }
    let (coast, drive) = (&p[0], &p[2]);
    assert_eq!(coast.flow, PowerFlow::Coast);
    assert!((coast.input_torque + drive.input_torque).abs() <= 1e-12 * drive.input_torque);
}

/// Given at the output or at the input, the same point: solving with the input torque a given
/// output torque needed gives that output torque back (1e-9 relative), drive and coast.
#[test]
fn input_or_output_given_is_the_same_point() {
    for p in points(&ev_reducer()) {
        let text = std::fs::read_to_string(crate::root().join("specs/ev_two_stage_reducer.gear")).unwrap();
        // (The duty cycle's steps name the ends `operating` does: given at the input, they go.)
        let (start, end) = (text.find("    duty_cycle \"").unwrap(), text.find("    friction {").unwrap());
        let text = format!("{}{}", &text[..start], &text[end..]).replace("        duty_cycle\n", "");
        let text = text
            .replace("output_torque = [-500, 150, 1000] N*m", &format!("input_torque = {:?} N*m", p.input_torque))
            .replace("output_speed  = [500, 1000] rpm", &format!("input_speed = {:?} rad/s", p.input_speed));
        let scene = gearloss::check("in.gear", &text).unwrap_or_else(|e| panic!("{}", e.render(false)));
        let q = &points(&scene)[0];
        assert_eq!(q.flow, p.flow);
        assert!(
            (q.output_torque - p.output_torque).abs() <= 1e-9 * p.output_torque.abs(),
            "{} vs {}",
            q.output_torque,
            p.output_torque
        );
        assert!((q.power_lost() - p.power_lost()).abs() <= 1e-9 * p.input_power.abs());
    }
}

/// The axial sense: a right-hand driving gear turning counter-clockwise about +z is pushed along
/// +z; the sign flips with the hand, with the sense of rotation and on the driven gear.
#[test]
fn axial_force_follows_hand_and_rotation() {
    use gearloss::drive::kinematics::StageKind;
    use gearloss::drive::{mesh_forces, GearPlace, Hand, Member, MeshForceSizes, Stage};
    let sizes = MeshForceSizes {
        working_pitch_radius: [0.02, 0.05],
        pitch_radius: [0.02, 0.05],
        working_pressure_angle: 0.36,
        helix_angle: 0.3,
        face_width: 0.03,
    };
    let stage = |hand| Stage {
        name: "s".into(),
        kind: StageKind::Parallel,
        places: [GearPlace { shaft: 0, at: 0.0 }, GearPlace { shaft: 1, at: 0.0 }],
        teeth: [20, 50],
        hand: Some(hand),
        direction: 0.7,
        lubrication: None,
    };
    let f_a = 100.0 * 0.3f64.tan() / 0.02;
    for (hand, omega, driving, on_driving) in [
        (Hand::Right, 1.0, Member::Pinion, f_a),
        (Hand::Left, 1.0, Member::Pinion, -f_a),
        (Hand::Right, -1.0, Member::Pinion, -f_a),
        (Hand::Left, -1.0, Member::Pinion, f_a),
        // The wheel driving: its own hand is the other, its radius the wheel's.
        (Hand::Right, 1.0, Member::Wheel, -100.0 * 0.3f64.tan() / 0.05),
    ] {
        let loads = mesh_forces((0, &stage(hand)), &sizes, driving, 100.0, omega);
        let d = driving.index();
        assert!((loads[d].force[2] - on_driving).abs() < 1e-9, "{hand:?} {omega} {driving:?}");
        assert_eq!(loads[1 - d].force, loads[d].force.map(|x| -x));
        // The moment on the driving gear opposes its rotation and is its torque.
        assert!((loads[d].torque() + omega.signum() * 100.0).abs() < 1e-9);
    }
}

/// A one-stage drive written with a stage gives the loss budget of the same pair written with
/// `gears` (specs/helical_gearbox.gear), at the pinion torque the drive puts into the mesh: each
/// bearing place's radial and axial load and its two losses, the seals, the gears' no-load loss
/// and the mesh loss, to 1e-12 relative.
#[test]
fn one_stage_drive_is_the_pair_budget() {
    let pair = crate::scene(&crate::root().join("specs/helical_gearbox.gear"));
    let drive = gearloss::check("one_stage.gear", ONE_STAGE).unwrap_or_else(|e| panic!("{}", e.render(false)));
    assert_the_pair_budget(&pair, &drive);
}

/// At every point of `drive` (one stage), each bearing place's loads and losses, the seals, the
/// gears' no-load loss and the mesh loss equal `pair`'s budget at the stage's driving torque and
/// speed, to 1e-12 relative.
pub(crate) fn assert_the_pair_budget(pair: &gearloss::Scene, drive: &gearloss::Scene) {
    use gearloss::geometry::Sharing;
    let g = pair.gears.geometry().unwrap();
    let tribology = pair.mesh().tribology(pair.mesh().reduced_modulus());
    let oil = pair.mesh().budget_oil(&tribology);
    let close = |a: f64, b: f64, what: &str| {
        assert!((a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1e-9), "{what}: {a} vs {b}")
    };
    let points = points(drive);
    assert!(!points.is_empty());
    for p in points {
        let stage = &p.stages[0];
        let (t, w) = (stage.driving_torque, stage.driving_speed);
        let budget = gearloss::losses::loss_budget(pair.gearbox.as_ref().unwrap(), &g, t, w, &oil);
        let places: Vec<_> = p.shafts.iter().flat_map(|s| &s.bearings).collect();
        assert_eq!(places.len(), budget.bearings.len());
        for (d, b) in places.iter().zip(&budget.bearings) {
            close(d.radial_load, b.loads.radial_load, "radial load");
            close(d.axial_load, b.loads.axial_load, "axial load");
            close(d.no_load, b.loads.no_load, "P_0");
            close(d.load, b.loads.load.unwrap(), "P_1");
        }
        let column = |c| budget.parts.iter().find(|(k, _)| *k == c).unwrap().1;
        close(
            p.losses.part(gearloss::losses::parts::LossColumn::Seals),
            column(gearloss::losses::parts::LossColumn::Seals),
            "seals",
        );
        close(
            p.losses.part(gearloss::losses::parts::LossColumn::GearNoLoad),
            column(gearloss::losses::parts::LossColumn::GearNoLoad),
            "no-load",
        );
        let state = gearloss::geometry::OperatingState { pinion_torque: t, pinion_speed: w };
        let ctx = gearloss::friction::LawContext { geometry: &g, state, tribology, sharing: Sharing::Equal };
        let law = pair.friction[0].build(&ctx).unwrap();
        let h_v = gearloss::efficiency::ohlendorf_loss_factor(&ctx);
        let mesh =
            gearloss::efficiency::charged_mesh_loss(&ctx, &*law, gearloss::efficiency::Formulation::External, h_v);
        close(stage.mesh_loss, mesh, "mesh loss");
    }
}

/// specs/helical_gearbox.gear written as a one-stage drive: the same pair, bearings, seals and
/// oil; the gear at 0 on both shafts (today's `at` is from the mesh mid-plane), a right-hand pinion
/// turning counter-clockwise so that its axial force points to +at as today's reading has it.
const ONE_STAGE: &str = r#"scene "one stage" {
    material steel { youngs_modulus = 210 GPa  poisson_ratio = 0.3 }
    lubricant = iso_vg(150, pao)
    stage "only" {
        gears {
            module = 3 mm  pressure_angle = 20 deg  helix_angle = 15 deg  hand = right  face_width = 30 mm
            pinion { teeth = 23  profile_shift = 0.25  shaft = pinion_shaft  at = 0 mm  material = steel  roughness_ra = 0.4 um }
            wheel  { teeth = 37  profile_shift = 0.10  shaft = wheel_shaft   at = 0 mm  material = steel  roughness_ra = 0.4 um }
        }
        lubrication = dip(pinion_immersion = 0 mm, wheel_immersion = 25 mm, axis_height = 120 mm, housing_width = 120 mm)
    }
    gearbox {
        shaft pinion_shaft { input
            bearing(type = tapered_roller, bore = 30 mm, outside = 62 mm, y = 1.6, at = -45 mm, locating)
            bearing(type = tapered_roller, bore = 30 mm, outside = 62 mm, y = 1.6, at = 45 mm)
            seal(diameter = 30 mm) }
        shaft wheel_shaft { output
            bearing(type = deep_groove_ball, bore = 40 mm, outside = 80 mm, static_load_rating = 19 kN, at = -50 mm, locating)
            bearing(type = cylindrical_roller, bore = 40 mm, outside = 80 mm, at = 70 mm)
            seal(diameter = 40 mm) }
    }
    operating { input_torque = [100, 400] N*m  input_speed = [1000, 3000] rpm  oil_temperature = 70 degC }
    friction { iso_14179_2 }
    analyses { efficiency(formulations = [external]) }
}"#;

/// Stage kinds: each row names its kinematics file in `src/drive/kinematics/` and has its model
/// `src/drive/<name>_stage.rs` registered in `stage_kinds.rs`; each such file has a row; every row
/// sits at its identity's index.
#[test]
fn stage_kinds_one_file_one_row() {
    use gearloss::drive::kinematics::STAGE_KINDS;
    let files: std::collections::BTreeSet<String> = std::fs::read_dir(crate::root().join("src/drive/kinematics"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !["mod.rs", "catalog.rs", "stage_kinematics.rs"].contains(&n.as_str()))
        .collect();
    let rows: std::collections::BTreeSet<String> = STAGE_KINDS.iter().map(|k| k.file.to_string()).collect();
    assert_eq!(files, rows, "files in src/drive/kinematics/ and rows of STAGE_KINDS differ");
    // Each kind's model (its StageModel, what the walk reads of it) is src/drive/<name>_stage.rs,
    // registered in stage_kinds.rs.
    let models: std::collections::BTreeSet<String> = std::fs::read_dir(crate::root().join("src/drive"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with("_stage.rs"))
        .collect();
    let named: std::collections::BTreeSet<String> =
        STAGE_KINDS.iter().map(|k| format!("{}_stage.rs", k.name)).collect();
    assert_eq!(models, named, "model files src/drive/*_stage.rs and rows of STAGE_KINDS differ");
    let registry = std::fs::read_to_string(crate::root().join("src/drive/stage_kinds.rs")).unwrap();
    for k in STAGE_KINDS {
        assert!(registry.contains(&format!("StageKind::{:?}", k.id)), "stage_kinds.rs has no row for {}", k.name);
    }
    for (i, k) in STAGE_KINDS.iter().enumerate() {
        assert_eq!(k.id as usize, i, "{}", k.name);
    }
}

/// The drive's thermal balance: at θ* the drive's whole loss equals what the housing gives off
/// (to 1e-9 relative; θ* is located to 1e-10 K), and the drive run at oil temperature θ* loses
/// P_V(θ*) again (1e-9): the balance reads the same drive.
#[test]
fn thermal_balance_of_the_drive() {
    let scene = ev_reducer();
    let drive = scene.drive.as_ref().unwrap();
    let eval = evaluate_drive(&scene, drive);
    assert_eq!(eval.balances.len(), eval.rows.len());
    let mut found = 0;
    for (b, row) in eval.balances.iter().zip(&eval.rows) {
        let Some(t) = b.balance.temperature else { continue };
        let (loss, q) = (b.loss, b.dissipation.total);
        found += 1;
        assert!((loss - q).abs() <= 1e-9 * loss, "{loss} vs {q}");
        let text = std::fs::read_to_string(crate::root().join("specs/ev_two_stage_reducer.gear")).unwrap();
        let at = text.replace("oil_temperature = 80 degC", &format!("oil_temperature = {:?} K", t));
        let at = gearloss::check("at.gear", &at).unwrap();
        let again = &evaluate_drive(&at, at.drive.as_ref().unwrap()).rows
            [eval.rows.iter().position(|r| std::ptr::eq(r, row)).unwrap()];
        assert!((again.point.power_lost() - loss).abs() <= 1e-9 * loss);
    }
    assert!(found >= 4, "{found} balances");
}

/// drive_records.csv: a row per operating point, law and formulation with every part; each row's
/// total is its parts' sum and P_in − P_out (1e-9), and every stage and bearing place has its columns.
#[test]
fn drive_records_hold_every_part() {
    let path = crate::root().join("specs/ev_two_stage_reducer.gear");
    let r = gearloss::run_to_files("ev.gear", &std::fs::read_to_string(path).unwrap()).unwrap();
    let csv = &r.files.iter().find(|(f, _)| f == "drive_records.csv").unwrap().1;
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("{name}"));
    assert_eq!(header.iter().filter(|h| h.starts_with("bearing_") && h.ends_with("_radial_N")).count(), 6);
    assert_eq!(header.iter().filter(|h| h.starts_with("stage_") && h.ends_with("_mesh_loss_W")).count(), 2);
    let rows: Vec<Vec<f64>> =
        lines.map(|l| l.split(',').map(|c| c.parse::<f64>().unwrap_or(f64::NAN)).collect()).collect();
    assert_eq!(rows.len(), 6);
    for row in &rows {
        assert_eq!(row.len(), header.len());
        let parts: f64 = ["meshes_W", "gear_no_load_W", "bearings_no_load_W", "bearings_load_W", "seals_W"]
            .iter()
            .map(|c| row[col(c)])
            .sum();
        let total = row[col("total_W")];
        assert!((parts - total).abs() <= 1e-9 * total);
        assert!(
            (row[col("input_power_W")] - row[col("output_power_W")] - total).abs()
                <= 1e-9 * row[col("input_power_W")].abs()
        );
    }
}

/// A law used outside its validity range on a stage is flagged: Drozdov–Gavrikov holds for rolling
/// velocities of 3–20 m/s, so at 10 rpm at the output every contact of both stages is outside
/// (246 of 246 in the report and in drive_records.csv: the 241 even positions along A–E, the pitch
/// point and both sides of B and D, where a pair alone reads it) and a warning names each stage.
#[test]
fn a_law_outside_its_validity_is_flagged_on_each_stage() {
    let text = std::fs::read_to_string(crate::root().join("specs/ev_two_stage_reducer.gear"))
        .unwrap()
        .replace("friction { iso_14179_2(x_l = 0.75) }", "friction { drozdov_gavrikov }")
        .replace("output_torque = [-500, 150, 1000] N*m", "output_torque = 300 N*m")
        .replace("output_speed  = [500, 1000] rpm", "output_speed = 10 rpm")
        .replace("efficiency_map(output_torque = -1000..1000 N*m count 41, output_speed = 10..1500 rpm count 30)", "")
        .replace("        thermal_balance\n", "");
    let r = gearloss::run_to_files("slow.gear", &text).unwrap_or_else(|e| panic!("{e}"));
    let json = &r.files.iter().find(|(f, _)| f == "report.json").unwrap().1;
    let report: gearloss::report::drive::DriveReport = serde_json::from_str(json).unwrap();
    assert_eq!(report.points[0].validity.iter().map(|v| (v.0, v.1)).collect::<Vec<_>>(), vec![(246, 246); 2]);
    let warned = |stage: &str| {
        report.findings.iter().any(|f| f.message.contains(&format!("stage `{stage}`: the law is outside")))
    };
    assert!(warned("first") && warned("second"));
    let csv = &r.files.iter().find(|(f, _)| f == "drive_records.csv").unwrap().1;
    assert!(csv.lines().nth(1).unwrap().contains(",246,"));
}

/// The thermal ratings: with the rated output torque the drive's sump settles on the oil's limit
/// (120 °C), and with the one at 95 °C on ISO/TR 14179-1's rating temperature (each to 1e-6 K), at
/// both speeds of the EV reducer.
#[test]
fn thermal_rating_puts_the_sump_on_the_limit() {
    let scene = ev_reducer();
    let eval = evaluate_drive(&scene, scene.drive.as_ref().unwrap());
    let rated: Vec<(usize, f64, f64)> = eval
        .balances
        .iter()
        .flat_map(|b| [(b.rating, 393.15), (b.rating_95, 368.15)].map(|(r, k)| r.map(|r| (b.speed_index, r, k))))
        .flatten()
        .collect();
    assert!(rated.len() >= 8, "{rated:?}");
    for (speed, torque, kelvin) in rated {
        let text = std::fs::read_to_string(crate::root().join("specs/ev_two_stage_reducer.gear")).unwrap();
        let rpm = [500, 1000][speed];
        let text = text
            .replace("output_torque = [-500, 150, 1000] N*m", &format!("output_torque = {torque:?} N*m"))
            .replace("output_speed  = [500, 1000] rpm", &format!("output_speed = {rpm} rpm"));
        let at = gearloss::check("rated.gear", &text).unwrap();
        let b = &evaluate_drive(&at, at.drive.as_ref().unwrap()).balances[0];
        assert!((b.balance.temperature.unwrap() - kelvin).abs() < 1e-6, "{:?} at {torque} N*m", b.balance);
    }
}

/// Several oil temperatures: one drive report per temperature in its folder, each the report the
/// drive gives at that temperature alone (report.json byte for byte), and their comparison at the
/// top; `gearloss render` draws the same files again from the folder's report.json files.
#[test]
fn a_drive_at_several_oil_temperatures() {
    let text = std::fs::read_to_string(crate::root().join("specs/ev_two_stage_reducer.gear")).unwrap();
    let swept = text.replace("oil_temperature = 80 degC", "oil_temperature = [60, 80] degC");
    let r = gearloss::run_to_files("swept.gear", &swept).unwrap_or_else(|e| panic!("{e}"));
    let file = |n: &str| &r.files.iter().find(|(f, _)| f == n).unwrap_or_else(|| panic!("{n}")).1;
    let alone = gearloss::run_to_files("ev.gear", &text).unwrap();
    let alone_json = &alone.files.iter().find(|(f, _)| f == "report.json").unwrap().1;
    assert_eq!(file("oil_temperature_80degC/report.json"), alone_json);
    // Each run listed with its own report's warnings and notes, as a pair's comparison lists them,
    // and the efficiency against the temperature drawn (the plot's values are report.json's rows).
    for t in ["60", "80"] {
        let report: serde_json::Value =
            serde_json::from_str(file(&format!("oil_temperature_{t}degC/report.json"))).unwrap();
        let findings = report["findings"].as_array().unwrap();
        let warnings = findings.iter().filter(|f| f["severity"] == "warning").count();
        let line = format!(
            "[{t} degC](oil_temperature_{t}degC/report.md): {warnings} warning{}, {} note{}",
            if warnings == 1 { "" } else { "s" },
            findings.len() - warnings,
            if findings.len() - warnings == 1 { "" } else { "s" }
        );
        assert!(file("report.md").contains(&line), "{line}");
    }
    assert!(file("report.md").contains("![efficiency against oil temperature](efficiency_vs_oil_temperature.svg)"));
    let plot = file("efficiency_vs_oil_temperature.svg");
    assert!(plot.contains("efficiency of the drive η (%)"));
    assert_eq!(crate::plot_text::outside(plot), Vec::new(), "text past the canvas");
    let dir = std::env::temp_dir().join(format!("gearloss-drive-oil-{}", std::process::id()));
    for (name, content) in &r.files {
        let path = dir.join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, content).unwrap();
    }
    let again = gearloss::rerender::render_folder(&dir).unwrap();
    for (name, content) in again {
        assert_eq!(&content, file(&name), "{name}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The drive's duty cycle: a step at an operating point's torque and speed loses what that point
/// loses at the oil temperature (1e-12); over the transient the sump's heat balances,
/// C (θ_end − θ_start) = Σ (E_lost − E_given off) to 1e-6; a standing step loses nothing.
#[test]
fn duty_cycle_of_the_drive_balances_its_energy() {
    let scene = ev_reducer();
    let eval = evaluate_drive(&scene, scene.drive.as_ref().unwrap());
    let duty = eval.duty.as_ref().unwrap();
    let fixed = duty.fixed.as_ref().unwrap();
    // Step 1 is 150 N*m at 500 rpm: operating row 3 (torque 150, speed 500).
    let row = eval.rows.iter().find(|r| (r.torque_index, r.speed_index) == (1, 0)).unwrap();
    assert!((fixed[0] - row.point.power_lost()).abs() <= 1e-12 * fixed[0]);
    assert_eq!(fixed[3], 0.0);
    let t = duty.transient.as_ref().unwrap().as_ref().unwrap();
    let c = scene.housing.as_ref().unwrap().heat_capacity.unwrap();
    let stored = c * (t.steps.last().unwrap().temperature - scene.housing.as_ref().unwrap().ambient);
    let net: f64 = t.steps.iter().map(|s| s.energy_lost - s.energy_dissipated).sum();
    assert!((stored - net).abs() <= 1e-6 * stored, "{stored} vs {net}");
    assert_eq!(t.steps[3].energy_lost, 0.0);
}

/// A drive's run in three shards, merged, is the single run: drive_records.csv byte for byte (the
/// shards' rows in order) and every report file (the tallies folded: the count, η's range over all
/// rows), for the EV reducer and for it with a lay shaft on three places (elastic shafts, their
/// plot). Shards of a drive at several oil temperatures are refused with a hint.
#[test]
fn a_drive_in_shards_merges_to_the_single_run() {
    shards_merge_to_the_single_run("specs/ev_reducer_three_bearing_lay_shaft.gear", "elastic");
    let (text, base) = shards_merge_to_the_single_run("specs/ev_two_stage_reducer.gear", "rigid");
    let swept = text.replace("oil_temperature = 80 degC", "oil_temperature = [60, 80] degC");
    let scene = gearloss::check("swept.gear", &swept).unwrap();
    let shard = Some(gearloss::Shard { index: 1, count: 2 });
    let e = gearloss::run_into("swept.gear", &swept, &scene, &base.join("no"), shard, &gearloss::Quiet).unwrap_err();
    assert_eq!(e.failure().unwrap().kind, gearloss::FailureKind::ShardedDrive);
    std::fs::remove_dir_all(&base).unwrap();
}

/// A drive's report shows its first 12 rows and every row of each detail point beyond them: the
/// large sweep (144 points × 2 laws, one formulation) with detail points 17 and 100 shows rows
/// 1–12, 33–34 and 199–200 of drive_records.csv, each that row (its total loss to 1e-12, relative),
/// and report.md says which; run in three shards and merged (the kept rows evaluated again, range by
/// range), every file of its folder is the single run's.
#[test]
fn a_drives_report_shows_its_detail_points_rows() {
    let spec = "tests/specs/ok/large_sweep.gear";
    let scene = crate::scene(&crate::root().join(spec));
    let eval = gearloss::evaluate::evaluate_drive(&scene, scene.drive.as_ref().unwrap());
    let rows = crate::pair_alone::DriveRows::of(&scene);
    let kept: Vec<usize> =
        eval.rows.iter().map(|r| rows.find((r.torque_index, r.speed_index), r.law_index, r.formulation)).collect();
    assert_eq!(kept, (0..12).chain([32, 33, 198, 199]).collect::<Vec<_>>());
    for (r, &k) in eval.rows.iter().zip(&kept) {
        let total = rows.value(k, "total_W");
        assert!(
            (r.point.power_lost() - total).abs() <= 1e-12 * total,
            "row {}: {} vs {total}",
            k + 1,
            r.point.power_lost()
        );
    }
    assert_eq!(eval.validity.len(), kept.len());
    let (_, base) = shards_merge_to_the_single_run(spec, "detail");
    let whole = std::fs::read_dir(base.join("whole")).unwrap().next().unwrap().unwrap().path();
    let md = std::fs::read_to_string(whole.join("report.md")).unwrap();
    assert!(
        md.contains("16 of 288 rows (operating points × laws × formulations): the first 12 and every row of detail points 17, 100;"),
        "{md}"
    );
    std::fs::remove_dir_all(&base).unwrap();
}

/// `spec` run whole and in three shards, merged: every file the same. The scene's text and the
/// folder it ran in (`whole/`, `shards/`, `merged/`).
fn shards_merge_to_the_single_run(spec: &str, tag: &str) -> (String, std::path::PathBuf) {
    let text = std::fs::read_to_string(crate::root().join(spec)).unwrap();
    let scene = gearloss::check("ev.gear", &text).unwrap();
    let base = std::env::temp_dir().join(format!("gearloss-drive-shards-{tag}-{}", std::process::id()));
    let whole = gearloss::run_into("ev.gear", &text, &scene, &base.join("whole"), None, &gearloss::Quiet).unwrap();
    let mut folders = Vec::new();
    for k in [2, 1, 3] {
        let shard = Some(gearloss::Shard { index: k, count: 3 });
        folders.push(
            gearloss::run_into("ev.gear", &text, &scene, &base.join("shards"), shard, &gearloss::Quiet).unwrap().folder,
        );
    }
    // Each shard's drive_records.csv stands alone, its header first (as a pair's shard's records.csv).
    let header = |folder: &std::path::Path| {
        std::fs::read_to_string(folder.join("drive_records.csv")).unwrap().lines().next().unwrap().to_string()
    };
    for folder in &folders {
        assert_eq!(header(folder), header(&whole.folder), "{}", folder.display());
    }
    let merged = gearloss::merge_into(&folders, &base.join("merged"), &gearloss::Quiet).unwrap();
    let mut names = whole.files.clone();
    names.sort();
    let mut got = merged.files.clone();
    got.sort();
    assert_eq!(names, got);
    for name in &names {
        let a = std::fs::read(whole.folder.join(name)).unwrap();
        let b = std::fs::read(merged.folder.join(name)).unwrap();
        assert!(a == b, "{name} differs");
    }
    (text, base)
}

/// Any number of stages in a chain: the EV reducer with a third, spur stage on a fourth shaft at
/// φ = 90° (its own shaft layout off the line of the others): speeds by the three ratios (1e-14),
/// every shaft in balance (1e-12), the power balance (1e-9), drive and coast.
#[test]
fn three_stages_with_a_spur_stage_across() {
    let text = std::fs::read_to_string(crate::root().join("specs/ev_two_stage_reducer.gear")).unwrap();
    let text = text
        .replace(
            "    gearbox {",
            r#"    stage "third" {
        direction = 90 deg
        gears {
            module = 3 mm  pressure_angle = 20 deg  face_width = 40 mm
            pinion { teeth = 25  shaft = output  at = 70 mm   material = steel  roughness_ra = 0.5 um }
            wheel  { teeth = 50  shaft = wheel   at = 60 mm   material = steel  roughness_ra = 0.5 um }
        }
        lubrication = dip(pinion_immersion = 0 mm, wheel_immersion = 20 mm, axis_height = 150 mm, housing_width = 200 mm)
    }
    gearbox {"#,
        )
        .replace("        shaft output { output\n", "        shaft output {\n")
        .replace(
            "        # The housing as one thermal node",
            "        shaft wheel  { output\n                       bearing(type = cylindrical_roller, bore = 60 mm, outside = 110 mm, at = 20 mm)\n                       bearing(type = deep_groove_ball, bore = 60 mm, outside = 110 mm, static_load_rating = 23.2 kN, at = 120 mm, locating) }\n        # The housing as one thermal node",
        );
    let scene = gearloss::check("three.gear", &text).unwrap_or_else(|e| panic!("{}", e.render(false)));
    let all = points(&scene);
    assert!(all.iter().any(|p| p.flow == PowerFlow::Coast));
    for p in all {
        assert_eq!(p.stages.len(), 3);
        let w = |n: &str| p.shafts.iter().find(|s| s.name == n).unwrap().speed;
        let ratio = w("wheel") / w("motor");
        assert!((ratio + 23.0 / 68.0 * 20.0 / 78.0 * 25.0 / 50.0).abs() < 1e-14, "{ratio}");
        p.shafts.iter().for_each(assert_shaft_balances);
        let source = p.input_power.abs().max(p.output_power.abs());
        assert!((p.power_lost() - p.losses.total()).abs() <= 1e-9 * source);
    }
}

/// A negative input speed turns every shaft the other way (speeds negated exactly) and the axial
/// forces with them; the shafts stay in balance and the power balance holds.
#[test]
fn a_negative_input_speed_turns_every_shaft_the_other_way() {
    let text = std::fs::read_to_string(crate::root().join("specs/ev_two_stage_reducer.gear")).unwrap();
    let at = |speed: &str| {
        let (start, end) = (text.find("    # A stretch of driving").unwrap(), text.find("    friction {").unwrap());
        let t = format!("{}{}", &text[..start], &text[end..])
            .replace("        duty_cycle\n", "")
            .replace("output_torque = [-500, 150, 1000] N*m", "input_torque = 80 N*m")
            .replace("output_speed  = [500, 1000] rpm", &format!("input_speed = {speed}"));
        points(&gearloss::check("neg.gear", &t).unwrap_or_else(|e| panic!("{}", e.render(false))))[0].clone()
    };
    let (ccw, cw) = (at("6000 rpm"), at("-6000 rpm"));
    for (a, b) in ccw.shafts.iter().zip(&cw.shafts) {
        assert_eq!(a.speed, -b.speed, "{}", a.name);
        assert_shaft_balances(b);
    }
    // The right-hand pinion driving: along +z turning counter-clockwise, along −z clockwise (the
    // magnitudes differ by the bearing losses before the mesh, which the reversed forces change).
    let axial = |p: &DrivePoint| p.shafts[0].gear_loads[0].force[2];
    assert!(axial(&ccw) > 0.0 && axial(&cw) < 0.0);
    assert!((axial(&ccw) + axial(&cw)).abs() < 1e-3 * axial(&ccw));
    assert!((cw.power_lost() - cw.losses.total()).abs() <= 1e-9 * cw.input_power);
}

/// The loss map's best point of each half is located, not the grid's: on the e-axle's map (25 × 12
/// points) η at the located point is at least the half's best grid point's, and no point a step of
/// 1e-3 of the search box away (inside the map, on the half's side of zero) is higher, to 1e-12
/// (the search stops where a sweep moves it by 1e-7 of the box; η is smooth there, so the loss of η
/// over that distance is far below 1e-12). Each neighbour is the drive solved afresh from a scene
/// with that operating point.
#[test]
fn drive_map_best_points_are_located_maxima() {
    let text = std::fs::read_to_string(crate::root().join("specs/planetary_two_stage.gear")).unwrap();
    let scene = crate::scene_from_text(&text);
    let eval = evaluate_drive(&scene, scene.drive.as_ref().unwrap());
    assert_eq!(eval.map_best.len(), 2);
    let (cell_t, cell_n) = (100.0, (1200.0 - 10.0) / 11.0);
    for b in &eval.map_best {
        let (t, w, eta) = b.located;
        let n = w * 30.0 / std::f64::consts::PI;
        assert!(eta >= b.grid.2, "{:?}: located η {eta} below the grid's {}", b.flow, b.grid.2);
        let (dt, dn) = (2e-3 * cell_t, 2e-3 * cell_n);
        let torques: Vec<f64> = [t - dt, t, t + dt].into_iter().filter(|x| x.abs() <= 1200.0 && x * t > 0.0).collect();
        let speeds: Vec<f64> = [n - dn, n, n + dn].into_iter().filter(|x| (10.0..=1200.0).contains(x)).collect();
        let list = |v: &[f64]| v.iter().map(|x| format!("{x:.15}")).collect::<Vec<_>>().join(", ");
        let at = text.replace(
            "output_torque = [-500, 300, 1200] N*m\n        output_speed  = [200, 800] rpm",
            &format!("output_torque = [{}] N*m\n        output_speed = [{}] rpm", list(&torques), list(&speeds)),
        );
        assert_ne!(at, text);
        let around = points(&crate::scene_from_text(&at));
        let centre = around
            .iter()
            .find(|p| (p.output_torque.abs() - t.abs()).abs() < 1e-9 && (p.output_speed.abs() - w).abs() < 1e-9)
            .expect("the located point among the neighbours");
        assert!((centre.efficiency - eta).abs() < 1e-12, "{} vs {eta}", centre.efficiency);
        for p in &around {
            assert!(
                p.efficiency <= eta + 1e-12,
                "{:?}: η {} at a neighbour above the located {eta}",
                b.flow,
                p.efficiency
            );
        }
    }
}

/// Where each no-load part acts: each gear's windage (Anderson & Loewenthal) on its own gear's
/// shaft, the jet's impulse on its stage's pinion's shaft. In the EV reducer (injection on both
/// stages) the output shaft carries the second wheel's windage alone, and the lay shaft the first
/// wheel's windage plus the second stage's jet and pinion windage. The two wheels' windages stand
/// in the ratio P_W ∝ (1 + 2.3 b/R) n^2.8 R^4.6 (the mist's viscosity cancels), R = m_n z/(2 cos β)
/// (no profile shift): checked to 1e-12, every point.
#[test]
fn each_gears_windage_acts_on_its_own_shaft() {
    let radius = |m: f64, z: f64, beta: f64| m * z / (2.0 * beta.to_radians().cos());
    let (r1, b1) = (radius(1.5177e-3, 68.0, 23.4), 35.44e-3);
    let (r2, b2) = (radius(2.5361e-3, 78.0, 18.4), 49.80e-3);
    for p in points(&ev_reducer()) {
        let [motor, lay, output] = [0, 1, 2].map(|j| &p.shafts[j]);
        assert!(output.gear_no_load > 0.0, "the second wheel's windage is on the output shaft");
        let ratio = (1.0 + 2.3 * b1 / r1) / (1.0 + 2.3 * b2 / r2)
            * (lay.speed / output.speed).abs().powf(2.8)
            * (r1 / r2).powf(4.6);
        let first_wheel = lay.gear_no_load - (p.stages[1].no_load - output.gear_no_load);
        assert!((first_wheel / (output.gear_no_load * ratio) - 1.0).abs() < 1e-12, "{first_wheel}");
        let books = motor.gear_no_load + lay.gear_no_load + output.gear_no_load;
        let stages = p.stages[0].no_load + p.stages[1].no_load;
        assert!((books - stages).abs() <= 1e-12 * stages, "{books} vs {stages}");
        assert!(motor.gear_no_load < p.stages[0].no_load);
    }
}

/// A bearing beyond its static rating is found over every row of the sweep, not only the rows the
/// report keeps (the first 12): the lay shaft's C_0 = 1.5 kN fixture at 11 output torques × 2
/// speeds (22 rows) passes P_0/C_0 = 1 only at its top torques, beyond the kept rows, and warns at
/// its worst row in the very words and numbers of the same scene run at that torque alone (whose 2
/// rows are all kept); at 10–60 N·m alone, nothing.
#[test]
fn a_bearing_beyond_its_rating_is_found_past_the_kept_rows() {
    let text = std::fs::read_to_string(crate::root().join("tests/specs/ok/bearing_beyond_static_rating.gear")).unwrap();
    let torques = "output_torque = [50, 100] N*m";
    assert!(text.contains(torques));
    let warnings = |t: &str| -> Vec<String> {
        let scene = gearloss::check("b.gear", &text.replace(torques, &format!("output_torque = {t} N*m")))
            .unwrap_or_else(|e| panic!("{}", e.render(false)));
        let drive = scene.drive.as_ref().unwrap();
        let eval = evaluate_drive(&scene, drive);
        assert!(eval.tally.rows <= 12 || eval.rows.len() == 12, "the report keeps the first 12 rows");
        let report = gearloss::report::drive::build_drive_report(&scene, drive, &eval);
        crate::messages_with(report.findings, "beyond its static rating")
    };
    let all = warnings("[10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110]");
    assert!(!all.is_empty() && all.iter().all(|w| w.contains("T_out = 110 N·m")), "{all:?}");
    assert_eq!(all, warnings("[110]"));
    assert_eq!(warnings("[10, 20, 30, 40, 50, 60]"), Vec::<String>::new());
}

/// A law's note on a stage counts and names operating points, not rows: the helical gearbox under
/// two laws and both formulations (4 points, 16 rows, the first 12 shown: 3 points) has ISO/TR
/// 14179-2's F_bt/b below 150 N/mm at its 100 N·m points only, and the note says so once, under
/// that law, each point once, with the first row's figures said to be the first's.
#[test]
fn a_stages_law_note_counts_operating_points() {
    let text = std::fs::read_to_string(crate::root().join("specs/helical_gearbox.gear")).unwrap();
    let text = text
        .replace("iso_14179_2\n", "iso_14179_2\n        coulomb(mu = 0.05)\n")
        .replace("formulations = [external]", "formulations = [external, internal]");
    let scene = crate::scene_from_text(&text);
    let drive = scene.drive.as_ref().unwrap();
    let report = gearloss::report::drive::build_drive_report(&scene, drive, &evaluate_drive(&scene, drive));
    assert_eq!(report.rows, 16);
    let notes = crate::messages_with(report.findings, "F_bt/b");
    assert_eq!(notes.len(), 1, "{notes:?}");
    assert!(
        notes[0].ends_with(
            "(figures at the first; at 2 of the 3 operating points shown, under iso_14179_2: \
             T_pinion = 100 N·m, n_in = 1000 rpm; T_pinion = 100 N·m, n_in = 3000 rpm)"
        ),
        "{}",
        notes[0]
    );
}
