//! What a new user meets first: the list commands, `new`, what `check` says would run and which
//! blocks nothing reads, and what `run` prints when it is done.

use std::process::Command;

fn gearloss() -> Command {
    Command::new(env!("CARGO_BIN_EXE_gearloss"))
}

fn stdout(args: &[&str]) -> String {
    let o = gearloss().args(args).current_dir(crate::root()).output().unwrap();
    assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8(o.stdout).unwrap()
}

/// `gearloss laws`, `oils` and `bearings` list what the language accepts, from the catalogues the
/// lowering checks names against (every law, base oil and bearing type appears).
#[test]
fn list_commands() {
    let laws = stdout(&["laws"]);
    for l in gearloss::friction::catalog::LAWS {
        assert!(laws.contains(&format!("\n{}  —", l.id.name())), "{} missing", l.id.name());
    }
    insta::assert_snapshot!("laws", laws);
    let oils = stdout(&["oils"]);
    for b in gearloss::tribology::lubricant::BaseOil::NAMES {
        assert!(oils.contains(&format!("\n{b} ")), "{b} missing");
    }
    insta::assert_snapshot!("oils", oils);
    let bearings = stdout(&["bearings"]);
    for b in gearloss::losses::BearingType::NAMES {
        assert!(bearings.contains(&format!("\n{b} ")), "{b} missing");
    }
    insta::assert_snapshot!("bearings", bearings);
}

