//! A scene run at several oil temperatures (`oil_temperature = [60, 90, 120] degC`): one full
//! report per temperature in its folder, and their comparison at the top.

use serde_json::Value;

/// The FZG C14 gearbox spec with a 4 × 4 map (the map is not what these tests look at) and the
/// oil temperature as given.
fn c14(oil_temperature: &str) -> String {
    std::fs::read_to_string(crate::root().join("specs/fzg_c14_gearbox.gear"))
        .unwrap()
        .replace("oil_temperature = 90 degC", &format!("oil_temperature = {oil_temperature}"))
        .replace("count 40", "count 4")
}

fn file<'a>(r: &'a gearloss::RenderedReport, name: &str) -> &'a str {
    &r.files.iter().find(|(f, _)| f == name).unwrap_or_else(|| panic!("no {name}")).1
}

/// Each temperature is a whole run: its folder holds the report a scene written at that one
/// temperature gives, byte for byte (the drive's report.json, drive_records.csv, report.md and its
/// pair's records.csv); the comparison's rows are the runs' rows in run order (its total the sum of
/// the run's loss parts).
#[test]
fn each_temperature_is_the_run_at_that_temperature() {
    let swept = gearloss::run_to_files("c14.gear", &c14("[60, 90, 120] degC")).unwrap();
    let single = gearloss::run_to_files("c14.gear", &c14("90 degC")).unwrap();
    for dir in ["oil_temperature_60degC", "oil_temperature_90degC", "oil_temperature_120degC"] {
        for f in ["report.md", "report.json", "drive_records.csv", "loss_map.csv", "loss_budget.svg"] {
            file(&swept, &format!("{dir}/{f}"));
        }
    }
    for f in ["report.json", "drive_records.csv", "report.md", "stages/pair/records.csv", "stages/pair/report.md"] {
        assert_eq!(file(&swept, &format!("oil_temperature_90degC/{f}")), file(&single, f), "{f}");
    }
    let top: Value = serde_json::from_str(file(&swept, "report.json")).unwrap();
    let one: Value = serde_json::from_str(file(&single, "report.json")).unwrap();
    let labels = top["rows"].as_array().unwrap();
    let rows = top["runs"][1]["rows"].as_array().unwrap();
    let points = one["points"].as_array().unwrap();
    assert_eq!((rows.len(), labels.len()), (points.len(), points.len()));
    for ((row, label), p) in rows.iter().zip(labels).zip(points) {
        let words = format!(
            "{} ({}, {})",
            p["label"].as_str().unwrap(),
            p["law"].as_str().unwrap(),
            p["formulation"].as_str().unwrap()
        );
        assert_eq!(label.as_str().unwrap(), words);
        // The comparison's total is the sum of the parts, the run's P_in − P_out: equal where the
        // books balance (1e-12 relative).
        let (sum, lost) = (row[0].as_f64().unwrap(), p["total_loss"].as_f64().unwrap());
        assert!((sum - lost).abs() <= 1e-12 * lost, "{label}: {sum} vs {lost}");
        assert_eq!(row[1], p["point"]["efficiency"]);
        assert_eq!(row[2], p["point"]["losses"]["meshes"]);
    }
    assert!(file(&swept, "report.md").contains("(oil_temperature_120degC/report.md)"));
    assert!(file(&swept, "efficiency_vs_oil_temperature.svg").starts_with("<svg"));
}

