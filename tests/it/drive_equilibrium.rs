//! `oil_temperature = equilibrium` in a drive: every row of the sweep at its own balance θ*, as a
//! scene of one pair reads its records.

/// The EV reducer spec with its oil at each row's balance, and as written (80 °C, its
/// `thermal_balance` analysis finding each row's θ*).
fn ev_scenes() -> (String, String) {
    let text = std::fs::read_to_string(crate::root().join("specs/ev_two_stage_reducer.gear")).unwrap();
    (text.replace("oil_temperature = 80 degC", "oil_temperature = equilibrium"), text)
}

/// The columns and rows of a CSV.
fn table(csv: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut lines = csv.lines();
    let head = lines.next().unwrap().split(',').map(str::to_string).collect();
    (head, lines.map(|l| l.split(',').map(str::to_string).collect()).collect())
}

/// Each row's whole loss (`total_W`, every mesh, gear, bearing and seal at θ*) equals what the
/// housing gives off at its θ* (1e-6 relative: the balance is located to 1e-10 K), and θ* is the
/// one the `thermal_balance` analysis finds for that row at a given oil temperature (1e-8 K); a row
/// without a balance says so and has no θ*.
#[test]
fn every_drive_row_is_at_its_own_balance() {
    let (at_balance, written) = ev_scenes();
    let scene = gearloss::check("eq.gear", &at_balance).unwrap_or_else(|e| panic!("{}", e.render(false)));
    let housing = scene.housing.clone().unwrap();
    let files = gearloss::run_to_files("eq.gear", &at_balance).unwrap().files;
    let file = |name: &str| files.iter().find(|(f, _)| f == name).unwrap().1.clone();
    let (head, rows) = table(&file("drive_records.csv"));
    let col = |name: &str| head.iter().position(|h| h == name).unwrap();
    let fixed = gearloss::check("ev.gear", &written).unwrap();
    let (fixed_report, _) = gearloss::run_drive::drive_report_files(&fixed, fixed.drive.as_ref().unwrap()).unwrap();
    assert_eq!(rows.len(), fixed_report.heat.thermal.len());
    let (mut balanced, mut without) = (0, 0);
    for (row, analysed) in rows.iter().zip(&fixed_report.heat.thermal) {
        let status = &row[col("thermal_status")];
        match analysed.oil_temperature.as_ref().map(|q| q.value.0) {
            Some(theta_k) => {
                let theta: f64 = row[col("oil_temperature_K")].parse().unwrap();
                assert!((theta - theta_k).abs() < 1e-8, "{theta} K vs {theta_k} K");
                let total: f64 = row[col("total_W")].parse().unwrap();
                let q = housing.dissipation(theta).total;
                assert!((total - q).abs() <= 1e-6 * q, "{total} W lost vs {q} W given off at {theta} K");
                assert!(status == "ok" || status == "above_limit", "{status}");
                balanced += 1;
            }
            None => {
                assert_eq!(row[col("oil_temperature_K")], "");
                assert_eq!(status, "no_equilibrium");
                without += 1;
            }
        }
    }
    assert!(balanced >= 4 && without >= 1, "{balanced} balanced, {without} without");
    // The report says where each point was read, and the oil table where the scene's oil is.
    let md = file("report.md");
    assert!(md.contains("oil temperature (the balance of point 1; each row at its own θ*)"), "{md}");
    assert_eq!(md.matches("At its own balance (`oil_temperature = equilibrium`): θ* = ").count(), balanced);
    assert!(md.contains("At `oil_temperature = equilibrium` the sump finds no balance"));
    // The oil each point rests on: read at its θ* (the first row's is the lubricant table's, at the
    // first balance; 1e-9), thinner where θ* is higher.
    let json: serde_json::Value = serde_json::from_str(&file("report.json")).unwrap();
    let oil_row = |what: &str| {
        json["oil"].as_array().unwrap().iter().find(|r| r[0].as_str().unwrap().starts_with(what)).unwrap()[1]
            .as_f64()
            .unwrap()
    };
    let points = json["points"].as_array().unwrap();
    let nu = |k: usize| points[k]["balance"]["kinematic_viscosity"].as_f64().unwrap();
    let theta = |k: usize| points[k]["balance"]["temperature"].as_f64().unwrap();
    let oil_nu = json["lubricant"]["kinematic_viscosity"]["value"].as_f64().unwrap();
    // (The lubricant's quantities are written to 10 significant digits.)
    assert!((nu(0) - oil_nu).abs() < 1e-9 * oil_nu, "{} vs the oil table's {oil_nu}", nu(0));
    assert!((theta(0) - 273.15 - oil_row("oil temperature")).abs() < 1e-9);
    assert!(theta(1) > theta(0) && nu(1) < nu(0), "{} K: {}, {} K: {}", theta(0), nu(0), theta(1), nu(1));
    let off = rows.iter().filter(|r| r[col("thermal_status")] != "ok").count();
    assert!(off >= 1);
    assert!(
        md.contains(&format!("at `oil_temperature = equilibrium` {off} of {} rows settle above", rows.len())),
        "{md}"
    );
}

