//! Helical planetary stages (`tests/specs/ok/planetary_helical.gear`: 24/24/72, β = 10°, the sun
//! right hand, two planet bearings 20 mm apart): the axial forces and the planets' tilting moment
//! against their closed forms, every shaft's statics (the sun's n F_a on its locating place, the
//! carrier's couples) and the books balanced, with three planets and with one; a floating sun.

use super::drive::assert_shaft_balances;

const SPEC: &str = "tests/specs/ok/planetary_helical.gear";

fn points(source: &str) -> Vec<gearloss::drive::DrivePoint> {
    let scene = gearloss::check("helical.gear", source).unwrap_or_else(|e| panic!("{e}"));
    let drive = scene.drive.as_ref().unwrap();
    gearloss::evaluate::evaluate_drive(&scene, drive).rows.into_iter().map(|r| r.point).collect()
}

fn spec() -> String {
    std::fs::read_to_string(crate::root().join(SPEC)).unwrap()
}

/// At each point where the sun drives (drive, T_in > 0): F_a = T_sun tan β/(n r_sun) in both
/// meshes with r_sun = m_n z_sun/(2 cos β); the sun's shaft puts n F_a on its locating place and
/// none on the other; the planet's tilting moment is F_a · 2 r_planet (no profile shift: r_w = r);
/// its two bearings carry |(B_t/2, B_r/2 ± M/L)| of its in-plane load B (the larger listed), all
/// to 1e-12.
#[test]
fn the_axial_forces_and_the_tilting_moment_follow_their_closed_forms() {
    let (beta, n) = (10f64.to_radians(), 3.0);
    let r = 2e-3 * 24.0 / (2.0 * beta.cos());
    let mut checked = 0;
    for p in points(&spec()) {
        if p.input_torque <= 0.0 {
            continue;
        }
        let pp = p.stages[0].planetary().unwrap();
        let f = &pp.forces;
        let t_sun = p.stages[0].driving_torque;
        let f_a = t_sun * beta.tan() / (n * r);
        assert!((f.axial - f_a).abs() <= 1e-12 * f_a, "{} against {f_a}", f.axial);
        assert!((p.stages[0].axial_force - f_a).abs() <= 1e-12 * f_a);
        assert!((f.tilting - f_a * 2.0 * r).abs() <= 1e-12 * f.tilting);
        let sun = &p.shafts[0];
        let locating = sun.bearings.iter().find(|b| b.locating).unwrap();
        assert!((locating.axial_load - n * f_a).abs() <= 1e-12 * n * f_a, "{}", locating.axial_load);
        assert!(sun.bearings.iter().filter(|b| !b.locating).all(|b| b.axial_load == 0.0));
        let (b_t, b_r) = (f.tangential[0] + f.tangential[1], f.centrifugal + f.radial[0] - f.radial[1]);
        let m = f.tilting / 20e-3;
        let want = (0.5 * b_t).hypot(0.5 * b_r + m).max((0.5 * b_t).hypot(0.5 * b_r - m));
        let planets = p.shafts[1].bearings.iter().find(|b| b.of_stage_members).unwrap();
        assert!((planets.radial_load - want).abs() <= 1e-12 * want, "{} against {want}", planets.radial_load);
        checked += 1;
    }
    assert_eq!(checked, 2);
}

/// Every shaft balances forces and moments with the helical stage's axial forces and the carrier's
/// couples (three planets: they cancel; one planet: the carrier's places take the couple), and
/// every point's books balance.
#[test]
fn every_shaft_balances_and_the_books_close() {
    let one = spec().replace("planets = 3", "planets = 1");
    for source in [spec(), one] {
        for p in points(&source) {
            assert!(p.settled() && p.books_gap.is_none(), "{}", p.unsettled_words());
            for s in &p.shafts {
                assert_shaft_balances(s);
            }
            let carrier = &p.shafts[1];
            let axial: f64 = carrier.gear_loads.iter().map(|l| l.force[2]).sum();
            let largest = carrier.gear_loads.iter().map(|l| l.force[2].abs()).fold(0.0, f64::max);
            assert!(largest > 0.0 && axial.abs() <= 1e-12 * largest, "the planets' axial forces cancel on the carrier");
        }
    }
}

/// A floating sun: the helical sun's shaft on one bearing place (its planets centre it). The place
/// takes n F_a along the axis and nothing across it (1e-12 of F_t: the three planets' forces
/// cancel), the shaft balances with that one reaction, and the report notes the floating sun. With
/// one planet the shaft needs its two places (refused).
#[test]
fn a_floating_sun_rests_on_one_place() {
    let second = "                       bearing(type = deep_groove_ball, bore = 25 mm, outside = 47 mm, static_load_rating = 6.55 kN, at = 100 mm)\n";
    let floating = spec().replacen(second, "", 1);
    assert_ne!(floating, spec());
    let (beta, n) = (10f64.to_radians(), 3.0);
    let r = 2e-3 * 24.0 / (2.0 * beta.cos());
    for p in points(&floating) {
        let sun = &p.shafts[0];
        assert_eq!(sun.bearings.len(), 1);
        let b = &sun.bearings[0];
        let f_t = p.stages[0].tangential_force;
        assert!(b.radial_load <= 1e-12 * f_t, "{}", b.radial_load);
        if p.input_torque > 0.0 {
            let f_a = p.stages[0].driving_torque * beta.tan() / (n * r);
            assert!((b.axial_load - n * f_a).abs() <= 1e-12 * n * f_a, "{}", b.axial_load);
        }
        for k in 0..3 {
            let sum: f64 = sun.gear_loads.iter().map(|l| l.force[k]).sum::<f64>() + b.reaction[k];
            assert!(sum.abs() <= 1e-12 * f_t, "{k}: {sum}");
        }
        let z = b.position.unwrap();
        let (mx, my) = (
            sun.gear_loads.iter().map(|l| l.point[1] * l.force[2] - (l.point[2] - z) * l.force[1]).sum::<f64>(),
            sun.gear_loads.iter().map(|l| (l.point[2] - z) * l.force[0] - l.point[0] * l.force[2]).sum::<f64>(),
        );
        assert!(mx.abs() <= 1e-12 * f_t && my.abs() <= 1e-12 * f_t, "moments {mx}, {my}");
    }
    let scene = gearloss::check("floating.gear", &floating).unwrap();
    let drive = scene.drive.as_ref().unwrap();
    let report =
        gearloss::report::drive::build_drive_report(&scene, drive, &gearloss::evaluate::evaluate_drive(&scene, drive));
    assert!(report.findings.iter().any(|f| f.message.contains("carries a floating sun on one bearing place")));
    let one = floating.replace("planets = 3", "planets = 1");
    let e = gearloss::check("one.gear", &one).expect_err("one planet does not centre the sun");
    assert!(e.diagnostics.iter().any(|d| d.reason.contains("has one bearing place")), "{e:?}");
}
