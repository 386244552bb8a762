//! Fixture-driven tests: every scene in specs/ and tests/specs/ok renders (snapshots of report.md
//! and report.json), every file in tests/specs/err fails with a diagnostic (snapshot of the
//! rendered text), and the committed reports/ are what the code writes today.

use std::path::Path;

fn source_name(path: &Path) -> String {
    // Relative to the project root, so snapshots hold no absolute path.
    path.strip_prefix(crate::root()).unwrap_or(path).display().to_string()
}

fn render(path: &Path) -> gearloss::RenderedReport {
    let source = std::fs::read_to_string(path).unwrap();
    gearloss::run_to_files(&source_name(path), &source).unwrap_or_else(|e| panic!("{e}"))
}

fn file<'a>(r: &'a gearloss::RenderedReport, name: &str) -> &'a str {
    &r.files.iter().find(|(n, _)| n == name).unwrap().1
}

#[test]
fn example_scenes_render() {
    insta::glob!("../../specs", "*.gear", |path| {
        let r = render(path);
        crate::plot_text::assert_text_inside(&source_name(path), &r.files);
        // report.md links every plot the folder holds (each report.md its own folder's).
        for (name, _) in r.files.iter().filter(|(n, _)| n.ends_with(".svg")) {
            let (dir, svg) = name.rsplit_once('/').map_or(("", name.as_str()), |(d, f)| (d, f));
            let md = if dir.is_empty() { "report.md".to_string() } else { format!("{dir}/report.md") };
            let text = &r.files.iter().find(|(n, _)| *n == md).expect("a report.md beside the plot").1;
            assert!(text.contains(&format!("]({svg})")), "{md} does not link {svg}");
        }
        insta::assert_snapshot!("md", file(&r, "report.md"));
        insta::assert_snapshot!("json", file(&r, "report.json"));
        // report.json is a fixed point of reading back and writing again (a run writes the text it
        // read back from; `render` writes it from the file): the same bytes both ways.
        let json = file(&r, "report.json");
        // (An oil sweep's report.json is the comparison, with a report per temperature beside it.)
        if let Ok(read) = serde_json::from_str::<gearloss::Report>(json) {
            assert_eq!(gearloss::render::render_json(&read), json, "report.json does not write back the same");
        }
        // A scene of one pair: its stage's report of one pair and its records.
        if let Some((_, md)) = r.files.iter().find(|(n, _)| n == "stages/pair/report.md") {
            insta::assert_snapshot!("pair_md", md);
        }
        if let Some((_, csv)) = r.files.iter().find(|(n, _)| n == "stages/pair/records.csv") {
            insta::assert_snapshot!("csv", csv);
        }
    });
}

#[test]
fn ok_fixtures_render() {
    insta::glob!("../specs/ok", "*.gear", |path| {
        let r = render(path);
        crate::plot_text::assert_text_inside(&source_name(path), &r.files);
        insta::assert_snapshot!(file(&r, "report.md"));
    });
}

/// Lowering on its own (`gearloss check --emit lowered`): the checked scene in SI of a pair, an
/// internal pair, a one-stage drive and a one-planet planetary stage. (A scene on a drive cycle
/// prints its whole trace: its lowering is held by the cycle tests instead.)
#[test]
fn lowered_forms() {
    for name in ["minimal", "internal_pair", "drive_one_stage", "planetary_one_planet"] {
        let path = crate::root().join(format!("tests/specs/ok/{name}.gear"));
        let scene = crate::scene(&path);
        let text = gearloss::lowered(&scene);
        let json: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(json["title"], scene.title.as_str());
        insta::assert_snapshot!(format!("lowered_{name}"), text);
    }
}

#[test]
fn err_fixtures_fail_with_diagnostics() {
    let mut count = 0;
    insta::glob!("../specs/err", "*.gear", |path| {
        count += 1;
        // A file that cannot be read as a scene (not UTF-8) fails where the binary reads it.
        let source = match gearloss::scene::source::read_text(path, gearloss::scene::source::MAX_SCENE_BYTES) {
            Ok(s) => s,
            Err(e) => {
                insta::assert_snapshot!(format!("cannot read {}: {e}", source_name(path)));
                return;
            }
        };
        let errors = gearloss::check(&source_name(path), &source).expect_err("an err fixture must fail");
        assert!(!errors.diagnostics.is_empty());
        for d in &errors.diagnostics {
            assert!(!d.hints.is_empty(), "every diagnostic carries a hint: {}", d.reason);
            assert!(d.span.end <= source.len());
            for text in std::iter::once(&d.reason).chain(&d.hints) {
                assert!(!text.chars().any(char::is_control), "a raw control character in a message: {text:?}");
            }
        }
        insta::assert_snapshot!(errors.render(false));
    });
    assert!(count >= 15, "only {count} bad inputs");
}