/// A scene of one pair at `oil_temperature = equilibrium` (specs/fzg_c14_thermal.gear) reads every
/// row at its own balance, as a drive does: θ* is the balance its `thermal_balance` analysis finds
/// for that row at the written oil temperature (1e-8 K), its whole loss `total_W` is what the
/// housing gives off at θ* (1e-6 relative: θ* located to 1e-10 K), and its mesh and its whole loss
/// are the pair's own with the oil moved to θ* (`pair_alone`: its law's charged mesh loss and its
/// gearbox's budget on its own two shafts; 1e-12 relative).
#[test]
fn a_pair_at_equilibrium_reads_each_row_at_its_own_balance() {
    let text = std::fs::read_to_string(crate::root().join("specs/fzg_c14_thermal.gear")).unwrap();
    let at_balance = text.replace("oil_temperature = 90 degC", "oil_temperature = equilibrium");
    let pair = gearloss::check("eq.gear", &at_balance).unwrap_or_else(|e| panic!("{}", e.render(false)));
    let housing = pair.housing.as_ref().unwrap();
    let rows = crate::pair_alone::DriveRows::of(&pair);
    let written = gearloss::check("fixed.gear", &text).unwrap();
    let fixed = gearloss::evaluate::evaluate_drive(&written, written.drive.as_ref().unwrap());
    let op = &pair.operating;
    let mut compared = 0;
    for b in &fixed.balances {
        let Some(theta) = b.balance.temperature else { continue };
        let k = rows.find((b.torque_index, b.speed_index), b.law_index, b.formulation);
        let drive_theta = rows.value(k, "oil_temperature_K");
        assert!((drive_theta - theta).abs() < 1e-8, "{drive_theta} K vs the analysis's {theta} K");
        let total = rows.value(k, "total_W");
        let q = housing.dissipation(drive_theta).total;
        assert!((total - q).abs() <= 1e-6 * q, "{total} W lost vs {q} W given off at {drive_theta} K");
        let hot = crate::pair_alone::at_kelvin(&pair, drive_theta);
        let state = (op.pinion_torque.values[b.torque_index].value, op.pinion_speed.values[b.speed_index].value);
        let [mesh, beside] = crate::pair_alone::PairAlone::new(&hot).losses((b.law_index, b.formulation), state);
        let meshes = rows.value(k, "meshes_W");
        assert!((meshes - mesh).abs() <= 1e-12 * mesh, "mesh {meshes} W vs the pair's own {mesh} W");
        assert!((total - (mesh + beside)).abs() <= 1e-12 * total, "{total} W vs the pair's own {} W", mesh + beside);
        compared += 1;
    }
    assert!(compared >= 4, "{compared} balances compared");
}
