//! Every scene of one pair is the one-stage drive it is: lowered as that drive
//! (`gearloss::scene::lower::lower_as_one_stage_drive`) and walked, it gives the pair's own numbers.

use gearloss::efficiency::Formulation;

/// The scenes of one pair that ask for efficiency, among the specs and the ok fixtures (an internal
/// pair's an internal stage).
fn pair_scenes() -> Vec<std::path::PathBuf> {
    pair_scene_files(|text| text.contains("efficiency("))
}

/// The scenes of one pair (a `gears` block, no `stage`) in specs/ and tests/specs/ok/ whose text
/// `wanted` accepts, sorted.
pub(crate) fn pair_scene_files(wanted: impl Fn(&str) -> bool) -> Vec<std::path::PathBuf> {
    let mut out = Vec::new();
    for dir in ["specs", "tests/specs/ok"] {
        for entry in std::fs::read_dir(crate::root().join(dir)).unwrap() {
            let path = entry.unwrap().path();
            let text = std::fs::read_to_string(&path).unwrap_or_default();
            let is_pair = text.contains("gears {") && !text.contains("stage \"");
            if path.extension().is_some_and(|e| e == "gear") && is_pair && wanted(&text) {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// At every operating point, law and formulation the drive's mesh loss is the loss the pair's own
/// report charges (ISO/TR 14179-2's P_in μ̄ H_V on a helical pair, else the contact-line integral),
/// and where the pair describes its gearbox the drive's whole loss is that mesh loss plus the
/// pair's own budget beside it (`losses::loss_budget` on the pair's two shafts and statics): 1e-12
/// relative (the walk's fixed point settles bearing loads to 1e-12). The mesh's driving torque is
/// the pair's `pinion_torque` (1e-12), the drive's input torque that plus the pinion shaft's
/// losses. At the scene's first oil temperature (a scene whose oil settles at the thermal balance
/// is compared at its written temperature, both sides alike).
#[test]
fn every_pair_is_its_one_stage_drive() {
    let mut compared = 0;
    let mut budgets = 0;
    let mut validities = 0;
    let scenes = pair_scenes();
    assert!(scenes.len() >= 15, "{} scenes", scenes.len());
    for path in &scenes {
        let name = path.strip_prefix(crate::root()).unwrap().display().to_string();
        let source = std::fs::read_to_string(path).unwrap();
        let pair = gearloss::check(&name, &source).unwrap_or_else(|e| panic!("{e}"));
        let ast = gearloss::parse(&name, &source).unwrap();
        let drive = gearloss::scene::lower::lower_as_one_stage_drive(&ast, path.parent())
            .unwrap_or_else(|e| panic!("{name}: {:?}", e.iter().map(|d| &d.reason).collect::<Vec<_>>()));
        let (pair, drive) = (pair.at_oil_temperature(0), drive.at_oil_temperature(0));
        let pair_report = gearloss::report_of(&pair);
        let alone = crate::pair_alone::PairAlone::new(&pair);
        let mut csv = Vec::new();
        gearloss::evaluate::evaluate_drive_into(&drive, drive.drive.as_ref().unwrap(), &mut csv).unwrap();
        let csv = String::from_utf8(csv).unwrap();
        let mut lines = csv.lines();
        let head: Vec<&str> = lines.next().unwrap().split(',').collect();
        let col = |name: &str| head.iter().position(|h| *h == name).unwrap();
        let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
        let labels: Vec<String> = pair.friction.iter().map(|l| l.label()).collect();
        for r in &pair_report.efficiency {
            let t = r.pinion_torque.value.0;
            let formulation = match r.formulation {
                Formulation::External => "external",
                Formulation::Internal => "internal",
            };
            let law = labels.iter().position(|l| *l == r.label).unwrap().to_string();
            let key = [r.torque_index.to_string(), r.speed_index.to_string(), law, formulation.to_string()];
            let row = rows
                .iter()
                .find(|row| {
                    ["torque_index", "speed_index", "law_index", "formulation"]
                        .iter()
                        .zip(&key)
                        .all(|(c, k)| row[col(c)] == k)
                })
                .unwrap_or_else(|| panic!("{name}: no drive row {key:?}"));
            let value = |c: &str| row[col(c)].parse::<f64>().unwrap();
            // `pinion_torque` is the torque into the mesh, the input's that plus the pinion shaft's losses.
            let at_pinion = value("stage_pair_driving_torque_N_m");
            assert!((at_pinion - t).abs() <= 1e-12 * t, "{name}: {key:?}: the mesh at {at_pinion} N·m");
            assert!(value("input_torque_N_m") >= t * (1.0 - 1e-12), "{name}: {key:?}");
            let charged = match (&r.ohlendorf, charges_iso(&pair, r)) {
                (Some(o), true) => o.power_loss.value.0,
                _ => r.power_loss.value.0,
            };
            let mesh = value("meshes_W");
            assert!(
                (mesh - charged).abs() <= 1e-12 * charged,
                "{name}, {} {formulation} at {t} N·m: drive {mesh} W, pair {charged} W",
                r.label
            );
            compared += 1;
            if pair.gearbox.is_some() {
                // The whole loss: that mesh loss and the pair's own budget beside it
                // (`losses::loss_budget` on the pair's two shafts, not the drive's walk).
                let law = labels.iter().position(|l| *l == r.label).unwrap();
                let [_, beside] = alone.losses((law, r.formulation), (t, r.pinion_speed.value.0));
                let total = charged + beside;
                assert!(
                    (value("total_W") - total).abs() <= 1e-12 * total,
                    "{name}, {} {formulation} at {t} N·m: drive loses {} W, the pair's own budget {total} W",
                    r.label,
                    value("total_W")
                );
                budgets += 1;
            }
        }
        // A law's validity on the stage's mesh is read at the contacts the pair alone reads it at:
        // at each detail point of the pair the same count outside, under every law.
        let speeds = pair.operating.pinion_speed.values.len();
        for p in &pair_report.operating_points {
            for (l, law) in p.friction.iter().enumerate() {
                let key = [(p.index / speeds).to_string(), (p.index % speeds).to_string(), l.to_string()];
                let Some(row) = rows.iter().find(|row| {
                    ["torque_index", "speed_index", "law_index"].iter().zip(&key).all(|(c, k)| row[col(c)] == k)
                }) else {
                    continue;
                };
                assert_eq!(
                    row[col("stage_pair_validity_outside")].parse::<usize>().unwrap(),
                    law.validity.outside,
                    "{name}: point {} {}",
                    p.index + 1,
                    law.label
                );
                validities += 1;
            }
        }
    }
    eprintln!("{} scenes: {compared} points compared, {budgets} with a budget, {validities} validities", scenes.len());
    assert!(compared >= 100 && budgets >= 20, "{compared} points compared, {budgets} budgets");
    assert!(validities >= 20, "{validities} validities compared");
}

/// Whether the pair's mesh loss as a budget charges it is ISO/TR 14179-2's own (the law on a helical pair).
fn charges_iso(scene: &gearloss::Scene, r: &gearloss::report::friction::EfficiencyRecord) -> bool {
    r.law == gearloss::friction::LawId::Iso14179_2
        && scene.gears.helix_angle.as_ref().is_some_and(|b| b.value.value != 0.0)
}

/// The thermal balance of every pair that asks for one, as its one-stage drive finds it, held
/// against the pair's own losses (`pair_alone`: its law's charged mesh loss and its gearbox's
/// budget on its own two shafts, with its oil moved to θ*): at each point, law and formulation the
/// drive's P_V(θ*) is the pair's own to 1e-12 relative, and what the housing gives off at θ* to
/// 1e-6 (θ* is located to 1e-10 K; a row without a balance is at the search's limit, 200 °C; a sump
/// its cooler would take below the ambient rests at the ambient, P_V ≤ P_Q there).
#[test]
fn every_pair_balances_its_own_losses() {
    let (mut compared, mut balanced, mut ratings) = (0, 0, 0);
    for path in pair_scenes() {
        let name = path.strip_prefix(crate::root()).unwrap().display().to_string();
        let source = std::fs::read_to_string(&path).unwrap();
        let pair = gearloss::check(&name, &source).unwrap();
        if pair.analyses.thermal_balance.is_none() || pair.operating.oil_temperatures.is_some() {
            continue;
        }
        let housing = pair.housing.as_ref().unwrap();
        let eval = gearloss::evaluate::evaluate_drive(&pair, pair.drive.as_ref().unwrap());
        let op = &pair.operating;
        for b in &eval.balances {
            let theta = b.balance.temperature.unwrap_or(473.15);
            let hot = crate::pair_alone::at_kelvin(&pair, theta);
            let state = (op.pinion_torque.values[b.torque_index].value, op.pinion_speed.values[b.speed_index].value);
            let [mesh, beside] = crate::pair_alone::PairAlone::new(&hot).losses((b.law_index, b.formulation), state);
            let own = mesh + beside;
            assert!(
                (b.loss - own).abs() <= 1e-12 * own,
                "{name}: P_V {} W vs the pair's own {own} W at {theta} K",
                b.loss
            );
            if b.balance.temperature.is_some() {
                // (A sump its cooler would take below the ambient rests at the ambient, P_V ≤ P_Q.)
                let q = housing.dissipation(theta).total;
                let at_ambient = theta == housing.ambient && b.loss <= q;
                assert!(
                    at_ambient || (b.loss - q).abs() <= 1e-6 * q,
                    "{name}: P_V {} W vs P_Q {q} W at θ* = {theta} K",
                    b.loss
                );
                balanced += 1;
            }
            ratings += usize::from(b.rating.is_some()) + usize::from(b.rating_95.is_some());
            compared += 1;
        }
    }
    eprintln!("{compared} balances compared, {balanced} balanced, {ratings} ratings");
    assert!(
        compared >= 5 && balanced >= 4 && ratings >= 6,
        "{compared} balances, {balanced} balanced, {ratings} ratings"
    );
}

/// Every scene of one pair among the specs and the ok fixtures, whatever it asks for, lowers as its
/// one-stage drive: one lowered form serves them all.
#[test]
fn every_pair_lowers_as_its_one_stage_drive() {
    let mut lowered = 0;
    for dir in ["specs", "tests/specs/ok"] {
        for entry in std::fs::read_dir(crate::root().join(dir)).unwrap() {
            let path = entry.unwrap().path();
            let text = std::fs::read_to_string(&path).unwrap_or_default();
            if path.extension().is_none_or(|e| e != "gear") || !text.contains("gears {") || text.contains("stage \"") {
                continue;
            }
            let name = path.strip_prefix(crate::root()).unwrap().display().to_string();
            let ast = gearloss::parse(&name, &text).unwrap();
            let drive = gearloss::scene::lower::lower_as_one_stage_drive(&ast, path.parent())
                .unwrap_or_else(|e| panic!("{name}: {:?}", e.iter().map(|d| &d.reason).collect::<Vec<_>>()));
            assert!(drive.drive.as_ref().is_some_and(|d| d.one_pair && d.layout.stages.len() == 1), "{name}");
            lowered += 1;
        }
    }
    assert!(lowered >= 30, "{lowered} pairs");
}

/// The warnings the pair alone gives of its mesh's geometry (a brittle tip, root interference, an
/// undercut gear, a ring close in teeth to its pinion, a helical overlap below 1, a helix above
/// 30°) are its one-stage drive's too, and those of the oil's service limit and of the housing's
/// inputs are the drive's alone: findings exist once for every scene. Each mesh warning of the pair
/// is the drive's, naming stage `pair`, and each of the drive's warnings on stage `pair`'s mesh is
/// the pair's (a drive of several stages warns of every stage's meshes alike,
/// tests/specs/ok/planetary_helical.gear's snapshot); the pair alone (no housing) warns of neither
/// the oil's limit nor the housing. And the drive's report reads the oil as the pair's does: its
/// lubricant report (η, ν, ρ, α, X_L, the data sheet and the source) is the pair's, field for
/// field, and its Scene table lists every input of the pair's gears and oil as the pair's does (as
/// written and in SI), the gears' keyed from stage `pair`, and its stage geometry is the pair's
/// (H_V, E', every diameter and point of the path of contact) field for field.
#[test]
fn every_pair_warns_as_its_one_stage_drive() {
    const MESH: [&str; 8] = [
        "pinion tip thickness",
        "wheel tip thickness",
        "contact at ",
        "the pinion is undercut",
        "the wheel is undercut",
        "the ring has only",
        "overlap ratio",
        "helix angle",
    ];
    const SCENE: [&str; 3] = ["oil temperature", "the housing's", "the oil cooler"];
    let (mut mesh, mut scene, mut oils, mut inputs, mut geometries, mut helical_plots) = (0, 0, 0, 0, 0, 0);
    for path in pair_scenes() {
        let name = path.strip_prefix(crate::root()).unwrap().display().to_string();
        let source = std::fs::read_to_string(&path).unwrap();
        let pair = gearloss::check(&name, &source).unwrap();
        let ast = gearloss::parse(&name, &source).unwrap();
        let drive = gearloss::scene::lower::lower_as_one_stage_drive(&ast, path.parent()).unwrap();
        let (pair, drive) = (pair.at_oil_temperature(0), drive.at_oil_temperature(0));
        let warnings = |f: &[gearloss::report::Finding]| -> Vec<String> {
            f.iter().filter(|f| f.severity == gearloss::report::Severity::Warning).map(|f| f.message.clone()).collect()
        };
        let pair_report = gearloss::report_of(&pair);
        let of_pair = warnings(&pair_report.findings);
        let eval = gearloss::evaluate::evaluate_drive(&drive, drive.drive.as_ref().unwrap());
        let drive_report = gearloss::report::drive::build_drive_report(&drive, drive.drive.as_ref().unwrap(), &eval);
        let of_drive = warnings(&drive_report.findings);
        // The oil as every mesh reads it: the same lubricant report, field for field.
        let json = |l| serde_json::to_string(&l).unwrap();
        if pair.operating.equilibrium.is_none() {
            assert_eq!(json(&pair_report.lubricant), json(&drive_report.lubricant), "{name}: the lubricant");
            oils += usize::from(drive_report.lubricant.is_some());
        }
        // The stage's geometry is the pair's, field for field (H_V as the walk integrates it; a
        // helical mesh's plane of action with the data its plot draws), but for the axial forces
        // by point, which a drive's report leaves to each point's table.
        let lean = |g: &gearloss::report::GeometryReport| {
            let mut v = serde_json::to_value(g).unwrap();
            if let Some(h) = v.get_mut("helical").and_then(|h| h.as_object_mut()) {
                h.remove("axial_force");
            }
            v
        };
        assert_eq!(drive_report.stage_geometry.len(), 1, "{name}");
        let stage = &drive_report.stage_geometry[0];
        assert_eq!(lean(&pair_report.geometry), lean(&stage.geometry), "{name}: the geometry");
        geometries += 1;
        // A helical pair's plane of action is drawn for its stage, as the pair's report draws it.
        let plot = stage.plot.as_ref().map(|p| p.file.as_str());
        assert_eq!(plot.is_some(), pair_report.geometry.helical.is_some(), "{name}: a plot iff helical");
        if let Some(file) = plot {
            let (_, drawn) = gearloss::run_drive::drive_report_files(&drive, drive.drive.as_ref().unwrap()).unwrap();
            let svg = &drawn.files.iter().find(|(f, _)| f == file).unwrap_or_else(|| panic!("{name}: {file}")).1;
            assert!(svg.contains("plane of action: contact lines at τ = 0, ¼, ½, ¾"), "{name}");
            helical_plots += 1;
        }
        // Every input the pair's Scene table lists — its gears, its oil, its gearbox's lubrication,
        // bearing places and seals, its housing — is the drive's, as written and in SI (the gears'
        // keyed from stage `pair`).
        let row_json = |r: &gearloss::report::InputRow| serde_json::to_string(r).unwrap();
        let drive_rows: Vec<String> = drive_report.inputs.iter().map(row_json).collect();
        for r in &pair_report.inputs {
            let gear = ["gears.", "pinion.", "wheel."].iter().any(|k| r.key.starts_with(k));
            let mut mine = r.clone();
            if gear {
                mine.key = format!("pair.{}", r.key);
            }
            assert!(drive_rows.contains(&row_json(&mine)), "{name}: the drive does not list {}", row_json(&mine));
            inputs += 1;
        }
        let stage = "stage `pair`: ";
        for w in of_pair.iter().filter(|w| MESH.iter().any(|m| w.starts_with(m))) {
            assert!(of_drive.contains(&format!("{stage}{w}")), "{name}: the drive does not warn: {w}\n{of_drive:#?}");
            mesh += 1;
        }
        for w in of_drive.iter().filter_map(|w| w.strip_prefix(stage)) {
            assert!(of_pair.iter().any(|p| p == w), "{name}: the pair does not warn: {w}");
        }
        assert!(!of_pair.iter().any(|w| SCENE.iter().any(|m| w.starts_with(m))), "{name}: {of_pair:#?}");
        scene += of_drive.iter().filter(|w| SCENE.iter().any(|m| w.starts_with(m))).count();
    }
    eprintln!("{mesh} mesh warnings, {scene} of the oil and the housing, {oils} lubricants, {inputs} inputs, {geometries} geometries, {helical_plots} planes of action");
    assert!(
        mesh >= 2 && scene >= 3 && oils >= 15 && inputs >= 200 && geometries >= 15 && helical_plots >= 3,
        "{mesh}, {scene}, {oils}, {inputs}"
    );
}

/// A pair loaded past Hertz's line contact (FZG type C at 30 000 N·m: b_H > R/10 at B) is flagged
/// alike as its one-stage drive: the drive counts every row at that torque (3 speeds × 2 laws × 2
/// formulations) and names the first with the contact the pair's own finding names, in the same
/// words and numbers (b_H, R/10 and the place, to the digits shown); at the rated torques nothing.
#[test]
fn a_pair_past_line_contact_is_flagged_as_its_one_stage_drive() {
    let source = std::fs::read_to_string(crate::root().join("specs/fzg_type_c.gear"))
        .unwrap()
        .replace("pinion_torque = [239.3, 372.6] N*m", "pinion_torque = [239.3, 30000] N*m");
    let pair = gearloss::check("c.gear", &source).unwrap();
    let said = gearloss::report_of(&pair).findings.into_iter().map(|f| f.message).collect::<Vec<_>>();
    let of_pair = said
        .iter()
        .find_map(|m| m.strip_prefix("operating point 4 (30000 N·m, 100 rpm): "))
        .unwrap_or_else(|| panic!("{said:#?}"));
    assert!(of_pair.starts_with("Hertz half-width b_H = "), "{of_pair}");
    let drive =
        gearloss::scene::lower::lower_as_one_stage_drive(&gearloss::parse("c.gear", &source).unwrap(), None).unwrap();
    let d = drive.drive.as_ref().unwrap();
    let report = gearloss::report::drive::build_drive_report(&drive, d, &gearloss::evaluate::evaluate_drive(&drive, d));
    assert_eq!((report.implausible_rows, report.rows), (12, 24));
    let first = report.first_implausible.as_deref().unwrap();
    assert!(first.starts_with("T_pinion = 30000 N·m, n_in = 100 rpm"), "{first}");
    assert!(first.ends_with(&format!("stage `pair`: {of_pair}")), "{first}\nvs the pair's\n{of_pair}");
    let warned = report.findings.iter().filter(|f| f.message.contains("no gear mesh can have")).count();
    assert_eq!(warned, 1);
}

/// A scene of one pair's efficiency map is its one-stage drive's loss map, and its cells hold
/// together by closed forms: at every cell, law and formulation of `specs/fzg_c14_gearbox.gear`'s
/// 40 × 40 map (both laws and formulations), loss_map.csv's parts sum to its whole loss, its η at
/// the pinion is 1 − P_V/(T_1 ω_1) of the cell's own pinion torque and speed (each to the CSV's ten
/// digits, 1e-9), and the report's grids hold as many cells; η at the pinion lies below the box's
/// P_out/P_in (the pinion shaft's own losses are on the pinion's side of T_1). Each best point's η
/// (located on η at the pinion) is at least its grid's best cell's.
#[test]
fn a_pairs_map_is_its_one_stage_drives_loss_map() {
    let source = std::fs::read_to_string(crate::root().join("specs/fzg_c14_gearbox.gear")).unwrap();
    let scene = gearloss::check("c14.gear", &source).unwrap();
    let (report, rendered) = gearloss::run_drive::drive_report_files(&scene, scene.drive.as_ref().unwrap()).unwrap();
    let csv = &rendered.files.iter().find(|(f, _)| f == "loss_map.csv").expect("loss_map.csv").1;
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| head.iter().position(|h| *h == n).unwrap_or_else(|| panic!("no column {n}"));
    let parts: Vec<usize> = ["meshes_W", "gear_no_load_W", "bearings_no_load_W", "bearings_load_W", "seals_W"]
        .iter()
        .map(|n| col(n))
        .collect();
    let (t_at, w_at, total_at, eta_at, own_at) = (
        col("pinion_torque_N_m"),
        col("pinion_speed_rad_s"),
        col("total_loss_W"),
        col("total_efficiency"),
        col("pinion_efficiency"),
    );
    let close = |a: f64, b: f64, what: &str| assert!((a - b).abs() <= 1e-9 * b.abs().max(1e-9), "{what}: {a} vs {b}");
    let mut cells = 0;
    for line in lines {
        // The law's label is quoted and holds commas only inside its quotes.
        let (before, rest) = line.split_once(",\"").unwrap();
        let (_, after) = rest.split_once("\",").unwrap();
        let v: Vec<f64> = before
            .split(',')
            .chain(["0", "0"])
            .chain(after.split(',').skip(1))
            .map(|x| x.parse().unwrap_or(0.0))
            .collect();
        let total = v[total_at];
        close(parts.iter().map(|i| v[*i]).sum::<f64>(), total, "parts");
        close(v[own_at], 1.0 - total / (v[t_at] * v[w_at]), "η at the pinion");
        assert!(v[own_at] < v[eta_at], "η at the pinion {} not below P_out/P_in {}", v[own_at], v[eta_at]);
        cells += 1;
    }
    assert_eq!(cells, 40 * 40 * 4);
    let grid_cells: usize = report.maps.iter().map(|m| m.loss.iter().map(Vec::len).sum::<usize>()).sum();
    assert_eq!(grid_cells, cells);
    for m in &report.maps {
        for b in &m.best {
            assert!(b.efficiency >= b.grid_efficiency - 1e-12, "{}: {} < {}", m.law, b.efficiency, b.grid_efficiency);
        }
        assert!(m.best.iter().any(|b| b.flow == "drive"), "{}: no best point", m.law);
    }
}

/// A scene of one pair's losses at an oil temperature, as its drive's thermal balance, ratings and
/// duty cycle read them (`evaluate::DriveLosses`: its walk's first pass with the oil moved to θ),
/// are the pair's own there (`pair_alone`: its law's charged mesh loss and its gearbox's budget on
/// its own two shafts, the scene's oil moved to θ): for every scene of one pair with a gearbox
/// among the specs and the ok fixtures, at its first three points, 40, 80 and 120 °C, every law and
/// both formulations, to 1e-13 relative (the walk starts with the input at T_1 plus the pinion
/// shaft's own losses, so the mesh has T_1 but for rounding).
#[test]
fn a_pairs_losses_at_an_oil_temperature_are_its_own() {
    let (mut scenes, mut compared, mut worst) = (0, 0, 0.0f64);
    for path in pair_scene_files(|text| text.contains("gearbox {") && !text.contains("vehicle")) {
        let name = path.strip_prefix(crate::root()).unwrap().display().to_string();
        let pair = gearloss::check(&name, &std::fs::read_to_string(&path).unwrap()).unwrap();
        let Some(drive) = pair.drive.as_ref() else { continue };
        if pair.gearbox.is_none() || pair.lubricant.as_ref().is_none_or(|l| l.oil.is_none()) {
            continue;
        }
        let pair = pair.at_oil_temperature(0);
        let losses = gearloss::evaluate::DriveLosses::new(&pair, drive);
        scenes += 1;
        let op = &pair.operating;
        for k in 0..op.count().min(3) {
            let state = gearloss::evaluate::state_at(op, k);
            for celsius in [40.0, 80.0, 120.0] {
                let theta = celsius + 273.15;
                let alone = crate::pair_alone::at_kelvin(&pair, theta);
                let own = crate::pair_alone::PairAlone::new(&alone);
                for law in 0..pair.friction.len() {
                    for f in [Formulation::External, Formulation::Internal] {
                        let got = losses.total(law, f, (state.pinion_torque, state.pinion_speed), theta);
                        let want: f64 = own.losses((law, f), (state.pinion_torque, state.pinion_speed)).iter().sum();
                        worst = worst.max((got - want).abs() / want);
                        assert!(
                            (got - want).abs() <= 1e-13 * want,
                            "{name} point {k} at {celsius} °C: {got} W vs {want} W"
                        );
                        compared += 1;
                    }
                }
            }
        }
    }
    eprintln!("{scenes} scenes, {compared} losses, largest difference {worst:.1e}");
    assert!(scenes >= 8 && compared >= 150, "{scenes} scenes, {compared} losses");
}
