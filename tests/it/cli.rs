//! The binary: exit codes, atomic report folders, diagnostics on stderr.

use std::path::Path;
use std::process::Command;

fn gearloss() -> Command {
    Command::new(env!("CARGO_BIN_EXE_gearloss"))
}

#[test]
fn run_writes_a_complete_report_folder() {
    let out = std::env::temp_dir().join(format!("gearloss-cli-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let status = gearloss()
        .args(["run", "specs/fzg_type_c.gear", "--out"])
        .arg(&out)
        .current_dir(crate::root())
        .output()
        .unwrap();
    assert!(status.status.success(), "{}", String::from_utf8_lossy(&status.stderr));
    for f in ["report.md", "report.json", "power_flow.svg", "stages/pair/report.md", "stages/pair/contact_state.svg"] {
        assert!(out.join("fzg_type_c").join(f).is_file(), "{f} missing");
    }
    // No temporary folder is left behind; running again replaces the folder.
    let again = gearloss()
        .args(["run", "specs/fzg_type_c.gear", "--out"])
        .arg(&out)
        .current_dir(crate::root())
        .output()
        .unwrap();
    assert!(again.status.success());
    let names: Vec<String> =
        std::fs::read_dir(&out).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into()).collect();
    assert_eq!(names, vec!["fzg_type_c".to_string()]);
    std::fs::remove_dir_all(&out).unwrap();
}

/// `render` on a report folder draws its files again from report.json (exit 0, the same bytes);
/// on a folder without a report it exits 3 and says which file it could not read.
#[test]
fn render_redraws_a_report_folder() {
    let out = std::env::temp_dir().join(format!("gearloss-cli-render-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let run = gearloss().args(["run", "specs/fzg_type_c.gear", "--out"]).arg(&out).current_dir(crate::root()).output();
    assert!(run.unwrap().status.success());
    let dir = out.join("fzg_type_c");
    let md = std::fs::read_to_string(dir.join("report.md")).unwrap();
    let pair_md = std::fs::read_to_string(dir.join("stages/pair/report.md")).unwrap();
    std::fs::remove_file(dir.join("report.md")).unwrap();
    std::fs::remove_file(dir.join("stages/pair/report.md")).unwrap();
    std::fs::remove_file(dir.join("stages/pair/contact_state.svg")).unwrap();
    let o = gearloss().arg("render").arg(&dir).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(std::fs::read_to_string(dir.join("report.md")).unwrap(), md);
    assert_eq!(std::fs::read_to_string(dir.join("stages/pair/report.md")).unwrap(), pair_md);
    assert!(dir.join("stages/pair/contact_state.svg").is_file());
    let o = gearloss().arg("render").arg(out.join("nothing")).output().unwrap();
    assert_eq!(o.status.code(), Some(3));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("cannot read") && err.contains("report.json"), "{err}");
    assert!(err.contains("help: give the folder `gearloss run` wrote"), "{err}");
    std::fs::remove_dir_all(&out).unwrap();
}

/// An edited report.json is read as the kind it is (by the field only that kind has) and the error
/// names that kind and its missing field: a drive's report without a point's `label` said a pair's
/// oil sweep missed `runs`.
#[test]
fn render_of_an_edited_report_names_its_own_kind() {
    let out = std::env::temp_dir().join(format!("gearloss-cli-render-kind-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    std::fs::create_dir_all(&out).unwrap();
    let report = crate::root().join("reports/two_stage_ev_reducer/report.json");
    let mut json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(report).unwrap()).unwrap();
    json["points"][0].as_object_mut().unwrap().remove("label");
    std::fs::write(out.join("report.json"), json.to_string()).unwrap();
    let o = gearloss().arg("render").arg(&out).output().unwrap();
    assert_eq!(o.status.code(), Some(3));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("is a drive's report") && err.contains("missing field `label`"), "{err}");
    std::fs::write(out.join("report.json"), "{\"rows\": []}").unwrap();
    let err = String::from_utf8_lossy(&gearloss().arg("render").arg(&out).output().unwrap().stderr).to_string();
    assert!(err.contains("none of its kinds"), "{err}");
    std::fs::remove_dir_all(&out).unwrap();
}

#[test]
fn bad_scene_exits_1_with_file_line_column() {
    let o =
        gearloss().args(["check", "tests/specs/err/wrong_dimension.gear"]).current_dir(crate::root()).output().unwrap();
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("tests/specs/err/wrong_dimension.gear:4:31"), "{err}");
    assert!(err.contains("expects a length"), "{err}");
}

#[test]
fn missing_file_exits_3_and_bad_arguments_exit_2() {
    let o = gearloss().args(["check", "no/such/scene.gear"]).output().unwrap();
    assert_eq!(o.status.code(), Some(3));
    let o = gearloss().args(["frobnicate"]).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
}

/// `check --emit lowered` prints the lowered form (JSON, SI) on stdout and nothing else; an
/// unknown form is a bad argument (exit 2).
#[test]
fn check_emits_the_lowered_form() {
    let out = gearloss()
        .args(["check", "tests/specs/ok/drive_one_stage.gear", "--emit", "lowered"])
        .current_dir(crate::root())
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["drive"]["layout"]["stages"][0]["name"], "only");
    assert_eq!(json["drive"]["layout"]["shafts"][0]["bearings"][0]["position"], -0.045);
    let bad = gearloss()
        .args(["check", "tests/specs/ok/drive_one_stage.gear", "--emit", "ast"])
        .current_dir(crate::root())
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
}

