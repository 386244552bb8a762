//! Each friction law against its paper: a published number, a closed form or a limit case.

use gearloss::evaluate::evaluate_mesh;
use gearloss::friction::catalog::ArgumentDefault;
use gearloss::friction::testing::contact;
use gearloss::friction::BenedictKelley;
use gearloss::friction::Composite;
use gearloss::friction::Coulomb;
use gearloss::friction::Misharin;
use gearloss::friction::ODonoghueCameron;
use gearloss::friction::SmoothedCoulomb;
use gearloss::friction::Xu;
use gearloss::friction::{FrictionLaw, Regime};

fn spec(name: &str) -> gearloss::Scene {
    crate::scene(&crate::root().join("specs").join(name))
}

fn law_index(scene: &gearloss::Scene, id: &str) -> usize {
    scene.friction.iter().position(|l| l.law.name() == id).unwrap()
}

/// Every catalogue entry sits at the index of its typed identity, has a unique scene name, and its
/// constructor builds a law that reports that identity.
#[test]
fn catalogue_entries_build_the_law_they_name() {
    use gearloss::friction::catalog::LAWS;
    let scene = spec("fzg_type_c.gear");
    let eval = evaluate_mesh(&scene.pair_alone().unwrap());
    let mut ctx = eval.law_context(eval.points[0].state);
    ctx.tribology.rz_mean = Some(2.0e-6); // FZG C gives Ra and Rq; Rz as a scene would give it
    for (i, entry) in LAWS.iter().enumerate() {
        assert_eq!(entry.id as usize, i, "{}", entry.id.name());
        // The row's name is the law's file and what a scene writes: the file exists, the scene name
        // finds this row, and the id's entry is this row.
        let file = crate::root().join("src/friction").join(format!("{}.rs", entry.id.name()));
        assert!(file.is_file(), "no file {} for the row {}", file.display(), entry.id.name());
        assert_eq!(gearloss::friction::catalog::entry(entry.id.name()).map(|e| e.id), Some(entry.id));
        assert_eq!(entry.id.entry().title, entry.title, "{}", entry.id.name());
        assert_eq!(LAWS.iter().filter(|e| e.id.name() == entry.id.name()).count(), 1);
        let arguments = entry.arguments.iter().filter_map(|a| match a.default {
            ArgumentDefault::Required => Some((a.name.to_string(), 0.05, String::new())),
            ArgumentDefault::Value(d) => Some((a.name.to_string(), d, String::new())),
            ArgumentDefault::Derived => None,
        });
        let spec = gearloss::model::FrictionLawSpec {
            law: entry.id,
            arguments: arguments.collect(),
            span: Default::default(),
        };
        assert_eq!(spec.build(&ctx).unwrap().id(), entry.id);
    }
}

