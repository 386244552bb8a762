//! Gear dynamics: propagators against closed forms and each other, Floquet theory against Liouville,
//! stability tongues, and every integrator against the exact propagator.

use gearloss::dynamics::numerics::{reference, states};
use gearloss::dynamics::PeriodicResponse;
use gearloss::dynamics::Trajectory;
use gearloss::dynamics::Verdict;
use gearloss::dynamics::{integrate, Integrator};
use gearloss::dynamics::{magnus_adaptive, AffineSegment, Method};
use gearloss::dynamics::{DynamicFormulation, Floquet, SdofSystem, StiffnessModel};
use gearloss::friction::Coulomb;
use gearloss::friction::{FrictionLaw, LawContext};
use gearloss::geometry::Sharing;
use gearloss::geometry::{OperatingState, PairGeometry};

/// FZG type C rectangular stiffness (N/m).
pub(crate) fn rectangular() -> StiffnessModel {
    StiffnessModel::pairs_in_contact(1.96e8, 3.92e8, 5.88e8)
}
pub(crate) const J: [f64; 2] = [3.45e-4, 15.24e-4];

pub(crate) fn fzg() -> (gearloss::Scene, PairGeometry) {
    let scene = crate::scene(&crate::root().join("specs/fzg_type_c.gear"));
    let g = scene.gears.geometry().unwrap();
    (scene, g)
}

pub(crate) fn ctx<'a>(scene: &gearloss::Scene, g: &'a PairGeometry, rpm: f64, torque: f64) -> LawContext<'a> {
    LawContext {
        geometry: g,
        state: OperatingState { pinion_torque: torque, pinion_speed: rpm * std::f64::consts::PI / 30.0 },
        tribology: scene.mesh().tribology(226e9),
        sharing: Sharing::Equal,
    }
}

pub(crate) fn system<'a>(
    c: LawContext<'a>,
    law: &'a dyn FrictionLaw,
    f: DynamicFormulation,
    zeta: f64,
) -> SdofSystem<'a> {
    let law = if f == DynamicFormulation::Base { None } else { Some(law) };
    SdofSystem::new(c, law, f, rectangular(), J, zeta)
}

/// det Φ(T) equals exp(∫ tr A) (Liouville) to 1e-10 relative, for every formulation.
#[test]
fn monodromy_determinant_matches_liouville() {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.08 };
    for f in [DynamicFormulation::Base, DynamicFormulation::External, DynamicFormulation::Internal] {
        let sys = system(ctx(&scene, &g, 1000.0, 239.3), &law, f, 0.05);
        let fl = Floquet::analyse(&sys);
        assert!(
            ((fl.determinant - fl.liouville) / fl.liouville).abs() < 1e-10,
            "{f:?}: {} vs {}",
            fl.determinant,
            fl.liouville
        );
        assert_eq!(fl.verdict, Verdict::Stable);
        assert_eq!(fl.method, if f == DynamicFormulation::Internal { Method::Magnus4 } else { Method::Exact });
    }
}

/// ζ = 0: det Φ = 1 and both multipliers on the unit circle (away from the tongues).
#[test]
fn undamped_multipliers_lie_on_the_unit_circle() {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.08 };
    for f in [DynamicFormulation::Base, DynamicFormulation::External] {
        let sys = system(ctx(&scene, &g, 1000.0, 239.3), &law, f, 0.0);
        let fl = Floquet::analyse(&sys);
        assert!((fl.determinant - 1.0).abs() < 1e-9, "{}", fl.determinant);
        for m in fl.multipliers {
            assert!((m.abs() - 1.0).abs() < 1e-9, "|λ| = {}", m.abs());
        }
        assert_eq!(fl.verdict, Verdict::Marginal);
    }
}

/// The exact propagator and converged Magnus agree on a segment where both apply (1e-9 relative).
#[test]
fn exact_and_magnus_agree() {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.08 };
    let sys = system(ctx(&scene, &g, 3000.0, 372.6), &law, DynamicFormulation::External, 0.05);
    for s in &sys.segments {
        let e = AffineSegment::of(&sys, s.start, s.end).propagate(s.start, s.end - s.start);
        let (m, _) = magnus_adaptive(&sys, s.start, s.end - s.start);
        assert!((e.phi - m.phi).norm() < 1e-9 * e.phi.norm(), "{:e}", (e.phi - m.phi).norm() / e.phi.norm());
        assert!((e.q - m.q).norm() < 1e-9 * e.q.norm().max(1e-30), "{} vs {}", e.q, m.q);
    }
}

