//! Every catalogue has one file per entry and one row per file (the pattern of clippy's
//! `declared_lints.rs`): a file without a row, or a row without a file, fails here.

use std::collections::BTreeSet;

/// The `.rs` files of a folder of `src/`, without the folder's own machinery.
fn entry_files(folder: &str, machinery: &[&str]) -> BTreeSet<String> {
    std::fs::read_dir(crate::root().join("src").join(folder))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".rs") && !machinery.contains(&n.as_str()))
        .collect()
}

/// Friction laws: `src/friction/<law name>.rs` for every row of `LAWS`, and no other law file.
#[test]
fn friction_laws_one_file_one_row() {
    let machinery =
        ["mod.rs", "catalog.rs", "law_id.rs", "needs.rs", "friction_law.rs", "law_context.rs", "testing.rs"];
    let files = entry_files("friction", &machinery);
    let rows: BTreeSet<String> =
        gearloss::friction::catalog::LAWS.iter().map(|l| format!("{}.rs", l.id.name())).collect();
    assert_eq!(files, rows, "files in src/friction/ and rows of LAWS differ");
}

/// Mesh stiffness models: each row names its file in `src/geometry/stiffness/`, each entry file
/// has a row; every row sits at its identity's index and names a distinct model.
#[test]
fn stiffness_models_one_file_one_row() {
    use gearloss::geometry::stiffness::MODELS;
    let files = entry_files("geometry/stiffness", &["mod.rs", "catalog.rs", "mesh_stiffness.rs", "stiffness_id.rs"]);
    let rows: BTreeSet<String> = MODELS.iter().map(|m| m.file.to_string()).collect();
    assert_eq!(files, rows, "files in src/geometry/stiffness/ and rows of MODELS differ");
    for (i, m) in MODELS.iter().enumerate() {
        assert_eq!(m.id as usize, i, "{}", m.name);
        assert_eq!(MODELS.iter().filter(|x| x.name == m.name).count(), 1, "{}", m.name);
    }
}

/// Each stiffness model against a hand value on the FZG type C pair (ε_α ≈ 1.44): the rectangular
/// mean is single + (double − single)(ε_α − 1) exactly; the table's mean is the mean of its values
/// and it interpolates linearly; a spur pair's density gives n k b; ISO's builds the rectangular
/// k_n = n c' b and a helical pair a density whose mean per face width is c_γα (1e-9: the mean
/// is integrated). Tolerances 1e-12 relative.
#[test]
fn stiffness_models_by_hand() {
    use gearloss::geometry::stiffness::{StiffnessId, StiffnessModel};
    use gearloss::geometry::teeth::iso_6336_method_b;
    let scene = crate::scene(&crate::root().join("specs/fzg_type_c.gear"));
    let g = scene.gears.geometry().unwrap();
    let period = 1e-3;
    let taus = g.cycle_break_times(&[]);
    let eps = g.contact_ratio;
    let rect = StiffnessModel::pairs_in_contact(2e8, 4e8, 6e8);
    let mean = rect.mean(&g, &taus, period);
    assert!((mean / (2e8 + 2e8 * (eps - 1.0)) - 1.0).abs() < 1e-12, "{mean} with ε_α = {eps}");
    let table = StiffnessModel::table(vec![1e8, 3e8, 2e8, 2e8]);
    assert_eq!(table.mean(&g, &taus, period), 2e8);
    assert!((table.at(&g, 0.125) - 2e8).abs() < 1e-3 && table.slope(&g, 0.1) == 8e8);
    let density = StiffnessModel::per_length(1.5e10, &g);
    assert!((density.at(&g, 0.999 * (eps - 1.0)) / (2.0 * 1.5e10 * g.face_width) - 1.0).abs() < 1e-12);
    let bodies = scene.gears.bodies();
    let iso = StiffnessModel::iso_6336(&g, &bodies);
    assert_eq!(iso.id(), StiffnessId::PairsInContact);
    let roots = [0, 1].map(|i| bodies.radii(&g, i).0);
    let c = iso_6336_method_b(&g, bodies.young, roots).c_single * g.face_width * 1e9;
    assert!((iso.upper_bound(&g) / (3.0 * c) - 1.0).abs() < 1e-12);
    // A helical pair's density: its mean transverse mesh stiffness per face width is ISO's c_γα.
    let scene = crate::scene(&crate::root().join("specs/metric_helical.gear"));
    let (g, bodies) = (scene.gears.geometry().unwrap(), scene.gears.bodies());
    let iso = StiffnessModel::iso_6336(&g, &bodies);
    assert_eq!(iso.id(), StiffnessId::PerLength);
    let roots = [0, 1].map(|i| bodies.radii(&g, i).0);
    let c_gamma = iso_6336_method_b(&g, bodies.young, roots).c_gamma_alpha * 1e9;
    let mean = iso.mean(&g, &g.cycle_break_times(&[]), period) / g.face_width;
    assert!((mean / c_gamma - 1.0).abs() < 1e-9, "{mean} vs c_γα {c_gamma}");
}