/// A law's constructor and its catalogue row agree on what it needs: with one input of the scene
/// taken away, the law builds when the row does not name the input and fails naming it when the row
/// does; a required argument left out fails naming the argument. (Lowering checks the rows with
/// spans; evaluation builds the laws and would stop, never report NaN, if the two disagreed.)
#[test]
fn laws_name_the_input_they_miss() {
    use gearloss::friction::catalog::{FrictionLawSpec, Needs, LAWS};
    use gearloss::friction::LawContext;
    let scene = spec("fzg_type_c.gear");
    let eval = evaluate_mesh(&scene.pair_alone().unwrap());
    let mut full = eval.law_context(eval.points[0].state);
    let t = &mut full.tribology;
    t.rz_mean = t.rz_mean.or(Some(2.0e-6)); // FZG C gives Ra and Rq; Rz as a scene would give it
    assert!(t
        .ra_mean
        .and(t.rq_mean)
        .and(t.rq_composite)
        .and(t.kinematic_viscosity)
        .and(t.pressure_viscosity)
        .is_some());
    type TakeAway = fn(&mut gearloss::tribology::Tribology);
    let inputs: [(Needs, TakeAway); 5] = [
        (Needs::RoughnessRa, |t| t.ra_mean = None),
        (Needs::RoughnessRq, |t| (t.rq_mean, t.rq_composite) = (None, None)),
        (Needs::RoughnessRz, |t| t.rz_mean = None),
        (Needs::KinematicViscosity, |t| t.kinematic_viscosity = None),
        (Needs::PressureViscosity, |t| t.pressure_viscosity = None),
    ];
    for entry in LAWS {
        let given: Vec<_> = entry
            .arguments
            .iter()
            .filter_map(|a| match a.default {
                ArgumentDefault::Required => Some((a.name.to_string(), 0.05, String::new())),
                ArgumentDefault::Value(d) => Some((a.name.to_string(), d, String::new())),
                ArgumentDefault::Derived => None,
            })
            .collect();
        let spec = FrictionLawSpec { law: entry.id, arguments: given.clone(), span: Default::default() };
        for (need, take_away) in inputs {
            let mut tribology = full.tribology;
            take_away(&mut tribology);
            let ctx = LawContext { tribology, ..full };
            match spec.build(&ctx) {
                Ok(_) => assert!(!entry.needs.contains(&need), "{} built without {}", entry.id.name(), need.key()),
                Err(m) => {
                    assert!(entry.needs.contains(&need), "{} asks for {} its row omits", entry.id.name(), need.key());
                    assert_eq!((m.law, m.key.as_str()), (entry.id, need.key()));
                }
            }
        }
        for required in entry.arguments.iter().filter(|a| a.default == ArgumentDefault::Required) {
            let arguments = given.iter().filter(|(n, _, _)| n != required.name).cloned().collect();
            let spec = FrictionLawSpec { law: entry.id, arguments, span: Default::default() };
            let m = spec.build(&full).err().expect("a required argument left out");
            assert_eq!(m.key, required.name);
        }
    }
}

/// He–Cho–Singh's 29700 is Benedict and Kelley's 3.17e8 (lb/in, cP, in/s) in N/mm, cP, m/s:
/// the conversion gives 29 662, which rounds to 2.97e4 at the three figures printed.
#[test]
fn benedict_kelley_constant_is_the_imperial_one_converted() {
    let from_imperial = BenedictKelley::CONSTANT_FROM_IMPERIAL;
    assert!((from_imperial - 29_662.0).abs() < 1.0, "{from_imperial}");
    assert_eq!(format!("{:.2e}", from_imperial), format!("{:.2e}", BenedictKelley::CONSTANT));
}

/// Xu: zero at P, rising with |SR| at low SR (the linear, isothermal region; He–Cho–Singh §4).
#[test]
fn xu_vanishes_at_the_pitch_point_and_rises_with_slip() {
    let law = Xu::from_units(95.0, 0.3);
    let mut c = contact();
    c.slide_to_roll = 0.0;
    assert_eq!(law.magnitude(&c), 0.0);
    let mut last = 0.0;
    for k in 1..=10 {
        c.slide_to_roll = 0.002 * k as f64;
        let m = law.magnitude(&c);
        assert!(m > last, "SR {}: {m} ≤ {last}", c.slide_to_roll);
        last = m;
    }
}

/// Bernard Table 4: Xu is lowest at the pitch point (μ = 0 there), the Benedict–Kelley forms diverge there,
/// and Bernard's form runs ≈ 0.08 above He–Cho–Singh's eq 14 (physics notes).
#[test]
fn bernard_table_4_xu_lowest_at_the_pitch_point() {
    let scene = spec("bernard_table4.gear");
    let eval = evaluate_mesh(&scene.pair_alone().unwrap());
    let pe = &eval.points[0];
    let xu = &pe.laws[law_index(&scene, "xu")];
    let p_row = pe.table.iter().position(|(n, _)| *n == Some("P")).unwrap();
    assert_eq!(xu.table[p_row], Some(0.0));
    for (i, v) in xu.table.iter().enumerate() {
        if i != p_row {
            assert!(v.unwrap().abs() > 0.0);
        }
    }
    for id in ["benedict_kelley", "benedict_kelley_bernard", "misharin", "odonoghue_cameron", "drozdov_gavrikov"] {
        let l = &pe.laws[law_index(&scene, id)];
        assert!(l.diverges_at_pitch && l.table[p_row].is_none(), "{id}");
        assert!(l.mean_abs_mu.value.is_finite() && l.mean_abs_mu.value > 0.0, "{id}");
    }
    let bk = pe.laws[law_index(&scene, "benedict_kelley")].mean_abs_mu.value;
    let bkb = pe.laws[law_index(&scene, "benedict_kelley_bernard")].mean_abs_mu.value;
    assert!((0.06..0.10).contains(&(bkb - bk)), "Bernard {bkb} vs eq 14 {bk}");
}