/// What the temperature changes, against closed forms: ν falls with the temperature (ASTM D341);
/// ISO/TR 14179-2's μ_mZ ∝ η_oil^-0.05 with everything else fixed, and the mesh loss of the
/// internal formulation is P_in μ H_V to first order in μ, so the meshes' loss at 60 °C over that at
/// 120 °C equals (η60/η120)^-0.05 to within the second-order term, below 0.2 % here (μ ≈ 0.05
/// changes by 9 %), at each of the comparison's rows of the internal formulation.
#[test]
fn the_temperature_moves_viscosity_and_friction_as_the_laws_say() {
    let swept = gearloss::run_to_files("c14.gear", &c14("[60, 90, 120] degC")).unwrap();
    let top: Value = serde_json::from_str(file(&swept, "report.json")).unwrap();
    let runs = top["runs"].as_array().unwrap();
    let nu: Vec<f64> = runs.iter().map(|r| r["lubricant"]["kinematic_viscosity"]["value"].as_f64().unwrap()).collect();
    let eta: Vec<f64> = runs.iter().map(|r| r["lubricant"]["dynamic_viscosity"]["value"].as_f64().unwrap()).collect();
    assert!(nu[0] > nu[1] && nu[1] > nu[2], "ν = {nu:?}");
    let kelvin: Vec<f64> = runs.iter().map(|r| r["kelvin"].as_f64().unwrap()).collect();
    assert_eq!(kelvin, [333.15, 363.15, 393.15]);
    let expected = (eta[0] / eta[2]).powf(-0.05);
    let mut checked = 0;
    for (j, label) in top["rows"].as_array().unwrap().iter().enumerate() {
        if !label.as_str().unwrap().ends_with("internal)") {
            continue;
        }
        let meshes = |run: usize| runs[run]["rows"][j][2].as_f64().unwrap();
        let ratio = meshes(0) / meshes(2);
        assert!((ratio / expected - 1.0).abs() < 2e-3, "{label}: {ratio} vs {expected}");
        checked += 1;
    }
    assert_eq!(checked, 6);
}

/// Every scene's comparison of oil temperatures is its drive's (`rows` beside `runs`); a folder
/// written before a pair's scene ran as its one-stage drive holds a pair's comparison (`runs`
/// alone), which `render` names and refuses with what to do rather than failing to parse it.
#[test]
fn render_names_a_pairs_comparison_it_no_longer_draws() {
    let dir = std::env::temp_dir().join(format!("gearloss-old-pair-sweep-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("report.json"), r#"{"title": "old", "runs": []}"#).unwrap();
    let e = gearloss::rerender::render_folder(&dir).unwrap_err();
    std::fs::remove_dir_all(&dir).unwrap();
    let f = e.failure().expect("a failure with a kind");
    assert_eq!(f.kind, gearloss::FailureKind::NotAReport);
    assert!(f.reason.contains("comparison of one pair's runs"), "{}", f.reason);
    assert!(f.hints.iter().any(|h| h.contains("run the scene again")), "{:?}", f.hints);
}

/// A pair's report.json of that time with its own efficiency map is named and refused the same way
/// (a pair's report today has no map: its scene's map is the one-stage drive's loss map).
#[test]
fn render_names_a_pairs_report_with_its_own_map() {
    let dir = std::env::temp_dir().join(format!("gearloss-old-pair-map-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("report.json"), r#"{"title": "old", "geometry": {}, "efficiency_map": {}}"#).unwrap();
    let e = gearloss::rerender::render_folder(&dir).unwrap_err();
    std::fs::remove_dir_all(&dir).unwrap();
    let f = e.failure().expect("a failure with a kind");
    assert_eq!(f.kind, gearloss::FailureKind::NotAReport);
    assert!(f.reason.contains("its own efficiency map"), "{}", f.reason);
}

/// `run` takes the scene lowering built, which always has its drive (one pair its one-stage
/// drive); a scene assembled without one is refused with the kind `NotLowered`, not a panic.
#[test]
fn run_refuses_a_scene_lowering_did_not_build() {
    let mut scene = gearloss::check("c14.gear", &c14("90 degC")).unwrap();
    assert!(scene.drive.is_some(), "lowering gives every scene its drive");
    scene.drive = None;
    let out = std::env::temp_dir().join(format!("gearloss-not-lowered-{}", std::process::id()));
    let e = gearloss::run_into("c14.gear", "", &scene, &out, None, &gearloss::Quiet).unwrap_err();
    assert_eq!(e.failure().expect("a failure").kind, gearloss::FailureKind::NotLowered);
    assert!(!out.exists() || std::fs::read_dir(&out).unwrap().next().is_none(), "nothing written");
    let _ = std::fs::remove_dir_all(&out);
}
