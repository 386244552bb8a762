//! The analyses of one pair on a drive's stages equal the pair alone: each analysed mesh's report
//! is the report of the same pair written as a scene of its own at the torque and speed the drive's
//! power walk gives it (every number to 1e-12 relative), and the mesh efficiency the walk charged
//! equals the pair alone's loss as a budget charges it (1e-12).

use gearloss::evaluate::{stage_pairs, StagePair};

const SPEC: &str = "specs/ev_reducer_stage_meshes.gear";

fn drive_scene(path: &str, edit: impl Fn(String) -> String) -> gearloss::Scene {
    let source = edit(std::fs::read_to_string(crate::root().join(path)).unwrap());
    gearloss::check(path, &source).unwrap_or_else(|e| panic!("{e}"))
}

/// Splits `text` into its numbers and the text between them (the skeleton).
fn numbers_and_skeleton(text: &str) -> (Vec<f64>, String) {
    let (mut numbers, mut skeleton) = (Vec::new(), String::new());
    let b = text.as_bytes();
    let mut i = 0;
    while i < b.len() {
        let starts = b[i].is_ascii_digit()
            || (b[i] == b'-' && i + 1 < b.len() && b[i + 1].is_ascii_digit())
            || (b[i] == b'.' && i + 1 < b.len() && b[i + 1].is_ascii_digit());
        let after_word = i > 0 && (b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_');
        if !starts || after_word {
            skeleton.push(text[i..].chars().next().unwrap());
            i += text[i..].chars().next().unwrap().len_utf8();
            continue;
        }
        let start = i;
        i += 1;
        while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.') {
            i += 1;
        }
        if i + 1 < b.len() && (b[i] == b'e' || b[i] == b'E') {
            let mut j = i + 1;
            if b[j] == b'-' || b[j] == b'+' {
                j += 1;
            }
            if j < b.len() && b[j].is_ascii_digit() {
                i = j;
                while i < b.len() && b[i].is_ascii_digit() {
                    i += 1;
                }
            }
        }
        numbers.push(text[start..i].parse::<f64>().unwrap());
        skeleton.push('#');
    }
    (numbers, skeleton)
}

/// The same text around numbers that agree to `tol` relative (of the larger magnitude).
fn assert_reports_agree(stage: &str, alone: &str, tol: f64) -> usize {
    let (a, sa) = numbers_and_skeleton(stage);
    let (b, sb) = numbers_and_skeleton(alone);
    assert_eq!(sa, sb, "the two reports differ in more than their numbers");
    assert_eq!(a.len(), b.len());
    for (k, (x, y)) in a.iter().zip(&b).enumerate() {
        let scale = x.abs().max(y.abs());
        assert!((x - y).abs() <= tol * scale, "number {k}: {x} vs {y}");
    }
    a.len()
}

/// The scene of one stage's pair written by hand as a user would: the stage's gears without their
/// places, the pinion's torque and speed printed exactly (shortest round-trip decimal).
fn pair_alone_source(p: &StagePair, title: &str, gears: &str, speed_unit_per_rad_s: f64) -> String {
    let spec = std::fs::read_to_string(crate::root().join(SPEC)).unwrap();
    let block = |name: &str| {
        let start = spec.find(name).unwrap();
        let end = start + spec[start..].find("\n    }\n").unwrap();
        spec[start..end + 6].to_string()
    };
    format!(
        "scene {title:?} {{\n    material steel {{ youngs_modulus = 210 GPa  poisson_ratio = 0.3 }}\n    lubricant \"SAE 70W-75W\" {{ nu_40 = 30.8 mm^2/s  nu_100 = 5.9 mm^2/s  density_15 = 845 kg/m^3  base = mineral\n                              pressure_viscosity = 1.8e-8 1/Pa }}\n{gears}\n    operating {{ pinion_torque = [{:?}] N*m  pinion_speed = [{:?}] rpm  oil_temperature = 80 degC }}\n    friction {{ iso_14179_2(x_l = 0.75)  benedict_kelley }}\n{}\n    analyses {{ efficiency(formulations = [external])  friction_along_loa  film  dynamics }}\n}}\n",
        p.at.unwrap().pinion_torque,
        p.at.unwrap().pinion_speed / speed_unit_per_rad_s,
        block("    dynamics {"),
    )
}

