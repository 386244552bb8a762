//! The lubricant at temperature, the loss models and the loss budget end to end (issue: a gearbox
//! power-loss calculator). Tolerances are stated per test.

use gearloss::evaluate::evaluate_mesh;
use gearloss::geometry::OperatingState;
use gearloss::losses::parts::LossColumn;
use gearloss::losses::{loss_budget, Bearing, BearingType, Gearbox, Lubrication, Oil, Seal};
use gearloss::losses::{windage_loss, GearsRunning};

/// A mineral oil of 50 mm²/s and 870 kg/m³.
const OIL: Oil = Oil { nu: Some(50e-6), rho: Some(870.0), eta: 50e-6 * 870.0, mineral: true };

fn spec(name: &str) -> gearloss::Scene {
    crate::scene(&crate::root().join("specs").join(name))
}

/// `count` bearings of `kind` with d_m = 50 mm at position `at` (m), Palmgren's table values.
fn bearing_at(kind: BearingType, at: f64, count: usize) -> Bearing {
    Bearing {
        kind,
        mean_diameter: 0.05,
        count,
        static_load_rating: None,
        f0: None,
        f1: None,
        y: None,
        position: Some(at),
        skf: None,
    }
}

fn rpm(n: f64) -> f64 {
    n * std::f64::consts::PI / 30.0
}

/// `lubricant = iso_vg(100, mineral)` at 90 °C: ν by ASTM D341 computed by hand through the
/// catalogue's ν40 = 100 and ν100 (to 1e-6 relative), η = ρ ν, ρ = ρ15 (1 − 7e-4 · 75).
#[test]
fn catalogue_oil_at_temperature_by_hand() {
    let scene = spec("fzg_c14_gearbox.gear");
    let l = scene.lubricant.as_ref().unwrap();
    let oil = l.oil.as_ref().unwrap();
    let (nu40, nu100) = (oil.nu_40 * 1e6, oil.nu_100 * 1e6);
    let w = |nu: f64| (nu + 0.7f64).log10().log10();
    let b = (w(nu40) - w(nu100)) / (373.15f64.log10() - 313.15f64.log10());
    let a = w(nu40) + b * 313.15f64.log10();
    let nu90 = 10f64.powf(10f64.powf(a - b * 363.15f64.log10())) - 0.7;
    let rho90 = 885.0 * (1.0 - 7e-4 * 75.0);
    let eta = l.dynamic_viscosity.value.value;
    assert!((eta / (rho90 * nu90 * 1e-6) - 1.0).abs() < 1e-6, "η = {eta} vs {}", rho90 * nu90 * 1e-6);
    // The catalogue oil is a VG 100 of VI 95: ν40 = 100 mm²/s exactly.
    assert!((nu40 - 100.0).abs() < 1e-12);
    assert!((gearloss::tribology::lubricant::viscosity_index(nu40, nu100).unwrap() - 95.0).abs() < 1e-6);
}

/// The C14 point of the peer comparison: FZG C at load stage 8 (239.3 N·m), 1500 rpm, ISO VG 100
/// mineral at 90 °C, Ra 0.3 µm, `x_l = 0.846`: μ_mZ within 0.5 % of the peer's 0.04487.
#[test]
fn c14_mu_matches_the_peer() {
    use gearloss::friction::Iso14179_2;
    let scene = spec("fzg_c14_gearbox.gear");
    let eval = evaluate_mesh(&scene.pair_alone().unwrap());
    let state = OperatingState { pinion_torque: 239.3, pinion_speed: rpm(1500.0) };
    let mu = Iso14179_2::new(&eval.law_context(state), Some(0.846)).unwrap().mu_mz;
    assert!((mu / 0.04487 - 1.0).abs() < 5e-3, "μ_mZ = {mu}");
    // X_L of the lubricant (mineral: 1.0) when the law has no `x_l`.
    let default = Iso14179_2::new(&eval.law_context(state), None).unwrap().mu_mz;
    assert!((default / mu - 1.0 / 0.846).abs() < 1e-12);
}