/// O'Donoghue–Cameron on Bernard Table 4: R in m gives μ ≈ 1–4 (implausible), R in mm 0.03–0.1 (physics notes).
#[test]
fn odonoghue_cameron_radius_unit() {
    let scene = spec("bernard_table4.gear");
    let eval = evaluate_mesh(&scene.pair_alone().unwrap());
    let law = ODonoghueCameron::new(&eval.tribology).unwrap();
    let pe = &eval.points[0];
    let a = &pe.table[0].1; // point A: SR ≈ 1
    let in_m = law.magnitude_with_radius_scale(a, 1.0);
    let in_mm = law.magnitude_with_radius_scale(a, 1e3);
    assert!((0.5..5.0).contains(&in_m), "R in m: {in_m}");
    assert!((0.02..0.1).contains(&in_mm), "R in mm: {in_mm}");
    assert!((in_m / in_mm - 1e3f64.sqrt()).abs() < 1e-9);
}

/// Misharin: 0.3865 (ν U² SR)^−1/4 is 0.3865 at ν = 1 cSt, U = 1 m/s, SR = 1; invalid outside SR ∈ [0.4, 1.3]
/// and outside its μ range 0.02–0.08 (ν = 100 cSt, U = 6 m/s, SR = 1: μ = 0.0499, valid; ν = 1 cSt:
/// μ = 0.41, invalid).
#[test]
fn misharin_closed_form_and_range() {
    let law = Misharin { kinematic_viscosity_cst: 1.0 };
    let mut c = contact();
    c.entrainment_velocity = 1.0;
    c.slide_to_roll = 1.0;
    assert!((law.magnitude(&c) - 0.3865).abs() < 1e-15);
    c.slide_to_roll = 16.0;
    assert!((law.magnitude(&c) - 0.3865 / 2.0).abs() < 1e-15);
    assert!(law.validity(&c).is_err());
    c.slide_to_roll = 0.8;
    assert_eq!(law.validity(&c), Err("μ outside Misharin's 0.02–0.08"));
    let thick = Misharin { kinematic_viscosity_cst: 100.0 };
    c.entrainment_velocity = 6.0;
    c.slide_to_roll = 1.0;
    assert!((thick.magnitude(&c) - 0.3865 * 3600f64.powf(-0.25)).abs() < 1e-15);
    assert!(thick.validity(&c).is_ok());
}

/// Smoothed Coulomb: odd in s, zero at P, tends to Coulomb as Φ|s| grows (within 2/(πΦ|s|)·2μ/π).
#[test]
fn smoothed_coulomb_limits() {
    let law = SmoothedCoulomb { mu: 0.06, phi: 50e3 };
    let coulomb = Coulomb { mu: 0.06 };
    let mut c = contact();
    for s in [1e-6, 1e-5, 1e-4, 1e-3, 5e-3] {
        c.s = s;
        let plus = law.mu(&c);
        c.s = -s;
        assert_eq!(law.mu(&c), -plus);
        let px = 50e3 * s;
        // atan(x) = π/2 − 1/x + O(x⁻³) and x/(1+x²) = 1/x + O(x⁻³): the error is O((Φs)⁻³).
        if px > 10.0 {
            c.s = s;
            assert!((plus - coulomb.mu(&c)).abs() < 0.06 * 2.0 / px.powi(3), "s {s}");
        }
    }
}

/// Benedict–Kelley eq 14, hand-computed at the test contact: w = 319 N/mm, η = 95 cP, v_s = 1.39 m/s,
/// v_Σ = 2.65 m/s, S = 0.3 µm.
#[test]
fn benedict_kelley_hand_value() {
    let law = BenedictKelley { viscosity_cp: 95.0, roughness_um: 0.3 };
    let c = contact();
    let expected = 0.0127 * 1.13 / 0.83 * (29_700.0 * 319.0 / (95.0 * 1.39 * 2.65f64.powi(2))).log10();
    assert!((law.mu(&c) + expected).abs() < 1e-12, "{} vs −{expected}", law.mu(&c));
}

