//! The 6-DOF model (He–Cho–Singh eqs 1–9): limits, balances and Floquet identities on FZG type C.

use gearloss::dynamics::Method;
use gearloss::dynamics::{Bearing, SixDofSystem};
use gearloss::dynamics::{DynamicFormulation, Floquet, PeriodicModel, SdofSystem, StiffnessModel};
use gearloss::friction::Coulomb;
use gearloss::friction::{FrictionLaw, LawContext};
use gearloss::geometry::Sharing;
use gearloss::geometry::{OperatingState, PairGeometry};

/// FZG type C rectangular stiffness (N/m).
fn rectangular() -> StiffnessModel {
    StiffnessModel::pairs_in_contact(1.96e8, 3.92e8, 5.88e8)
}
const J: [f64; 2] = [3.45e-4, 15.24e-4];
/// FZG type C gears as steel discs: m = ρ π b d² / 4 with b = 14 mm (spec comment of fzg_bearings.gear).
const MASS: [f64; 2] = [0.59, 1.21];

pub(crate) fn fzg() -> (gearloss::Scene, PairGeometry) {
    let scene = crate::scene(&crate::root().join("specs/fzg_type_c.gear"));
    let g = scene.gears.geometry().unwrap();
    (scene, g)
}

pub(crate) fn ctx<'a>(scene: &gearloss::Scene, g: &'a PairGeometry, rpm: f64) -> LawContext<'a> {
    LawContext {
        geometry: g,
        state: OperatingState { pinion_torque: 239.3, pinion_speed: rpm * std::f64::consts::PI / 30.0 },
        tribology: scene.mesh().tribology(226e9),
        sharing: Sharing::Equal,
    }
}

fn bearings(k: f64) -> [Bearing; 2] {
    [Bearing { loa: k, oloa: k, damping_ratio: 0.02 }; 2]
}

fn six<'a>(c: LawContext<'a>, law: Option<&'a dyn FrictionLaw>, k: f64) -> SixDofSystem<'a> {
    let f = if law.is_some() { DynamicFormulation::Internal } else { DynamicFormulation::Base };
    SixDofSystem::new(SdofSystem::new(c, law, f, rectangular(), J, 0.05), MASS, bearings(k))
}

/// Bearings → ∞: the torsional result tends to the SDOF internal formulation (base at μ = 0) with
/// an error like 1/K: the DTE of the periodic state at t = 0 and the spectral radius of the mesh mode
/// differ by less than 2e-3 relative at K = 1e11 N/m, and the error falls by 10 ± 3 per decade of K.
#[test]
fn stiff_bearings_give_the_sdof_model() {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.08 };
    for l in [None, Some(&law as &dyn FrictionLaw)] {
        let c = ctx(&scene, &g, 1000.0);
        let f = if l.is_some() { DynamicFormulation::Internal } else { DynamicFormulation::Base };
        let sdof = Floquet::analyse(&SdofSystem::new(c, l, f, rectangular(), J, 0.05));
        let x_ref = sdof.periodic_state.unwrap()[0];
        let errors: Vec<f64> = [1e11, 1e12, 1e13]
            .iter()
            .map(|k| {
                let s = six(c, l, *k);
                let fl = Floquet::analyse(&s);
                let x = fl.periodic_state.unwrap();
                (SixDofSystem::deflection(&x).0 - x_ref).abs() / x_ref.abs()
            })
            .collect();
        assert!(errors[0] < 2e-3, "{errors:?}");
        for w in errors.windows(2) {
            let ratio = w[0] / w[1];
            assert!((7.0..13.0).contains(&ratio), "1/K convergence: {errors:?}");
        }
    }
}

/// μ = 0: the OLOA motions are exactly zero in the periodic state.
#[test]
fn without_friction_nothing_moves_off_the_line_of_action() {
    let (scene, g) = fzg();
    let s = six(ctx(&scene, &g, 1000.0), None, 5e8);
    let x = Floquet::analyse(&s).periodic_state.unwrap();
    for i in [3, 4, 8, 9] {
        assert_eq!(x[i], 0.0, "state {i}");
    }
    assert!(x[1] != 0.0 && x[2] != 0.0);
}

