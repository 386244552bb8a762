//! The SDOF dynamics against closed forms: Airy's equation, the forced response to a static
//! transmission error, Meissner's instability tongues and the primary resonance.

use super::dynamics::{ctx, fzg, system, J};
use gearloss::dynamics::PeriodicResponse;
use gearloss::dynamics::{magnus_adaptive, Method};
use gearloss::dynamics::{DynamicFormulation, Floquet, SdofSystem, StiffnessModel};
use gearloss::friction::Coulomb;

/// He & Singh's Airy closed form (undamped, internal formulation, stiffness linear in t on each
/// segment) against the Magnus route: the homogeneous propagators and the forced parts agree to 1e-8.
#[test]
fn airy_closed_form_matches_magnus() {
    use gearloss::dynamics::airy_propagator;
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.3 };
    for rpm in [300.0, 3000.0] {
        let sys = system(ctx(&scene, &g, rpm, 239.3), &law, DynamicFormulation::Internal, 0.0);
        for s in &sys.segments {
            let h = s.end - s.start;
            let airy = airy_propagator(&sys, s.start, s.end, h).expect("applies: undamped internal");
            let (m, _) = magnus_adaptive(&sys, s.start, h);
            let rel = (airy - m.phi).norm() / m.phi.norm();
            assert!(rel < 1e-8, "{rpm} rpm, segment {s:?}: {rel:e}");
            // With the forcing (Duhamel over Ai and Bi): q agrees too.
            let full = gearloss::dynamics::airy_propagation(&sys, s.start, s.end, h).unwrap();
            let rel_q = (full.q - m.q).norm() / m.q.norm();
            assert!(rel_q < 1e-8, "{rpm} rpm, segment {s:?}: q {rel_q:e}");
        }
    }
    // Not applicable when damped.
    let damped = system(ctx(&scene, &g, 1000.0, 239.3), &law, DynamicFormulation::Internal, 0.05);
    assert!(airy_propagator(&damped, damped.segments[0].start, damped.segments[0].end, 1e-4).is_none());
}

/// Static transmission error: with constant stiffness (single = double) and ε = a cos(ω t) the base
/// model's steady DTE has the closed-form amplitude a |k + iωc| / |k − m ω² + iωc| about F0/k
/// (tolerance 1e-6 relative on the peak-to-peak; propagated by Magnus, since the forcing is not affine).
#[test]
fn transmission_error_response_matches_the_closed_form() {
    let (scene, g) = fzg();
    let c = ctx(&scene, &g, 3000.0, 239.3);
    let k = 3.0e8;
    let mut sys =
        SdofSystem::new(c, None, DynamicFormulation::Base, StiffnessModel::pairs_in_contact(k, k, k), J, 0.05);
    let a = 2e-6;
    sys.transmission_error = vec![(a, 0.0)];
    assert!(!sys.exact_applies());
    let fl = Floquet::analyse(&sys);
    assert_eq!(fl.method, Method::Magnus4);
    let r = PeriodicResponse::compute(&sys, &fl).unwrap();
    let (m, cd, w) = (sys.equivalent_mass, sys.damping, 2.0 * std::f64::consts::PI / sys.period);
    let amplitude = a * k.hypot(w * cd) / (k - m * w * w).hypot(w * cd);
    // Located extrema of a pure harmonic: half the peak-to-peak is the amplitude (1e-8 relative), and
    // so is the first harmonic of the spectrum (Gauss–Kronrod Fourier coefficient).
    let half = r.dte_peak_to_peak / 2.0;
    assert!((half - amplitude).abs() <= 1e-8 * amplitude, "{half} vs {amplitude}");
    assert!((r.spectrum[0].1 - amplitude).abs() <= 1e-8 * amplitude, "{} vs {amplitude}", r.spectrum[0].1);
    assert!((r.dte_mean.value - sys.static_force / k).abs() < 1e-9 * sys.static_force / k);
    assert!(r.dte_mean.error < 1e-9 * sys.static_force / k);
    // The tooth force k(x − ε) + c(ẋ − ε̇) oscillates about F0: its located extrema are F0 ± the
    // force amplitude, so their mean is F0 (1e-6 relative).
    let mid = 0.5 * (r.tooth_force_max.value + r.tooth_force_min.value);
    assert!((mid - sys.static_force).abs() < 1e-6 * sys.static_force, "{mid}");
}