/// The peer's mesh loss, 279.65 W, is P_in μ_mZ H_V with Ohlendorf's H_V = 0.1950 and its μ_mZ for
/// load stage 8 applied at the wheel (239.3 N·m and 1500 rpm on the wheel, the peer's element `W`:
/// the pinion at 159.53 N·m and 2250 rpm, the same input power): there Schlenk's μ_mZ is the
/// pinion-side 0.04487 times ((1/1.5)/1.5)^0.2 = 0.038152, and 37 589.6 W · 0.1950 · 0.038152 =
/// 279.65 W. gearloss at that point, `x_l = 0.846`, external formulation: within 0.5 % of 279.65 W
/// (it gives 278.90 W, −0.27 %: μ −0.16 %, H −0.1 %).
#[test]
fn c14_mesh_loss_matches_the_peer_with_the_load_at_the_wheel() {
    use gearloss::efficiency::{evaluate_efficiencies, Formulation};
    use gearloss::friction::Iso14179_2;
    let scene = spec("fzg_c14_gearbox.gear");
    let eval = evaluate_mesh(&scene.pair_alone().unwrap());
    let state = OperatingState { pinion_torque: 239.3 / 1.5, pinion_speed: rpm(2250.0) };
    let input = state.pinion_torque * state.pinion_speed;
    assert!((input - 239.3 * rpm(1500.0)).abs() < 1e-9 * input);
    let ctx = eval.law_context(state);
    let law = Iso14179_2::new(&ctx, Some(0.846)).unwrap();
    let peer_mu = 0.04487 * (1.0f64 / 2.25).powf(0.2);
    assert!((law.mu_mz / peer_mu - 1.0).abs() < 5e-3, "μ_mZ = {} vs {peer_mu}", law.mu_mz);
    assert!((input * 0.1950 * peer_mu - 279.65).abs() < 0.01, "the peer's arithmetic");
    let p = evaluate_efficiencies(&ctx, &law, &[Formulation::External])[0].power_loss;
    assert!((p / 279.65 - 1.0).abs() < 5e-3, "mesh loss {p} W vs the peer's 279.65 W");
}

/// The budget by hand at 239.3 N·m, 1500 rpm: Mauz churning, Palmgren bearings (two NJ 406 per
/// shaft sharing F_bt equally), seals 7.69e-6 d² n, each the scene's drive row's (drive_records.csv,
/// first law, external; to 1e-9 relative); and the row's total is its mesh loss plus the parts
/// (1e-12 relative).
#[test]
fn budget_by_hand() {
    let scene = spec("fzg_c14_gearbox.gear");
    let eval = evaluate_mesh(&scene.pair_alone().unwrap());
    let g = &eval.geometry;
    let (t, w1) = (239.3, rpm(1500.0));
    let w2 = w1 / g.gear_ratio;
    let nu = eval.tribology.kinematic_viscosity.unwrap();
    let rows = crate::pair_alone::DriveRows::of(&scene);
    let k = rows.find((1, 1), 0, gearloss::efficiency::Formulation::External);
    let part = |c: &str| rows.value(k, c);

    let v_t = w1 * g.working_pitch_radius[0];
    let (e1, e2, h_c, l_h, width): (f64, f64, f64, f64, f64) = (41.2, 59.2, 100.0, 200.0, 14.0);
    let c_sp = (4.0 * e2 / (3.0 * h_c)).powf(1.5) * 2.0 * h_c / l_h;
    let c1 = 0.063 * (e1 + e2) / 10.0 + 0.0128 * (width / 10.0f64).powi(3);
    let c2 = (e1 + e2) / 800.0 + 0.2;
    let churning = c_sp * c1 * (c2 * v_t / 10.0).exp() * w1;
    assert!((part("gear_no_load_W") / churning - 1.0).abs() < 1e-9);

    let dm = 60.0;
    let m0 = |w: f64| {
        let nn = nu * 1e6 * w * 30.0 / std::f64::consts::PI;
        1e-7 * 2.5 * nn.powf(2.0 / 3.0) * dm * dm * dm * 1e-3
    };
    let no_load = 2.0 * (m0(w1) * w1 + m0(w2) * w2);
    assert!((part("bearings_no_load_W") / no_load - 1.0).abs() < 1e-9);
    let fr = t / g.base_radius[0] / 2.0;
    let load = 2.0 * 0.0003 * fr * dm * 1e-3 * (w1 + w2);
    assert!((part("bearings_load_W") / load - 1.0).abs() < 1e-9);
    let seals = 7.69e-6 * 900.0 * (1500.0 + 1000.0);
    assert!((part("seals_W") / seals - 1.0).abs() < 1e-9);
    assert!((rows.value(k, "stage_pair_driving_torque_N_m") - t).abs() <= 1e-12 * t);

    let parts = ["meshes_W", "gear_no_load_W", "bearings_no_load_W", "bearings_load_W", "seals_W"].map(part);
    let total = part("total_W");
    assert!((parts.iter().sum::<f64>() - total).abs() <= 1e-12 * total, "{parts:?} vs {total}");
}

