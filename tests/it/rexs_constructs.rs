//! REXS import of the constructs real models use, one hand-made fixture each in
//! `tests/rexs/constructs/` (each described in `tests/rexs/SOURCES.md`): a model without oil,
//! shaft sections and three-place shafts, shaft–hub connections and bearing kinds, REXS 1.0's face
//! start, profile shifts from the centre distance, designations by the dimension plans, hostile
//! names, the ends from the torque loads.

use std::collections::BTreeMap;

use super::rexs::{code_lines, file_gears, import, rexs, CYLINDRICAL};

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

/// REXS 1.0 gives a gear's `u_coordinate_on_shaft` at its face start: the 1.4 model written as
/// 1.0 with every gear's u moved back by b/2 gives the same scene, with no warning that u and the
/// support vector disagree.
#[test]
fn rexs_1_0_reads_the_face_start() {
    let old = import("constructs/rexs_1_0_face_start.rexs");
    assert_eq!(code_lines(&old.scene), code_lines(&import(CYLINDRICAL[0]).scene));
    assert!(!old.warnings.iter().any(|w| w.contains("differs from its support vector")), "{:?}", old.warnings);
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

/// A gear on a sleeve splined to its shaft (the REXS 1.4 model with gear 17 moved onto shaft 905,
/// which sits on shaft 13 from u = 20 mm through an `involute_spline_connection`; XML and its JSON
/// twin): the sleeve is one with shaft 13, the gear at its place along u, so the scene's code is
/// the original model's, and the reader says so.
#[test]
fn a_gear_on_a_sleeve_sits_on_the_shaft_it_is_joined_to() {
    let original = code_lines(&import(CYLINDRICAL[0]).scene);
    for name in ["constructs/gear_on_a_sleeve.rexs", "constructs/gear_on_a_sleeve.rexsj"] {
        let imported = import(name);
        assert_eq!(code_lines(&imported.scene), original, "{name}");
        assert!(imported.warnings.iter().any(|w| w.contains("gear 17: on shaft 905, joined to shaft 13")), "{name}");
        gearloss::check(name, &imported.scene).unwrap_or_else(|e| panic!("{name}: {e}"));
    }
}
