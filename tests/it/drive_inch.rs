//! A drive sized in inches is shown in inch–pound units, as a pair sized in inches is.

use gearloss::report::number::UnitSystem;

/// tests/specs/ok/drive_inch_pound.gear (P_nd = 8 1/in, b = 1.25 in, places in inches): report.md
/// shows forces in lbf, powers in hp, lengths in in; every shown number is the SI value of
/// report.json converted (to the cell's decimals: 1 lbf = 4.4482216152605 N, 1 hp = 550 lbf·ft/s,
/// 1 in = 25.4 mm), and no heading is left in N, W or mm. The same drive sized in millimetres is
/// shown in SI and its report.json has no `unit_system`.
#[test]
fn drives_sized_in_inches_are_reported_in_inch_units() {
    let path = crate::root().join("tests/specs/ok/drive_inch_pound.gear");
    let text = std::fs::read_to_string(&path).unwrap();
    let report = |source: &str| {
        let scene = gearloss::check("drive.gear", source).unwrap();
        let drive = scene.drive.clone().unwrap();
        let (report, rendered) = gearloss::run_drive::drive_report_files(&scene, &drive).unwrap();
        let md = rendered.files.iter().find(|(name, _)| name == "report.md").unwrap().1.clone();
        (report, md)
    };
    let (r, md) = report(&text);
    assert_eq!(r.unit_system, UnitSystem::Inch);
    assert_eq!(serde_json::to_value(&r).unwrap()["unit_system"], "inch");
    let (lbf, inch) = (4.448_221_615_260_5, 0.0254);
    let hp = 550.0 * lbf * 12.0 * inch;
    let close = |cell: &str, value: f64, decimals: i32| {
        let shown: f64 = cell.parse().unwrap_or_else(|_| panic!("{cell:?} is not a number"));
        assert!((shown - value).abs() <= 0.5 * 10f64.powi(-decimals) + 1e-12, "{cell} vs {value}");
    };
    let table = |heading: &str| -> Vec<Vec<String>> {
        md.lines()
            .skip_while(|l| !l.starts_with(heading))
            .skip(2)
            .take_while(|l| l.starts_with('|'))
            .map(|l| l.trim_matches('|').split('|').map(|c| c.trim().to_string()).collect())
            .collect()
    };
    // The headline: P_in and the losses in hp (W's decimals and three more).
    let headline = table("| point | law | formulation | flow |");
    assert_eq!(headline.len(), r.points.len());
    for (row, p) in headline.iter().zip(&r.points) {
        let d = &p.point;
        close(&row[6], d.input_power / hp, 5);
        close(&row[9], d.output_power / hp, 5);
        close(&row[10], d.losses.meshes / hp, 6);
        close(&row[14], d.losses.total() / hp, 6);
    }
    // The first point's stage: forces in lbf (N's decimals and one more), its mesh loss in hp.
    let stage = &table("| stage | driving |")[0];
    let s = &r.points[0].point.stages[0];
    close(&stage[5], s.tangential_force / lbf, 3);
    close(&stage[6], s.radial_force / lbf, 3);
    close(&stage[7], s.axial_force / lbf, 3);
    close(&stage[9], s.mesh_loss / hp, 6);
    // Its bearing places: at in inches, loads per bearing in lbf.
    let places = table("| shaft | place at (in) |");
    let bearings: Vec<_> = r.points[0].point.shafts.iter().flat_map(|s| &s.bearings).collect();
    assert_eq!(places.len(), bearings.len());
    for (row, b) in places.iter().zip(bearings) {
        close(&row[1], b.position.unwrap() / inch, 3);
        close(&row[4], b.radial_load / lbf, 3);
        close(&row[5], b.axial_load / lbf, 3);
    }
    // The inputs: the oil at 160 °F as written, the dip's sizes in inches.
    assert!(md.contains("| oil temperature | 160.0 °F |"), "{md}");
    assert!(md.contains("dip: immersion 0.000 / 1.000 in, axis height 5.000 in, housing width 5.000 in"), "{md}");
    for si in ["(N)", "(W)", "(mm)", " W in at", "(N·m)", " mm", "degC"] {
        assert!(!md.contains(si), "an SI unit {si} left in the inch report");
    }
    // A planetary stage sized in inches: its inputs and its planets' forces and losses too.
    let planetary = std::fs::read_to_string(crate::root().join("specs/planetary_reducer.gear")).unwrap();
    let (r, md) = report(&planetary.replace("face_width = 25 mm", "face_width = 0.984251968503937 in"));
    assert_eq!(r.unit_system, UnitSystem::Inch);
    assert!(md.contains("| neighbour gap (in) |") && md.contains("| planet mass (lb) |"), "{md}");
    let p = r.points[0].point.stages[0].planetary().unwrap();
    let shown = format!("F_t {:.3} lbf (sun mesh)", p.forces.tangential[0] / lbf);
    assert!(md.contains(&shown), "{shown} missing");
    // At two oil temperatures: the comparison page's losses in hp too.
    let swept = text.replace("oil_temperature = 160 degF", "oil_temperature = [140, 160] degF");
    let files = gearloss::run_to_files("drive.gear", &swept).unwrap();
    let top = &files.files.iter().find(|(name, _)| name == "report.md").unwrap().1;
    assert!(top.contains("## Total loss (hp) and η (%)") && top.contains("## Meshes and bearings (hp)"), "{top}");
    // The same drive sized in millimetres: SI.
    let metric = text
        .replace("diametral_pitch = 8 1/in", "module = 3.175 mm")
        .replace("face_width = 1.25 in", "face_width = 31.75 mm");
    let (r, md) = report(&metric);
    assert_eq!(r.unit_system, UnitSystem::Si);
    assert!(serde_json::to_value(&r).unwrap().get("unit_system").is_none());
    assert!(md.contains("| F_t (N) | F_r (N) | F_a (N) |") && md.contains("| P_0 (W) | P_1 (W) |"), "{md}");
}
