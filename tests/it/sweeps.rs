//! Sweeps at scale: the records stream in sweep order, the report stays bounded, shards merge into
//! a single run byte for byte, and concurrent runs into one folder all succeed.

use std::path::{Path, PathBuf};
use std::process::Command;

use gearloss::evaluate::{evenly, ALL_IN_DETAIL, MAP_VALUES, PLOTTED_VALUES};
use gearloss::{Plan, Shard};

fn gearloss() -> Command {
    Command::new(env!("CARGO_BIN_EXE_gearloss"))
}

fn temp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gearloss-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn run(args: &[&str], out: &Path) -> std::process::Output {
    let o = gearloss().args(args).arg("--out").arg(out).current_dir(crate::root()).output().unwrap();
    assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
    o
}

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into()).collect();
    v.sort();
    v
}

/// Every file under `dir` (its subfolders' too), by its path from `dir`, sorted.
fn files_under(dir: &Path) -> Vec<String> {
    let mut v = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let (path, name) = (e.as_ref().unwrap().path(), e.unwrap().file_name().to_string_lossy().into_owned());
        if path.is_dir() {
            v.extend(files_under(&path).into_iter().map(|f| format!("{name}/{f}")));
        } else {
            v.push(name);
        }
    }
    v.sort();
    v
}

/// Shards cover every point exactly once, in order, for any N (including N above the point count).
#[test]
fn shards_partition_the_points_in_order() {
    for n in [1, 7, 100, 1000] {
        for count in [1, 2, 3, 4, 7, 16, 2000] {
            let mut next = 0;
            for index in 1..=count {
                let r = Shard { index, count }.range(n);
                assert_eq!(r.start, next, "n {n}, shard {index}/{count}");
                next = r.end;
            }
            assert_eq!(next, n);
        }
    }
}

/// The report keeps a bounded set of rows whatever the sweep: at most 2 × 6 × PLOTTED_VALUES + MAP_VALUES²
/// + the detail points, independent of the number of points.
#[test]
fn the_kept_points_are_bounded() {
    let scene = crate::scene(&crate::root().join("tests/specs/ok/large_sweep.gear"));
    for (nt, ns) in [(10, 10), (1000, 1000), (3000, 10), (1, 100_000)] {
        let mut op = scene.operating.clone();
        op.pinion_torque.values = vec![op.pinion_torque.values[0]; nt];
        op.pinion_torque.written_values = vec![1.0; nt];
        op.pinion_speed.values = vec![op.pinion_speed.values[0]; ns];
        op.pinion_speed.written_values = vec![1.0; ns];
        let plan = Plan::new(&op, None, &[]);
        let kept = (0..nt * ns).filter(|k| plan.kept(*k)).count();
        let bound = 2 * 6 * PLOTTED_VALUES + MAP_VALUES * MAP_VALUES + plan.detail.len();
        if nt * ns <= ALL_IN_DETAIL {
            assert_eq!(kept, nt * ns);
        } else {
            assert!(kept <= bound, "{nt} × {ns}: {kept} kept, bound {bound}");
            assert!(plan.detail.len() <= 9, "{nt} × {ns}: {} detail points", plan.detail.len());
        }
    }
    assert_eq!(evenly(10, 3), vec![0, 4, 9]);
    assert_eq!(evenly(2, 6), vec![0, 1]);
}

/// A large sweep's report: 9 default detail points plus the two the scene names; every point in the
/// records, in sweep order, one row per point × law × formulation.
#[test]
fn a_large_sweep_reports_a_bounded_set_and_records_every_point() {
    let path = crate::root().join("tests/specs/ok/large_sweep.gear");
    let source = std::fs::read_to_string(&path).unwrap();
    let r = gearloss::run_to_files("large_sweep.gear", &source).unwrap();
    // The pair's files, in its stage's folder.
    let file = |n: &str| &r.files.iter().find(|(f, _)| *f == format!("stages/pair/{n}")).unwrap().1;
    let csv: Vec<&str> = file("records.csv").lines().collect();
    assert_eq!(csv.len(), 1 + 144 * 2);
    let points: Vec<usize> = csv[1..].iter().map(|l| l.split(',').next().unwrap().parse().unwrap()).collect();
    assert!(points.windows(2).all(|w| w[0] <= w[1]), "rows in sweep order");
    assert_eq!((points[0], points[points.len() - 1]), (1, 144));
    let jsonl: Vec<&str> = file("records.jsonl").lines().collect();
    assert_eq!(jsonl.len(), 144 * 2);
    let report: serde_json::Value = serde_json::from_str(file("report.json")).unwrap();
    assert_eq!(report["operating_points"].as_array().unwrap().len(), 9 + 2);
    assert_eq!(report["records"]["rows"], 288);
    assert!(r.files.iter().any(|(f, _)| f == "stages/pair/map_efficiency.svg"));
    // The extremes over the sweep are those of the records (exact over the evaluated points).
    let rows: Vec<serde_json::Value> = jsonl.iter().map(|l| serde_json::from_str(l).unwrap()).collect();
    let bk: Vec<&serde_json::Value> = rows.iter().filter(|x| x["law"] == "benedict_kelley").collect();
    let (min_at, min) = bk
        .iter()
        .map(|x| (x["point"].as_u64().unwrap(), x["mean_efficiency"].as_f64().unwrap()))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap();
    let e = report["sweep"]["efficiency"].as_array().unwrap().iter().find(|e| e["label"] == "benedict_kelley").unwrap();
    assert_eq!(e["min_efficiency"]["point"].as_u64().unwrap(), min_at);
    assert!((e["min_efficiency"]["value"].as_f64().unwrap() - min).abs() < 1e-9);
}

