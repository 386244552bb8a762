//! REXS import: every example model imports, checks and runs; the imported stages carry the file's
//! own attribute values (read here independently of the importer); the XML and JSON exports of one
//! model give one scene; broken models are refused with a clear message and nothing written.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

pub(crate) fn rexs(name: &str) -> PathBuf {
    crate::root().join("tests/rexs").join(name)
}

pub(crate) const CYLINDRICAL: [&str; 3] = [
    "FVA-Industriegetriebe_2stufig_1-4.rexs",
    "FVA-Industriegetriebe_2stufig_1-4.rexsj",
    "FVA-Industriegetriebe_2_stufig_1-6.rexs",
];

pub(crate) fn import(name: &str) -> gearloss::rexs::Imported {
    gearloss::rexs::import_file(&rexs(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// A scene's lines outside comments, after its `scene "…"` line (which names the file).
pub(crate) fn code_lines(scene: &str) -> Vec<String> {
    scene
        .lines()
        .filter(|l| !l.trim_start().starts_with('#'))
        .skip(1)
        .map(|l| l.split('#').next().unwrap().to_string())
        .collect()
}

/// A gear as the file gives it, read with a plain XML or JSON parser.
#[derive(Debug, Default, Clone)]
pub(crate) struct FileGear {
    pub(crate) teeth: f64,
    pub(crate) module: f64,
    pub(crate) beta: f64,
    pub(crate) width: f64,
    pub(crate) u: f64,
    pub(crate) alpha: f64,
    pub(crate) x: f64,
}

/// Every `cylindrical_gear`'s attributes and its flank's pressure angle and profile shift, by the
/// file's own names (the flank found through the `flank` relation).
pub(crate) fn file_gears(path: &Path) -> Vec<FileGear> {
    let text = std::fs::read_to_string(path).unwrap();
    let text = text.trim_start_matches('\u{feff}');
    let mut attrs: BTreeMap<u64, (String, BTreeMap<String, f64>)> = BTreeMap::new();
    let mut flanks: BTreeMap<u64, u64> = BTreeMap::new();
    if text.trim_start().starts_with('<') {
        let doc = roxmltree::Document::parse(text).unwrap();
        for c in doc
            .descendants()
            .filter(|n| n.has_tag_name("component") && n.parent().is_some_and(|p| p.has_tag_name("components")))
        {
            let id: u64 = c.attribute("id").unwrap().parse().unwrap();
            let values = c
                .children()
                .filter(|a| a.has_tag_name("attribute"))
                .filter_map(|a| Some((a.attribute("id")?.to_string(), a.text()?.trim().parse::<f64>().ok()?)))
                .collect();
            attrs.insert(id, (c.attribute("type").unwrap().to_string(), values));
        }
        for r in doc.descendants().filter(|n| n.has_tag_name("relation") && n.attribute("type") == Some("flank")) {
            let role = |name: &str| {
                r.children()
                    .find(|x| x.attribute("role") == Some(name))
                    .map(|x| x.attribute("id").unwrap().parse().unwrap())
            };
            flanks.insert(role("gear").unwrap(), role("left").unwrap());
        }
    } else {
        let doc: serde_json::Value = serde_json::from_str(text).unwrap();
        for c in doc["model"]["components"].as_array().unwrap() {
            let values = c["attributes"]
                .as_array()
                .unwrap()
                .iter()
                .filter_map(|a| {
                    Some((a["id"].as_str()?.to_string(), a.get("floating_point").or(a.get("integer"))?.as_f64()?))
                })
                .collect();
            attrs.insert(c["id"].as_u64().unwrap(), (c["type"].as_str().unwrap().to_string(), values));
        }
        for r in doc["model"]["relations"].as_array().unwrap().iter().filter(|r| r["type"] == "flank") {
            let role = |name: &str| {
                r["refs"].as_array().unwrap().iter().find(|x| x["role"] == name).unwrap()["id"].as_u64().unwrap()
            };
            flanks.insert(role("gear"), role("left"));
        }
    }
    attrs
        .iter()
        .filter(|(_, (kind, _))| kind == "cylindrical_gear")
        .map(|(id, (_, a))| {
            let flank = &attrs[&flanks[id]].1;
            FileGear {
                teeth: a["number_of_teeth"],
                module: a["normal_module"],
                beta: a["helix_angle_reference_diameter"],
                width: a["face_width"],
                u: a["u_coordinate_on_shaft"],
                alpha: flank["normal_pressure_angle"],
                x: flank["addendum_modification_coefficient"],
            }
        })
        .collect()
}

/// Each example imports, its scene checks and runs (report.md names both stages).
#[test]
fn every_cylindrical_example_imports_checks_and_runs() {
    for name in CYLINDRICAL {
        let imported = import(name);
        let files =
            gearloss::run_to_files(name, &imported.scene).unwrap_or_else(|e| panic!("{name}: {e}\n{}", imported.scene));
        let md = &files.files.iter().find(|(f, _)| f == "report.md").unwrap().1;
        assert!(md.contains("| 27/51 |") && md.contains("| 23/34 |"), "{name}: the geometry table names both stages");
        assert!(
            imported.warnings.iter().any(|w| w.contains("tip_diameter")),
            "{name}: the implausible tip diameter is said"
        );
    }
}

/// Every stage of the imported scene carries its two gears' values as the file writes them:
/// teeth, normal module, |β| and the pinion's hand from the sign, face width, α_n, x and the
/// gear's position on its shaft.
#[test]
fn the_stages_carry_the_files_values() {
    for name in CYLINDRICAL {
        let scene = gearloss::check(name, &import(name).scene).unwrap_or_else(|e| panic!("{e}"));
        let drive = scene.drive.as_ref().unwrap();
        let gears = file_gears(&rexs(name));
        assert_eq!(drive.pairs.len(), 2);
        for (k, pair) in drive.pairs.iter().enumerate() {
            let stage = &drive.layout.stages[k];
            for (m, gear) in [&pair.pinion, &pair.wheel].into_iter().enumerate() {
                let z = f64::from(gear.teeth.value);
                let file =
                    gears.iter().find(|g| g.teeth == z).unwrap_or_else(|| panic!("{name}: no gear with {z} teeth"));
                assert_eq!(pair.module.value.value, file.module * 1e-3, "{name}: module");
                assert_eq!(pair.face_width.value.value, file.width * 1e-3, "{name}: face width");
                assert!((pair.pressure_angle.value.value - file.alpha.to_radians()).abs() < 1e-15);
                let beta = pair.helix_angle.as_ref().unwrap().value.value;
                assert!((beta - file.beta.abs().to_radians()).abs() < 1e-15, "{name}: β");
                assert_eq!(gear.profile_shift.value, file.x);
                assert!((stage.places[m].at - file.u * 1e-3).abs() < 1e-15, "{name}: at");
                if m == 0 {
                    let hand = if file.beta > 0.0 { gearloss::drive::Hand::Right } else { gearloss::drive::Hand::Left };
                    assert_eq!(stage.hand, Some(hand), "{name}: the pinion's hand");
                }
            }
        }
    }
}

/// The 1.4 model's XML and JSON exports give the same scene (its first line names the file).
#[test]
fn xml_and_json_of_one_model_give_one_scene() {
    let body = |n: &str| import(n).scene.lines().skip(1).collect::<Vec<_>>().join("\n");
    assert_eq!(body(CYLINDRICAL[0]), body(CYLINDRICAL[1]));
}

/// Every broken model fails with its messages (a snapshot each: all of a model's errors at once,
/// `two_gears_without_teeth.rexs` two) and a hint each.
#[test]
fn broken_models_are_refused() {
    let mut count = 0;
    insta::glob!("../rexs/err", "*.rexs*", |path| {
        count += 1;
        let e = gearloss::rexs::import_file(path).expect_err("a broken model must fail");
        assert!(e.all().all(|e| !e.hint.is_empty()));
        let all: Vec<String> = e.all().map(|e| format!("{e}\nhelp: {}", e.hint)).collect();
        insta::assert_snapshot!(all.join("\n"));
    });
    assert!(count >= 7, "{count} broken models");
}

/// `gearloss import` writes the scene, never over a file, and writes nothing for a broken model.
#[test]
fn the_command_writes_the_scene_or_nothing() {
    let dir = std::env::temp_dir().join(format!("gearloss-import-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("unit.gear");
    let _ = std::fs::remove_file(&out);
    let bin = env!("CARGO_BIN_EXE_gearloss");
    let run =
        |model: &Path| std::process::Command::new(bin).arg("import").arg(model).arg("-o").arg(&out).output().unwrap();
    // A file that an old temporary name (`unit.gear.partial`) would have overwritten stays as it is.
    let neighbour = dir.join("unit.gear.partial");
    std::fs::write(&neighbour, "a model of the user's").unwrap();
    let broken = run(&rexs("err/unknown_version.rexs"));
    assert_eq!(broken.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&broken.stderr).contains("REXS version `3.1`"));
    assert!(!out.exists(), "nothing written for a broken model");
    let ok = run(&rexs(CYLINDRICAL[2]));
    assert!(ok.status.success(), "{}", String::from_utf8_lossy(&ok.stderr));
    assert!(std::fs::read_to_string(&out).unwrap().contains("REXS cylindrical_stage 10"));
    let again = run(&rexs(CYLINDRICAL[2]));
    assert_eq!(again.status.code(), Some(3), "never over an existing file");
    assert_eq!(std::fs::read_to_string(&neighbour).unwrap(), "a model of the user's");
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".import-"))
        .collect();
    assert!(left.is_empty(), "temporary files left: {left:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The 1.6 model's load spectrum: four cases (20, 30, 35, 15 % of the time; 543, 3456, 1234,
/// 789 rpm; 567, 345, 456, 789 N·m; 70 °C) as the duty cycle's steps in file order (1 h chosen,
/// the model gives no operating time), and the ratio 51/27 · 34/23 between input and output.
/// The same spectrum from `constructs/load_cases_as_power_and_custom_shares.rexs`: case 1's load
/// as power (kW) at its speed, case 2's share as `custom_load_duration_fraction`, case 4 with no
/// share (it gets what the others leave): the same steps to 1e-9.
#[test]
fn the_load_spectrum_becomes_the_duty_cycle() {
    for name in [CYLINDRICAL[2], "constructs/load_cases_as_power_and_custom_shares.rexs"] {
        load_spectrum(name);
    }
}

fn load_spectrum(name: &str) {
    let scene = gearloss::check("unit.gear", &import(name).scene).unwrap();
    let steps = &scene.duty_cycle.as_ref().unwrap().steps;
    let rpm = std::f64::consts::PI / 30.0;
    let want = [(0.20, 543.0, 567.0), (0.30, 3456.0, 345.0), (0.35, 1234.0, 456.0), (0.15, 789.0, 789.0)];
    assert_eq!(steps.len(), 4);
    for (s, (share, n, t)) in steps.iter().zip(want) {
        assert!((s.duration - share * 3600.0).abs() < 1e-9, "{name}: {}", s.duration);
        assert!((s.pinion_speed - n * rpm).abs() < 1e-9 * n && (s.pinion_torque - t).abs() < 1e-9 * t, "{name}");
    }
    assert!((scene.operating.oil_temperature.as_ref().unwrap().value.value - 343.15).abs() < 1e-9);
    let drive = scene.drive.as_ref().unwrap();
    let speeds = gearloss::drive::walk::shaft_speeds(
        &drive.layout,
        gearloss::drive::EndValue { at: gearloss::drive::ShaftEnd::Input, value: 1.0 },
    );
    let ratio = 1.0 / speeds[drive.layout.output];
    assert!((ratio - 51.0 / 27.0 * 34.0 / 23.0).abs() < 1e-12, "{ratio}");
}

/// Every file an import reads goes through the scene reader's guards: `/dev/zero` and a FIFO are
/// refused before anything is read (they read 2 GiB, and blocked forever), a `.rexsz` whose model
/// inflates past 64 MiB is refused after at most 64 MiB + 1 byte, never inflated whole.
#[test]
fn hostile_files_are_refused_before_they_are_read_whole() {
    let zero = gearloss::rexs::import_file(Path::new("/dev/zero")).expect_err("a device is no model");
    assert!(zero.to_string().contains("not a regular file"), "{zero}");
    let dir = std::env::temp_dir().join(format!("gearloss-rexs-hostile-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let fifo = dir.join("model.rexs");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    if made.is_ok_and(|s| s.success()) {
        let e = gearloss::rexs::import_file(&fifo).expect_err("a pipe is no model");
        assert!(e.to_string().contains("not a regular file"), "{e}");
    }
    // A zip bomb: 80 MiB of one character, deflated to a few hundred kB.
    let bomb = dir.join("bomb.rexsz");
    {
        use std::io::Write;
        let mut z = zip::ZipWriter::new(std::fs::File::create(&bomb).unwrap());
        let options = zip::write::SimpleFileOptions::default().compression_method(zip::CompressionMethod::Deflated);
        z.start_file("model.rexs", options).unwrap();
        let block = vec![b' '; 1 << 20];
        z.write_all(b"<model>").unwrap();
        for _ in 0..80 {
            z.write_all(&block).unwrap();
        }
        z.finish().unwrap();
    }
    assert!(std::fs::metadata(&bomb).unwrap().len() < 4 << 20);
    let e = gearloss::rexs::import_file(&bomb).expect_err("the bomb is refused");
    assert!(e.to_string().contains("inflates to more than 64 MiB"), "{e}");
    // XML nested 100 000 deep (it overflowed the stack): refused before the tree is built.
    let deep = dir.join("deep.rexs");
    std::fs::write(
        &deep,
        format!("<model version=\"1.4\">{}{}</model>", "<a>".repeat(100_000), "</a>".repeat(100_000)),
    )
    .unwrap();
    let e = gearloss::rexs::import_file(&deep).expect_err("nesting past 64 is refused");
    assert!(e.to_string().contains("nests elements more than 64 deep"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A `.rexsz` is read for its one model: a tool's manifest `.json` stored first is passed over
/// (it was refused), and two models in one archive are refused naming both (the first was taken
/// without a word).
#[test]
fn a_zip_gives_its_one_model_or_names_them_all() {
    let dir = std::env::temp_dir().join(format!("gearloss-rexs-zips-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let model = std::fs::read(rexs(CYLINDRICAL[1])).unwrap();
    let zipped = |name: &str, members: &[(&str, &[u8])]| {
        use std::io::Write;
        let path = dir.join(name);
        let mut z = zip::ZipWriter::new(std::fs::File::create(&path).unwrap());
        for (member, bytes) in members {
            z.start_file(*member, zip::write::SimpleFileOptions::default()).unwrap();
            z.write_all(bytes).unwrap();
        }
        z.finish().unwrap();
        path
    };
    let manifest = br#"{"manifest": {"files": ["gear_unit.json"], "tool": "export"}}"#;
    let first = zipped("manifest_first.rexsz", &[("manifest.json", manifest), ("gear_unit.json", &model)]);
    let from_zip = gearloss::rexs::import_file(&first).unwrap_or_else(|e| panic!("{e}"));
    let plain = import(CYLINDRICAL[1]);
    assert_eq!(code_lines(&from_zip.scene), code_lines(&plain.scene));
    let two = zipped("two_models.rexsz", &[("a.rexsj", &model), ("b.rexsj", &model)]);
    let e = gearloss::rexs::import_file(&two).expect_err("two models are refused");
    assert!(e.to_string().contains("holds 2 models: `a.rexsj`, `b.rexsj`"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}
