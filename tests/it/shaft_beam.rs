//! The elastic shaft against closed forms and an independent method: the three-moment equation on
//! three equal spans, a symmetric continuous beam, springs converging to rigid supports, the
//! Timoshenko span, equilibrium of every shaft to 1e-12 of its largest force, two places equal to
//! the rigid beam's statics whatever the sections, and the flexibility method (unit-load integrals
//! by Simpson's rule, exact on piecewise-linear moments) on a stepped shaft to 1e-9.

use gearloss::drive::shaft_beam::{solve, BeamTheory, PlaneLoad, ShaftBody, ShaftSection, Support};
use gearloss::drive::shaft_bending::support_reactions;
use gearloss::drive::{GearLoad, Member, Shaft};

const E: f64 = 210e9;

fn rigid(at: &[f64]) -> Vec<Support> {
    at.iter().map(|&at| Support { at, stiffness: None }).collect()
}

fn force(at: f64, fx: f64, fy: f64) -> PlaneLoad {
    PlaneLoad { at, force: [fx, fy], couple: [0.0, 0.0] }
}

/// A stepped, partly hollow shaft from 0 to 300 mm.
fn stepped(theory: BeamTheory) -> ShaftBody {
    let s = |from: f64, to: f64, d: f64, bore: f64| ShaftSection { from, to, outer_diameter: d, bore };
    ShaftBody {
        sections: vec![
            s(0.0, 0.05, 0.035, 0.0),
            s(0.05, 0.12, 0.048, 0.012),
            s(0.12, 0.21, 0.055, 0.02),
            s(0.21, 0.3, 0.04, 0.0),
        ],
        material: "steel".into(),
        youngs_modulus: E,
        poisson_ratio: 0.3,
        theory,
    }
}

/// Uniform shaft, supports A, B, C at 0, L, 2L, a load P at a from A: the three-moment equation
/// gives M_B = −P a (L² − a²)/(4 L²), R_A = P (L − a)/L + M_B/L, R_C = M_B/L, R_B = P − R_A − R_C
/// (Timoshenko & Gere, the continuous beam). Tolerance 1e-12 of P.
#[test]
fn three_equal_spans_follow_the_three_moment_equation() {
    let l = 0.1;
    let body = ShaftBody::uniform(0.0, 2.0 * l, 0.04, E, 0.3, BeamTheory::EulerBernoulli);
    for a in [0.02, 0.05, 0.071] {
        let p = 2500.0;
        let s = solve(&body, &rigid(&[0.0, l, 2.0 * l]), &[force(a, p, 0.0)]).unwrap();
        let m_b = -p * a * (l * l - a * a) / (4.0 * l * l);
        let r_a = p * (l - a) / l + m_b / l;
        let r_c = m_b / l;
        let want = [r_a, p - r_a - r_c, r_c];
        for (r, w) in s.reactions.iter().zip(want) {
            // Reactions act on the shaft, against the load.
            assert!((r[0] + w).abs() < 1e-12 * p, "a = {a}: {} vs {}", -r[0], w);
            assert_eq!(r[1], 0.0);
        }
    }
}

/// Two equal spans with P at the middle of each: 5P/16, 11P/8, 5P/16 (the symmetric continuous
/// beam), in the y–z plane this time.
#[test]
fn a_symmetric_continuous_beam() {
    let body = ShaftBody::uniform(-0.02, 0.42, 0.05, E, 0.3, BeamTheory::EulerBernoulli);
    let p = 1000.0;
    let s = solve(&body, &rigid(&[0.0, 0.2, 0.4]), &[force(0.1, 0.0, p), force(0.3, 0.0, p)]).unwrap();
    for (r, w) in s.reactions.iter().zip([5.0 / 16.0, 11.0 / 8.0, 5.0 / 16.0]) {
        assert!((r[1] + w * p).abs() < 1e-12 * p, "{r:?}");
    }
    // Symmetry: no slope over the middle support.
    assert!(s.slope[s.node(0.2)][1].abs() < 1e-12 * s.slope[s.node(0.0)][1].abs());
}

