//! The thermal balance end to end: the duty cycle's books, the heat-balance curve, the rating on
//! the limit, the zero-speed and zero-torque steps, the step limit (the balance at
//! `oil_temperature = equilibrium`: drive_equilibrium.rs).

use gearloss::model::Formulation;

fn thermal_scene() -> gearloss::Scene {
    crate::scene(&crate::root().join("specs/fzg_c14_thermal.gear"))
}

/// The scene's report: its one-stage drive's, which holds the duty cycle and the heat balance.
fn thermal_report(scene: &gearloss::Scene) -> gearloss::report::drive::DriveReport {
    gearloss::run_drive::drive_report_files(scene, scene.drive.as_ref().unwrap()).expect("the spec runs").0
}

/// The report's duty cycle keeps its books: C (θ_end − θ_0) = E_lost − E_dissipated to 1e-9 of
/// E_lost, and the sum of the step energies is the cycle's. Its error estimate is below 1e-9 K.
#[test]
fn duty_cycle_energy_is_conserved() {
    let scene = thermal_scene();
    let report = thermal_report(&scene);
    let d = report.heat.duty_cycle.as_ref().expect("the scene asks for its duty cycle");
    let c = scene.housing.as_ref().unwrap().heat_capacity.unwrap();
    let end = d.steps.last().unwrap().oil_temperature_end.unwrap().si();
    let lost = d.energy_lost.unwrap().si();
    let given = d.energy_dissipated.unwrap().si();
    let start = d.ambient_temperature.si();
    assert!((c * (end - start) - (lost - given)).abs() < 1e-9 * lost, "{} vs {}", c * (end - start), lost - given);
    let steps: f64 = d.steps.iter().map(|s| s.energy_lost.unwrap().si()).sum();
    assert!((steps - lost).abs() < 1e-9 * lost);
    assert!(d.error_estimate.unwrap().si() < 1e-9, "{:?}", d.error_estimate);
    // Standing still, the first step stays at ambient and loses nothing.
    assert_eq!(d.steps[0].oil_temperature_end.unwrap().si(), start);
    assert_eq!(d.steps[0].energy_lost.unwrap().si(), 0.0);
}

/// The heat balance's curve (the plot's, at the first row): from ambient past the oil's limit in
/// ascending steps, P_Q at each temperature the housing's own dissipation there (exact),
/// P_V − P_Q positive below the located θ* and negative above it (θ* is located, not read off the
/// curve), and θ* the first row's own balance (its thermal record, 1e-12 K).
#[test]
fn heat_balance_curve_brackets_the_located_balance() {
    let scene = thermal_scene();
    let housing = scene.housing.clone().unwrap();
    let report = thermal_report(&scene);
    let c = report.heat.heat_balance.as_ref().expect("the scene asks for its heat balance");
    assert_eq!(c.temperature[0], housing.ambient);
    assert!(*c.temperature.last().unwrap() > housing.max_oil_temperature, "the curve runs past the limit");
    assert!(c.temperature.windows(2).all(|w| w[1] > w[0]));
    for (t, q) in c.temperature.iter().zip(&c.dissipation) {
        assert_eq!(*q, housing.dissipation(*t).total, "P_Q at {t} K");
    }
    let theta = c.oil_temperature.as_ref().expect("a balance").si();
    for ((t, p), q) in c.temperature.iter().zip(&c.power_loss).zip(&c.dissipation) {
        if *t < theta {
            assert!(p > q, "{t} K below θ* = {theta} K: P_V {p} ≤ P_Q {q}");
        } else if *t > theta {
            assert!(p < q, "{t} K above θ* = {theta} K: P_V {p} ≥ P_Q {q}");
        }
    }
    let first = report.heat.thermal.first().expect("the first row's balance");
    assert!((first.oil_temperature.as_ref().unwrap().si() - theta).abs() < 1e-12, "{theta} K");
}

/// At the rating torque the balance is the limit (to 1e-6 K), and at the 95 °C rating it is 95 °C:
/// the scene run at each row's rating torques and speed alone finds its sump there. A rating is the
/// speed's: the report gives every torque at one speed the same two ratings.
#[test]
fn rating_torque_puts_the_balance_on_the_limit() {
    let scene = thermal_scene();
    let housing = scene.housing.as_ref().unwrap();
    let text = std::fs::read_to_string(crate::root().join("specs/fzg_c14_thermal.gear")).unwrap();
    let eval = gearloss::evaluate::evaluate_drive(&scene, scene.drive.as_ref().unwrap());
    let mut rated = 0;
    for b in eval.balances.iter().filter(|b| b.law_index == 0 && b.formulation == Formulation::External) {
        let rpm = ["1500", "3000"][b.speed_index];
        for (rating, target) in [(b.rating, housing.max_oil_temperature), (b.rating_95, 368.15)] {
            let torque = rating.expect("a rating at each speed");
            let alone = text
                .replace("pinion_torque   = [94.1, 239.3] N*m", &format!("pinion_torque = {torque:?} N*m"))
                .replace("pinion_speed    = [1500, 3000] rpm", &format!("pinion_speed = {rpm} rpm"));
            let at = gearloss::check("rated.gear", &alone).unwrap();
            let row = &gearloss::evaluate::evaluate_drive(&at, at.drive.as_ref().unwrap()).balances[0];
            let theta = row.balance.temperature.unwrap();
            assert!((theta - target).abs() < 1e-6, "{torque} N·m at {rpm} rpm: θ* = {theta} K, not {target} K");
            rated += 1;
        }
    }
    assert_eq!(rated, 8);
    let report = thermal_report(&scene);
    let by_speed = |speed: f64| {
        let mut at: Vec<_> = report
            .heat
            .thermal
            .iter()
            .filter(|t| t.pinion_speed.si() == speed)
            .map(|t| {
                (t.thermal_rating.as_ref().map(|r| r.torque.si()), t.thermal_rating_95.as_ref().map(|r| r.torque.si()))
            })
            .collect();
        assert!(at.len() >= 2, "{speed}: {at:?}");
        at.dedup();
        at.len()
    };
    assert_eq!(by_speed(scene.operating.pinion_speed.values[1].value), 1);
}