/// Model V: the regime at every row follows Λ (1 and 4 the bounds), both switches occur over the
/// speed sweep, and Λ equals 1 or 4 at every switch point found inside a zone.
#[test]
fn composite_switches_regime_where_lambda_crosses_1_and_4() {
    let scene = spec("composite_speed_sweep.gear");
    let eval = evaluate_mesh(&scene.pair_alone().unwrap());
    let k = law_index(&scene, "composite");
    let mut seen = std::collections::BTreeSet::new();
    for pe in &eval.points {
        let law = &pe.laws[k];
        let film = pe.film.as_ref().unwrap();
        for (i, r) in law.regimes.as_ref().unwrap().iter().enumerate() {
            let lambda = film[i].lambda.unwrap();
            assert_eq!(*r, Composite::regime_of(lambda), "Λ = {lambda}");
            seen.insert(format!("{r:?}"));
        }
        let ctx = eval.law_context(pe.state);
        let built = scene.friction[k].build(&ctx).unwrap();
        let g = &eval.geometry.points;
        for u in &law.switch_points {
            let inside_zone = (u - g.b).abs() > 1e-7 && (u - g.d).abs() > 1e-7;
            if inside_zone {
                let c = ctx.contact_at(*u);
                let composite = Composite::new(&ctx, 0.8e-3, None, 50e3).unwrap();
                let lambda = composite.lambda(&c);
                assert!((lambda - 1.0).abs() < 1e-6 || (lambda - 4.0).abs() < 1e-6, "Λ = {lambda} at a switch");
            }
            let _ = built.regime(&ctx.contact_at(*u));
        }
    }
    for r in [Regime::Boundary, Regime::Mixed, Regime::FullFilm] {
        assert!(seen.contains(&format!("{r:?}")), "{r:?} never reached over the sweep: {seen:?}");
    }
}

/// Dowson–Toyoda central film by hand: h_c = 3.06 G^0.56 U^0.69 W^−0.10 R.
#[test]
fn film_thickness_hand_value() {
    use gearloss::tribology::FilmInputs;
    let f = FilmInputs { dynamic_viscosity: 0.095, pressure_viscosity: 2e-8, reduced_modulus: 226e9 };
    let c = contact();
    let (u, g, w): (f64, f64, f64) = (0.095 * 1.325 / (226e9 * 4.97e-3), 2e-8 * 226e9, 3.19e5 / (226e9 * 4.97e-3));
    let hc = 3.06 * g.powf(0.56) * u.powf(0.69) * w.powf(-0.10) * 4.97e-3;
    let hmin = 2.65 * u.powf(0.70) * g.powf(0.54) * w.powf(-0.13) * 4.97e-3;
    assert!((f.central(&c) - hc).abs() < 1e-15 && (f.minimum(&c) - hmin).abs() < 1e-15);
    assert!(hc > 0.1e-6 && hc < 2e-6, "h_c = {hc} m is an EHL film of tenths of µm");
}

/// ISO/TR 14179-2 by hand for FZG type C at 1000 rpm, 239.3 N·m (X_L = 1, Ra 0.3 µm, 95 mPa·s).
#[test]
fn iso_14179_2_hand_value() {
    use gearloss::friction::Iso14179_2;
    let scene = spec("fzg_type_c.gear");
    let g = scene.gears.geometry().unwrap();
    let eval = evaluate_mesh(&scene.pair_alone().unwrap());
    let state =
        gearloss::geometry::OperatingState { pinion_torque: 239.3, pinion_speed: 1000.0 * std::f64::consts::PI / 30.0 };
    let law = Iso14179_2::new(&eval.law_context(state), None).unwrap();
    let aw = g.operating_pressure_angle;
    let fbt_b = 239.3 / g.base_radius[0] / 14.0;
    let vt = state.pinion_speed * g.working_pitch_radius[0];
    let v_sum = 2.0 * vt * aw.sin();
    let rho = 1.5 / 2.5f64.powi(2) * 91.5 * aw.sin();
    let expected = 0.048 * (fbt_b.max(150.0) / (v_sum * rho)).powf(0.2) * 95f64.powf(-0.05) * 0.3f64.powf(0.25);
    assert!((law.mu_mz - expected).abs() < 1e-12, "{} vs {expected}", law.mu_mz);
    assert!((0.02..0.08).contains(&expected));
}