/// The injection gearbox on SKF-model bearings by hand at 239.3 N·m, 3000 rpm: the jet's impulse
/// ρ Q v_t (v_t + v_j) plus both gears' Anderson–Loewenthal windage; each 16006 bearing (two per
/// shaft, F_r = F_bt/2, F_a = 0) with M_rr = φ_ish φ_rs R1 d_m^1.96 F_r^0.54 (νn)^0.6 and
/// M_sl = μ_sl S1 d_m^-0.26 F_r^(5/3), written out here in N·mm, rpm and mm²/s, each the scene's drive
/// row's (drive_records.csv, first law, external; to 1e-9 relative).
#[test]
fn injection_and_skf_budget_by_hand() {
    let scene = spec("fzg_c14_injection.gear");
    let eval = evaluate_mesh(&scene.pair_alone().unwrap());
    let g = &eval.geometry;
    let (t, w1) = (239.3, rpm(3000.0));
    let rows = crate::pair_alone::DriveRows::of(&scene);
    let k = rows.find((1, 1), 0, gearloss::efficiency::Formulation::External);
    let part = |c: &str| rows.value(k, c);
    let nu = eval.tribology.kinematic_viscosity.unwrap() * 1e6;
    let eta_cp = eval.tribology.dynamic_viscosity * 1e3;
    let rho = eval.tribology.density().unwrap();

    let n = [3000.0, 3000.0 / g.gear_ratio];
    let r = g.working_pitch_radius;
    let v_t = w1 * r[0];
    let impulse = rho * 2e-3 / 60.0 * v_t * (v_t + 10.0);
    let windage: f64 = (0..2)
        .map(|i| {
            2.82e-7
                * (1.0 + 2.3 * 0.014 / r[i])
                * n[i].powf(2.8)
                * r[i].powf(4.6)
                * (0.028 * eta_cp + 0.019).powf(0.2)
                * 1e3
        })
        .sum();
    assert!((part("gear_no_load_W") / (impulse + windage) - 1.0).abs() < 1e-9);
    assert!(windage > 1.0 && windage < impulse, "windage {windage} W, impulse {impulse} W");

    let (d, big_d) = (30.0, 55.0);
    let dm: f64 = 42.5;
    let fr = t / g.base_radius[0] / 2.0;
    let (mut rolling, mut sliding) = (0.0, 0.0);
    for n in n {
        let phi_ish = 1.0 / (1.0 + 1.84e-9 * (n * dm).powf(1.28) * nu.powf(0.64));
        let phi_rs = (-3e-8 * nu * n * (d + big_d) * (3.1 / (2.0 * (big_d - d))).sqrt()).exp();
        let m_rr = phi_ish * phi_rs * 4.3e-7 * dm.powf(1.96) * fr.powf(0.54) * (nu * n).powf(0.6);
        let phi_bl = (-2.6e-8 * (n * nu).powf(1.4) * dm).exp();
        let m_sl = (0.15 * phi_bl + 0.05 * (1.0 - phi_bl)) * 4.63e-3 * dm.powf(-0.26) * fr.powf(5.0 / 3.0);
        let w = n * std::f64::consts::PI / 30.0;
        rolling += 2.0 * m_rr * 1e-3 * w;
        sliding += 2.0 * m_sl * 1e-3 * w;
    }
    assert!((part("bearings_no_load_W") / rolling - 1.0).abs() < 1e-9, "{} vs {rolling}", part("bearings_no_load_W"));
    assert!((part("bearings_load_W") / sliding - 1.0).abs() < 1e-9, "{} vs {sliding}", part("bearings_load_W"));
}