#[test]
fn each_stage_mesh_reports_what_its_pair_alone_reports() {
    let scene = drive_scene(SPEC, |s| s);
    let drive = scene.drive.as_ref().unwrap();
    let pairs = stage_pairs(&scene, drive);
    // Both stages at points 2 (recuperation: the wheels drive) and 4 (full load).
    assert_eq!(pairs.len(), 4);
    let rpm = std::f64::consts::PI / 30.0;
    let gear =
        |teeth: u32, rest: &str| format!("{{ teeth = {teeth}  material = steel  roughness_ra = 0.5 um  {rest} }}");
    let mut checked = 0;
    for p in &pairs {
        let stage = p.problem.as_ref().expect("load goes through every mesh at these points");
        let (head, small, big) = if p.stage == 0 {
            (
                "module = 1.5177 mm  pressure_angle = 20 deg  helix_angle = 23.4 deg  face_width = 35.44 mm",
                gear(23, "inertia = 5.7e-5 kg*m^2"),
                gear(68, "inertia = 4.4e-3 kg*m^2"),
            )
        } else {
            (
                "module = 2.5361 mm  pressure_angle = 20 deg  helix_angle = 18.4 deg  face_width = 49.80 mm",
                gear(20, "inertia = 3.1e-4 kg*m^2"),
                gear(78, "inertia = 7.3e-2 kg*m^2"),
            )
        };
        // In coast the stage's wheel drives: the pair alone has it in the pinion's place.
        let (pinion, wheel) = if p.members[0] == "pinion" { (&small, &big) } else { (&big, &small) };
        let gears = format!("    gears {{\n        {head}\n        pinion {pinion}\n        wheel {wheel}\n    }}");
        let source = pair_alone_source(p, &stage.title, &gears, rpm);
        let alone = gearloss::check("alone.gear", &source).unwrap_or_else(|e| panic!("{e}\n{source}"));
        let (a, b) = (gearloss::mesh_report(stage), gearloss::report_of(&alone));
        assert!(a.dynamics.is_some() && !a.efficiency.is_empty(), "the stage's report holds the analyses asked for");
        let numbers = assert_reports_agree(&format!("{a:?}"), &format!("{b:?}"), 1e-12);
        assert!(numbers > 1000, "only {numbers} numbers compared");
        checked += 1;
    }
    assert_eq!(checked, 4);
}

#[test]
fn the_walks_mesh_efficiency_is_the_pair_alones_charged_loss() {
    for (path, edit) in [
        (SPEC, None),
        ("specs/planetary_two_stage.gear", Some(("efficiency_map(", "friction_along_loa\n        efficiency_map("))),
        // `efficiency` alone with `detail_points` (given below): each stage's mesh at every named point.
        ("tests/specs/ok/drive_detail_points_in_full.gear", Some(("detail_points = [2]", ""))),
        // `load_sharing = stiffness` with tip relief, in drive and in coast.
        (STIFFNESS_SHARED, None),
        // An internal stage: in coast the ring drives, the pinion in the pinion's place.
        ("tests/specs/ok/drive_internal_stage.gear", None),
    ] {
        let scene = drive_scene(path, |s| match edit {
            Some((from, to)) => s.replacen(from, to, 1).replacen(
                "oil_temperature = 80 degC",
                "oil_temperature = 80 degC  detail_points = [1, 2, 3, 4, 5, 6]",
                1,
            ),
            None => s,
        });
        let drive = scene.drive.as_ref().unwrap();
        let (report, rendered) = gearloss::run_drive::drive_report_files(&scene, drive).unwrap();
        assert!(report.stage_pairs.len() >= 2, "{path}: {} meshes", report.stage_pairs.len());
        if path.contains("detail_points") {
            let points: Vec<usize> = report.stage_pairs.iter().map(|p| p.point.unwrap()).collect();
            assert_eq!(points, [1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6]);
        }
        for p in &report.stage_pairs {
            let charged = p.pair_charged_efficiency.expect("the scene asks for efficiency");
            assert!(
                (p.mesh_efficiency.unwrap() - charged).abs() <= 1e-12,
                "{path}, stage {} {:?} at point {:?}: walk {:?} vs alone {charged}",
                p.stage,
                p.mesh,
                p.point,
                p.mesh_efficiency
            );
            let folder = p.folder.as_ref().unwrap();
            assert!(rendered.files.iter().any(|(f, _)| *f == format!("{folder}/report.md")), "{folder}");
        }
        if path.contains("planetary") {
            assert!(report.stage_pairs.iter().any(|p| p.mesh.as_deref() == Some("planet–ring")));
        }
    }
}

#[test]
fn only_the_named_stages_are_analysed() {
    let scene = drive_scene(SPEC, |s| {
        s.replace("        dynamics\n    }", "        dynamics\n        stages = [second]\n    }")
    });
    let pairs = stage_pairs(&scene, scene.drive.as_ref().unwrap());
    assert_eq!(pairs.len(), 2);
    assert!(pairs.iter().all(|p| p.stage_name == "second"));
    assert_eq!(pairs.iter().map(|p| p.at.unwrap().point).collect::<Vec<_>>(), vec![1, 3]);
}

/// A one-stage drive whose pair shares its load by the teeth's stiffness (specs/fzg_c_tip_relief.gear's pair).
const STIFFNESS_SHARED: &str = "tests/specs/ok/drive_stage_stiffness_sharing.gear";