/// `gearloss new` writes a template that checks and runs, and never overwrites a file (exit 3).
#[test]
fn new_writes_a_template_that_runs() {
    let dir = std::env::temp_dir().join(format!("gearloss-new-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("scene.gear");
    let o = gearloss().arg("new").arg(&file).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let scene = gearloss::check("scene.gear", &std::fs::read_to_string(&file).unwrap()).unwrap();
    assert!(scene.analyses.efficiency.is_some() && scene.gearbox.is_some());
    assert!(gearloss::scene::summary::unused_blocks(&scene).is_empty());
    let again = gearloss().arg("new").arg(&file).output().unwrap();
    assert_eq!(again.status.code(), Some(3));
    assert!(String::from_utf8_lossy(&again.stderr).contains("never overwrites"));
    let run = gearloss().arg("run").arg(&file).arg("--out").arg(dir.join("out")).output().unwrap();
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `gearloss new --kind drive|planetary|cycle` writes a drive template that checks with no unused
/// block (the cycle's trace written beside it, and kept where a file of its name is already
/// there), and `run` runs the drive and the planetary one.
#[test]
fn new_writes_drive_templates_that_check() {
    let dir = std::env::temp_dir().join(format!("gearloss-new-kinds-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for kind in ["drive", "planetary", "cycle"] {
        let file = dir.join(format!("{kind}.gear"));
        let o = gearloss().args(["new", "--kind", kind]).arg(&file).output().unwrap();
        assert!(o.status.success(), "{kind}: {}", String::from_utf8_lossy(&o.stderr));
        let text = std::fs::read_to_string(&file).unwrap();
        let scene = gearloss::check(&file.display().to_string(), &text)
            .unwrap_or_else(|e| panic!("{kind}: {}", e.render(false)));
        assert!(scene.drive.is_some(), "{kind}: not a drive");
        assert!(gearloss::scene::summary::unused_blocks(&scene).is_empty(), "{kind}");
        if kind != "cycle" {
            let run = gearloss().arg("run").arg(&file).arg("--out").arg(dir.join("out")).output().unwrap();
            assert!(run.status.success(), "{kind}: {}", String::from_utf8_lossy(&run.stderr));
        }
    }
    assert_eq!(std::fs::read(dir.join("wltc_3b.csv")).unwrap(), gearloss::listing::CYCLE_TRACE.1);
    let again = gearloss().args(["new", "--kind", "cycle"]).arg(dir.join("second.gear")).output().unwrap();
    assert!(again.status.success());
    assert!(String::from_utf8_lossy(&again.stdout).contains("kept"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `check` says what `run` would compute, and warns about a `dynamics` block no analysis reads
/// (the report says it too).
#[test]
fn check_says_what_would_run_and_what_is_unused() {
    let text = std::fs::read_to_string(crate::root().join("tests/specs/ok/dynamics_iso6336.gear")).unwrap();
    let unused =
        text.replace("analyses { dynamics }", "analyses { friction_along_loa }\n    friction { coulomb(mu = 0.05) }");
    let dir = std::env::temp_dir().join(format!("gearloss-check-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("unused.gear");
    std::fs::write(&file, &unused).unwrap();
    let out = stdout(&["check", file.to_str().unwrap()]);
    let out = out.replace(file.to_str().unwrap(), "unused.gear");
    insta::assert_snapshot!("check_unused_dynamics", out);
    assert!(out.contains("warning: the `dynamics` block is not used"), "{out}");
    let report = gearloss::report_of(&gearloss::check("unused.gear", &unused).unwrap());
    assert!(report.findings.iter().any(|f| f.message.starts_with("the `dynamics` block is not used")));
    let used = stdout(&["check", "tests/specs/ok/dynamics_iso6336.gear"]);
    assert!(!used.contains("warning:") && used.contains("dynamics: sdof model, 3 formulation(s)"), "{used}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `run` prints the answer: the headline (efficiency and budget per operating point, the dynamics
/// verdicts), the count of warnings with the first ones, and the folder.
#[test]
fn run_prints_the_headline_and_the_warnings() {
    let out = std::env::temp_dir().join(format!("gearloss-headline-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let o = gearloss()
        .args(["run", "specs/fzg_bearings.gear", "--out"])
        .arg(&out)
        .current_dir(crate::root())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8(o.stdout).unwrap().replace(out.to_str().unwrap(), "OUT");
    insta::assert_snapshot!("run_fzg_bearings", text);
    assert!(text.contains("stable at every operating point") && text.contains("wrote OUT/"), "{text}");
    std::fs::remove_dir_all(&out).unwrap();
}

/// An efficiency one rounding step above 1 is rounding, not a finding; 1e-12 above 1 is one
/// (tolerance: 4 ulps of 1, 8.9e-16).
#[test]
fn efficiency_within_ulps_of_one_is_no_finding() {
    use gearloss::efficiency::EfficiencyResult;
    use gearloss::evaluate::implausible_efficiency;
    use gearloss::numerics::Integral;
    let e = |max: f64| EfficiencyResult {
        formulation: gearloss::model::Formulation::Internal,
        mean: Integral { value: 0.99, error: 1e-12, evaluations: 1 },
        power_loss: 1.0,
        min: 0.98,
        max,
    };
    assert!(implausible_efficiency("xu", &e(1.0 + f64::EPSILON), 100.0).is_empty());
    assert!(implausible_efficiency("xu", &e(1.0), 100.0).is_empty());
    assert_eq!(implausible_efficiency("xu", &e(1.0 + 1e-12), 100.0).len(), 1);
    let us = gearloss::report_of(&crate::scene(&crate::root().join("specs/us_spur_inch.gear")));
    assert!(!us.findings.iter().any(|f| f.message.contains("efficiency outside")), "{:?}", us.findings);
}

/// Findings a reader can act on: one K_v-from-the-stiffness-step note for all the points it holds
/// at; a law note that holds at some points names them; an oil above its base oil's service
/// temperature is a warning (190 °C mineral), at 90 °C none.
#[test]
fn findings_are_grouped_and_name_their_points() {
    let dynamics = gearloss::report_of(&crate::scene(&crate::root().join("specs/fzg_dynamics.gear")));
    let kv: Vec<&str> = dynamics.findings.iter().map(|f| f.message.as_str()).filter(|m| m.contains("K_v ≈")).collect();
    assert_eq!(kv.len(), 1, "{kv:?}");
    assert!(kv[0].contains("239.3 N·m, 100 rpm (base 2.0000, external"), "{}", kv[0]);
    let composite = gearloss::report_of(&crate::scene(&crate::root().join("specs/composite_speed_sweep.gear")));
    let magnitudes: Vec<&str> =
        composite.findings.iter().map(|f| f.message.as_str()).filter(|m| m.contains("Model IV magnitude")).collect();
    assert!(!magnitudes.is_empty() && magnitudes.iter().all(|m| m.contains("(at operating point")), "{magnitudes:?}");
    let text = std::fs::read_to_string(crate::root().join("specs/fzg_c14_gearbox.gear")).unwrap();
    let hot = gearloss::report_of(&gearloss::check("hot.gear", &text.replace("90 degC", "190 degC")).unwrap());
    assert!(hot.findings.iter().any(|f| f.message.starts_with("oil temperature 190 °C is above the 100 °C")));
    let warm = gearloss::report_of(&gearloss::check("warm.gear", &text).unwrap());
    assert!(!warm.findings.iter().any(|f| f.message.starts_with("oil temperature")));
}

/// records.csv and records.jsonl carry the same columns (a stage's pair's, and the drive's
/// drive_records.csv and .jsonl): every key a JSON line writes is a CSV
/// column, and every CSV column that holds a value in some row is a key of the JSON lines (the CSV
/// keeps its fixed columns, empty where the scene has no such rows). The gearbox's inputs are
/// echoed in the report (md and json).
#[test]
fn records_agree_and_the_gearbox_is_echoed() {
    for spec in ["specs/fzg_c14_gearbox.gear", "specs/fzg_bearings.gear", "specs/fzg_c14_thermal.gear"] {
        let text = std::fs::read_to_string(crate::root().join(spec)).unwrap();
        let r = gearloss::run_to_files(spec, &text).unwrap();
        let file = |n: &str| &r.files.iter().find(|(f, _)| f == n).unwrap_or_else(|| panic!("{spec}: no {n}")).1;
        for (csv, jsonl) in
            [("stages/pair/records.csv", "stages/pair/records.jsonl"), ("drive_records.csv", "drive_records.jsonl")]
        {
            let csv = file(csv);
            let names: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
            let filled: std::collections::BTreeSet<&str> = csv
                .lines()
                .skip(1)
                .flat_map(|l| {
                    // No quoted commas in these scenes' rows except the parameters cell, which is last
                    // before the budget: split on commas outside quotes.
                    let mut cells = Vec::new();
                    let (mut quoted, mut start) = (false, 0);
                    for (i, c) in l.char_indices() {
                        match c {
                            '"' => quoted = !quoted,
                            ',' if !quoted => {
                                cells.push(&l[start..i]);
                                start = i + 1;
                            }
                            _ => {}
                        }
                    }
                    cells.push(&l[start..]);
                    cells.into_iter().zip(names.iter().copied()).filter(|(c, _)| !c.is_empty()).map(|(_, n)| n)
                })
                .collect();
            let header: std::collections::BTreeSet<&str> = names.iter().copied().collect();
            let mut keys = std::collections::BTreeSet::new();
            for line in file(jsonl).lines() {
                let v: serde_json::Value = serde_json::from_str(line).unwrap();
                keys.extend(v.as_object().unwrap().keys().cloned());
            }
            let keys: std::collections::BTreeSet<&str> = keys.iter().map(String::as_str).collect();
            assert!(keys.is_subset(&header), "{spec}: {:?} not in the CSV", keys.difference(&header));
            assert_eq!(filled, keys, "{spec}");
        }
    }
    // The run's report (the one-stage drive's) echoes the gearbox.
    let text = std::fs::read_to_string(crate::root().join("specs/fzg_c14_thermal.gear")).unwrap();
    let scene = gearloss::check("t.gear", &text).unwrap();
    let (drive, _) = gearloss::run_drive::drive_report_files(&scene, scene.drive.as_ref().unwrap()).unwrap();
    for key in ["gearbox.lubrication (dip).wheel_immersion", "pinion_shaft.seal 1.diameter", "gearbox.housing.area"] {
        assert!(drive.inputs.iter().any(|i| i.key == key), "{key} not echoed");
    }
    let immersion = drive.inputs.iter().find(|i| i.key.ends_with("wheel_immersion")).unwrap();
    assert_eq!((immersion.written.as_str(), immersion.si.si()), ("59.2 mm", 0.0592));
}

/// Plots that read: a sweep panel of more than eight curves labels its laws once each and colours
/// the curves by the other swept value with a colour bar (no per-curve legend entries); a panel of
/// eight or fewer keeps one entry per curve; legends are wide enough for their labels.
#[test]
fn many_curves_get_a_colour_scale() {
    let text = std::fs::read_to_string(crate::root().join("tests/specs/ok/large_sweep.gear")).unwrap();
    let r = gearloss::run_to_files("large_sweep.gear", &text).unwrap();
    let svg = &r.files.iter().find(|(f, _)| f == "stages/pair/sweep_speed.svg").unwrap().1;
    assert!(svg.contains("pinion torque (N·m)"), "colour bar label missing");
    assert!(!svg.contains("external @ 20.0 N·m"), "per-curve legend entries where a colour scale belongs");
    assert!(svg.contains("Benedict–Kelley (He–Cho–Singh eq 14) external"));
    let few = gearloss::run_to_files(
        "fzg_type_c.gear",
        &std::fs::read_to_string(crate::root().join("specs/fzg_type_c.gear")).unwrap(),
    )
    .unwrap();
    let svg = &few.files.iter().find(|(f, _)| f == "stages/pair/sweep_speed.svg").unwrap().1;
    assert!(svg.contains("Coulomb μ = 0.04 external @ 239.3 N·m"), "eight curves keep their labels");
}

/// A scene that sizes its pair in inches is shown in inch–pound units (report.md and the plots:
/// in, µin, lbf, ksi, ft/min, hp), report.json stays SI and says `unit_system: inch`; each shown
/// number is the SI value converted (to the cell's decimals). What decides is the pair's size:
/// the same pair in mm with its torques in lbf·in stays SI; a face width in inches alone is inch.
#[test]
fn inch_scenes_are_reported_in_inch_units() {
    use gearloss::report::number::UnitSystem;
    let path = crate::root().join("specs/us_spur_inch.gear");
    let r = gearloss::report_of(&crate::scene(&path));
    assert_eq!(r.unit_system, UnitSystem::Inch);
    let json = serde_json::to_value(&r).unwrap();
    assert_eq!(json["unit_system"], "inch");
    assert_eq!(json["geometry"]["face_width"]["unit"], "m");
    assert!((r.geometry.face_width.si() - 0.03175).abs() < 1e-15);
    let md = gearloss::render::markdown::render_markdown(&r);
    for cell in
        ["| face width | b | 1.2500 in |", "| diametral pitch | P = 1/m | 8.0000 1/in |", "| module | m | 0.12500 in |"]
    {
        assert!(md.contains(cell), "{cell} missing");
    }
    // The first contact table: every dimensional column (in, ft/min, lbf/in, ksi, µin) is the SI value converted.
    let rows: Vec<Vec<&str>> = md
        .lines()
        .skip_while(|l| !l.starts_with("| point | T1C in | s in |"))
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|l| l.trim_matches('|').split('|').map(str::trim).collect())
        .collect();
    let contact = &r.operating_points[0].contact;
    assert_eq!(rows.len(), contact.len());
    let (inch, psi) = (0.0254, 4.448_221_615_260_5 / (0.0254 * 0.0254));
    for (row, c) in rows.iter().zip(contact) {
        let close = |cell: &str, value: f64, decimals: i32| {
            let shown: f64 = cell.parse().unwrap();
            assert!((shown - value).abs() <= 0.5 * 10f64.powi(-decimals) + 1e-12, "{cell} vs {value}");
        };
        let lengths = [&c.distance_from_t1, &c.s, &c.radius_of_curvature_pinion, &c.radius_of_curvature_wheel];
        for (k, q) in lengths.into_iter().chain([&c.reduced_radius]).enumerate() {
            close(row[1 + k], q.si() / inch, 4);
        }
        let speeds = [&c.velocity_pinion, &c.velocity_wheel, &c.sliding_velocity, &c.sum_velocity];
        for (k, q) in speeds.into_iter().enumerate() {
            close(row[6 + k], q.si() * 60.0 / (12.0 * inch), 1);
        }
        close(row[13], c.load_per_width.si() * inch / 4.448_221_615_260_5, 1);
        close(row[14], c.hertz_pressure.si() / (1e3 * psi), 2);
        close(row[15], c.hertz_half_width.si() / (inch * 1e-6), 0);
    }
    assert!(md.contains("F_bn = 1277.01 lbf") && md.contains("v_t = 1183.4 ft/min"), "{md}");
    let si_cells =
        md.lines().filter(|l| !l.starts_with("| module |")).filter(|l| l.contains(" mm") || l.contains("N/mm"));
    assert_eq!(si_cells.count(), 0, "SI cells left in an inch report (the module is a millimetre measure)");
    // The same pair sized in millimetres (torques still in lbf·in) is reported in SI.
    let text = std::fs::read_to_string(&path).unwrap();
    let metric = text.replace("diametral_pitch = 8 1/in", "module = 3.175 mm").replace("1.25 in", "31.75 mm");
    let si = gearloss::report_of(&gearloss::check("metric.gear", &metric).unwrap());
    assert_eq!(si.unit_system, UnitSystem::Si);
    assert!(serde_json::to_value(&si).unwrap().get("unit_system").is_none());
    assert!(gearloss::render::markdown::render_markdown(&si).contains("| point | T1C mm | s mm |"));
    let face_only = text.replace("diametral_pitch = 8 1/in", "module = 3.175 mm");
    let face = gearloss::report_of(&gearloss::check("face.gear", &face_only).unwrap());
    assert_eq!(face.unit_system, UnitSystem::Inch);
    // A gearbox sized in inches: its budget, bearings, housing and balance in inch–pound units too
    // (the scene's report, its one-stage drive's).
    let thermal = std::fs::read_to_string(crate::root().join("specs/fzg_c14_thermal.gear")).unwrap();
    let run = gearloss::run_to_files("box.gear", &thermal.replace("14 mm", "0.5906 in")).unwrap();
    let md = &run.files.iter().find(|(f, _)| f == "report.md").unwrap().1;
    let cells = [
        "| shaft | place at (in) | type × count | locating | F_r per bearing (lbf) | F_a per bearing (lbf) | P_0 (hp) | P_1 (hp) |",
        "| oil limit | 248.0 °F |",
        "| θ* °F |",
        " total (hp) |",
    ];
    for cell in cells {
        assert!(md.contains(cell), "{cell} missing");
    }
    assert!(md.contains("| `gearbox.lubrication (dip).axis_height` | 3.93701 in | 0.1 m |"));
}

/// A given lubricant whose η and ν imply a density no oil has (ρ = η/ν outside 700–1200 kg/m³:
/// the two at different temperatures, here the grade's 220 cSt at 40 °C beside the sump's 20 cP)
/// is a warning naming the density, in the scene's units; the consistent spec scene has none.
#[test]
fn viscosities_that_imply_no_oil_are_a_warning() {
    let path = crate::root().join("specs/us_spur_inch.gear");
    let density = |r: &gearloss::report::Report| -> Vec<String> {
        r.findings.iter().filter(|f| f.message.contains("imply a density")).map(|f| f.message.clone()).collect()
    };
    assert!(density(&gearloss::report_of(&crate::scene(&path))).is_empty());
    let text = std::fs::read_to_string(&path).unwrap().replace("= 23 cSt", "= 220 cSt");
    let found = density(&gearloss::report_of(&gearloss::check("mixed.gear", &text).unwrap()));
    assert_eq!(found.len(), 1, "{found:?}");
    // ρ = 2.9e-6 reyn / 220 cSt = 90.88 kg/m³ = 5.67 lb/ft³.
    assert!(found[0].contains("ρ = η/ν = 5.67 lb/ft³, outside the 43.7–74.9 lb/ft³"), "{}", found[0]);
}