/// Matsumoto: ξ = 0.5 log10(Rz/h_min) clamped; a very thick film gives μ_EHL, a very thin one μ_bl.
#[test]
fn matsumoto_limits() {
    use gearloss::friction::Matsumoto;
    use gearloss::tribology::FilmInputs;
    let film = FilmInputs { dynamic_viscosity: 0.095, pressure_viscosity: 2e-8, reduced_modulus: 226e9 };
    let c = contact();
    let h = film.minimum(&c);
    let at = |rz: f64| Matsumoto { mu_boundary: 0.1, mu_ehl: 0.02, rz_mean: rz, film }.magnitude(&c);
    assert!((at(h * 1e-3) - 0.02).abs() < 1e-15);
    assert!((at(h * 1e3) - 0.1).abs() < 1e-15);
    // ξ = 0.5 at Rz = 10 h_min.
    assert!((at(10.0 * h) - 0.06).abs() < 1e-12);
}

/// No law puts NaN or infinity into a report: every scene's report.json has no null number.
#[test]
fn no_scene_report_has_a_non_finite_number() {
    for name in ["bernard_table4.gear", "composite_speed_sweep.gear", "fzg_type_c.gear", "us_spur_inch.gear"] {
        let scene = spec(name);
        let report = gearloss::report_of(&scene);
        assert!(
            gearloss::report::non_finite_paths(&report).is_empty(),
            "{name}: {:?}",
            gearloss::report::non_finite_paths(&report)
        );
    }
}

/// The mean |μ| of a law that diverges at P converges with the tolerance (the singularity is integrated).
#[test]
fn divergent_means_converge() {
    use gearloss::numerics::integrate;
    let scene = spec("bernard_table4.gear");
    let eval = evaluate_mesh(&scene.pair_alone().unwrap());
    let ctx = eval.law_context(eval.points[0].state);
    let law = BenedictKelley::new(&eval.tribology).unwrap();
    let p = eval.geometry.points;
    let f = |u: f64| law.mu(&ctx.contact_at(u)).abs();
    let coarse = integrate(f, &[p.a, p.b, p.p, p.d, p.e], 1e-6).value;
    let fine = integrate(f, &[p.a, p.b, p.p, p.d, p.e], 1e-12).value;
    assert!(((coarse - fine) / fine).abs() < 2e-6, "{coarse} vs {fine}");
}

/// Model V's regime switches are located, not read off a grid: at every speed of the NASA sweep the
/// switch points equal the regime changes of a 10⁵-point scan of A–E (same count, each within one scan
/// step), and inside a zone Λ equals 1 or 4 there to 1e-9.
#[test]
fn composite_switches_match_a_dense_scan() {
    let scene = spec("composite_speed_sweep.gear");
    let eval = evaluate_mesh(&scene.pair_alone().unwrap());
    let g = eval.geometry.points;
    for pe in &eval.points {
        let ctx = eval.law_context(pe.state);
        let law = Composite::new(&ctx, 0.8e-3, None, 50e3).unwrap();
        let n = 100_000;
        let step = (g.e - g.a) / n as f64;
        let mut scanned = Vec::new();
        let mut prev = Composite::regime_of(law.lambda(&ctx.contact_at(g.a)));
        for i in 1..n {
            let u = g.a + step * i as f64;
            let r = Composite::regime_of(law.lambda(&ctx.contact_at(u)));
            if r != prev {
                scanned.push(u);
            }
            prev = r;
        }
        let found = law.switch_points();
        assert_eq!(found.len(), scanned.len(), "{:?}: {found:?} vs scan {scanned:?}", pe.state);
        for (a, b) in found.iter().zip(&scanned) {
            assert!((a - b).abs() <= step, "switch {a} vs scan {b}");
            if (a - g.b).abs() > 1e-9 && (a - g.d).abs() > 1e-9 {
                let lambda = law.lambda(&ctx.contact_at(*a));
                assert!((lambda - 1.0).abs() < 1e-9 || (lambda - 4.0).abs() < 1e-9, "Λ = {lambda} at {a}");
            }
        }
    }
}
