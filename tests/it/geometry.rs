//! Spur geometry against the paper and independent hand calculations.

use std::f64::consts::PI;

use gearloss::geometry::{involute, PairGeometry, TipSource};

fn fzg() -> PairGeometry {
    let scene = crate::scene(&crate::root().join("specs/fzg_type_c.gear"));
    scene.gears.geometry().unwrap()
}

/// FZG type C (Fernandes et al. Table 1; issue 2): ε_α = 1.4362 ± 1e-4, α_w = 22.4388° ± 1e-4°, T1T2 = 34.93 mm.
#[test]
fn fzg_type_c_against_the_paper() {
    let g = fzg();
    assert!((g.contact_ratio - 1.4362).abs() < 1e-4, "ε_α = {}", g.contact_ratio);
    assert!(
        (g.operating_pressure_angle.to_degrees() - 22.4388).abs() < 1e-4,
        "α_w = {}",
        g.operating_pressure_angle.to_degrees()
    );
    assert!((g.line_of_action_length * 1e3 - 34.93).abs() < 5e-3, "T1T2 = {} mm", g.line_of_action_length * 1e3);
    assert_eq!(g.tip_source, [TipSource::Given, TipSource::Given]);
}

/// The same pair by hand, along another route: α_w from acos, T1T2 = sqrt(a² − (r_b1 + r_b2)²),
/// path of contact from the two tip circles, ε from the ISO 21771 tangent form. Tolerance 1e-12 relative.
#[test]
fn fzg_type_c_by_an_independent_hand_calculation() {
    let g = fzg();
    let (m, alpha, a) = (4.5e-3, 20f64.to_radians(), 91.5e-3);
    let (rb1, rb2) = (m * 16.0 / 2.0 * alpha.cos(), m * 24.0 / 2.0 * alpha.cos());
    let (ra1, ra2) = (82.45e-3 / 2.0, 118.35e-3 / 2.0);
    let t1t2 = (a * a - (rb1 + rb2).powi(2)).sqrt();
    let alpha_w = ((rb1 + rb2) / a).acos();
    let ga = (ra1 * ra1 - rb1 * rb1).sqrt() + (ra2 * ra2 - rb2 * rb2).sqrt() - t1t2;
    let eps = ga / (PI * m * alpha.cos());
    let eps_tan = (16.0 * ((rb1 / ra1).acos().tan() - alpha_w.tan())
        + 24.0 * ((rb2 / ra2).acos().tan() - alpha_w.tan()))
        / (2.0 * PI);
    let rel = |x: f64, y: f64| ((x - y) / y).abs();
    assert!(rel(g.line_of_action_length, t1t2) < 1e-12);
    assert!(rel(g.operating_pressure_angle, alpha_w) < 1e-12);
    assert!(rel(g.contact_ratio, eps) < 1e-12);
    assert!(rel(g.contact_ratio, eps_tan) < 1e-12);
    // Points: B = E − p_b, D = A + p_b, P = r_b1 tan α_w; approach + recess ratios add up to ε_α.
    let p = g.points;
    assert!(rel(p.e - p.b, g.base_pitch) < 1e-12 && rel(p.d - p.a, g.base_pitch) < 1e-12);
    assert!(rel(p.p, rb1 * alpha_w.tan()) < 1e-12);
    assert!(rel(g.addendum_contact_ratio[0] + g.addendum_contact_ratio[1], g.contact_ratio) < 1e-12);
    // The zero-backlash centre distance of the paper's profile shifts is the given 91.5 mm to 0.1 µm.
    assert!((g.zero_backlash_center_distance - a).abs() < 1e-6, "a_0 = {}", g.zero_backlash_center_distance);
}

/// The inch scene: shifted teeth, tip diameters by the addendum rule, centre distance from the
/// involute function. ε_α checked by ISO 21771's tangent form, computed here from scratch.
#[test]
fn inch_scene_contact_ratio_by_the_iso_21771_tangent_form() {
    let scene = crate::scene(&crate::root().join("specs/us_spur_inch.gear"));
    let g = scene.gears.geometry().unwrap();
    let m = 0.0254 / 8.0;
    let alpha = 20f64.to_radians();
    let (z1, z2, x1, x2) = (20.0, 45.0, 0.25, -0.1);
    // inv α_w = inv α + 2 tan α (x1 + x2)/(z1 + z2), solved by bisection (independent of the library's Newton).
    let target = involute(alpha) + 2.0 * alpha.tan() * (x1 + x2) / (z1 + z2);
    let (mut lo, mut hi) = (0.1f64, 1.0f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid.tan() - mid < target {
            lo = mid
        } else {
            hi = mid
        }
    }
    let alpha_w = 0.5 * (lo + hi);
    let da = |z: f64, x: f64| m * (z + 2.0 + 2.0 * x);
    let alpha_a = |z: f64, x: f64| ((m * z * alpha.cos()) / da(z, x)).acos();
    let eps =
        (z1 * (alpha_a(z1, x1).tan() - alpha_w.tan()) + z2 * (alpha_a(z2, x2).tan() - alpha_w.tan())) / (2.0 * PI);
    assert!((g.contact_ratio - eps).abs() < 1e-10, "ε_α = {} vs ISO 21771 {eps}", g.contact_ratio);
    assert!((g.contact_ratio_iso21771() - eps).abs() < 1e-10);
    assert!((g.operating_pressure_angle - alpha_w).abs() < 1e-12);
    assert_eq!(g.tip_source, [TipSource::AddendumRule, TipSource::AddendumRule]);
    assert!((g.module - m).abs() < 1e-15, "m = 1/P_d");
}