/// Quasi-static limit: far below resonance (20 rpm, f_mesh/f_n ≈ 1e-3) the DTE in the middle of each
/// zone, after the ringing that follows a stiffness jump has decayed, is F0/k(t) to 1e-6 relative.
/// The dynamic factor is then exactly k_double/k_single = 2 (to 1e-5): x is continuous across the
/// stiffness step at the entry of a pair, so just after it F = k_double · F0/k_single. It is located
/// as the one-sided limit at τ = 0⁺ (the start of double contact).
#[test]
fn low_speed_dte_is_quasi_static() {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.0 };
    let sys = system(ctx(&scene, &g, 20.0, 239.3), &law, DynamicFormulation::Base, 0.05);
    let fl = Floquet::analyse(&sys);
    let r = PeriodicResponse::compute(&sys, &fl).unwrap();
    let tr = Trajectory::new(&sys, &fl.period, fl.periodic_state.unwrap());
    let f0 = 239.3 / g.base_radius[0];
    for s in &sys.segments {
        let mid = 0.5 * (s.start + s.end);
        let x = tr.state(tr.piece_of(mid), mid)[0];
        let k = sys.stiffness_at(mid);
        assert!((x - f0 / k).abs() < 1e-6 * f0 / k, "{x} vs {}", f0 / k);
    }
    assert!((r.dynamic_factor - 2.0).abs() < 1e-5, "K_v = {}", r.dynamic_factor);
    assert!(r.tooth_force_max.time.abs() < 1e-9 || (r.tooth_force_max.time - 1.0).abs() < 1e-9);
}

/// Every located extremum against a brute force of 10⁵ samples of the same propagated state, at 100,
/// 1000 and 20 000 rpm and in every formulation: DTE max, min and peak-to-peak, and the tooth force
/// maximum agree to 1e-6 relative (of the peak-to-peak, of max F), and no sample exceeds the located
/// maximum or falls below the located minimum by more than round-off (1e-12 of the peak-to-peak).
/// At 100 rpm (f_n/f_mesh ≈ 224) a uniform brute force needs 10⁶ samples to resolve the ringing to
/// 1e-6 (its own sampling error is (ω_n Δt)²/8 of the ringing amplitude: 3e-6 of the peak-to-peak with
/// 10⁵ samples), so it uses 10⁶ there.
#[test]
fn located_extrema_match_a_brute_force() {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.08 };
    for rpm in [100.0, 1000.0, 20_000.0] {
        for f in [DynamicFormulation::Base, DynamicFormulation::External, DynamicFormulation::Internal] {
            let sys = system(ctx(&scene, &g, rpm, 239.3), &law, f, 0.05);
            let fl = Floquet::analyse(&sys);
            let r = PeriodicResponse::compute(&sys, &fl).unwrap();
            let n = if rpm < 500.0 { 1_000_000 } else { 100_000 };
            let taus: Vec<f64> = (0..n).map(|i| i as f64 / n as f64).collect();
            // The brute force samples the same state function (each sample propagated from the grid
            // node before it), so it tests the location, not the propagator; the propagator's own
            // accuracy is tested against a march of n steps from X*(0) here (1e-7 of the
            // peak-to-peak: the march accumulates n rounding errors) and elsewhere against Magnus.
            let tr = Trajectory::new(&sys, &fl.period, fl.periodic_state.unwrap());
            let xs: Vec<_> = taus
                .iter()
                .map(|t| {
                    let t = t * sys.period;
                    tr.state(tr.piece_of(t), t)
                })
                .collect();
            let marched = states(&sys, &fl.period, fl.periodic_state.unwrap(), &taus[..n.min(100_000)]);
            let drift = marched.iter().zip(&xs).map(|(a, b)| (a[0] - b[0]).abs()).fold(0.0, f64::max);
            assert!(drift < 1e-7 * r.dte_peak_to_peak, "{rpm} rpm {f:?}: march drifts {drift:e}");
            let (lo, hi) = xs.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x[0]), b.max(x[0])));
            let fmax = taus
                .iter()
                .zip(&xs)
                .map(|(t, x)| sys.tooth_force(t * sys.period, t * sys.period, &[x[0], x[1]]))
                .fold(f64::NEG_INFINITY, f64::max);
            let p2p = r.dte_peak_to_peak;
            let what = format!("{rpm} rpm {f:?}");
            assert!(hi <= r.dte_max.value + 1e-12 * p2p, "{what}: sample {hi} above located {}", r.dte_max.value);
            assert!(lo >= r.dte_min.value - 1e-12 * p2p, "{what}: sample {lo} below located {}", r.dte_min.value);
            assert!((hi - r.dte_max.value).abs() < 1e-6 * p2p, "{what}: max {hi} vs {}", r.dte_max.value);
            assert!((lo - r.dte_min.value).abs() < 1e-6 * p2p, "{what}: min {lo} vs {}", r.dte_min.value);
            assert!(((hi - lo) - p2p).abs() < 1e-6 * p2p, "{what}: p-p {} vs {p2p}", hi - lo);
            let located = r.tooth_force_max.value;
            assert!(fmax <= located * (1.0 + 1e-12), "{what}: sample F {fmax} above located {located}");
            assert!((fmax - located).abs() < 1e-6 * located, "{what}: F max {fmax} vs {located}");
        }
    }
}