/// The walk's mesh efficiency of a stage shared by stiffness is the pair written alone's
/// (specs/fzg_c_tip_relief.gear, benedict_kelley, external) at 50, 135 and 300 N·m to 1e-12, and
/// not equal sharing's (they differ by more than 1e-5 at every point: the test can fail).
#[test]
fn a_stage_shared_by_stiffness_is_the_pair_alone() {
    let shared = drive_scene(STIFFNESS_SHARED, |s| s);
    let (report, _) = gearloss::run_drive::drive_report_files(&shared, shared.drive.as_ref().unwrap()).unwrap();
    let pair = gearloss::report_of(&drive_scene("specs/fzg_c_tip_relief.gear", |s| s));
    let mut checked = 0;
    let external = gearloss::efficiency::Formulation::External;
    for r in pair.efficiency.iter().filter(|r| r.label == "benedict_kelley" && r.formulation == external) {
        let torque = r.pinion_torque.value.0;
        let charged = 1.0 - r.power_loss.value.0 / (torque * r.pinion_speed.value.0);
        let stage = report.stage_pairs.iter().find(|p| (p.pinion_torque.unwrap() - torque).abs() < 1e-9).unwrap();
        assert!(
            (stage.mesh_efficiency.unwrap() - charged).abs() <= 1e-12,
            "{torque} N·m: {:?} vs {charged}",
            stage.mesh_efficiency
        );
        checked += 1;
    }
    assert_eq!(checked, 3);
    let equal = drive_scene(STIFFNESS_SHARED, |s| s.replace("load_sharing = stiffness", ""));
    let (equal, _) = gearloss::run_drive::drive_report_files(&equal, equal.drive.as_ref().unwrap()).unwrap();
    for (a, b) in report.stage_pairs.iter().zip(&equal.stage_pairs) {
        assert!(
            (a.mesh_efficiency.unwrap() - b.mesh_efficiency.unwrap()).abs() > 1e-5,
            "point {:?}: {:?} vs {:?}",
            a.point,
            a.mesh_efficiency,
            b.mesh_efficiency
        );
    }
}

/// A drive that lists no friction law and asks only for an analysis of one pair walks its meshes
/// passing their power whole: with no bearings, each point's mesh is at the input's torque (the
/// wheel's u × |T_in| in coast) and speed exactly (1e-12), and each is run as its pair alone.
#[test]
fn a_drive_without_laws_walks_its_meshes_whole() {
    let scene = drive_scene("tests/specs/ok/drive_pair_analyses_only.gear", |s| s);
    assert!(scene.friction.is_empty() && scene.analyses.efficiency.is_none());
    let (report, rendered) = gearloss::run_drive::drive_report_files(&scene, scene.drive.as_ref().unwrap()).unwrap();
    assert!(report.points.is_empty());
    let expected = [(202.5, 2.0 / 3.0), (50.0, 1.0), (135.0, 1.0), (300.0, 1.0)];
    assert_eq!(report.stage_pairs.len(), expected.len());
    for (p, (torque, speed)) in report.stage_pairs.iter().zip(expected) {
        assert!((p.pinion_torque.unwrap() - torque).abs() <= 1e-12 * torque, "{:?}: {:?}", p.point, p.pinion_torque);
        assert!(
            (p.pinion_speed_rpm.unwrap() - 1000.0 * speed).abs() <= 1e-9,
            "{:?}: {:?}",
            p.point,
            p.pinion_speed_rpm
        );
        assert_eq!(p.mesh_efficiency, Some(1.0));
        let folder = p.folder.as_ref().expect("run as its pair alone");
        let md = &rendered.files.iter().find(|(f, _)| *f == format!("{folder}/report.md")).unwrap().1;
        assert!(md.contains("ransmission error"), "{folder}");
    }
}

/// A drive that asks for nothing runs each stage's mesh as its pair alone at its first point: that
/// report, from its geometry on, is tests/specs/ok/minimal.gear's stage's (the same pair alone) byte
/// for byte.
#[test]
fn a_drive_that_asks_nothing_reports_its_meshes_as_pairs() {
    let scene = drive_scene("tests/specs/ok/drive_nothing_asked.gear", |s| s);
    assert!(scene.analyses.asks_nothing());
    let (report, rendered) = gearloss::run_drive::drive_report_files(&scene, scene.drive.as_ref().unwrap()).unwrap();
    assert_eq!(report.stage_pairs.len(), 1);
    let folder = report.stage_pairs[0].folder.as_ref().unwrap();
    let stage = &rendered.files.iter().find(|(f, _)| *f == format!("{folder}/report.md")).unwrap().1;
    let source = std::fs::read_to_string(crate::root().join("tests/specs/ok/minimal.gear")).unwrap();
    let alone = gearloss::run_to_files("minimal.gear", &source).unwrap();
    let alone = &alone.files.iter().find(|(f, _)| f == "stages/pair/report.md").unwrap().1;
    let from_geometry = |md: &str| md[md.find("## Geometry").unwrap()..].to_string();
    assert_eq!(from_geometry(stage), from_geometry(alone));
}