/// High contact ratio pairs are supported: n pairs in contact and shares 1/2 and 1/3.
#[test]
fn high_contact_ratio_pairs_share_load_by_thirds() {
    let input = crate::high_contact_ratio_input();
    let g = PairGeometry::compute(&input).unwrap();
    assert!(g.contact_ratio > 2.0 && g.contact_ratio < 3.0, "ε_α = {}", g.contact_ratio);
    let p = g.points;
    // Within a mesh cycle the reference pair sees 3 pairs while a third pair is inside (A, E), else 2.
    let n_at = |u: f64| g.pairs_in_contact(u);
    assert_eq!(n_at(p.a + 1e-6), 3);
    let frac = g.contact_ratio - 2.0;
    assert_eq!(n_at(p.a + (frac + 0.5 * (1.0 - frac)) * g.base_pitch), 2);
    // Time-average of 1/n over one base pitch equals 1/ε_α (the load is always carried once in total).
    let k = 200_000;
    let mean_pairs: f64 =
        (0..k).map(|i| n_at(p.a + (i as f64 + 0.5) / k as f64 * g.base_pitch) as f64).sum::<f64>() / k as f64;
    assert!((mean_pairs - g.contact_ratio).abs() < 1e-4, "mean pairs {mean_pairs} vs ε_α {}", g.contact_ratio);
}

#[test]
fn equal_sharing_carries_the_whole_load_between_b_and_d() {
    let g = fzg();
    let p = g.points;
    for (u, n) in [(p.a, 2), (p.b, 1), (p.p, 1), (p.d, 1), (p.e, 2), (0.5 * (p.a + p.b), 2), (0.5 * (p.d + p.e), 2)] {
        assert_eq!(g.pairs_in_contact(u), n, "at {u}");
    }
}

/// Kinematics: v_s = ω1 (1 + z1/z2) |s| (physics notes), zero at P; Hertz p_H·b_H·π/2 = w.
#[test]
fn contact_state_closed_forms() {
    use gearloss::geometry::OperatingState;
    use gearloss::geometry::{reduced_modulus, Sharing};
    let g = fzg();
    let op = OperatingState { pinion_torque: 302.0, pinion_speed: 1000.0 * PI / 30.0 };
    let e_r = reduced_modulus([206e9, 206e9], [0.3, 0.3]);
    assert!((e_r - 2.0 * 206e9 / (2.0 * 0.91)).abs() < 1.0);
    for i in 0..=20 {
        let u = g.points.a + (g.points.e - g.points.a) * i as f64 / 20.0;
        let c = g.contact_at(u, &op, e_r, Sharing::Equal);
        let vs = op.pinion_speed * (1.0 + 16.0 / 24.0) * c.s.abs();
        assert!((c.sliding_velocity - vs).abs() < 1e-12 * (1.0 + vs));
        assert!((PI / 2.0 * c.hertz_pressure * c.hertz_half_width - c.load_per_width).abs() < 1e-9 * c.load_per_width);
        assert!(
            (c.reduced_radius - c.radius_of_curvature[0] * c.radius_of_curvature[1] / g.line_of_action_length).abs()
                < 1e-15
        );
    }
    assert!(g.contact_at(g.points.p, &op, e_r, Sharing::Equal).sliding_velocity < 1e-12);
}

/// Where the number of pairs in contact changes, for any contact ratio: for the 40/60 pair with
/// ε_α ≈ 2.47 the points A+kp_b and E−kp_b (k = 1, 2) inside A–E, in order, each with a change of
/// the pair count across it (3 ↔ 2), the count constant between them, and none of them called B or
/// D (the single-contact limits, which do not exist here); they are rows of the contact table. For
/// FZG type C (ε_α = 1.44) the classical A B P D E.
#[test]
fn pair_change_points_for_any_contact_ratio() {
    let g = PairGeometry::compute(&crate::high_contact_ratio_input()).unwrap();
    assert!(g.contact_ratio > 2.0 && g.contact_ratio < 3.0, "ε_α = {}", g.contact_ratio);
    let changes = g.pair_change_points();
    let (a, e, pb) = (g.points.a, g.points.e, g.base_pitch);
    let mut expected = vec![a + pb, a + 2.0 * pb, e - pb, e - 2.0 * pb];
    expected.retain(|u| *u > a && *u < e);
    expected.sort_by(f64::total_cmp);
    assert_eq!(changes.iter().map(|c| c.1).collect::<Vec<_>>(), expected);
    assert!(changes.iter().all(|(n, _)| *n != "B" && *n != "D"), "{changes:?}");
    let d = 1e-6 * pb;
    let mut knots = vec![a];
    knots.extend(changes.iter().map(|c| c.1));
    knots.push(e);
    for w in knots.windows(2) {
        let (lo, hi) = (g.pairs_in_contact(w[0] + d), g.pairs_in_contact(w[1] - d));
        assert_eq!(lo, hi, "count changes inside ({}, {})", w[0], w[1]);
        assert!(lo == 2 || lo == 3);
    }
    for (name, u) in &changes {
        let (before, after) = (g.pairs_in_contact(u - d), g.pairs_in_contact(u + d));
        assert!(before != after && before.min(after) == 2 && before.max(after) == 3, "{name}: {before} → {after}");
    }
    let rows = gearloss::evaluate::table_positions(&g);
    for (name, _) in &changes {
        assert!(rows.iter().any(|(n, _)| n == &Some(*name)), "{name} not in the table");
    }
    let fzg = crate::scene(&crate::root().join("specs/fzg_type_c.gear")).gears.geometry().unwrap();
    let names: Vec<&str> = fzg.named_points().iter().map(|p| p.0).collect();
    assert_eq!(names, ["A", "B", "P", "D", "E"]);
}