/// Springs of stiffness k at the supports converge to the rigid reactions as 1/k: the error
/// falls tenfold for each tenfold k from 1e11 N/m on (within 1 %), and at k = 1e14 N/m it is
/// below 1e-5 of the load (the solve stays well conditioned).
#[test]
fn stiff_springs_converge_to_rigid_supports() {
    let body = stepped(BeamTheory::EulerBernoulli);
    let at = [0.03, 0.14, 0.27];
    let loads = [force(0.08, 3000.0, -1200.0), force(0.2, -800.0, 2500.0)];
    let exact = solve(&body, &rigid(&at), &loads).unwrap().reactions;
    let error = |k: f64| {
        let springs: Vec<Support> = at.iter().map(|&at| Support { at, stiffness: Some(k) }).collect();
        let r = solve(&body, &springs, &loads).unwrap().reactions;
        r.iter().zip(&exact).map(|(a, b)| (a[0] - b[0]).hypot(a[1] - b[1])).fold(0.0, f64::max)
    };
    let (e11, e12, e13) = (error(1e11), error(1e12), error(1e13));
    assert!((e11 / e12 - 10.0).abs() < 0.1 && (e12 / e13 - 10.0).abs() < 0.1, "{e11} {e12} {e13}");
    assert!(error(1e14) < 1e-5 * 3000.0);
}

/// A simply supported Timoshenko span with P at its middle: δ = P L³/(48 E I) + P L/(4 κ G A)
/// (bending plus shear), to 1e-12 relative; Euler–Bernoulli gives the first term alone.
#[test]
fn a_timoshenko_span_adds_the_shear_deflection() {
    let (l, d, p) = (0.12, 0.05, 10_000.0);
    for theory in [BeamTheory::EulerBernoulli, BeamTheory::Timoshenko] {
        let body = ShaftBody::uniform(0.0, l, d, E, 0.3, theory);
        let s = solve(&body, &rigid(&[0.0, l]), &[force(l / 2.0, p, 0.0)]).unwrap();
        let section = &body.sections[0];
        let g = E / 2.6;
        let bending = p * l.powi(3) / (48.0 * E * section.second_moment());
        let shear = p * l / (4.0 * section.shear_coefficient(0.3) * g * section.area());
        let want = if theory == BeamTheory::Timoshenko { bending + shear } else { bending };
        let w = s.deflection[s.node(l / 2.0)][0];
        assert!((w - want).abs() < 1e-12 * want, "{theory:?}: {w} vs {want}");
    }
    // Cowper's κ: 6(1+ν)/(7+6ν) for a solid circle.
    let solid = ShaftSection { from: 0.0, to: 1.0, outer_diameter: 0.05, bore: 0.0 };
    assert!((solid.shear_coefficient(0.3) - 7.8 / 8.8).abs() < 1e-15);
}

fn gear(point: [f64; 3], force: [f64; 3]) -> GearLoad {
    GearLoad { stage: 0, member: Member::Pinion, shaft: 0, point, force }
}

fn shaft(at: &[f64], stiffness: Vec<Option<f64>>, body: Option<ShaftBody>, locating: usize) -> Shaft {
    let bearing = |p: f64| gearloss::losses::Bearing {
        kind: gearloss::losses::BearingType::CylindricalRoller,
        mean_diameter: 0.05,
        count: 1,
        static_load_rating: None,
        f0: None,
        f1: None,
        y: None,
        position: Some(p),
        skf: None,
    };
    Shaft {
        name: "lay".into(),
        bearings: at.iter().map(|&p| bearing(p)).collect(),
        locating,
        locating_given: true,
        seals: Vec::new(),
        body,
        stiffness,
    }
}

/// Helical gears' force vectors (axial forces making couples at their radii).
fn helical_loads() -> Vec<GearLoad> {
    vec![
        gear([-0.052, 0.011, 0.06], [1200.0, 3300.0, -1400.0]),
        gear([0.026, -0.004, 0.17], [-4600.0, 12600.0, 4200.0]),
        gear([0.0, 0.031, 0.23], [900.0, -2000.0, 650.0]),
    ]
}