/// The lever rule: bearings at −40 and +60 mm carry 60 % and 40 % of F_bt; a helical pair's axial
/// force goes to the first, and its moment F_a r_w / 100 mm adds along the line of centres.
#[test]
fn lever_rule_and_axial_moment() {
    let scene = spec("metric_helical.gear");
    let g = scene.gears.geometry().unwrap();
    let place = |at: f64| bearing_at(BearingType::CylindricalRoller, at, 1);
    let gb =
        Gearbox { lubrication: None, bearings: [vec![place(-0.04), place(0.06)], vec![]], seals: [vec![], vec![]] };
    let t = 200.0;
    let b = loss_budget(&gb, &g, t, rpm(1000.0), &OIL);
    let f_bt = t / g.base_radius[0];
    let (ft, fr) = (f_bt * g.operating_pressure_angle.cos(), f_bt * g.operating_pressure_angle.sin());
    let m = g.axial_force(t) * g.working_pitch_radius[0] / 0.1;
    let r1 = (0.6 * ft).hypot(0.6 * fr - m);
    let r2 = (0.4 * ft).hypot(0.4 * fr + m);
    let [b0, b1] = [b.bearings[0].loads, b.bearings[1].loads];
    assert!((b0.radial_load / r1 - 1.0).abs() < 1e-12, "{} vs {r1}", b0.radial_load);
    assert!((b1.radial_load / r2 - 1.0).abs() < 1e-12);
    assert!((b0.axial_load - g.axial_force(t)).abs() < 1e-9 && b1.axial_load == 0.0);
    assert!(b.part(LossColumn::GearNoLoad).is_none() && b.part(LossColumn::Seals).is_none());
}