/// The FZG dynamics scene's DTE peak-to-peak (base model, 239.3 N·m) at 1000 rpm and 100 rpm, against
/// the values of an independent dense evaluation (4.9801e-5 m and 48.78 µm, to 1e-4 relative): a
/// 256-point grid read 1 % and 49 % low there.
#[test]
fn fzg_peak_to_peak_matches_the_independent_values() {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.08 };
    for (rpm, expected) in [(1000.0, 4.9801e-5), (100.0, 48.78e-6)] {
        let sys = system(ctx(&scene, &g, rpm, 239.3), &law, DynamicFormulation::Base, 0.05);
        let r = PeriodicResponse::compute(&sys, &Floquet::analyse(&sys)).unwrap();
        assert!((r.dte_peak_to_peak / expected - 1.0).abs() < 1e-4, "{rpm} rpm: {}", r.dte_peak_to_peak);
    }
}

/// The principal parametric tongue near f_mesh ≈ 2 f_n is found unstable, and no steady state is claimed there.
#[test]
fn instability_tongue_is_reported_unstable() {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.0 };
    let probe = system(ctx(&scene, &g, 1000.0, 239.3), &law, DynamicFormulation::Base, 0.01);
    let fn_hz = probe.natural_frequency();
    let centre = 2.0 * fn_hz * 60.0 / 16.0;
    let mut worst = (0.0, 0.0);
    for i in 0..200 {
        let rpm = centre * (0.7 + 0.6 * i as f64 / 199.0);
        let sys = system(ctx(&scene, &g, rpm, 239.3), &law, DynamicFormulation::Base, 0.01);
        let fl = Floquet::analyse(&sys);
        if fl.spectral_radius > worst.0 {
            worst = (fl.spectral_radius, rpm);
        }
        if fl.verdict == Verdict::Unstable {
            assert!(fl.periodic_state.is_none() && PeriodicResponse::compute(&sys, &fl).is_none());
        }
    }
    assert!(worst.0 > 1.0, "no tongue found: max ρ = {} at {} rpm", worst.0, worst.1);
}

fn integrator_errors(rpm: f64, formulation: DynamicFormulation) -> Vec<(Integrator, f64)> {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.08 };
    let sys = system(ctx(&scene, &g, rpm, 239.3), &law, formulation, 0.05);
    let x0 = sys.static_state();
    let times: Vec<f64> = (0..=64).map(|i| 2.0 * sys.period + sys.period * i as f64 / 64.0).collect();
    let reference = reference(&sys, x0, &times);
    let p2p = {
        let xs: Vec<f64> = reference.iter().map(|x| x[0]).collect();
        xs.iter().cloned().fold(f64::NEG_INFINITY, f64::max) - xs.iter().cloned().fold(f64::INFINITY, f64::min)
    };
    Integrator::ALL
        .iter()
        .map(|m| {
            let (states, _) = integrate(&sys, *m, 1e-8, [x0[0], x0[1]], &times).unwrap();
            let err = states.iter().zip(&reference).map(|(a, b)| (a[0] - b[0]).abs()).fold(0.0, f64::max) / p2p;
            (*m, err)
        })
        .collect()
}

