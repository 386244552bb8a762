//! The internal pair (a pinion in a ring, ISO 21771): geometry against the standard's closed forms,
//! friction along its path against independent integrals, and the checks that refuse a ring.

use gearloss::efficiency::{local_power_loss, mean_efficiency, ohlendorf_loss_factor};
use gearloss::friction::BenedictKelley;
use gearloss::friction::Coulomb;
use gearloss::friction::{FrictionLaw, LawContext};
use gearloss::geometry::{involute, trochoid_margin, OperatingState, PairGeometry, PairInput, PairPart};
use gearloss::geometry::{reduced_modulus, Sharing};
use gearloss::model::Formulation::{External, Internal};

/// A planet of 25 teeth in a ring of 75, m = 2 mm, 20°, b = 25 mm; the ring's tip at `ring_tip`.
fn ring_input(ring_tip: Option<f64>) -> PairInput {
    PairInput {
        module: 2e-3,
        pressure_angle: 20f64.to_radians(),
        helix_angle: 0.0,
        teeth: [25, 75],
        profile_shift: [0.0, 0.0],
        tip_diameter: [None, ring_tip],
        center_distance: None,
        face_width: 0.025,
        internal: true,
    }
}

fn ctx(g: &PairGeometry) -> LawContext<'_> {
    let scene = crate::scene(&crate::root().join("tests/specs/ok/internal_pair.gear"));
    LawContext {
        geometry: g,
        state: OperatingState { pinion_torque: 60.0, pinion_speed: 1000.0 * std::f64::consts::PI / 30.0 },
        tribology: scene.mesh().tribology(reduced_modulus([206e9; 2], [0.3; 2])),
        sharing: Sharing::Equal,
    }
}

/// ISO 21771 by hand: a = m (z2 − z1)/2 = 50 mm, d_a2 = d2 − 2 m = 146 mm, T1T2 = −a sin α,
/// ε_α = [z1 (tan α_a1 − tan α_w) + z2 (tan α_a2 − tan α_w)]/2π with z2 = −75; to 1e-12.
#[test]
fn geometry_matches_iso_21771_closed_forms() {
    let g = PairGeometry::compute(&ring_input(None)).unwrap();
    let alpha = 20f64.to_radians();
    assert!((g.center_distance - 0.050).abs() < 1e-15);
    assert!((g.tip_radius[1] - 0.073).abs() < 1e-15, "ring tip radius {}", g.tip_radius[1]);
    assert!((g.gear_ratio + 3.0).abs() < 1e-15);
    assert!((g.line_of_action_length + 0.050 * alpha.sin()).abs() < 1e-15);
    let (rb1, rb2) = (0.025 * alpha.cos(), 0.075 * alpha.cos());
    let tan_a1 = (0.027f64.powi(2) - rb1 * rb1).sqrt() / rb1;
    let tan_a2 = (0.073f64.powi(2) - rb2 * rb2).sqrt() / rb2;
    let eps = (25.0 * (tan_a1 - alpha.tan()) - 75.0 * (tan_a2 - alpha.tan())) / (2.0 * std::f64::consts::PI);
    assert!((g.contact_ratio - eps).abs() < 1e-12, "ε_α {} vs {eps}", g.contact_ratio);
    assert!((g.contact_ratio_iso21771() - eps).abs() < 1e-12);
    // T1A = √(r_a2² − r_b2²) − a sin α_w: the ring's tip point lies between T1 and P.
    let t1a = (0.073f64.powi(2) - rb2 * rb2).sqrt() - 0.050 * alpha.sin();
    assert!((g.points.a - t1a).abs() < 1e-15 && g.points.a > 0.0 && g.points.a < g.points.p);
    // The ring's tooth at its tip: s_a2 = 2 r_a2 (π/(2 z2) − inv α + inv α_a2).
    let alpha_a2 = (rb2 / 0.073).acos();
    let s_a2 = 2.0 * 0.073 * (std::f64::consts::PI / 150.0 - involute(alpha) + involute(alpha_a2));
    assert!((g.tip_thickness[1] - s_a2).abs() < 1e-15, "s_a2 {} vs {s_a2}", g.tip_thickness[1]);
}