#[test]
fn check_and_units_succeed() {
    let o = gearloss().args(["check", "specs/us_spur_inch.gear"]).current_dir(crate::root()).output().unwrap();
    assert!(o.status.success());
    let o = gearloss().args(["units"]).output().unwrap();
    assert!(o.status.success());
    let table = String::from_utf8_lossy(&o.stdout);
    assert!(table.contains("reyn") && table.contains("lbf*s/in^2"), "{table}");
}

/// Files are capped before they are read: a scene above 16 MiB, a device, a pipe are refused with exit 3.
#[test]
fn oversized_or_special_scene_files_are_refused_before_reading() {
    let dir = std::env::temp_dir().join(format!("gearloss-big-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let big = dir.join("big.gear");
    let f = std::fs::File::create(&big).unwrap();
    f.set_len(gearloss::scene::source::MAX_SCENE_BYTES + 1).unwrap();
    for (path, reason) in [(big.as_path(), "larger than the limit"), (Path::new("/dev/zero"), "not a regular file")] {
        let o = gearloss().arg("check").arg(path).output().unwrap();
        assert_eq!(o.status.code(), Some(3), "{}", path.display());
        assert!(String::from_utf8_lossy(&o.stderr).contains(reason), "{}", String::from_utf8_lossy(&o.stderr));
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A closed stdout or stderr (`gearloss check x | head -1`) is not a panic.
#[test]
fn a_closed_pipe_is_not_a_panic() {
    let mut child = gearloss()
        .args(["check", "tests/specs/err/several_errors.gear"])
        .current_dir(crate::root())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stderr.take());
    drop(child.stdout.take());
    assert_eq!(child.wait().unwrap().code(), Some(1));
}

/// A scene with an oil temperature sweep: the binary writes each temperature's folder and the
/// comparison at the top in one report folder; `--shard` is refused with a message and exit 1.
#[test]
fn oil_temperature_sweep_writes_one_folder_per_temperature() {
    let out = std::env::temp_dir().join(format!("gearloss-cli-oil-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let o = gearloss()
        .args(["run", "specs/fzg_c14_oil_temperatures.gear", "--out"])
        .arg(&out)
        .current_dir(crate::root())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let dir = out.join("fzg_c14_gearbox_at_five_oil_temperatures");
    for f in ["report.md", "report.json", "efficiency_vs_oil_temperature.svg"] {
        assert!(dir.join(f).is_file(), "{f} missing");
    }
    for t in [40, 60, 80, 100, 120] {
        for f in ["report.md", "drive_records.csv", "loss_budget.svg", "stages/pair/records.csv"] {
            assert!(dir.join(format!("oil_temperature_{t}degC")).join(f).is_file(), "{t}: {f} missing");
        }
    }
    let o = gearloss()
        .args(["run", "specs/fzg_c14_oil_temperatures.gear", "--shard", "1/2", "--out"])
        .arg(&out)
        .current_dir(crate::root())
        .output()
        .unwrap();
    assert!(!o.status.success());
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("5 oil temperatures"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    std::fs::remove_dir_all(&out).unwrap();
}

/// A drive writes the record files `--records` names, as a pair does: drive_records.csv, .jsonl
/// and .parquet, any of them, without a warning; the default is CSV and JSON Lines.
#[test]
fn records_of_a_drive_are_written_as_asked() {
    let out = std::env::temp_dir().join(format!("gearloss-drive-parquet-{}", std::process::id()));
    let scene = crate::root().join("tests/specs/ok/drive_one_stage.gear");
    let run = |formats: &str| {
        let o = gearloss().arg("run").arg(&scene).arg("--out").arg(&out).args(["--records", formats]).output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let dir = std::fs::read_dir(&out).unwrap().next().unwrap().unwrap().path();
        let mut names: Vec<String> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|n| n.starts_with("drive_records"))
            .collect();
        names.sort();
        (names, String::from_utf8_lossy(&o.stderr).into_owned())
    };
    assert_eq!(run("parquet").0, vec!["drive_records.parquet"]);
    assert_eq!(run("csv,parquet").0, vec!["drive_records.csv", "drive_records.parquet"]);
    let (names, said) = run("jsonl");
    assert_eq!(names, vec!["drive_records.jsonl"]);
    assert!(!said.contains("warning"), "{said}");
    assert_eq!(run("csv,jsonl,parquet").0, vec!["drive_records.csv", "drive_records.jsonl", "drive_records.parquet"]);
    let _ = std::fs::remove_dir_all(&out);
    // At several oil temperatures each run's folder holds the formats asked for.
    let swept = out.with_extension("gear");
    let text = std::fs::read_to_string(&scene).unwrap();
    std::fs::write(&swept, text.replace("oil_temperature = 70 degC", "oil_temperature = [60, 80] degC")).unwrap();
    let o = gearloss().arg("run").arg(&swept).arg("--out").arg(&out).args(["--records", "parquet"]).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let dir = std::fs::read_dir(&out).unwrap().next().unwrap().unwrap().path();
    for run in ["oil_temperature_60degC", "oil_temperature_80degC"] {
        assert!(dir.join(run).join("drive_records.parquet").is_file(), "{run}");
        assert!(!dir.join(run).join("drive_records.csv").exists(), "{run}: only the formats asked for");
    }
    let _ = std::fs::remove_dir_all(&out);
    let _ = std::fs::remove_file(&swept);
}

/// Ctrl-C during a run: the process exits 130 and leaves nothing in the output folder: neither the
/// report folder nor its temporary one (`.<slug>.tmp-<pid>-<n>`).
#[test]
fn an_interrupted_run_leaves_no_folder_behind() {
    let dir = std::env::temp_dir().join(format!("gearloss-interrupt-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    // 250 000 points with records: minutes of work, interrupted as soon as its folder appears.
    let scene = std::fs::read_to_string(crate::root().join("tests/specs/ok/large_sweep.gear"))
        .unwrap()
        .replace("20..240 N*m count 12", "20..240 N*m count 500")
        .replace("200..6000 rpm count 12", "200..6000 rpm count 500");
    std::fs::write(dir.join("big.gear"), scene).unwrap();
    let out = dir.join("out");
    let mut child = gearloss()
        .args(["run", "big.gear", "--out", "out"])
        .current_dir(&dir)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let entries = || -> Vec<String> {
        std::fs::read_dir(&out)
            .map_or_else(|_| Vec::new(), |d| d.map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect())
    };
    let started = std::time::Instant::now();
    while !entries().iter().any(|e| e.starts_with(".large_sweep.tmp-")) {
        assert!(started.elapsed().as_secs() < 120, "no temporary folder appeared: {:?}", entries());
        assert!(child.try_wait().unwrap().is_none(), "the run ended before it could be interrupted");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    let kill = Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap();
    assert!(kill.success());
    let done = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&done.stderr);
    assert_eq!(done.status.code(), Some(130), "{stderr}");
    assert!(stderr.contains("interrupted: nothing was written (1 unfinished"), "{stderr}");
    assert_eq!(entries(), Vec::<String>::new());
    std::fs::remove_dir_all(&dir).unwrap();
}