/// Statics of both shafts of a helical pair (issue 26): with positions on both shafts, each shaft's
/// reactions balance the gear force in x, y, z and the moments about x and y to 1e-12 of the
/// force × span scale; the budget's loads are those reactions per bearing. The wheel takes the
/// opposite axial pattern: its gear force is the pinion's reversed and its contact lies on the other
/// side of its axis, so in its own frame only the axial force changes sign, and the moment F_a r_w2
/// unloads its first place where the pinion's loads it (by hand: lever · F_r + F_a r_w2 / span).
#[test]
fn both_shafts_balance_forces_and_moments() {
    use gearloss::losses::pair_statics::{shaft_reactions, GearForce};
    let scene = spec("metric_helical.gear");
    let g = scene.gears.geometry().unwrap();
    let place = |at: f64, count: usize| bearing_at(BearingType::TaperedRoller, at, count);
    let gb = Gearbox {
        lubrication: None,
        bearings: [vec![place(-0.04, 1), place(0.06, 1)], vec![place(-0.05, 2), place(0.07, 1)]],
        seals: [vec![], vec![]],
    };
    let t = 400.0;
    let b = loss_budget(&gb, &g, t, rpm(1000.0), &OIL);
    let f_bt = t / g.base_radius[0];
    let (ft, fr, fa) =
        (f_bt * g.operating_pressure_angle.cos(), f_bt * g.operating_pressure_angle.sin(), g.axial_force(t));
    assert!(fa > 0.1 * ft, "a helical pair: F_a = {fa} N");
    for (s, places, sign) in [(0, [-0.04, 0.06], 1.0), (1, [-0.05, 0.07], -1.0)] {
        let r_w = g.working_pitch_radius[s];
        let f = GearForce { tangential: ft, radial: fr, axial: sign * fa, radius: r_w };
        let [r1, r2] = shaft_reactions(f, places);
        let gear = [-fr, ft, sign * fa];
        let scale = f_bt * 0.12;
        for k in 0..3 {
            assert!((r1[k] + r2[k] + gear[k]).abs() < 1e-12 * f_bt, "shaft {s} force {k}");
        }
        // Moments about the gear centre: bearings at (0, 0, p_i), the gear force at (r_w, 0, 0).
        let m_x = -places[0] * r1[1] - places[1] * r2[1];
        let m_y = places[0] * r1[0] + places[1] * r2[0] - r_w * gear[2];
        assert!(m_x.abs() < 1e-12 * scale && m_y.abs() < 1e-12 * scale, "shaft {s}: {m_x} {m_y}");
        // The budget's loads per bearing, in the scene's order.
        let counts = [gb.bearings[s][0].count as f64, gb.bearings[s][1].count as f64];
        let [l1, l2] = [b.bearings[2 * s].loads, b.bearings[2 * s + 1].loads];
        assert_eq!(b.bearings[2 * s].shaft, ["pinion", "wheel"][s]);
        assert!((l1.radial_load - r1[0].hypot(r1[1]) / counts[0]).abs() < 1e-12 * f_bt);
        assert!((l2.radial_load - r2[0].hypot(r2[1]) / counts[1]).abs() < 1e-12 * f_bt);
        assert!((l1.axial_load - fa / counts[0]).abs() < 1e-12 * fa && l2.axial_load == 0.0);
        // By hand, the lever rule with the axial moment's sign of this shaft.
        let span = places[1] - places[0];
        let (lever1, m) = (places[1] / span, fa * r_w / span);
        let by_hand = (lever1 * ft).hypot(lever1 * fr - sign * m) / counts[0];
        assert!((l1.radial_load / by_hand - 1.0).abs() < 1e-12, "shaft {s}: {} vs {by_hand}", l1.radial_load);
    }
}

/// Limits: no oil above the gears gives no churning; injection at zero flow leaves only the two
/// gears' windage; a gearbox with nothing in it adds nothing.
#[test]
fn loss_limits() {
    let g = spec("fzg_c14_gearbox.gear").gears.geometry().unwrap();
    let gears = GearsRunning { omega: [100.0, 50.0], pitch_radius: [0.05, 0.1], face_width: 0.014 };
    let dry = Lubrication::Dip { immersion: [0.0, 0.0], axis_height: 0.1, housing_width: 0.2 };
    assert_eq!(dry.power_loss(&gears, &OIL), Some(0.0));
    let jet = Lubrication::Injection { flow: 0.0, jet_speed: 10.0 };
    let rpm = |w: f64| w * 30.0 / std::f64::consts::PI;
    let windage = windage_loss(rpm(100.0), 0.05, 0.014, OIL.eta) + windage_loss(rpm(50.0), 0.1, 0.014, OIL.eta);
    assert_eq!(jet.power_loss(&gears, &OIL), Some(windage));
    let empty = Gearbox {
        lubrication: None,
        bearings: [vec![], vec![]],
        seals: [vec![Seal { diameter: 0.03, count: 0 }], vec![]],
    };
    assert_eq!(loss_budget(&empty, &g, 100.0, 100.0, &OIL).beside_mesh(), 0.0);
}