/// A profile-shifted pair at zero backlash: inv α_w = inv α + 2 tan α (x1 + x2)/(z1 + z2) with z2 < 0,
/// |a| = (r_b2 − r_b1)/cos α_w (ISO 21771), and ε_α by the line of action equals the tangent form.
#[test]
fn shifted_internal_pair_at_zero_backlash() {
    let input = PairInput { profile_shift: [0.3, -0.2], tip_diameter: [None, Some(0.1475)], ..ring_input(None) };
    let g = PairGeometry::compute(&input).unwrap();
    let alpha = 20f64.to_radians();
    let inv = involute(alpha) + 2.0 * alpha.tan() * (0.3 - 0.2) / (25.0 - 75.0);
    assert!((involute(g.operating_pressure_angle) - inv).abs() < 1e-14);
    let a = (0.075 - 0.025) * alpha.cos() / g.operating_pressure_angle.cos();
    assert!((g.center_distance - a).abs() < 1e-15);
    assert!((g.contact_ratio - g.contact_ratio_iso21771()).abs() < 1e-12);
}

/// The contact at P rolls without sliding; elsewhere v_s = |v1 − v2| and R = ρ1|ρ2|/(|ρ2| − ρ1).
#[test]
fn contact_state_of_a_concave_ring() {
    let g = PairGeometry::compute(&ring_input(Some(0.147))).unwrap();
    let c = ctx(&g);
    let at_p = c.contact_at(g.points.p);
    assert!((at_p.rolling_velocity[0] - at_p.rolling_velocity[1]).abs() < 1e-12 && at_p.sliding_velocity == 0.0);
    for k in 0..=10 {
        let u = g.points.a + (g.points.e - g.points.a) * k as f64 / 10.0;
        let p = c.contact_at(u);
        let (r1, r2) = (u, u - g.line_of_action_length);
        assert!((p.radius_of_curvature[1] + r2).abs() < 1e-15);
        assert!((p.reduced_radius - r1 * r2 / (r2 - r1)).abs() < 1e-12 * r2);
        let omega2 = c.state.pinion_speed / 3.0;
        let vs = (c.state.pinion_speed * r1 - omega2 * r2).abs();
        assert!((p.sliding_velocity - vs).abs() < 1e-12, "u {u}: {} vs {vs}", p.sliding_velocity);
    }
}

/// Coulomb friction along the internal path: 1 − η̄ = μ (1/r_b1 − 1/|r_b2|) ∫ w(u)|u − T1P| du / p_b, w the
/// share of the pair (1/2 in double contact, 1 in single), integrated in closed form piece by piece;
/// to 1e-12. With equal sharing Ohlendorf's H_V (u = −3) is the same number.
#[test]
fn coulomb_loss_matches_the_closed_form_integral() {
    let g = PairGeometry::compute(&ring_input(Some(0.147))).unwrap();
    let c = ctx(&g);
    let mu = 0.05;
    let p = g.points;
    // ∫ |u − P| du over [x, y], exact.
    let abs_int = |x: f64, y: f64| {
        let f = |t: f64| 0.5 * (t - p.p) * (t - p.p).abs();
        f(y) - f(x)
    };
    let integral = 0.5 * abs_int(p.a, p.b) + abs_int(p.b, p.d) + 0.5 * abs_int(p.d, p.e);
    let (rb1, rb2) = (g.base_radius[0], g.base_radius[1]);
    let loss = mu * (1.0 / rb1 - 1.0 / rb2) * integral / g.base_pitch;
    let eta = mean_efficiency(&c, &Coulomb { mu }, External);
    assert!((eta.value - (1.0 - loss)).abs() < 1e-12, "{} vs {}", eta.value, 1.0 - loss);
    let h_v = ohlendorf_loss_factor(&c);
    assert!((eta.value - (1.0 - mu * h_v)).abs() < 1e-12, "H_V {h_v}");
    // The internal formulation (friction in the torques) moves η by less than μ² here.
    let internal = mean_efficiency(&c, &Coulomb { mu }, Internal).value;
    assert!((internal - eta.value).abs() < mu * mu, "{internal} vs {}", eta.value);
    assert!((mean_efficiency(&c, &Coulomb { mu: 0.0 }, Internal).value - 1.0).abs() < 1e-15);
}

