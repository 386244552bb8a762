//! REXS import: every example model imports, checks and runs; the imported stages carry the file's
//! own attribute values (read here independently of the importer); the XML and JSON exports of one
//! model give one scene; broken models are refused with a clear message and nothing written.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn rexs(name: &str) -> PathBuf {
    crate::root().join("tests/rexs").join(name)
}

const CYLINDRICAL: [&str; 3] = [
    "FVA-Industriegetriebe_2stufig_1-4.rexs",
    "FVA-Industriegetriebe_2stufig_1-4.rexsj",
    "FVA-Industriegetriebe_2_stufig_1-6.rexs",
];

fn import(name: &str) -> gearloss::rexs::Imported {
    gearloss::rexs::import_file(&rexs(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// A scene's lines outside comments, after its `scene "…"` line (which names the file).
fn code_lines(scene: &str) -> Vec<String> {
    scene
        .lines()
        .filter(|l| !l.trim_start().starts_with('#'))
        .skip(1)
        .map(|l| l.split('#').next().unwrap().to_string())
        .collect()
}

/// A gear as the file gives it, read with a plain XML or JSON parser.
#[derive(Debug, Default, Clone)]
struct FileGear {
    teeth: f64,
    module: f64,
    beta: f64,
    width: f64,
    u: f64,
    alpha: f64,
    x: f64,
}

/// Every `cylindrical_gear`'s attributes and its flank's pressure angle and profile shift, by the
/// file's own names (the flank found through the `flank` relation).
fn file_gears(path: &Path) -> Vec<FileGear> {
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

/// A model without a lubricant and without a lubricant temperature (the 1.4 model with both cut
/// out): the scene chooses an ISO VG 220 mineral oil at 70 °C, marks both `chosen:` on lines of their
/// own (a comment on the operating line swallowed its closing brace), checks and runs.
#[test]
fn a_model_without_oil_gets_a_chosen_one_and_runs() {
    let name = "constructs/no_lubricant_no_oil_temperature.rexs";
    let imported = import(name);
    let scene = &imported.scene;
    assert!(scene.contains("    lubricant = iso_vg(220, mineral)\n"), "{scene}");
    assert!(scene.contains("# chosen: the model gives no lubricant"), "{scene}");
    assert!(scene.contains("# chosen: the oil at 70 °C"), "{scene}");
    for line in scene.lines() {
        let comment = line.split_once('#').map_or("", |(_, c)| c);
        assert!(!comment.contains('}'), "a closing brace inside a comment: {line}");
    }
    assert!(imported.warnings.iter().any(|w| w.contains("ISO VG 220 mineral gear oil is chosen")));
    let checked = gearloss::check(name, scene).unwrap_or_else(|e| panic!("{e}"));
    assert!((checked.operating.oil_temperature.as_ref().unwrap().value.value - 343.15).abs() < 1e-9);
    gearloss::run_to_files(name, scene).unwrap_or_else(|e| panic!("{e}"));
}

/// Every `shaft_section` of the XML examples (start, length, outer and inner diameters, read here
/// with a plain XML parser) is a section of its shaft in the checked scene, and every shaft's
/// sections are exactly the file's.
#[test]
fn shaft_sections_become_the_shafts_sections() {
    for name in [CYLINDRICAL[0], CYLINDRICAL[2], "constructs/three_bearings_on_a_shaft.rexs"] {
        let text = std::fs::read_to_string(rexs(name)).unwrap();
        let doc = roxmltree::Document::parse(text.trim_start_matches('\u{feff}')).unwrap();
        let value = |c: roxmltree::Node, id: &str| -> f64 {
            c.children().find(|a| a.attribute("id") == Some(id)).unwrap().text().unwrap().trim().parse().unwrap()
        };
        let mut want: BTreeMap<u64, Vec<[f64; 4]>> = BTreeMap::new();
        for r in doc.descendants().filter(|n| n.has_tag_name("relation") && n.attribute("type") == Some("assembly")) {
            let role = |role: &str| r.children().find(|x| x.attribute("role") == Some(role));
            let (Some(shaft), Some(part)) = (role("assembly"), role("part")) else { continue };
            if part.attribute("hint") != Some("shaft_section") {
                continue;
            }
            let id = part.attribute("id").unwrap();
            let c = doc.descendants().find(|n| n.has_tag_name("component") && n.attribute("id") == Some(id)).unwrap();
            let from = value(c, "u_coordinate_on_shaft");
            let section =
                [from, from + value(c, "length"), value(c, "outer_diameter_begin"), value(c, "inner_diameter_begin")];
            want.entry(shaft.attribute("id").unwrap().parse().unwrap()).or_default().push(section.map(|x| x * 1e-3));
        }
        let scene = gearloss::check(name, &import(name).scene).unwrap_or_else(|e| panic!("{e}"));
        let layout = &scene.drive.as_ref().unwrap().layout;
        assert_eq!(want.len(), layout.shafts.len(), "{name}");
        for (id, mut sections) in want {
            sections.sort_by(|a, b| a[0].total_cmp(&b[0]));
            let shaft = layout.shafts.iter().find(|s| s.name == format!("shaft_{id}")).unwrap();
            let body = shaft.body.as_ref().unwrap_or_else(|| panic!("{name}: shaft {id} has no sections"));
            let got: Vec<[f64; 4]> = body.sections.iter().map(|x| [x.from, x.to, x.outer_diameter, x.bore]).collect();
            for (g, w) in got.iter().zip(&sections) {
                assert!(g.iter().zip(w).all(|(a, b)| (a - b).abs() < 1e-15), "{name} shaft {id}: {g:?} vs {w:?}");
            }
            assert_eq!(got.len(), sections.len());
        }
    }
}

/// A shaft on three bearing places (the 1.4 model with an NU 216 added between the lay shaft's
/// gears) imports with its sections and runs as an elastic beam: the report shows its bending.
#[test]
fn a_shaft_on_three_places_imports_and_runs() {
    let name = "constructs/three_bearings_on_a_shaft.rexs";
    let imported = import(name);
    let scene = gearloss::check(name, &imported.scene).unwrap_or_else(|e| panic!("{e}"));
    let lay = &scene.drive.as_ref().unwrap().layout.shafts.iter().find(|s| s.name == "shaft_13").unwrap();
    assert_eq!(lay.bearings.len(), 3);
    assert!(lay.body.is_some());
    let files = gearloss::run_to_files(name, &imported.scene).unwrap_or_else(|e| panic!("{e}"));
    let md = &files.files.iter().find(|(f, _)| f == "report.md").unwrap().1;
    assert!(md.contains("## Shaft sections (elastic beams)") && md.contains("| shaft_13 | 130.00 |"), "{md}");
    assert!(files.files.iter().any(|(f, _)| f == "shaft_moments.svg"));
}

/// Gears on their shafts through shaft–hub connections (a feather key and a spline: `side`
/// relations), a `rolling_bearing_with_detailed_geometry`, a needle bearing with its REXS type and
/// a thrust bearing added (the 1.4 model so changed): the same scene as the model itself, line for
/// line outside the comments; the needle bearing's stand-in and the thrust bearing are said.
#[test]
fn hub_connections_and_bearing_kinds_import() {
    let changed = import("constructs/hub_connections_and_bearing_kinds.rexs");
    assert_eq!(code_lines(&changed.scene), code_lines(&import(CYLINDRICAL[0]).scene));
    let said = changed.warnings.join("\n");
    assert!(said.contains("`radial_needle_roller_bearing` is modelled as a cylindrical_roller bearing"), "{said}");
    assert!(said.contains("component 903") && said.contains("a thrust bearing takes no radial load"), "{said}");
    assert!(!said.contains("feather_key_connection"), "a connection is read, not listed as unused: {said}");
}

/// The 1.4 model with every `addendum_modification_coefficient` cut out: each stage's Σx follows
/// from its centre distance (190 mm) and equals the file's own x₁ + x₂ (0.46283 and 0.30148, given
/// to 6 digits) to 1e-5, each x marked `chosen:` in the scene; the scene runs.
#[test]
fn profile_shifts_follow_from_the_centre_distance() {
    let name = "constructs/no_profile_shifts.rexs";
    let imported = import(name);
    let scene = gearloss::check(name, &imported.scene).unwrap_or_else(|e| panic!("{e}"));
    let file = file_gears(&rexs(CYLINDRICAL[0]));
    for pair in &scene.drive.as_ref().unwrap().pairs {
        let x = pair.pinion.profile_shift.value + pair.wheel.profile_shift.value;
        let z = |g: &gearloss::model::Gear| f64::from(g.teeth.value);
        let want: f64 =
            file.iter().filter(|g| g.teeth == z(&pair.pinion) || g.teeth == z(&pair.wheel)).map(|g| g.x).sum();
        assert!((x - want).abs() < 1e-5, "Σx {x} vs the file's {want}");
        assert!(pair.pinion.profile_shift.value > pair.wheel.profile_shift.value, "the pinion's share is the larger");
    }
    assert_eq!(imported.scene.matches("chosen: x from the centre distance").count(), 4);
    gearloss::run_to_files(name, &imported.scene).unwrap_or_else(|e| panic!("{e}"));
}

/// REXS 1.0 gives a gear's `u_coordinate_on_shaft` at its face start: the 1.4 model written as
/// 1.0 with every gear's u moved back by b/2 gives the same scene, with no warning that u and the
/// support vector disagree.
#[test]
fn rexs_1_0_reads_the_face_start() {
    let old = import("constructs/rexs_1_0_face_start.rexs");
    assert_eq!(code_lines(&old.scene), code_lines(&import(CYLINDRICAL[0]).scene));
    assert!(!old.warnings.iter().any(|w| w.contains("differs from its support vector")), "{:?}", old.warnings);
}

/// Designations outside the built-in table read by the ISO 15 / ISO 355 dimension plans (6305-2Z
/// 25/62 mm, 30212-A 60/110, NU 2216 E 80/140, the catalogues' sizes), a concept bearing without type
/// or designation a deep groove ball bearing, and C₀ estimated where a ball bearing needs it: each
/// chosen value marked in the scene and said; the scene runs.
#[test]
fn designations_follow_the_dimension_plans() {
    let name = "constructs/designations_by_dimension_plan.rexs";
    let imported = import(name);
    let line = |id: &str| imported.scene.lines().find(|l| l.contains(&format!("# REXS {id} `"))).unwrap().to_string();
    assert!(line("33").contains("type = deep_groove_ball, bore = 25 mm, outside = 62 mm"), "{}", line("33"));
    assert!(line("33").contains("chosen: C_0 estimated"));
    assert!(line("35").contains("type = tapered_roller, bore = 60 mm, outside = 110 mm"), "{}", line("35"));
    assert!(line("37").contains("type = cylindrical_roller, bore = 80 mm, outside = 140 mm"), "{}", line("37"));
    assert!(line("38").contains("type = deep_groove_ball") && line("38").contains("chosen: C_0 estimated"));
    assert!(imported.warnings.iter().any(|w| w.contains("names none: a deep groove ball bearing (chosen)")));
    gearloss::run_to_files(name, &imported.scene).unwrap_or_else(|e| panic!("{e}"));
}

/// Names with line breaks, quotes and scene text in them (a shaft, the lubricant, the exporting
/// application) stay inside their comment or string: the scene is the plain model's, line for line
/// outside comments and the lubricant's name.
#[test]
fn hostile_names_stay_in_their_comments() {
    let imported = import("constructs/hostile_names.rexs");
    let scene = &imported.scene;
    assert!(!scene.lines().any(|l| l.trim_start().starts_with("operating { input_torque = 1 N*m }")), "{scene}");
    assert!(scene.contains("lubricant \"Oil 'X'  }\" {"), "{scene}");
    let other = |s: &str| code_lines(s).into_iter().filter(|l| !l.contains("lubricant \"")).collect::<Vec<_>>();
    assert_eq!(other(scene), other(&import(CYLINDRICAL[0]).scene));
}

/// No shaft flagged `defines_speed`: the two shafts with torque loads are the ends, the one whose
/// speed the model gives the input (said), and the scene is the flagged model's.
#[test]
fn the_ends_follow_from_the_torque_loads() {
    let imported = import("constructs/no_flagged_input.rexs");
    assert_eq!(code_lines(&imported.scene), code_lines(&import(CYLINDRICAL[0]).scene));
    assert!(
        imported
            .warnings
            .iter()
            .any(|w| w.contains("shaft 12 is the input (the model gives its speed), shaft 14 the output")),
        "{:?}",
        imported.warnings
    );
}

/// The 1.4 model's XML and JSON exports give the same scene (its first line names the file).
#[test]
fn xml_and_json_of_one_model_give_one_scene() {
    let body = |n: &str| import(n).scene.lines().skip(1).collect::<Vec<_>>().join("\n");
    assert_eq!(body(CYLINDRICAL[0]), body(CYLINDRICAL[1]));
}

/// The planetary stage (XML, JSON, zipped) is refused naming the component, not half imported.
#[test]
fn a_planetary_stage_is_refused_by_name() {
    for name in [
        "FVA_Planetary_stage_-_Minus_gearing_1.1.rexs",
        "FVA_Planetary_stage_-_Minus_gearing_1.1.rexsj",
        "FVA_Planetary_stage_-_Minus_gearing_1.1.rexsz",
        "FVA_Planetary_stage_-_Minus_gearing_1.1_vers2.rexsj",
    ] {
        let e = gearloss::rexs::import_file(&rexs(&format!("planetary/{name}"))).expect_err(name);
        assert!(e.to_string().contains("planetary stages are not imported"), "{name}: {e}");
        assert!(e.component.as_deref().is_some_and(|c| c.contains("planet_carrier")), "{name}: {e}");
    }
}

/// Every broken model fails with its message (a snapshot each) and a hint.
#[test]
fn broken_models_are_refused() {
    let mut count = 0;
    insta::glob!("../rexs/err", "*.rexs*", |path| {
        count += 1;
        let e = gearloss::rexs::import_file(path).expect_err("a broken model must fail");
        assert!(!e.hint.is_empty());
        insta::assert_snapshot!(format!("{e}\nhelp: {}", e.hint));
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
    let broken = run(&rexs("err/unknown_version.rexs"));
    assert_eq!(broken.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&broken.stderr).contains("REXS version `3.1`"));
    assert!(!out.exists(), "nothing written for a broken model");
    let ok = run(&rexs(CYLINDRICAL[2]));
    assert!(ok.status.success(), "{}", String::from_utf8_lossy(&ok.stderr));
    assert!(std::fs::read_to_string(&out).unwrap().contains("REXS cylindrical_stage 10"));
    let again = run(&rexs(CYLINDRICAL[2]));
    assert_eq!(again.status.code(), Some(3), "never over an existing file");
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
    std::fs::remove_dir_all(&dir).unwrap();
}