/// The scene's report (its one-stage drive's): every row's parts add up to its whole loss in
/// drive_records.csv (meshes, gears' no-load, both bearing columns and seals; 1e-12 relative), the
/// headline leads report.md and loss_budget.svg is drawn; the map is the drive's (loss_map.csv a
/// row per grid point, law and formulation, and loss_map.svg).
#[test]
fn report_budget_and_map() {
    let source = std::fs::read_to_string(crate::root().join("specs/fzg_c14_gearbox.gear")).unwrap();
    let run = gearloss::run_to_files("fzg_c14_gearbox.gear", &source).unwrap().files;
    let file = |name: &str| &run.iter().find(|(f, _)| f == name).unwrap_or_else(|| panic!("no {name}")).1;
    let rows = crate::pair_alone::DriveRows::parse(file("drive_records.csv"));
    assert_eq!(rows.len(), 9 * 2 * 2);
    for k in 0..rows.len() {
        let parts: f64 = ["meshes_W", "gear_no_load_W", "bearings_no_load_W", "bearings_load_W", "seals_W"]
            .iter()
            .map(|c| rows.value(k, c))
            .sum();
        let total = rows.value(k, "total_W");
        assert!((parts - total).abs() <= 1e-12 * total, "row {k}: {parts} W vs {total} W");
        assert!(rows.value(k, "gear_no_load_W") > 0.0 && rows.value(k, "bearings_load_W") > 0.0, "row {k}");
    }
    let md = file("report.md");
    assert!(md.find("## Headline").unwrap() < md.find("## Scene").unwrap());
    assert!(file("loss_budget.svg").contains("<svg"));
    assert_eq!(file("loss_map.csv").lines().count(), 1 + 40 * 40 * 2 * 2);
    assert!(file("loss_map.svg").contains("<svg"));
}

/// A pair's bearing beyond its static rating is found at any point of its sweep, not only at the
/// rows its report keeps: the spec with C_0 = 4 kN on the pinion shaft's bearings,
/// 401 pinion torques at 500 rpm from 50 to 250 N·m (P_0/C_0 ≤ 0.9) but for one point the report
/// does not keep set to 372.6 N·m, warns at that point in the very words and numbers of the same
/// pair run at 372.6 N·m alone; without it, nothing.
#[test]
fn a_pairs_bearing_beyond_its_rating_is_found_at_any_point() {
    let source = std::fs::read_to_string(crate::root().join("specs/fzg_c14_gearbox.gear")).unwrap();
    let rated = source.replacen(
        "bearing(type = cylindrical_roller, bore = 30 mm, outside = 90 mm, count = 2)",
        "bearing(type = cylindrical_roller, bore = 30 mm, outside = 90 mm, count = 2, static_load_rating = 4 kN)",
        1,
    );
    let at = |torques: &[f64]| -> String {
        let list: Vec<String> = torques.iter().map(|t| format!("{t}")).collect();
        rated
            .replace(
                "pinion_torque   = [94.1, 239.3, 372.6] N*m",
                &format!("pinion_torque   = [{}] N*m", list.join(", ")),
            )
            .replace("pinion_speed    = [500, 1500, 3000] rpm", "pinion_speed    = [500] rpm")
            .lines()
            .filter(|l| !l.contains("efficiency_map("))
            .collect::<Vec<_>>()
            .join("\n")
    };
    let report = |src: &str| {
        let scene = gearloss::check("s.gear", src).unwrap_or_else(|e| panic!("{}", e.render(false)));
        gearloss::run_drive::drive_report_files(&scene, scene.drive.as_ref().unwrap()).unwrap().0
    };
    let warnings = |src: &str| crate::messages_with(report(src).findings, "beyond its static rating");
    let mut torques: Vec<f64> = (0..401).map(|k| 50.0 + 0.5 * f64::from(k)).collect();
    assert_eq!(warnings(&at(&torques)), Vec::<String>::new());
    let hidden = 150;
    torques[hidden] = 372.6;
    let kept = report(&at(&torques));
    assert!(kept.points.iter().all(|p| !p.label.contains("372.6")), "the report keeps the point");
    let found = warnings(&at(&torques));
    assert!(!found.is_empty() && found.iter().all(|w| w.contains("372.6 N·m, n_in = 500 rpm")), "{found:?}");
    assert_eq!(found, warnings(&at(&[372.6])));
}