/// Dynamic models: each row names its file in `src/dynamics/models/`, each entry file has a row;
/// every row sits at its identity's index, names a distinct model, takes the base formulation and
/// builds a model that answers to its own identity.
#[test]
fn dynamic_models_one_file_one_row() {
    use gearloss::dynamics::models::{ModelInputs, MODELS};
    let files = entry_files("dynamics/models", &["mod.rs", "catalog.rs", "gear_dynamics.rs", "model_id.rs"]);
    let rows: BTreeSet<String> = MODELS.iter().map(|m| m.file.to_string()).collect();
    assert_eq!(files, rows, "files in src/dynamics/models/ and rows of MODELS differ");
    let bearing = gearloss::dynamics::Bearing { loa: 1e8, oloa: 1e8, damping_ratio: 0.02 };
    let inputs = ModelInputs { mass: [Some(1.0), Some(4.0)], bearings: Some([bearing; 2]) };
    let bare = ModelInputs { mass: [None, None], bearings: None };
    for (i, m) in MODELS.iter().enumerate() {
        assert_eq!(m.id as usize, i, "{}", m.name);
        assert_eq!(MODELS.iter().filter(|x| x.name == m.name).count(), 1, "{}", m.name);
        assert!(m.formulations.contains(&gearloss::dynamics::DynamicFormulation::Base), "{}", m.name);
        assert_eq!((m.build)(&inputs).map(|b| b.id()), Some(m.id), "{}", m.name);
        // A model on bearings is not built without its masses and bearings; one off them needs neither.
        assert_eq!((m.build)(&bare).is_some(), !m.on_bearings, "{}", m.name);
    }
}

/// Loss parts: each row names its file in `src/losses/parts/`, each entry file has a row; every row
/// sits at its identity's index; every budget column is filled by exactly one part, and the
/// columns sit at their identities' indices with distinct keys.
#[test]
fn loss_parts_one_file_one_row() {
    use gearloss::losses::parts::{COLUMNS, PARTS};
    let files = entry_files("losses/parts", &["mod.rs", "catalog.rs", "loss_column.rs", "loss_part.rs", "part_id.rs"]);
    let rows: BTreeSet<String> = PARTS.iter().map(|p| p.file.to_string()).collect();
    assert_eq!(files, rows, "files in src/losses/parts/ and rows of PARTS differ");
    for (i, p) in PARTS.iter().enumerate() {
        assert_eq!(p.id as usize, i, "{}", p.name);
    }
    for (i, c) in COLUMNS.iter().enumerate() {
        assert_eq!(c.column as usize, i, "{}", c.key);
        assert_eq!(PARTS.iter().filter(|p| p.columns.contains(&c.column)).count(), 1, "{}", c.key);
        assert_eq!(COLUMNS.iter().filter(|x| x.key == c.key).count(), 1, "{}", c.key);
    }
}

