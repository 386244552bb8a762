//! records.parquet against records.csv: the same cells, every float to the bit; shards merged into
//! the single run's rows; a broken shard file refused by name; the format list read as documented.

use std::path::{Path, PathBuf};
use std::process::Command;

use gearloss::evaluate::read_parquet_records;
use gearloss::evaluate::Cell;

fn gearloss() -> Command {
    Command::new(env!("CARGO_BIN_EXE_gearloss"))
}

fn temp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gearloss-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn run(args: &[&str], out: &Path) {
    let o = gearloss().args(args).arg("--out").arg(out).current_dir(crate::root()).output().unwrap();
    assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
}

type Table = (Vec<(String, gearloss::evaluate::ColumnType)>, Vec<Vec<Cell>>);

fn parquet(dir: &Path) -> Table {
    parquet_file(&dir.join("records.parquet"))
}

fn parquet_file(path: &Path) -> Table {
    read_parquet_records(std::fs::File::open(path).unwrap(), &path.display().to_string()).unwrap()
}

/// A CSV line's cells (RFC 4180 quotes).
fn split_csv(line: &str) -> Vec<String> {
    let (mut out, mut cell, mut quoted, mut chars) = (Vec::new(), String::new(), false, line.chars().peekable());
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                cell.push('"');
                chars.next();
            }
            ('"', _) => quoted = !quoted,
            (',', false) => out.push(std::mem::take(&mut cell)),
            _ => cell.push(c),
        }
    }
    out.push(cell);
    out
}

/// Every scene that writes records, its Parquet and CSV: the same columns (the CSV's, then the
/// parameters' own), and on every row the same cells: integers equal, floats equal to the bit
/// (the CSV's shortest text parsed), text equal, an empty CSV cell a null; each parameter column
/// holds the value the `parameters` cell writes.
#[test]
fn parquet_holds_the_csvs_values_to_the_bit() {
    for scene in
        ["specs/fzg_type_c.gear", "specs/helical_gearbox.gear", "specs/fzg_c14_thermal.gear", "specs/fzg_dynamics.gear"]
    {
        let out = temp(&format!("pq-{}", scene.replace('/', "_")));
        run(&["run", scene, "--records", "parquet,csv"], &out);
        // The pair's records, in its stage's folder (the drive's are checked below).
        let dir = std::fs::read_dir(&out).unwrap().next().unwrap().unwrap().path().join("stages/pair");
        assert!(!dir.join("records.jsonl").exists(), "{scene}: only the formats asked for");
        assert_parquet_is_the_csv(&dir, scene);
        let _ = std::fs::remove_dir_all(&out);
    }
}

/// `dir`'s records.parquet against its records.csv: the same columns (the CSV's, then the
/// parameters' own), and on every row the same cells: integers equal, floats equal to the bit (the
/// CSV's shortest text parsed), text equal, an empty CSV cell a null; each parameter column holds
/// the value the `parameters` cell writes.
fn assert_parquet_is_the_csv(dir: &Path, scene: &str) {
    let csv = std::fs::read_to_string(dir.join("records.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<String> = split_csv(lines.next().unwrap());
    let (columns, rows) = parquet(dir);
    let names: Vec<&str> = columns.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(&names[..header.len()], header.iter().map(String::as_str).collect::<Vec<_>>().as_slice(), "{scene}");
    let lines: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), lines.len(), "{scene}: rows");
    assert!(!rows.is_empty());
    for (row, line) in rows.iter().zip(&lines) {
        let cells = split_csv(line);
        for (k, text) in cells.iter().enumerate() {
            match &row[k] {
                Cell::Int(i) => assert_eq!(i.to_string(), *text, "{scene}: {}", header[k]),
                Cell::Real(x) => {
                    assert_eq!(x.to_bits(), text.parse::<f64>().unwrap().to_bits(), "{scene}: {}", header[k])
                }
                Cell::Text(t) => assert_eq!(t, text, "{scene}: {}", header[k]),
                Cell::Empty => assert!(text.is_empty(), "{scene}: {} is null in Parquet, {text} in CSV", header[k]),
            }
        }
        for (k, (name, _)) in columns.iter().enumerate().skip(header.len()) {
            let parameters = &cells[header.iter().position(|h| h == "parameters").unwrap()];
            if let Cell::Real(x) = row[k] {
                let short = name.trim_start_matches("param_");
                assert!(
                    parameters.split("; ").any(|p| p.split('=').nth(1).is_some_and(|v| v
                        .split(' ')
                        .next()
                        .unwrap()
                        .parse::<f64>()
                        .unwrap()
                        == x)
                        && short.starts_with(p.split('=').next().unwrap())),
                    "{scene}: {name} = {x} not in `{parameters}`"
                );
            }
        }
    }
}