/// Every integrator against the exact propagator at rtol 1e-8, with restarts at the switch times:
/// nominal (1000 rpm) and stiff (f_n/f_mesh ≈ 1000, 22 rpm). Global error < 1e-4 of the peak-to-peak DTE
/// (local tolerance 1e-8 on the scaled state; the global error of the implicit methods on the stiff case is ≈ 1e-5).
#[test]
fn integrators_match_the_exact_propagator() {
    for (rpm, f) in [
        (1000.0, DynamicFormulation::External),
        (22.4, DynamicFormulation::External),
        (1000.0, DynamicFormulation::Internal),
    ] {
        for (m, err) in integrator_errors(rpm, f) {
            eprintln!("{m:?} {rpm} rpm {f:?}: {err:e}");
            assert!(err < 1e-4, "{m:?} at {rpm} rpm {f:?}: error {err:e} of the peak-to-peak DTE");
        }
    }
}

fn check_sane(sys: &SdofSystem) -> Floquet<2> {
    let fl = Floquet::analyse(sys);
    assert!(fl.spectral_radius.is_finite() && fl.determinant.is_finite());
    assert!(
        ((fl.determinant - fl.liouville) / fl.liouville).abs() < 1e-8,
        "det {} vs {}",
        fl.determinant,
        fl.liouville
    );
    if let Some(r) = PeriodicResponse::compute(sys, &fl) {
        let ser = &r.series;
        assert!(ser.dte.iter().chain(&ser.tooth_force).chain(&ser.friction_force).all(|v| v.is_finite()));
        assert!(r.dte_peak_to_peak.is_finite() && r.dynamic_factor.is_finite());
    } else {
        assert_eq!(fl.verdict, Verdict::Unstable);
    }
    fl
}

/// Extreme cases give a correct result or a clear verdict, never NaN: μ = 0.4, ζ = 0.001, very light
/// and very heavy torque (the linear model scales exactly with the load).
#[test]
fn extreme_friction_damping_and_load() {
    let (scene, g) = fzg();
    let strong = Coulomb { mu: 0.4 };
    for f in [DynamicFormulation::External, DynamicFormulation::Internal] {
        check_sane(&system(ctx(&scene, &g, 1000.0, 239.3), &strong, f, 0.05));
        check_sane(&system(ctx(&scene, &g, 1000.0, 239.3), &strong, f, 0.001));
    }
    let law = Coulomb { mu: 0.08 };
    let p2p = |torque: f64| {
        let sys = system(ctx(&scene, &g, 1000.0, torque), &law, DynamicFormulation::External, 0.05);
        let fl = check_sane(&sys);
        PeriodicResponse::compute(&sys, &fl).unwrap().dte_peak_to_peak
    };
    let (light, heavy) = (p2p(0.1), p2p(5000.0));
    assert!((heavy / light - 50_000.0).abs() < 1e-6 * 50_000.0, "{heavy} / {light}");
}