/// det Φ(T) = exp(∫ tr A dt) (Liouville) to 1e-9 relative with friction; the exact and Magnus
/// propagations of the frictionless model agree to 1e-9, and so do the spectral rank-one and Magnus
/// propagations of the model with friction (periodic state relative to its norm, spectral radius).
#[test]
fn liouville_and_two_propagation_methods() {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.08 };
    let s = six(ctx(&scene, &g, 1000.0), Some(&law), 5e8);
    let fl = Floquet::analyse(&s);
    assert!((fl.determinant / fl.liouville - 1.0).abs() < 1e-9, "{} vs {}", fl.determinant, fl.liouville);
    let exact = six(ctx(&scene, &g, 1000.0), None, 5e8);
    let mut magnus = six(ctx(&scene, &g, 1000.0), None, 5e8);
    magnus.mesh.allow_exact = false;
    let (a, b) = (Floquet::analyse(&exact), Floquet::analyse(&magnus));
    assert_eq!(format!("{:?}", a.method), "Exact");
    assert_eq!(format!("{:?}", b.method), "Magnus4");
    let (xa, xb) = (a.periodic_state.unwrap(), b.periodic_state.unwrap());
    assert!(
        (xa - xb).component_div(&exact.state_scale()).norm() < 1e-9 * xa.component_div(&exact.state_scale()).norm()
    );
    assert!((a.spectral_radius - b.spectral_radius).abs() < 1e-9);
    let mut magnus = six(ctx(&scene, &g, 1000.0), Some(&law), 5e8);
    magnus.mesh.allow_exact = false;
    let b = Floquet::analyse(&magnus);
    assert_eq!((fl.method, b.method), (Method::Spectral, Method::Magnus4));
    let (xa, xb) = (fl.periodic_state.unwrap(), b.periodic_state.unwrap());
    let scale = s.state_scale();
    assert!((xa - xb).component_div(&scale).norm() < 1e-9 * xa.component_div(&scale).norm());
    assert!((fl.spectral_radius - b.spectral_radius).abs() < 1e-9);
}

mod response {
    use gearloss::dynamics::Floquet;
    use gearloss::dynamics::SixDofResponse;
    use gearloss::friction::Coulomb;
    use gearloss::friction::FrictionLaw;

    use super::{ctx, fzg, six};

    /// The mean OLOA bearing force balances the mean friction force Σ μ_i N_i (pinion +, wheel −), to
    /// 1e-8 relative: y is periodic, so the means of ÿ and ẏ vanish.
    #[test]
    fn mean_oloa_bearing_force_balances_the_mean_friction_force() {
        let (scene, g) = fzg();
        let law = Coulomb { mu: 0.08 };
        let s = six(ctx(&scene, &g, 1000.0), Some(&law), 5e8);
        let r = SixDofResponse::compute(&s, &Floquet::analyse(&s)).unwrap();
        let f = r.friction_force.mean.value;
        assert!(f.abs() > 1.0, "mean friction force {f}");
        assert!((r.gears[0].bearing_force_oloa.mean.value - f).abs() < 1e-8 * f.abs());
        assert!((r.gears[1].bearing_force_oloa.mean.value + f).abs() < 1e-8 * f.abs());
        // Along the line of action both bearings carry the mean mesh force N̄, pinion − and wheel +
        // (equal to 1e-8); N̄ is within 5 % of F0 = T_p/r_b1 (mean (1 − f) N = F0 exactly).
        let (p, w) = (r.gears[0].bearing_force_loa.mean.value, r.gears[1].bearing_force_loa.mean.value);
        assert!((p + w).abs() < 1e-8 * w.abs(), "{p} {w}");
        let n0 = s.mesh.static_force;
        assert!((w - n0).abs() < 0.05 * n0, "{w} vs {n0}");
    }