/// A drive's stage meshes analysed as pairs write their record files in the formats the run asks
/// for, each streamed into its folder: the EV reducer's stage meshes (one point each) and a pair
/// on a drive cycle (its stage analysed over the scene's whole sweep, `stages/pair/`), each
/// records.parquet the bits of its records.csv, and no records.jsonl where it was not asked for.
#[test]
fn stage_pairs_write_the_formats_the_run_asks_for() {
    for (scene, folders) in [("specs/ev_reducer_stage_meshes.gear", 2), ("tests/specs/ok/cycle_pair_udds.gear", 1)] {
        let out = temp(&format!("pq-stages-{}", scene.replace('/', "_")));
        run(&["run", scene, "--records", "parquet,csv"], &out);
        let dir = std::fs::read_dir(&out).unwrap().next().unwrap().unwrap().path();
        let mut analysed = 0;
        for stage in std::fs::read_dir(dir.join("stages")).unwrap() {
            let stage = stage.unwrap().path();
            if stage.join("records.csv").exists() {
                assert!(!stage.join("records.jsonl").exists(), "{}: only the formats asked for", stage.display());
                assert_parquet_is_the_csv(&stage, scene);
                analysed += 1;
            }
        }
        assert!(analysed >= folders, "{scene}: {analysed} stage folders with records");
        let _ = std::fs::remove_dir_all(&out);
    }
}

/// Three shards with Parquet records, merged: the single run's rows and columns; a shard's file
/// cut short is refused, naming it, and nothing is written.
#[test]
fn shards_merge_into_the_single_runs_parquet() {
    let out = temp("pq-shards");
    let scene = "tests/specs/ok/large_sweep.gear";
    run(&["run", scene, "--records", "parquet"], &out.join("single"));
    let mut shards = Vec::new();
    for k in 1..=3 {
        run(&["run", scene, "--shard", &format!("{k}/3"), "--records", "parquet"], &out.join("shards"));
        shards.push(out.join("shards").join(format!("large_sweep.shard-{k}-of-3")));
    }
    let o = gearloss().arg("merge").args(&shards).arg("--out").arg(out.join("merged")).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for records in ["stages/pair/records.parquet", "drive_records.parquet"] {
        let single = parquet_file(&out.join("single/large_sweep").join(records));
        let merged = parquet_file(&out.join("merged/large_sweep").join(records));
        assert!(single.1.len() > 100, "{records}");
        assert_eq!(single, merged, "{records}");
    }
    assert!(!out.join("merged/large_sweep/stages/pair/records.csv").exists());
    // Cut the second shard's file in half.
    let bad = shards[1].join("stages/pair/records.parquet");
    let bytes = std::fs::read(&bad).unwrap();
    std::fs::write(&bad, &bytes[..bytes.len() / 2]).unwrap();
    let o = gearloss().arg("merge").args(&shards).arg("--out").arg(out.join("broken")).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && err.contains("shard-2-of-3") && err.contains("stages/pair/records.parquet"),
        "{err}"
    );
    assert!(!out.join("broken/large_sweep").exists(), "nothing written");
    let _ = std::fs::remove_dir_all(&out);
}