/// Mauz's dip churning was tested up to 60 m/s pitch-line speed: a scene whose fastest point is
/// beyond (20 000 rpm: v_t = 76.7 m/s on the FZG C pinion) gets one warning; the spec (at most
/// 6000 rpm, 23 m/s) none.
#[test]
fn churning_beyond_its_tested_speed_is_flagged() {
    let source = std::fs::read_to_string(crate::root().join("specs/fzg_c14_gearbox.gear")).unwrap();
    let warnings = |src: &str| -> usize {
        let out = gearloss::run_to_files("s.gear", src).unwrap_or_else(|_| panic!("the scene runs"));
        let json = &out.files.iter().find(|(f, _)| f == "report.json").unwrap().1;
        let v: serde_json::Value = serde_json::from_str(json).unwrap();
        v["findings"].as_array().unwrap().iter().filter(|f| f["message"].as_str().unwrap().contains("Mauz")).count()
    };
    assert_eq!(warnings(&source), 0);
    let fast = source.replace("pinion_speed    = [500, 1500, 3000] rpm", "pinion_speed    = [500, 20000] rpm");
    assert_ne!(fast, source);
    assert_eq!(warnings(&fast), 1);
}

/// A drive's stage is warned as a pair is, by its name, at the fastest speed the scene turns it
/// at. The EV reducer with both stages dip-lubricated: at most 1000 rpm out (the map's 1500 rpm:
/// the first pinion at v_t = 34.5 m/s) nothing; at 3000 rpm out the first stage's pinion runs at
/// v_t = ω_out (68/23)(78/20) m_n z_1/(2 cos β) = 68.9 m/s (no profile shift, so r_w = r) and is
/// warned at that speed (to the 0.1 m/s printed), the second's at 32.7 m/s is not.
#[test]
fn a_drives_churning_beyond_its_tested_speed_is_flagged_by_stage() {
    let text = std::fs::read_to_string(crate::root().join("specs/ev_two_stage_reducer.gear")).unwrap();
    let injection = "lubrication = injection(flow = 2.5 l/min, jet_speed = 0.4 m/s)";
    assert_eq!(text.matches(injection).count(), 2);
    let dipped = text.replace(injection, EV_DIP);
    let warnings = |src: &str| {
        churning_warnings(&gearloss::check("ev.gear", src).unwrap_or_else(|e| panic!("{}", e.render(false))))
    };
    assert_eq!(warnings(&dipped), Vec::<String>::new());
    let fast = dipped.replace("output_speed  = [500, 1000] rpm", "output_speed  = [500, 3000] rpm");
    assert_ne!(fast, dipped);
    let v_t = ev_first_pinion_v_t(3000.0 * std::f64::consts::PI / 30.0);
    assert!((v_t - 68.9).abs() < 0.05, "{v_t}");
    assert_first_stage_warned(&warnings(&fast), v_t);
}

/// Dip lubrication of the EV reducer's stages, for the churning checks.
pub(crate) const EV_DIP: &str =
    "lubrication = dip(pinion_immersion = 5 mm, wheel_immersion = 20 mm, axis_height = 80 mm, housing_width = 150 mm)";

/// The EV reducer's first pinion's pitch-line speed (m/s) at the output's ω_out (rad/s):
/// ω_out (68/23)(78/20) m_n z_1/(2 cos β), no profile shift (r_w = r).
pub(crate) fn ev_first_pinion_v_t(omega_out: f64) -> f64 {
    let r_1 = 1.5177e-3 * 23.0 / (2.0 * 23.4f64.to_radians().cos());
    omega_out * (68.0 / 23.0) * (78.0 / 20.0) * r_1
}

/// A drive scene's warnings of churning read beyond Mauz's tested speed.
pub(crate) fn churning_warnings(scene: &gearloss::Scene) -> Vec<String> {
    let drive = scene.drive.as_ref().unwrap();
    let eval = gearloss::evaluate::evaluate_drive(scene, drive);
    let report = gearloss::report::drive::build_drive_report(scene, drive, &eval);
    crate::messages_with(report.findings, "Mauz")
}