    /// He & Singh §3 ("friction has most significant effect in the OLOA dynamics") and He–Cho–Singh:
    /// with friction the OLOA bearing force has mesh harmonics (orders 1 and 2 above 5 % of the mean
    /// friction force; exactly zero without friction), and of the DTE harmonics 1–5 the second is
    /// the one friction amplifies most (ratio of amplitudes with μ = 0.08 to μ = 0).
    #[test]
    fn friction_excites_the_oloa_harmonics_and_the_second_dte_harmonic_most() {
        let (scene, g) = fzg();
        let law = Coulomb { mu: 0.08 };
        let with = six(ctx(&scene, &g, 1000.0), Some(&law), 5e8);
        let without = six(ctx(&scene, &g, 1000.0), None, 5e8);
        let rw = SixDofResponse::compute(&with, &Floquet::analyse(&with)).unwrap();
        let r0 = SixDofResponse::compute(&without, &Floquet::analyse(&without)).unwrap();
        let f = rw.friction_force.mean.value.abs();
        for o in 0..2 {
            assert!(rw.gears[0].bearing_force_oloa.spectrum[o] > 0.05 * f, "order {}", o + 1);
            assert_eq!(r0.gears[0].bearing_force_oloa.spectrum[o], 0.0);
        }
        let ratios: Vec<f64> = (0..5).map(|o| rw.dte.spectrum[o] / r0.dte.spectrum[o]).collect();
        let best = ratios.iter().enumerate().max_by(|a, b| a.1.total_cmp(b.1)).unwrap().0;
        assert_eq!(best + 1, 2, "amplification by order {ratios:?}");
    }

    /// He–Cho–Singh: Model III (Xu) gives the smallest OLOA excitation near the pitch point: within
    /// ±2 % of a mesh period around the pitch passage max |μ̄| is smallest for Xu, among Coulomb
    /// (μ = 0.08), Benedict–Kelley and Xu.
    #[test]
    fn xu_gives_the_smallest_oloa_excitation_near_the_pitch_point() {
        let (scene, g) = fzg();
        let c = ctx(&scene, &g, 1000.0);
        let spec = |name: &str| {
            let l = gearloss::friction::catalog::entry(name).unwrap();
            let arguments = l
                .arguments
                .iter()
                .filter_map(|a| match a.default {
                    gearloss::friction::catalog::ArgumentDefault::Value(d) => {
                        Some((a.name.to_string(), d, "default".to_string()))
                    }
                    _ => None,
                })
                .collect();
            gearloss::friction::catalog::FrictionLawSpec { law: l.id, arguments, span: Default::default() }
                .build(&c)
                .unwrap()
        };
        let laws: Vec<(String, Box<dyn FrictionLaw>)> = vec![
            ("coulomb".into(), Box::new(Coulomb { mu: 0.08 })),
            ("benedict_kelley".into(), spec("benedict_kelley")),
            ("xu".into(), spec("xu")),
        ];
        let tau_p = g.pitch_times()[0];
        let mut peaks = Vec::new();
        for (name, law) in &laws {
            let s = six(c, Some(law.as_ref()), 5e8);
            let t = s.mesh.period;
            let peak = (0..=400)
                .map(|i| (tau_p - 0.02 + 0.04 * i as f64 / 400.0) * t)
                .map(|x| s.mean_mu(x).abs())
                .fold(0.0f64, f64::max);
            peaks.push((name.clone(), peak));
        }
        let xu = peaks.iter().find(|p| p.0 == "xu").unwrap().1;
        assert!(peaks.iter().all(|p| p.0 == "xu" || p.1 > xu), "{peaks:?}");
    }
}