/// A shard whose record file was cut short or edited, whose manifest's scene was edited, or that
/// was run with other `--records` than the first is refused by `merge`, naming the folder and the
/// file; nothing is written.
#[test]
fn merge_refuses_shards_that_do_not_hold_what_they_wrote() {
    let out = temp("shard-digests");
    let scene = "tests/specs/ok/large_sweep.gear";
    let cut = |k: usize, records: &str| {
        let at = out.join(format!("set-{k}-{records}"));
        run(&["run", scene, "--shard", &format!("{k}/3"), "--records", records], &at);
        at.join(format!("large_sweep.shard-{k}-of-3"))
    };
    let merge = |shards: &[std::path::PathBuf]| {
        let o = gearloss().arg("merge").args(shards).arg("--out").arg(out.join("merged")).output().unwrap();
        assert!(!out.join("merged/large_sweep").exists(), "nothing written");
        (o.status.code(), String::from_utf8_lossy(&o.stderr).into_owned())
    };
    let shards: Vec<_> = (1..=3).map(|k| cut(k, "csv")).collect();
    // A record file with a row fewer.
    let csv = shards[1].join("stages/pair/records.csv");
    let text = std::fs::read_to_string(&csv).unwrap();
    std::fs::write(&csv, &text[..text[..text.len() - 1].rfind('\n').unwrap() + 1]).unwrap();
    let (code, err) = merge(&shards);
    assert_eq!(code, Some(1));
    assert!(err.contains("shard-2-of-3/stages/pair/records.csv is not the file its shard wrote"), "{err}");
    std::fs::write(&csv, &text).unwrap();
    // The scene in a manifest edited (μ 0.05 → 0.09 in every shard's, the shards still of one scene).
    for s in &shards {
        let m = s.join("shard.json");
        std::fs::write(&m, std::fs::read_to_string(&m).unwrap().replace("mu = 0.05", "mu = 0.09")).unwrap();
    }
    let (_, err) = merge(&shards);
    assert!(err.contains("shard-1-of-3/shard.json: the scene in the manifest was edited"), "{err}");
    // Shards run with other record files than the first.
    let mixed = vec![cut(1, "csv"), cut(2, "parquet"), cut(3, "csv")];
    let (_, err) = merge(&mixed);
    assert!(err.contains("shard-2-of-3 holds the record files") && err.contains("different `--records`"), "{err}");
    // A tally that is not the kind its scene's run writes (its stage pair's in the drive's place).
    let good = vec![cut(1, "csv"), cut(2, "csv"), cut(3, "csv")];
    let m = good[2].join("shard.json");
    let kept = std::fs::read_to_string(&m).unwrap();
    let mut manifest: serde_json::Value = serde_json::from_str(&kept).unwrap();
    manifest["tally"] = manifest["stage_pair"][1].clone();
    std::fs::write(&m, serde_json::to_string(&manifest).unwrap()).unwrap();
    let (code, err) = merge(&good);
    assert_eq!(code, Some(1));
    assert!(err.contains("shard-3-of-3/shard.json: the tally is not one this scene's run writes"), "{err}");
    std::fs::write(&m, kept).unwrap();
    // As they were written, they merge.
    let o = gearloss().arg("merge").args(&good).arg("--out").arg(out.join("merged")).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    std::fs::remove_dir_all(&out).unwrap();
}