/// `found` is one warning: stage `first`'s, at `v_t` (m/s, to the 0.1 printed).
pub(crate) fn assert_first_stage_warned(found: &[String], v_t: f64) {
    assert_eq!(found.len(), 1, "{found:?}");
    let words = format!("stage `first`: gear churning: the fastest pitch-line speed, v_t = {v_t:.1} m/s");
    assert!(found[0].starts_with(&words), "{}", found[0]);
}

/// The map's best point is located on the model, not read off the grid: for the spec gearbox (a
/// scene of one pair: its one-stage drive's loss map, η at the pinion 1 − P_V/(T_1 ω_1); its first
/// law, external) the located η is at least the grid's best; evaluated again as the scene's own
/// operating points, the located point gives the same η (1e-9) and its neighbours (±0.5 % in speed,
/// −0.5 % in torque: 400 N·m is the map's top) give no more (1e-12).
#[test]
fn map_best_point_is_located() {
    let path = crate::root().join("specs/fzg_c14_gearbox.gear");
    let text = std::fs::read_to_string(&path).unwrap();
    let scene = gearloss::check("map.gear", &text).unwrap();
    let drive_report = |s: &gearloss::Scene| {
        gearloss::run_drive::drive_report_files(s, s.drive.as_ref().unwrap()).expect("the spec runs").0
    };
    let report = drive_report(&scene);
    let law = scene.friction[0].label();
    let m = report.maps.iter().find(|m| m.law == law && m.formulation == "external").expect("the map");
    let b = m.best.iter().find(|b| b.flow == "drive").expect("its best point");
    assert!(b.efficiency >= b.grid_efficiency - 1e-12, "{} < grid {}", b.efficiency, b.grid_efficiency);
    let (t, n) = (b.torque, b.speed_rpm);
    let points = format!(
        "pinion_torque   = [{:.9}, {:.9}] N*m\n        pinion_speed    = [{:.9}, {:.9}, {:.9}] rpm",
        0.995 * t,
        t,
        0.995 * n,
        n,
        1.005 * n
    );
    let again = text.replace(
        "pinion_torque   = [94.1, 239.3, 372.6] N*m\n        pinion_speed    = [500, 1500, 3000] rpm",
        &points,
    );
    assert_ne!(again, text);
    let rpm = 30.0 / std::f64::consts::PI;
    // Every row of the sweep is in drive_records.csv (the report keeps the first 12): η at the pinion
    // 1 − P_V/(T_1 ω_1) from its pinion torque, speed and whole loss.
    let again = gearloss::check("again.gear", &again).unwrap();
    let files = gearloss::run_drive::drive_report_files(&again, again.drive.as_ref().unwrap()).unwrap().1.files;
    let csv = &files.iter().find(|(f, _)| f == "drive_records.csv").expect("drive_records.csv").1;
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| head.iter().position(|h| *h == n).unwrap_or_else(|| panic!("no column {n}"));
    let (law_at, f_at, t_at, n_at, loss_at) = (
        col("law_index"),
        col("formulation"),
        col("stage_pair_driving_torque_N_m"),
        col("input_speed_rpm"),
        col("total_W"),
    );
    let eta: Vec<(f64, f64, f64)> = lines
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|v| v[law_at] == "0" && v[f_at] == "external")
        .map(|v| {
            let x = |i: usize| v[i].parse::<f64>().unwrap();
            (x(t_at), x(n_at), 1.0 - x(loss_at) / (x(t_at) * x(n_at) / rpm))
        })
        .collect();
    assert_eq!(eta.len(), 6);
    let located = eta.iter().find(|(tq, w, _)| (tq - t).abs() < 1e-6 && (w - n).abs() < 1e-6 * n).unwrap().2;
    assert!((located - b.efficiency).abs() < 1e-9, "{located} vs {}", b.efficiency);
    for (tq, w, e) in &eta {
        assert!(*e <= located + 1e-12, "{tq} N·m, {w} rpm: {e} above the located {located}");
    }
}