/// A drive's drive_records.parquet and drive_records.jsonl against its drive_records.csv (a
/// parallel and a planetary drive): the same columns (keys) in order, every cell equal (floats to
/// the bit, whole numbers and text as written); three shards with Parquet and JSON Lines records
/// merged are the single run's rows (the JSON Lines byte for byte).
#[test]
fn a_drives_parquet_holds_its_csv_and_merges_from_shards() {
    for (scene, slug) in [
        ("specs/ev_two_stage_reducer.gear", "two_stage_ev_reducer"),
        ("specs/planetary_two_stage.gear", "e_axle_with_a_planetary_first_stage"),
    ] {
        let out = temp(&format!("drive-pq-{slug}"));
        run(&["run", scene, "--records", "parquet,csv,jsonl"], &out.join("single"));
        let dir = out.join("single").join(slug);
        let csv = std::fs::read_to_string(dir.join("drive_records.csv")).unwrap();
        let mut lines = csv.lines();
        let header = split_csv(lines.next().unwrap());
        let (columns, rows) = parquet_file(&dir.join("drive_records.parquet"));
        assert_eq!(columns.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>(), header, "{scene}");
        let lines: Vec<&str> = lines.collect();
        assert_eq!(rows.len(), lines.len(), "{scene}");
        let jsonl = std::fs::read_to_string(dir.join("drive_records.jsonl")).unwrap();
        assert_eq!(jsonl.lines().count(), lines.len(), "{scene}");
        for (object, row) in jsonl.lines().zip(&rows) {
            let object: serde_json::Value = serde_json::from_str(object).unwrap();
            let object = object.as_object().unwrap();
            assert_eq!(object.keys().collect::<Vec<_>>().len(), header.len(), "{scene}");
            for ((name, _), cell) in columns.iter().zip(row) {
                let value = &object[name];
                match cell {
                    Cell::Int(i) => assert_eq!(value.as_i64(), Some(*i), "{scene}: {name}"),
                    Cell::Real(x) => assert_eq!(value.as_f64().map(f64::to_bits), Some(x.to_bits()), "{scene}: {name}"),
                    Cell::Text(t) => assert_eq!(value.as_str(), Some(t.as_str()), "{scene}: {name}"),
                    // (A row without a balance has no θ*, a coasting row no thermal ratings.)
                    Cell::Empty => assert!(
                        value.is_null() && (name.starts_with("thermal_rating") || name == "oil_temperature_K"),
                        "{scene}: {name}"
                    ),
                }
            }
        }
        for (row, line) in rows.iter().zip(&lines) {
            for (k, text) in split_csv(line).iter().enumerate() {
                match &row[k] {
                    Cell::Int(i) => assert_eq!(i.to_string(), *text, "{scene}: {}", header[k]),
                    Cell::Real(x) => assert_eq!(x.to_bits(), text.parse::<f64>().unwrap().to_bits(), "{}", header[k]),
                    Cell::Text(t) => assert_eq!(t, text, "{scene}: {}", header[k]),
                    Cell::Empty => assert_eq!(*text, "", "{scene}: {}", header[k]),
                }
            }
        }
        let mut shards = Vec::new();
        for k in 1..=3 {
            run(&["run", scene, "--shard", &format!("{k}/3"), "--records", "parquet,jsonl"], &out.join("shards"));
            shards.push(out.join("shards").join(format!("{slug}.shard-{k}-of-3")));
        }
        let o = gearloss().arg("merge").args(&shards).arg("--out").arg(out.join("merged")).output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let merged = out.join("merged").join(slug);
        assert_eq!(parquet_file(&merged.join("drive_records.parquet")), (columns, rows), "{scene}");
        assert!(!merged.join("drive_records.csv").exists(), "{scene}: only the formats asked for");
        assert_eq!(std::fs::read_to_string(merged.join("drive_records.jsonl")).unwrap(), jsonl, "{scene}");
        let _ = std::fs::remove_dir_all(&out);
    }
}

/// A stage named with a comma (a stage's name is free text): drive_records.csv's header quotes it,
/// so the header has as many cells as every row and names the stage's columns whole.
#[test]
fn a_stage_name_with_a_comma_keeps_the_csv_whole() {
    let out = temp("drive-comma");
    let text = std::fs::read_to_string(crate::root().join("specs/ev_two_stage_reducer.gear")).unwrap();
    std::fs::create_dir_all(&out).unwrap();
    let scene = out.join("comma.gear");
    std::fs::write(&scene, text.replace("stage \"first\"", "stage \"first, fast\"")).unwrap();
    run(&["run", scene.to_str().unwrap()], &out);
    let csv = std::fs::read_to_string(out.join("two_stage_ev_reducer/drive_records.csv")).unwrap();
    let header = split_csv(csv.lines().next().unwrap());
    assert!(header.contains(&"stage_first, fast_mesh_efficiency".to_string()), "{header:?}");
    for line in csv.lines().skip(1) {
        assert_eq!(split_csv(line).len(), header.len(), "{line}");
    }
    let _ = std::fs::remove_dir_all(&out);
}

/// `--records` takes a list of csv, jsonl, parquet; anything else is refused by name.
#[test]
fn the_record_formats_are_read_as_documented() {
    let f: gearloss::RecordFormats = "parquet, csv".parse().unwrap();
    assert_eq!((f.csv, f.jsonl, f.parquet), (true, false, true));
    assert_eq!(f.files(), vec!["records.csv", "records.parquet"]);
    assert_eq!(gearloss::RecordFormats::default().files(), vec!["records.csv", "records.jsonl"]);
    assert!("xlsx".parse::<gearloss::RecordFormats>().unwrap_err().contains("`xlsx`"));
    assert!("".parse::<gearloss::RecordFormats>().is_err());
}
