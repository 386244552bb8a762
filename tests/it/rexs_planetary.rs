//! REXS import of planetary stages: FVA's planetary example (XML, its zip, its JSON exports) and
//! the hand-made planetary constructs in `tests/rexs/constructs/` import into the planetary stage
//! kind, check and run; the values are the file's (read here with a plain XML parser).

use super::rexs::{import, rexs};

const FVA: &str = "planetary/FVA_Planetary_stage_-_Minus_gearing_1.1";

/// One component's numeric attributes by id, read with roxmltree (not the importer).
fn file_numbers(path: &str, id: &str) -> std::collections::BTreeMap<String, f64> {
    let text = std::fs::read_to_string(rexs(path)).unwrap();
    let doc = roxmltree::Document::parse(text.trim_start_matches('\u{feff}')).unwrap();
    let c = doc.descendants().find(|n| n.has_tag_name("component") && n.attribute("id") == Some(id)).unwrap();
    c.children()
        .filter(|a| a.has_tag_name("attribute"))
        .filter_map(|a| Some((a.attribute("id")?.to_string(), a.text()?.trim().parse::<f64>().ok()?)))
        .collect()
}

/// The XML model, its zip and its second JSON export give one scene whose planetary stage is the
/// file's: sun 17, planets 22 (three), ring 61 teeth, m_n 4 mm, b 50 mm, a 78 mm, the ring held
/// by its engaged couplings, the sun on its shaft at 25 mm (input), the carrier on `Steg 1` with
/// the planets' plane at 125 mm (output), two bearings per planet between the pin (Ø 43.2 mm)
/// and the planet's bore (Ø 57 mm). It runs: the ratio is 1 + 61/17 and the input power the
/// XML file's torque × speed.
#[test]
fn the_fva_planetary_stage_imports_checks_and_runs() {
    let xml = format!("{FVA}.rexs");
    let body = |n: &str| import(n).scene.lines().skip(1).collect::<Vec<_>>().join("\n");
    assert_eq!(body(&xml), body(&format!("{FVA}.rexsz")));
    let sun = file_numbers(&xml, "53");
    let planet = file_numbers(&xml, "247");
    let ring = file_numbers(&xml, "58");
    for name in [xml.clone(), format!("{FVA}_vers2.rexsj")] {
        let imported = import(&name);
        let scene = gearloss::check(&name, &imported.scene).unwrap_or_else(|e| panic!("{name}: {e}"));
        let drive = scene.drive.as_ref().unwrap();
        let stage = &drive.layout.stages[0];
        let p = stage.planetary().expect("a planetary stage");
        let teeth = [&sun, &planet, &ring].map(|g| g["number_of_teeth"] as u32);
        assert_eq!(p.teeth, teeth, "{name}");
        assert_eq!((p.planets, teeth), (3, [17, 22, 61]), "{name}");
        assert!((p.center_distance - 78e-3).abs() < 1e-12, "{name}");
        assert!((p.face_width - planet["face_width"] * 1e-3).abs() < 1e-12, "{name}");
        assert!((drive.pairs[0].geometry().unwrap().module - sun["normal_module"] * 1e-3).abs() < 1e-15);
        let names: Vec<&str> = p.members.iter().map(|m| m.name()).collect();
        assert_eq!(names, ["sun", "carrier"], "{name}: the ring is held");
        let shafts: Vec<&str> = drive.layout.shafts.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(shafts[stage.places[0].shaft], "shaft_34");
        assert_eq!(shafts[stage.places[1].shaft], "shaft_4");
        assert!((stage.places[0].at - 25e-3).abs() < 1e-12 && (stage.places[1].at - 125e-3).abs() < 1e-12);
        assert_eq!((shafts[drive.layout.input], shafts[drive.layout.output]), ("shaft_34", "shaft_4"));
        let b = p.planet_bearing.as_ref().expect("the planets' bearings");
        assert_eq!(b.count, 2, "{name}");
        assert!((b.mean_diameter - 0.5 * (43.2e-3 + 57e-3)).abs() < 1e-12, "{name}: {}", b.mean_diameter);
        assert!(imported.scene.contains("shaft = housing }  # REXS ring_gear 58"), "{name}");
        let files = gearloss::run_to_files(&name, &imported.scene).unwrap_or_else(|e| panic!("{name}: {e}"));
        let json: serde_json::Value =
            serde_json::from_str(&files.files.iter().find(|(f, _)| f == "report.json").unwrap().1).unwrap();
        let point = &json["points"][0]["point"];
        let (n_in, n_out) = (point["input_speed"].as_f64().unwrap(), point["output_speed"].as_f64().unwrap());
        assert!((n_in / n_out - (1.0 + 61.0 / 17.0)).abs() < 1e-12, "{name}: {}", n_in / n_out);
        if name == xml {
            let p_in = point["input_power"].as_f64().unwrap();
            let (torque, speed) = (file_numbers(&xml, "38"), file_numbers(&xml, "34"));
            let want = torque["torque_around_u_axis"] * speed["rotational_speed"] * std::f64::consts::PI / 30.0;
            assert!((p_in - want).abs() < 1e-9 * want, "{name}: {p_in}");
        }
    }
}