/// ARCHITECTURE.md's rule, held for every folder of `src/`: a file reaches its siblings through
/// `super::<sibling>`, never what its folder's `mod.rs` declares or re-exports (`super::{Trait}`):
/// the trait of a catalogue lives in a file of its own. Comments and test modules are not code of
/// the file's layer and are not read.
#[test]
fn no_file_imports_its_folders_mod_rs() {
    fn walk(dir: &std::path::Path, out: &mut Vec<String>) {
        let entries: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
        let siblings: BTreeSet<String> = entries
            .iter()
            .filter_map(|p| {
                let name = p.file_name()?.to_str()?;
                Some(name.strip_suffix(".rs").unwrap_or(name).to_string())
            })
            .collect();
        for path in &entries {
            if path.is_dir() {
                walk(path, out);
                continue;
            }
            let name = path.file_name().unwrap().to_str().unwrap();
            if !name.ends_with(".rs") || ["mod.rs", "lib.rs", "main.rs"].contains(&name) {
                continue;
            }
            let text = std::fs::read_to_string(path).unwrap();
            let code = text.split("#[cfg(test)]").next().unwrap();
            for line in code.lines().filter(|l| !l.trim_start().starts_with("//")) {
                let mut rest = line;
                while let Some(at) = rest.find("super::") {
                    let before = rest[..at].chars().last();
                    rest = &rest[at + "super::".len()..];
                    if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':') {
                        continue;
                    }
                    let names: Vec<&str> = match rest.strip_prefix('{') {
                        Some(group) => group.split('}').next().unwrap().split(',').collect(),
                        None => vec![rest],
                    };
                    for n in names {
                        let n: String = n.trim().chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
                        if !n.is_empty() && n != "super" && n != "self" && !siblings.contains(&n) {
                            out.push(format!("{}: super::{n}", path.display()));
                        }
                    }
                }
            }
        }
    }
    let mut out = Vec::new();
    walk(&crate::root().join("src"), &mut out);
    assert!(out.is_empty(), "files that reach into their folder's mod.rs:\n{}", out.join("\n"));
}

/// The per-mesh evaluation reads a `MeshProblem`, never the scene (ARCHITECTURE.md, "One path"):
/// no code line of its files (comments and test modules aside) names the type `Scene`, and the files
/// that take one mesh's problem name `MeshProblem`. A new per-mesh file joins the list.
#[test]
fn the_per_mesh_evaluation_never_reads_the_scene() {
    let takes_a_problem = [
        "evaluate/prepare.rs",
        "evaluate/stages.rs",
        "evaluate/stream.rs",
        "evaluate/details.rs",
        "evaluate/dynamics.rs",
        "evaluate/teeth.rs",
        "evaluate/contact_curves.rs",
        "evaluate/records.rs",
        "report/mod.rs",
        "report/scene.rs",
        "report/friction.rs",
        "report/points.rs",
        "report/dynamics.rs",
        "report/teeth.rs",
        "report/teeth_validity.rs",
        "report/checks.rs",
        "report/sweep.rs",
        "run_pair.rs",
    ];
    let beneath =
        ["evaluate/laws.rs", "evaluate/setup.rs", "evaluate/tally.rs", "evaluate/cases.rs", "evaluate/plan.rs"];
    let mut out = Vec::new();
    for file in takes_a_problem.iter().chain(&beneath) {
        let text = std::fs::read_to_string(crate::root().join("src").join(file)).unwrap();
        let code: Vec<&str> =
            text.split("#[cfg(test)]").next().unwrap().lines().filter(|l| !l.trim_start().starts_with("//")).collect();
        let names = |word: &str| {
            code.iter().any(|l| {
                l.match_indices(word).any(|(at, _)| {
                    let edge = |c: Option<char>| !c.is_some_and(|c| c.is_alphanumeric() || c == '_');
                    edge(l[..at].chars().last()) && edge(l[at + word.len()..].chars().next())
                })
            })
        };
        if names("Scene") {
            out.push(format!("{file} names Scene"));
        }
        if takes_a_problem.contains(file) && !names("MeshProblem") {
            out.push(format!("{file} does not take a MeshProblem"));
        }
    }
    assert!(out.is_empty(), "{}", out.join("\n"));
}