/// Meissner's closed form: the base model with rectangular stiffness is m ẍ + c ẋ + k_i x = 0 on
/// each zone, whose transition matrix is the damped oscillator's,
/// e^{−σh} [[cos ω_d h + σ/ω_d sin, sin/ω_d], [−ω_i²/ω_d sin, cos − σ/ω_d sin]], ω_d² = k_i/m − σ².
/// Its monodromy (double zone, then single zone) gives the spectral radius in closed form.
fn meissner_spectral_radius(sys: &SdofSystem) -> f64 {
    use nalgebra::Matrix2;
    let sigma = sys.damping / (2.0 * sys.equivalent_mass);
    let mut phi = Matrix2::<f64>::identity();
    for s in &sys.segments {
        let k = sys.stiffness_at(0.5 * (s.start + s.end));
        let w2 = k / sys.equivalent_mass;
        let wd = (w2 - sigma * sigma).sqrt();
        let h = s.end - s.start;
        let (c, sn, e) = ((wd * h).cos(), (wd * h).sin(), (-sigma * h).exp());
        let step = Matrix2::new(c + sigma / wd * sn, sn / wd, -w2 / wd * sn, c - sigma / wd * sn) * e;
        phi = step * phi;
    }
    let (tr, det) = (phi.trace(), phi.determinant());
    let disc = 0.25 * tr * tr - det;
    if disc >= 0.0 {
        (0.5 * tr).abs() + disc.sqrt()
    } else {
        det.sqrt()
    }
}

/// The FZG scene's stability map: the spectral radius equals Meissner's closed form to 1e-9 at every
/// map speed tested, and the principal tongue's bounds (located by root finding on ρ − 1, README:
/// 40 300–48 900 rpm) are the closed form's ρ = 1 + 1e-9 crossings to 1e-6 relative.
#[test]
fn instability_tongue_matches_the_meissner_closed_form() {
    let mut scene = crate::scene(&crate::root().join("specs/fzg_dynamics.gear"));
    scene.analyses.dynamics = false;
    scene.analyses.numerics = false;
    let eval = gearloss::evaluate(&scene.pair_alone().unwrap());
    let d = eval.dynamics.as_ref().unwrap();
    let g = &eval.geometry;
    let base = d.formulations.iter().position(|f| *f == DynamicFormulation::Base).unwrap();
    let law = Coulomb { mu: 0.0 };
    let closed = |w: f64| {
        let c = ctx(&scene, g, w * 30.0 / std::f64::consts::PI, 239.3);
        meissner_spectral_radius(&system(c, &law, DynamicFormulation::Base, 0.05))
    };
    for row in d.stability_map.as_ref().unwrap().iter().step_by(37) {
        let (rho, expected) = (row.spectral_radius[base], closed(row.pinion_speed));
        assert!((rho - expected).abs() < 1e-9 * expected.max(1e-3), "ω {}: {rho} vs {expected}", row.pinion_speed);
    }
    let tongue = d.unstable_ranges[base]
        .iter()
        .find(|(a, b)| a * 30.0 / std::f64::consts::PI > 35_000.0 && b * 30.0 / std::f64::consts::PI < 55_000.0)
        .expect("the principal tongue");
    for bound in [tongue.0, tongue.1] {
        let (below, above) = (closed(bound * (1.0 - 1e-6)), closed(bound * (1.0 + 1e-6)));
        assert!((below - 1.0 - 1e-9) * (above - 1.0 - 1e-9) < 0.0, "bound {bound}: ρ {below} / {above}");
    }
    let rpm = |w: f64| w * 30.0 / std::f64::consts::PI;
    assert!((rpm(tongue.0) - 40_300.0).abs() < 100.0 && (rpm(tongue.1) - 48_900.0).abs() < 100.0, "{tongue:?}");
}

/// The primary resonance quoted in README (near 22 400 rpm, f_mesh ≈ f_n = 5975 Hz): the base model's
/// dynamic factor over 15 000–30 000 rpm (every 50 rpm) peaks within 3 % of 60 f_n / z1.
#[test]
fn primary_resonance_is_near_the_natural_frequency() {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.0 };
    let probe = system(ctx(&scene, &g, 1000.0, 239.3), &law, DynamicFormulation::Base, 0.05);
    let resonance = 60.0 * probe.natural_frequency() / 16.0;
    let (mut best, mut at) = (0.0, 0.0);
    for i in 0..=300 {
        let rpm = 15_000.0 + 50.0 * i as f64;
        let sys = system(ctx(&scene, &g, rpm, 239.3), &law, DynamicFormulation::Base, 0.05);
        if let Some(kv) = PeriodicResponse::dynamic_factor(&sys, &Floquet::analyse(&sys)) {
            if kv > best {
                (best, at) = (kv, rpm);
            }
        }
    }
    assert!((at / resonance - 1.0).abs() < 0.03, "K_v peak {best} at {at} rpm, 60 f_n/z1 = {resonance}");
    assert!((resonance - 22_400.0).abs() < 50.0, "{resonance}");
}