/// Contact ratios near 1.05, near 1.95 and 2.5 (three pairs in contact): sane Floquet results and
/// a stiffness that follows the number of pairs.
#[test]
fn extreme_contact_ratios() {
    use gearloss::geometry::PairInput;
    let (scene, _) = fzg();
    let fzg_input = scene.gears.pair_input();
    let hcr_input = crate::high_contact_ratio_input();
    let with_ratio = |base: PairInput, target: f64| -> PairGeometry {
        // Scale both tip diameters' addenda until ε_α hits the target (bisection on the scale).
        let (mut lo, mut hi) = (0.3, 1.6);
        let g_at = |s: f64| {
            let mut i: PairInput = base;
            for k in 0..2 {
                let r = base.module * base.teeth[k] as f64 / 2.0;
                let ra = base.tip_diameter[k].unwrap() / 2.0;
                i.tip_diameter[k] = Some(2.0 * (r + s * (ra - r)));
            }
            PairGeometry::compute(&i)
        };
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            match g_at(mid) {
                Ok(g) if g.contact_ratio < target => lo = mid,
                Err(p)
                    if p.iter()
                        .any(|x| x.part == gearloss::geometry::PairPart::Pair && !x.hint.contains("3 and above")) =>
                {
                    lo = mid
                }
                _ => hi = mid,
            }
        }
        g_at(hi).or_else(|_| g_at(lo)).unwrap()
    };
    let law = Coulomb { mu: 0.08 };
    for (base, target) in [(fzg_input, 1.05), (hcr_input, 1.95)] {
        let g = with_ratio(base, target);
        assert!((g.contact_ratio - target).abs() < 1e-3, "ε_α = {}", g.contact_ratio);
        for f in [DynamicFormulation::Base, DynamicFormulation::External, DynamicFormulation::Internal] {
            check_sane(&system(ctx(&scene, &g, 3000.0, 239.3), &law, f, 0.05));
        }
    }
    let hcr = with_ratio(hcr_input, 2.5);
    assert!((hcr.contact_ratio - 2.5).abs() < 1e-3, "ε_α = {}", hcr.contact_ratio);
    for f in [DynamicFormulation::Base, DynamicFormulation::External, DynamicFormulation::Internal] {
        let sys = system(ctx(&scene, &hcr, 2000.0, 400.0), &law, f, 0.05);
        let pairs: Vec<usize> =
            sys.segments.iter().map(|s| hcr.pairs_at(0.5 * (s.start + s.end) / sys.period)).collect();
        assert!(pairs.contains(&3) && pairs.contains(&2), "{pairs:?}");
        check_sane(&sys);
    }
}

/// Tooth separation is reported where the tooth force turns negative (FZG, 3000 rpm), located: F
/// changes sign within ±1e-9 of a period of every reported bound, and is negative in between.
#[test]
fn tooth_separation_is_reported() {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.08 };
    let sys = system(ctx(&scene, &g, 3000.0, 239.3), &law, DynamicFormulation::External, 0.05);
    let fl = Floquet::analyse(&sys);
    let r = PeriodicResponse::compute(&sys, &fl).unwrap();
    let tr = Trajectory::new(&sys, &fl.period, fl.periodic_state.unwrap());
    let force = |tau: f64| {
        let t = tau * sys.period;
        let x = tr.state(tr.piece_of(t), t);
        sys.tooth_force(t, t, &[x[0], x[1]])
    };
    assert!(r.tooth_force_min.value < 0.0 && !r.separation.is_empty());
    for (a, b) in &r.separation {
        assert!(a < b && force(0.5 * (a + b)) < 0.0);
        assert!(force(a - 1e-9) > 0.0 && force(a + 1e-9) < 0.0, "entry at {a}");
        assert!(force(b - 1e-9) < 0.0 && force(b + 1e-9) > 0.0, "exit at {b}");
    }
}

/// The accuracy the benchmarks claim: DOP853 at rtol 1e-10 reaches ≤ 1e-8 of the peak-to-peak DTE on
/// the nominal case (1000 rpm) and Radau5 at rtol 1e-12 reaches ≤ 1e-6 on the stiff case (22.4 rpm).
#[test]
fn benchmark_configurations_reach_their_accuracy() {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.08 };
    for (rpm, method, rtol, bound) in
        [(1000.0, Integrator::Dop853, 1e-10, 1e-8), (22.4, Integrator::Radau5, 1e-12, 1e-6)]
    {
        let sys = system(ctx(&scene, &g, rpm, 239.3), &law, DynamicFormulation::External, 0.05);
        let times: Vec<f64> = (0..=64).map(|i| 9.0 * sys.period + sys.period * i as f64 / 64.0).collect();
        let x0 = sys.static_state();
        let reference = reference(&sys, x0, &times);
        let xs: Vec<f64> = reference.iter().map(|x| x[0]).collect();
        let p2p =
            xs.iter().cloned().fold(f64::NEG_INFINITY, f64::max) - xs.iter().cloned().fold(f64::INFINITY, f64::min);
        let (states, _) = integrate(&sys, method, rtol, [x0[0], x0[1]], &times).unwrap();
        let err = states.iter().zip(&reference).map(|(a, b)| (a[0] - b[0]).abs()).fold(0.0, f64::max) / p2p;
        assert!(err <= bound, "{method:?} at {rpm} rpm: {err:e}");
    }
}