/// The "done when": the committed FZG-on-bearings report (kept up to date by
/// `specs::committed_reports_are_up_to_date`) carries the 6-DOF records, each dimensional value as
/// {"value", "unit"}.
#[test]
fn six_dof_report_carries_the_required_fields() {
    let text =
        std::fs::read_to_string(crate::root().join("reports/fzg_type_c_on_bearings/stages/pair/report.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let d = &v["dynamics"];
    assert_eq!(d["model"], "six_dof");
    assert!(d["stiffness_ratio"].as_f64().unwrap() > 1.0);
    for p in d["points"].as_array().unwrap() {
        for f in p["formulations"].as_array().unwrap() {
            assert!(f["spectral_radius"].is_number());
            assert_eq!(f["floquet_multipliers"].as_array().unwrap().len(), 10);
            for key in ["dte_peak_to_peak", "dte_mean"] {
                assert_eq!(f[key]["unit"], "m", "{key}");
            }
            assert!(f["dynamic_factor"].as_f64().unwrap() > 1.0);
            let gears = f["gears"].as_array().unwrap();
            assert_eq!(gears.len(), 2);
            for g in gears {
                for key in ["bearing_force_oloa_peak_to_peak", "bearing_force_oloa_mean"] {
                    assert_eq!(g[key]["unit"], "N", "{key}");
                    assert!(g[key]["value"].is_number());
                }
                assert_eq!(g["oloa_displacement_peak_to_peak"]["unit"], "m");
            }
        }
    }
}

/// He & Singh's helical 6-DOF through the same model: on the NASA-ART pair (μ = 0.2, ζ = 0.05) the
/// stiff-bearing limit is again the helical SDOF internal formulation (DTE of the periodic state to
/// 2e-3 relative at K = 1e11 N/m, 1/K convergence), and μ = 0 leaves y ≡ 0.
#[test]
fn helical_six_dof_tends_to_the_helical_sdof() {
    let g = crate::helical::nasa_art(21.5);
    let law = Coulomb { mu: 0.2 };
    let (scene, _) = fzg();
    let c = LawContext {
        geometry: &g,
        state: OperatingState { pinion_torque: 226.0, pinion_speed: 1000.0 * std::f64::consts::PI / 30.0 },
        tribology: scene.mesh().tribology(226e9),
        sharing: Sharing::Equal,
    };
    let k = StiffnessModel::per_length(5.676e9, &g);
    let j = [9.4117e-4, 1.8530e-3];
    let sdof = |l: Option<&'static Coulomb>| {
        let f = if l.is_some() { DynamicFormulation::Internal } else { DynamicFormulation::Base };
        SdofSystem::new(c, l.map(|x| x as &dyn FrictionLaw), f, k.clone(), j, 0.05)
    };
    let law: &'static Coulomb = Box::leak(Box::new(law));
    let x_ref = Floquet::analyse(&sdof(Some(law))).periodic_state.unwrap()[0];
    let errors: Vec<f64> = [1e11, 1e12]
        .iter()
        .map(|kb| {
            let s = SixDofSystem::new(sdof(Some(law)), [0.6, 0.9], bearings(*kb));
            let x = Floquet::analyse(&s).periodic_state.unwrap();
            (SixDofSystem::deflection(&x).0 - x_ref).abs() / x_ref.abs()
        })
        .collect();
    assert!(errors[0] < 2e-3 && (7.0..13.0).contains(&(errors[0] / errors[1])), "{errors:?}");
    let s = SixDofSystem::new(sdof(None), [0.6, 0.9], bearings(5e8));
    let x = Floquet::analyse(&s).periodic_state.unwrap();
    assert!([3, 4, 8, 9].iter().all(|i| x[*i] == 0.0));
}

/// The located largest friction force on one pair equals a 2·10⁴-sample brute force over the period
/// to 1e-6 relative (never below it by more than rounding), and it is μ N on the single-contact pair:
/// at most μ × max N.
#[test]
fn largest_pair_friction_force_is_located() {
    use gearloss::dynamics::SixDofResponse;
    use gearloss::dynamics::Trajectory;
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.08 };
    let s = six(ctx(&scene, &g, 1000.0), Some(&law), 5e8);
    let fl = Floquet::analyse(&s);
    let r = SixDofResponse::compute(&s, &fl).unwrap();
    let tr = Trajectory::new(&s, &fl.period, fl.periodic_state.unwrap());
    let t_mesh = s.mesh.period;
    let brute = (0..20_000)
        .map(|i| (i as f64 + 0.5) / 20_000.0 * t_mesh)
        .map(|t| {
            let p = tr.piece_of(t);
            let tp = tr.parameter_time(p, t);
            s.largest_pair_mu(tp) * s.mesh_force(tp, &tr.state(p, t)).abs()
        })
        .fold(0.0f64, f64::max);
    let located = r.pair_friction_force_max.value;
    assert!(located >= brute * (1.0 - 1e-12), "{located} < {brute}");
    assert!(located <= brute * (1.0 + 1e-6), "{located} vs {brute}");
    assert!(located <= 0.08 * r.mesh_force[1].value * (1.0 + 1e-12));
}