/// Every shaft balances: ΣF = 0 and the moments about x and y through its origin vanish, to 1e-12
/// of the largest force (× the shaft's length for the moments), on 2, 3 and 4 places, rigid and
/// sprung, Euler–Bernoulli and Timoshenko; the locating place takes −ΣF_z.
#[test]
fn every_shaft_balances_forces_and_moments() {
    let loads = helical_loads();
    let largest = 12600.0;
    let layouts: [&[f64]; 3] = [&[0.02, 0.28], &[0.02, 0.12, 0.28], &[0.02, 0.1, 0.2, 0.28]];
    for at in layouts {
        for theory in [BeamTheory::EulerBernoulli, BeamTheory::Timoshenko] {
            for k in [None, Some(3e8)] {
                let stiffness = at.iter().enumerate().map(|(i, _)| if i == 1 { k } else { None }).collect();
                let s = shaft(at, stiffness, Some(stepped(theory)), at.len() - 1);
                let (r, _) = support_reactions(&s, &loads, false, None);
                let mut sum = [0.0; 5];
                for l in &loads {
                    let ([x, y, z], [fx, fy, fz]) = (l.point, l.force);
                    sum = [sum[0] + fx, sum[1] + fy, sum[2] + fz, sum[3] + y * fz - z * fy, sum[4] + z * fx - x * fz];
                }
                for (p, r) in at.iter().zip(&r) {
                    sum = [sum[0] + r[0], sum[1] + r[1], sum[2] + r[2], sum[3] - p * r[1], sum[4] + p * r[0]];
                }
                for (i, v) in sum.iter().enumerate() {
                    let scale = if i < 3 { largest } else { largest * 0.3 };
                    assert!(v.abs() < 1e-12 * scale, "{at:?} {theory:?} {k:?}: residual {i} = {v}");
                }
                assert_eq!(r[at.len() - 1][2], -(-1400.0 + 4200.0 + 650.0));
            }
        }
    }
}

/// Two places: the rigid beam's statics, whatever the sections and springs (1e-12 of the largest
/// force), and the stiffness solve itself agrees with it.
#[test]
fn two_places_are_the_rigid_beams_statics() {
    let loads = helical_loads();
    let at = [0.02, 0.28];
    let statics = gearloss::drive::statics::shaft_reactions(&loads, at, 0);
    for body in [None, Some(stepped(BeamTheory::EulerBernoulli)), Some(stepped(BeamTheory::Timoshenko))] {
        let s = shaft(&at, vec![Some(2e8), None], body.clone(), 0);
        let (r, bending) = support_reactions(&s, &loads, true, None);
        assert_eq!(r, statics.to_vec(), "two places take the closed form");
        assert_eq!(bending.is_some(), body.is_some());
        if let Some(body) = body {
            let planes = gearloss::drive::shaft_bending::plane_loads(&loads);
            let beam = solve(
                &body,
                &[Support { at: 0.02, stiffness: Some(2e8) }, Support { at: 0.28, stiffness: None }],
                &planes,
            )
            .unwrap();
            for (a, b) in beam.reactions.iter().zip(&statics) {
                assert!((a[0] - b[0]).abs() < 1e-12 * 12600.0 && (a[1] - b[1]).abs() < 1e-12 * 12600.0);
            }
        }
    }
}

/// 1/(EI) of the stepped shaft at z.
fn flexibility(body: &ShaftBody, z: f64) -> f64 {
    1.0 / (body.youngs_modulus * body.section_at(z).unwrap().second_moment())
}

/// The bending moment at z of a simple beam on [a, b] (rigid, the primary structure) under point
/// forces `loads` (position, force), sagging positive.
fn simple_beam_moment(a: f64, b: f64, loads: &[(f64, f64)], z: f64) -> f64 {
    let r_a: f64 = loads.iter().map(|(p, f)| f * (b - p) / (b - a)).sum();
    let mut m = r_a * (z - a);
    for (p, f) in loads.iter().filter(|(p, _)| *p < z) {
        m -= f * (z - p);
    }
    m
}

/// ∫ M₁ M₂ / EI over [a, b], Simpson's rule on each piece between `breaks` (exact: each piece is
/// quadratic).
fn unit_load_integral(body: &ShaftBody, breaks: &[f64], m1: &dyn Fn(f64) -> f64, m2: &dyn Fn(f64) -> f64) -> f64 {
    breaks
        .windows(2)
        .map(|w| {
            let (x0, x1) = (w[0], w[1]);
            let xm = 0.5 * (x0 + x1);
            let f = |x: f64| m1(x) * m2(x) * flexibility(body, xm);
            (x1 - x0) / 6.0 * (f(x0) + 4.0 * f(xm) + f(x1))
        })
        .sum()
}