/// Zero speed loses nothing; zero torque loses only the losses beside the mesh, the pair's own
/// (`pair_alone`: its gearbox's budget on its own two shafts at no load, 1e-12 relative): the duty
/// cycle's standing first step and its idling fifth (0 N·m at 2000 rpm) at the fixed oil temperature.
#[test]
fn standing_and_idling_steps() {
    let scene = thermal_scene();
    let report = thermal_report(&scene);
    let steps = &report.heat.duty_cycle.as_ref().expect("the scene's duty cycle").steps;
    let p_v = |k: usize| steps[k].power_loss_fixed.as_ref().expect("the loss at the fixed oil temperature").si();
    assert_eq!(p_v(0), 0.0);
    let idle = 2000.0 * std::f64::consts::PI / 30.0;
    let [mesh, beside] = crate::pair_alone::PairAlone::new(&scene).losses((0, Formulation::External), (0.0, idle));
    assert_eq!(mesh, 0.0);
    assert!(beside > 0.0 && (p_v(4) - beside).abs() <= 1e-12 * beside, "{} W vs {beside} W", p_v(4));
}

/// A duty cycle of more than 10 000 steps is refused at its step 10 001.
#[test]
fn too_many_duty_steps() {
    let path = crate::root().join("specs/fzg_c14_thermal.gear");
    let steps = "        step(duration = 1 s, pinion_torque = 10 N*m, pinion_speed = 100 rpm)\n".repeat(10_001);
    let text = std::fs::read_to_string(&path)
        .unwrap()
        .replace("    duty_cycle \"EV-like cycle\" {\n", &format!("    duty_cycle \"EV-like cycle\" {{\n{steps}"));
    let err = gearloss::check("steps.gear", &text).unwrap_err().render(false);
    assert!(err.contains("above the limit of 10000"), "{err}");
}

/// With `analyses { thermal_balance }` every row of a drive's records carries its balance, not only
/// the rows its report keeps: the spec at 10 torques × 2 speeds (20 rows, the report keeps 12). At
/// every row P_V at θ* (`loss_at_balance_W`) is what the housing gives off there
/// (`dissipation_W`, 1e-6 relative: θ* located to 1e-10 K) and the sum of its paths (1e-12); a
/// kept row's columns are the report's balance (θ* to 1e-12 K, the ratings to 1e-12 relative: the
/// same code); a row past the kept ones is the balance of the scene run at that row's torque and
/// speed alone (θ* to 1e-9 K), and its ratings are its speed's, every row at that speed alike.
#[test]
fn every_drive_row_carries_its_balance() {
    let text = std::fs::read_to_string(crate::root().join("specs/fzg_c14_thermal.gear")).unwrap();
    let swept = text.replace("pinion_torque   = [94.1, 239.3] N*m", "pinion_torque = 50..300 N*m count 10");
    let scene = gearloss::check("swept.gear", &swept).unwrap_or_else(|e| panic!("{}", e.render(false)));
    let rows = crate::pair_alone::DriveRows::of(&scene);
    assert_eq!(rows.len(), 20);
    let report = thermal_report(&scene);
    let housing = scene.housing.as_ref().unwrap();
    let close =
        |a: f64, b: f64, tol: f64, what: &str| assert!((a - b).abs() <= tol * b.abs().max(1.0), "{what}: {a} vs {b}");
    let mut ratings_at = std::collections::HashMap::new();
    for k in 0..rows.len() {
        let theta = rows.value(k, "oil_temperature_K");
        let p_v = rows.value(k, "loss_at_balance_W");
        close(p_v, housing.dissipation(theta).total, 1e-6, "P_V = P_Q");
        let paths: f64 = ["convection", "radiation", "foundation", "cooler"]
            .iter()
            .map(|p| rows.value(k, &format!("dissipation_{p}_W")))
            .sum();
        close(paths, rows.value(k, "dissipation_W"), 1e-12, "the paths");
        let rating = (rows.value(k, "thermal_rating_N_m"), rows.value(k, "thermal_rating_95_N_m"));
        let speed = rows.cell(k, "speed_index").to_string();
        assert_eq!(*ratings_at.entry(speed).or_insert(rating), rating, "row {k}: a speed's ratings");
        if let Some(kept) = report.heat.thermal.get(k) {
            close(theta, kept.oil_temperature.as_ref().unwrap().si(), 1e-12, "a kept row's θ*");
            close(rating.0, kept.thermal_rating.as_ref().unwrap().torque.si(), 1e-12, "a kept row's rating");
        }
    }
    assert!(report.heat.thermal.len() < rows.len());
    let k = 17;
    let (torque, rpm) = (rows.value(k, "stage_pair_driving_torque_N_m"), rows.value(k, "input_speed_rpm"));
    let alone = text
        .replace("pinion_torque   = [94.1, 239.3] N*m", &format!("pinion_torque = {torque:?} N*m"))
        .replace("pinion_speed    = [1500, 3000] rpm", &format!("pinion_speed = {rpm:?} rpm"));
    let at = gearloss::check("alone.gear", &alone).unwrap();
    let first = &thermal_report(&at).heat.thermal[0];
    close(
        rows.value(k, "oil_temperature_K"),
        first.oil_temperature.as_ref().unwrap().si(),
        1e-9 / 400.0,
        "row 18 alone",
    );
}