/// `run --shard K/4` four times, then `merge`: the record files equal a single run's byte for byte,
/// and so do report.md and report.json.
#[test]
fn four_shards_merged_equal_one_run() {
    let out = temp("shards");
    let scene = "tests/specs/ok/large_sweep.gear";
    run(&["run", scene], &out.join("single"));
    let mut shards = Vec::new();
    for k in 1..=4 {
        let o = run(&["run", scene, "--shard", &format!("{k}/4")], &out.join("shards"));
        assert!(String::from_utf8_lossy(&o.stdout).contains(&format!("large_sweep.shard-{k}-of-4")));
        shards.push(out.join("shards").join(format!("large_sweep.shard-{k}-of-4")));
    }
    // Merge in any order: the manifests say which shard is which.
    shards.reverse();
    let o = gearloss().arg("merge").args(&shards).arg("--out").arg(out.join("merged")).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let single = out.join("single/large_sweep");
    let merged = out.join("merged/large_sweep");
    assert_eq!(files_under(&single), files_under(&merged));
    for f in files_under(&single) {
        assert!(std::fs::read(single.join(&f)).unwrap() == std::fs::read(merged.join(&f)).unwrap(), "{f} differs");
    }
    // A missing shard is an error that names it.
    let o = gearloss().arg("merge").args(&shards[1..]).arg("--out").arg(out.join("bad")).output().unwrap();
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("missing 4/4") && err.contains("help: run `gearloss run --shard 4/4`"), "{err}");
    std::fs::remove_dir_all(&out).unwrap();
}

/// Every file under `dir`, as paths relative to it, sorted.
fn tree(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let path = e.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        if path.is_dir() {
            out.extend(tree(&path).into_iter().map(|f| format!("{name}/{f}")));
        } else {
            out.push(name);
        }
    }
    out.sort();
    out
}

/// A pair on a drive cycle runs as its one-stage drive, its stage's pair analysed over the whole
/// sweep in `stages/pair/`. Sharded, each shard runs its points of that pair too (its records in
/// the shard's `stages/pair/`, its tally in the manifest), and the merge folds them as a pair's
/// shards: every file of the merged folder, the stage's among them, equals the single run's byte
/// for byte (CSV and Parquet records). A shard whose manifest lost the stage's tally, or whose stage
/// records were edited, is refused, named.
#[test]
fn a_one_pair_drives_stage_is_sharded_with_it() {
    let out = temp("stage-shards");
    let scene = "tests/specs/ok/cycle_pair_udds.gear";
    let records = ["--records", "csv,parquet"];
    run(&["run", scene, records[0], records[1]], &out.join("single"));
    let mut shards = Vec::new();
    for k in 1..=2 {
        run(&["run", scene, "--shard", &format!("{k}/2"), records[0], records[1]], &out.join("shards"));
        let shard = out.join("shards").join(format!("one_pair_on_the_udds.shard-{k}-of-2"));
        let pair_rows = std::fs::read_to_string(shard.join("stages/pair/records.csv")).unwrap().lines().count() - 1;
        assert!(pair_rows > 0, "shard {k} ran its points of the stage's pair");
        shards.push(shard);
    }
    let o = gearloss().arg("merge").args(&shards).arg("--out").arg(out.join("merged")).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let single = out.join("single/one_pair_on_the_udds");
    let merged = out.join("merged/one_pair_on_the_udds");
    let files = tree(&single);
    assert!(
        files.contains(&"stages/pair/records.parquet".to_string())
            && files.contains(&"stages/pair/report.md".to_string())
    );
    assert_eq!(files, tree(&merged));
    for f in &files {
        assert!(std::fs::read(single.join(f)).unwrap() == std::fs::read(merged.join(f)).unwrap(), "{f} differs");
    }
    // A shard whose manifest lost the stage's tally (written by hand) is refused, named.
    let manifest = shards[1].join("shard.json");
    let kept = std::fs::read_to_string(&manifest).unwrap();
    let mut m: serde_json::Value = serde_json::from_str(&kept).unwrap();
    m.as_object_mut().unwrap().remove("stage_pair").expect("the shard's manifest holds the stage's tally");
    std::fs::write(&manifest, serde_json::to_string(&m).unwrap()).unwrap();
    let o = gearloss().arg("merge").args(&shards).arg("--out").arg(out.join("bad")).output().unwrap();
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("shard-2-of-2 holds no records of the stage's pair in stages/pair"), "{err}");
    std::fs::write(&manifest, kept).unwrap();
    let edited = shards[1].join("stages/pair/records.csv");
    let text = std::fs::read_to_string(&edited).unwrap();
    std::fs::write(&edited, text.replacen(',', ";", 1)).unwrap();
    let o = gearloss().arg("merge").args(&shards).arg("--out").arg(out.join("bad")).output().unwrap();
    assert_eq!(o.status.code(), Some(1));
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("stages/pair/records.csv"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    std::fs::remove_dir_all(&out).unwrap();
}