/// The flexibility method on the stepped shaft: the outer supports rigid (the primary structure a
/// simple beam), the two inner ones redundant, one of them a spring. Compatibility
/// Σ_j f_ij X_j + X_i/k_i = −δ_i0 gives the redundant reactions; the solver's reactions and its
/// deflection under the first load agree to 1e-9 relative.
#[test]
fn the_flexibility_method_agrees_on_a_stepped_shaft() {
    let body = stepped(BeamTheory::EulerBernoulli);
    let (a, b) = (0.02, 0.29);
    let inner = [(0.11, None), (0.19, Some(5e8))];
    let loads = [(0.07, 4000.0), (0.15, -1500.0), (0.24, 2500.0)];
    let mut breaks: Vec<f64> = vec![a, b, 0.05, 0.12, 0.21, 0.11, 0.19, 0.07, 0.15, 0.24];
    breaks.sort_by(f64::total_cmp);
    let unit = |c: f64| move |z: f64| simple_beam_moment(a, b, &[(c, 1.0)], z);
    // Deflection w at c along the forces' sense under forces `f`: ∫ M(f) m_c / EI, m_c the moment
    // of a unit force at c in that sense (the unit-load method).
    let delta = |c: f64, f: &[(f64, f64)]| {
        let m = |z: f64| simple_beam_moment(a, b, f, z);
        unit_load_integral(&body, &breaks, &m, &unit(c))
    };
    let d0: Vec<f64> = inner.iter().map(|(c, _)| delta(*c, &loads)).collect();
    let f = |i: usize, j: usize| delta(inner[i].0, &[(inner[j].0, 1.0)]);
    let k = |i: usize| inner[i].1.map_or(0.0, |k: f64| 1.0 / k);
    // [f00 + 1/k0, f01; f10, f11 + 1/k1] X = −d0
    let m = [[f(0, 0) + k(0), f(0, 1)], [f(1, 0), f(1, 1) + k(1)]];
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    let x = [(-d0[0] * m[1][1] + d0[1] * m[0][1]) / det, (-d0[1] * m[0][0] + d0[0] * m[1][0]) / det];
    let supports = [
        Support { at: a, stiffness: None },
        Support { at: inner[0].0, stiffness: inner[0].1 },
        Support { at: inner[1].0, stiffness: inner[1].1 },
        Support { at: b, stiffness: None },
    ];
    let planes: Vec<PlaneLoad> = loads.iter().map(|&(p, fx)| force(p, fx, 0.0)).collect();
    let s = solve(&body, &supports, &planes).unwrap();
    for (i, xi) in x.iter().enumerate() {
        let r = s.reactions[i + 1][0];
        assert!((r - xi).abs() < 1e-9 * xi.abs(), "redundant {i}: solver {r}, flexibility {xi}");
    }
    let mut all = loads.to_vec();
    all.extend(inner.iter().zip(x).map(|((c, _), xi)| (*c, xi)));
    let w = delta(0.07, &all);
    let solved = s.deflection[s.node(0.07)][0];
    assert!((solved - w).abs() < 1e-9 * w.abs(), "deflection under the first load: {solved} vs {w}");
}

/// The largest stress is located at one-sided limits: |M(z)| recomputed here from the loads and
/// the reactions at 30 000 points strictly between nodes never exceeds it (1e-12), and comes within
/// 1e-3 of it (the grid is a check here, never the reported number).
#[test]
fn the_largest_stress_is_located() {
    let loads = helical_loads();
    let s = shaft(&[0.02, 0.12, 0.28], vec![None; 3], Some(stepped(BeamTheory::EulerBernoulli)), 0);
    let (reactions, bending) = support_reactions(&s, &loads, true, None);
    let b = bending.unwrap();
    let body = s.body.as_ref().unwrap();
    let mut items = gearloss::drive::shaft_bending::plane_loads(&loads);
    items.extend([0.02, 0.12, 0.28].iter().zip(&reactions).map(|(&at, r)| force(at, r[0], r[1])));
    let moment = |z: f64| {
        let mut m = [0.0; 2];
        for l in items.iter().filter(|l| l.at < z) {
            for (p, m) in m.iter_mut().enumerate() {
                *m += l.force[p] * (z - l.at) - l.couple[p];
            }
        }
        m[0].hypot(m[1])
    };
    let mut grid_max = 0.0_f64;
    for i in 0..30_000 {
        let z = 0.3 * (f64::from(i) + 0.5) / 30_000.0;
        grid_max = grid_max.max(moment(z) / body.section_at(z).unwrap().section_modulus());
    }
    assert!(b.max_stress >= grid_max * (1.0 - 1e-12), "{} < {grid_max}", b.max_stress);
    assert!((b.max_stress - grid_max).abs() < 1e-3 * grid_max, "{} vs {grid_max}", b.max_stress);
    assert!(b.max_stress_at > 0.02 && b.max_stress_at < 0.28);
}