/// The first JSON export writes the ring's couplings as not engaged (`"boolean": false`, where the
/// XML and the second export give `[true]`): nothing holds a member, and the model is refused
/// naming both couplings, not half imported.
#[test]
fn a_stage_with_no_member_held_is_refused_naming_the_couplings() {
    let e = gearloss::rexs::import_file(&rexs(&format!("{FVA}.rexsj"))).expect_err("no member is held");
    let all: Vec<String> = e.all().map(|e| e.to_string()).collect();
    assert_eq!(all.len(), 1, "{all:?}");
    assert!(all[0].contains("none of its members is held by the casing"), "{all:?}");
    assert!(all[0].contains("component 65") && all[0].contains("component 66"), "{all:?}");
    assert!(e.component.as_deref().is_some_and(|c| c.contains("planetary_stage")), "{e}");
}

/// Speeds of every shaft for 1 rad/s at the input.
fn ratio(drive: &gearloss::model::SceneDrive) -> f64 {
    let speeds = gearloss::drive::walk::shaft_speeds(
        &drive.layout,
        gearloss::drive::EndValue { at: gearloss::drive::ShaftEnd::Input, value: 1.0 },
    );
    1.0 / speeds[drive.layout.output]
}

/// The hand-made planetary constructs (`tests/rexs/constructs/planetary_fixtures.py` writes each as
/// XML and JSON; both give one scene): a ring that is a part of the casing, a carrier on two
/// cheeks with a bearing each (joined on the first cheek's shaft at their places along u), a
/// stage's pinion on the far cheek (on the carrier's shaft, at 100 + 40 mm), needle roller
/// planet bearings (two per planet, the cylindrical roller bearing's factors), then a parallel
/// stage: the ratio −(1 + 72/24)·60/20 = −12 (the external mesh turns the sense); the same with
/// a 10° helix (the sun right hand: `hand = right`, the planets' bearings 12 mm apart on their
/// pins: `bearing_spacing`), and with its sun floating (its shaft on one bearing). And a star stage, the carrier held by a coupling, the ring on the
/// output shaft: −72/24.
#[test]
fn the_planetary_constructs_import_and_run() {
    for (stem, want_ratio, held) in [
        ("planetary_and_parallel", -12.0, "ring"),
        ("helical_planetary", -12.0, "ring"),
        ("floating_sun", -12.0, "ring"),
        ("carrier_held", -3.0, "carrier"),
    ] {
        let body = |n: &str| import(n).scene.lines().skip(1).collect::<Vec<_>>().join("\n");
        let (xml, json) = (format!("constructs/{stem}.rexs"), format!("constructs/{stem}.rexsj"));
        assert_eq!(body(&xml), body(&json), "{stem}: XML and JSON give one scene");
        let imported = import(&xml);
        let scene = gearloss::check(&xml, &imported.scene).unwrap_or_else(|e| panic!("{stem}: {e}"));
        let drive = scene.drive.as_ref().unwrap();
        let p = drive.layout.stages[0].planetary().unwrap();
        assert_eq!((p.teeth, p.planets), ([24, 24, 72], 3), "{stem}");
        let turning: Vec<&str> = p.members.iter().map(|m| m.name()).collect();
        assert!(!turning.contains(&held) && turning.len() == 2, "{stem}: {turning:?}");
        assert!((ratio(drive) - want_ratio).abs() < 1e-12 * want_ratio.abs(), "{stem}: {}", ratio(drive));
        let b = p.planet_bearing.as_ref().unwrap();
        match &p.helix {
            Some(h) => {
                assert!(stem == "helical_planetary" || stem == "floating_sun", "{stem}");
                assert!((h.helix_angle - 10f64.to_radians()).abs() < 1e-15 && h.sun_hand == 1.0, "{h:?}");
                assert!((p.planet_bearing_spacing.unwrap() - 12e-3).abs() < 1e-15);
                assert!(imported.scene.contains("helix_angle = 10 deg  hand = right"));
            }
            None => assert!(stem != "helical_planetary" && stem != "floating_sun"),
        }
        let sun_places = drive.layout.shafts.iter().find(|s| s.name == "shaft_10").unwrap().bearings.len();
        assert_eq!(sun_places, if stem == "floating_sun" { 1 } else { 2 }, "{stem}");
        if stem != "carrier_held" {
            assert_eq!(b.count, 2);
            assert!((b.mean_diameter - 23e-3).abs() < 1e-12);
            let carrier = drive.layout.shafts.iter().find(|s| s.name == "shaft_31").unwrap();
            let at: Vec<f64> = carrier.bearings.iter().map(|b| b.position.unwrap()).collect();
            assert_eq!(at.len(), 2);
            assert!((at[0] - 10e-3).abs() < 1e-12 && (at[1] - 100e-3).abs() < 1e-12, "{at:?}");
            let lay = &drive.layout.stages[1];
            assert_eq!(drive.layout.shafts[lay.places[0].shaft].name, "shaft_31");
            assert!((lay.places[0].at - 140e-3).abs() < 1e-12);
            assert!(imported.warnings.iter().any(|w| w.contains("the carrier's other cheek")));
            assert!(imported.scene.contains("# The ring held by the casing itself"));
        } else {
            assert_eq!(b.count, 1);
            assert!(imported.scene.contains("carrier { shaft = housing }"), "{}", imported.scene);
        }
        gearloss::run_to_files(&xml, &imported.scene).unwrap_or_else(|e| panic!("{stem}: {e}"));
    }
}