/// Many runs writing the same folder at once all succeed and leave only the final folder.
#[test]
fn concurrent_runs_into_one_folder_all_succeed() {
    let out = temp("concurrent");
    let children: Vec<std::process::Child> = (0..24)
        .map(|_| {
            gearloss()
                .args(["run", "tests/specs/ok/minimal.gear", "--out"])
                .arg(&out)
                .current_dir(crate::root())
                .stdout(std::process::Stdio::null())
                .stderr(std::process::Stdio::piped())
                .spawn()
                .unwrap()
        })
        .collect();
    for c in children {
        let o = c.wait_with_output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    assert_eq!(names(&out), vec!["minimal".to_string()]);
    std::fs::remove_dir_all(&out).unwrap();
}

/// `--out` naming a file is "not a folder", exit 3, nothing written.
#[test]
fn out_naming_a_file_is_not_a_folder() {
    let dir = temp("out-file");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("a-file");
    std::fs::write(&file, "x").unwrap();
    let o = gearloss()
        .args(["run", "tests/specs/ok/minimal.gear", "--out"])
        .arg(&file)
        .current_dir(crate::root())
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(3));
    assert!(String::from_utf8_lossy(&o.stderr).contains("is not a folder"), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(names(&dir), vec!["a-file".to_string()]);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A run killed before it could clean up leaves `.slug.tmp-PID-N`; the next run into the same place
/// removes it (its process is gone).
#[test]
fn a_killed_runs_temporary_folder_is_removed_by_the_next_run() {
    let out = temp("stale");
    let stale = out.join(".minimal.tmp-999999999-0");
    std::fs::create_dir_all(&stale).unwrap();
    std::fs::write(stale.join("report.md"), "half").unwrap();
    run(&["run", "tests/specs/ok/minimal.gear"], &out);
    assert_eq!(names(&out), vec!["minimal".to_string()]);
    std::fs::remove_dir_all(&out).unwrap();
}

/// Plot axes of non-finite, huge or degenerate ranges never hang or fail: the panel is widened or
/// left empty.
#[test]
fn plots_of_extreme_values_finish() {
    use gearloss::render::svg::{figure, Panel};
    for x in [vec![1e308, 1.7e308], vec![0.0, f64::MIN_POSITIVE], vec![1.0, 1.0], vec![f64::NAN, f64::INFINITY]] {
        for y in [vec![1e308, -1e308], vec![2.0, 2.0], vec![f64::NAN, 1.0], vec![5e-324, 0.0]] {
            let started = std::time::Instant::now();
            let panel = Panel { x: x.clone(), series: vec![("s".into(), y.clone())], ..Default::default() };
            assert!(figure("t", &[panel]).is_ok(), "{x:?} {y:?}");
            assert!(started.elapsed().as_secs() < 5, "{x:?} {y:?}");
        }
    }
}

/// Issue 40: the headline's range of a large sweep is the sweep's, not the kept rows': on a 50 × 50
/// map (2 500 points, a few hundred rows kept for the report) each law's line says "over 2500
/// operating points" and its lowest and highest η̄ are the records' minimum and maximum over every
/// point, at their points' torque and speed (to the headline's three decimals).
#[test]
fn the_headline_range_covers_every_point() {
    let source = std::fs::read_to_string(crate::root().join("tests/specs/ok/large_sweep.gear"))
        .unwrap()
        .replace("count 12", "count 50")
        .replace("detail_points = [17, 100]", "");
    let r = gearloss::run_to_files("large_sweep.gear", &source).unwrap();
    let file = |n: &str| &r.files.iter().find(|(f, _)| *f == format!("stages/pair/{n}")).unwrap().1;
    let report: serde_json::Value = serde_json::from_str(file("report.json")).unwrap();
    let kept = report["efficiency"].as_array().unwrap().len();
    assert!(kept < 2 * 2500 * 2, "the report keeps a bounded set ({kept} rows)");
    let rows: Vec<serde_json::Value> =
        file("records.jsonl").lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    let md = file("report.md");
    for (law, words) in [("benedict_kelley", "Benedict–Kelley"), ("coulomb", "Coulomb")] {
        let of: Vec<&serde_json::Value> =
            rows.iter().filter(|x| x["law"] == law && x["formulation"] == "external").collect();
        assert_eq!(of.len(), 2500);
        let eta = |x: &&serde_json::Value| x["mean_efficiency"].as_f64().unwrap();
        let lo = of.iter().map(eta).fold(f64::INFINITY, f64::min);
        let hi = of.iter().map(eta).fold(f64::NEG_INFINITY, f64::max);
        let line = md.lines().find(|l| l.starts_with(&format!("- {words}"))).unwrap();
        assert!(line.ends_with("over 2500 operating points."), "{line}");
        let expected = format!("from {:.3} % (", 100.0 * lo);
        assert!(line.contains(&expected) && line.contains(&format!("to {:.3} % (", 100.0 * hi)), "{line}: {lo} {hi}");
    }
}