#[test]
fn several_errors_are_all_reported() {
    let path = crate::root().join("tests/specs/err/several_errors.gear");
    let source = std::fs::read_to_string(&path).unwrap();
    let errors = gearloss::check("several_errors.gear", &source).unwrap_err();
    assert_eq!(errors.diagnostics.len(), 3, "{}", errors.render(false));
}

/// reports/ holds the rendered report of every scene in specs/. To refresh after a change:
/// `for f in specs/*.gear; do cargo run --locked -- run $f; done`.
#[test]
fn committed_reports_are_up_to_date() {
    let mut stale = Vec::new();
    for entry in std::fs::read_dir(crate::root().join("specs")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "gear") {
            let r = render(&path);
            let timing = |n: &str| n.rsplit('/').next().unwrap_or(n).starts_with(gearloss::render::TIMING_PREFIX);
            for (name, content) in r.files.iter().filter(|(n, _)| !timing(n)) {
                let committed = crate::root().join("reports").join(&r.slug).join(name);
                if std::fs::read_to_string(&committed).ok().as_deref() != Some(content.as_str()) {
                    stale.push(committed.display().to_string());
                }
            }
        }
    }
    assert!(stale.is_empty(), "out of date (run `gearloss run` on each scene in specs/): {stale:#?}");
}

#[test]
fn report_json_has_the_named_geometry_keys() {
    let r = render(&crate::root().join("specs/fzg_type_c.gear"));
    let v: serde_json::Value = serde_json::from_str(file(&r, "stages/pair/report.json")).unwrap();
    let eps = v["geometry"]["contact_ratio"].as_f64().unwrap();
    assert!((eps - 1.4362).abs() < 1e-4);
    let aw = &v["geometry"]["operating_pressure_angle"];
    assert_eq!(aw["unit"], "rad");
    assert!((aw["value"].as_f64().unwrap().to_degrees() - 22.4388).abs() < 1e-4);
    // Every dimensional number is {value, unit}: the contact rows carry units.
    let row = &v["operating_points"][0]["contact"][0];
    assert_eq!(row["hertz_pressure"]["unit"], "Pa");
    assert_eq!(row["point"], "A");
}

/// The report is data (issue 25): for every scene in specs/, its report folder written, then
/// report.md and every SVG deleted, `render` gives back every file byte for byte from report.json
/// alone (in each oil temperature's folder too); so for two drive fixtures whose stage geometry
/// has a number report.json rounds across a shown digit (the FZG C pair's T1B, 10.27605 mm: a
/// drive's run draws it as it reads back, as a pair's does).
#[test]
fn render_gives_back_every_file_from_report_json() {
    let base = std::env::temp_dir().join(format!("gearloss-render-{}", std::process::id()));
    let fixtures = ["drive_stage_stiffness_sharing.gear", "drive_pair_analyses_only.gear"]
        .map(|f| crate::root().join("tests/specs/ok").join(f));
    let specs = std::fs::read_dir(crate::root().join("specs")).unwrap().map(|e| e.unwrap().path());
    for path in specs.chain(fixtures) {
        if path.extension().is_none_or(|e| e != "gear") {
            continue;
        }
        let r = render(&path);
        let dir = base.join(&r.slug);
        for (name, content) in &r.files {
            let at = dir.join(name);
            std::fs::create_dir_all(at.parent().unwrap()).unwrap();
            if !(name.ends_with(".md") || name.ends_with(".svg")) {
                std::fs::write(&at, content).unwrap();
            }
        }
        let written = gearloss::rerender::render_into(&dir).unwrap_or_else(|e| panic!("{}: {e}", r.slug));
        for (name, content) in &r.files {
            let again = std::fs::read_to_string(dir.join(name)).unwrap_or_default();
            assert!(again == *content, "{}/{name} differs after render", r.slug);
        }
        let drawn = r.files.iter().filter(|(n, _)| n.ends_with(".md") || n.ends_with(".svg")).count();
        assert!(written.len() >= drawn, "{}: {} files drawn, {drawn} expected", r.slug, written.len());
    }
    let _ = std::fs::remove_dir_all(&base);
}