/// Benedict–Kelley (μ varies with load, speeds and the radii) along the internal path: the tool's mean
/// loss equals an independent integral of the local losses, ∫ Σ μ F v_s over one mesh period by
/// composite 8-point Gauss–Legendre on 64 pieces of each zone; to 1e-9 relative.
#[test]
fn benedict_kelley_loss_matches_an_independent_integral() {
    let g = PairGeometry::compute(&ring_input(Some(0.147))).unwrap();
    let c = ctx(&g);
    let law = BenedictKelley::new(&c.tribology).unwrap();
    let p = g.points;
    let (x8, w8) = gauss_legendre_8();
    let mut sum = 0.0;
    let mut cuts = [p.a, p.b, p.p, p.d, p.e];
    cuts.sort_by(f64::total_cmp);
    for (&from, &to) in cuts.iter().zip(&cuts[1..]) {
        for k in 0..64 {
            let (lo, hi) = (from + (to - from) * k as f64 / 64.0, from + (to - from) * (k + 1) as f64 / 64.0);
            for (x, w) in x8.iter().zip(&w8) {
                let u = 0.5 * (lo + hi) + 0.5 * (hi - lo) * x;
                sum += 0.5 * (hi - lo) * w * local_power_loss(&c, &law, &c.contact_at(u));
            }
        }
    }
    // Each pair runs A → E once per mesh period p_b / (ω1 r_b1): the mean power is the path integral over p_b.
    let mean = sum / g.base_pitch;
    let tool = (1.0 - mean_efficiency(&c, &law, External).value) * c.state.pinion_torque * c.state.pinion_speed;
    assert!((tool - mean).abs() < 1e-9 * mean, "tool {tool} W vs integral {mean} W");
    assert!(law.mu(&c.contact_at(p.a)) < 0.0 && law.mu(&c.contact_at(p.e)) > 0.0);
}

fn gauss_legendre_8() -> ([f64; 8], [f64; 8]) {
    let x = [0.1834346424956498, 0.525532409916329, 0.7966664774136267, 0.9602898564975363];
    let w = [0.362683783378362, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763];
    ([-x[3], -x[2], -x[1], -x[0], x[0], x[1], x[2], x[3]], [w[3], w[2], w[1], w[0], w[0], w[1], w[2], w[3]])
}

/// Stock Drive Products / KHK: a standard 20° internal pair clears trochoid interference when the
/// ring has ten teeth or more beyond its pinion; five teeth foul (rings of 35 teeth and more, whose
/// standard tip stays outside the base circle).
#[test]
fn trochoid_interference_follows_the_teeth_difference() {
    for z1 in [30u32, 40, 60, 100] {
        for (gap, clear) in [(10u32, true), (5, false)] {
            let input = PairInput { teeth: [z1, z1 + gap], tip_diameter: [None, None], ..ring_input(None) };
            let alpha = 20f64.to_radians();
            let r = [z1 as f64 * 1e-3, (z1 + gap) as f64 * 1e-3];
            let rb = r.map(|r| r * alpha.cos());
            let ra = [r[0] + 2e-3, r[1] - 2e-3];
            let margin = trochoid_margin(input.teeth, rb, ra, r[1] - r[0], alpha);
            assert_eq!(margin >= 0.0, clear, "z1 {z1}, gap {gap}: margin {margin}");
            if !clear {
                let problems = PairGeometry::compute(&input).unwrap_err();
                assert!(problems.iter().any(|p| p.reason.contains("trochoid")), "{problems:?}");
            }
        }
    }
}

/// A ring not larger than its pinion, a ring tip inside its base circle and a ring tip reaching past
/// T1 are refused with the part they are about.
#[test]
fn rings_that_cannot_mesh_are_refused() {
    let few = PairGeometry::compute(&PairInput { teeth: [30, 30], ..ring_input(None) }).unwrap_err();
    assert!(few.iter().any(|p| p.part == PairPart::Teeth(1) && p.reason.contains("more teeth on the ring")));
    let inside = PairGeometry::compute(&ring_input(Some(0.140))).unwrap_err();
    assert!(
        inside.iter().any(|p| p.part == PairPart::TipDiameter(1) && p.reason.contains("base circle")),
        "{inside:?}"
    );
    let beyond = PairGeometry::compute(&ring_input(Some(0.1415))).unwrap_err();
    assert!(beyond.iter().any(|p| p.reason.contains("interference point T1")), "{beyond:?}");
}
