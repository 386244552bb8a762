//! The one integration test binary (each extra `tests/*.rs` would relink every dependency).

mod catalogues;
mod cli;
mod drive;
mod drive_cycle;
mod drive_equilibrium;
mod drive_inch;
mod dynamics;
mod dynamics_closed_forms;
mod efficiency;
mod engine;
mod first_hour;
mod friction;
mod fuzz;
mod fuzz_campaign;
mod fuzz_mutations;
mod geometry;
mod helical;
mod helical_physics;
mod hostile_cycles;
mod internal_pair;
mod load_sharing;
mod losses;
mod oil_sweep;
mod one_stage;
mod one_stage_pair;
mod pair_alone;
mod pair_cycle;
mod planetary;
mod planetary_helical;
mod plot_text;
mod properties;
mod readme;
mod records_parquet;
mod rexs;
mod rexs_constructs;
mod rexs_planetary;
mod shaft_beam;
mod six_dof;
mod specs;
mod stage_pairs;
mod stiffness;
mod sweeps;
mod thermal;
mod undercut;
mod units;

use std::path::{Path, PathBuf};

/// The project root.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Reads a scene and lowers it, panicking with the rendered diagnostics if it fails.
/// The messages of `findings` that contain `words`.
pub fn messages_with(findings: Vec<gearloss::report::Finding>, words: &str) -> Vec<String> {
    findings.into_iter().filter(|f| f.message.contains(words)).map(|f| f.message).collect()
}

pub fn scene(path: &Path) -> gearloss::Scene {
    let source = std::fs::read_to_string(path).unwrap();
    gearloss::check(&path.display().to_string(), &source).unwrap_or_else(|e| panic!("{}", e.render(false)))
}

/// Lowers a scene from its text, panicking with the rendered diagnostics if it fails.
pub fn scene_from_text(source: &str) -> gearloss::Scene {
    gearloss::check("scene.gear", source).unwrap_or_else(|e| panic!("{}", e.render(false)))
}

/// A 40/60-tooth, 14.5° pair with a long addendum: ε_α ≈ 2.47, up to three pairs in contact.
pub fn high_contact_ratio_input() -> gearloss::geometry::PairInput {
    gearloss::geometry::PairInput {
        module: 3e-3,
        pressure_angle: 14.5f64.to_radians(),
        helix_angle: 0.0,
        teeth: [40, 60],
        profile_shift: [0.0, 0.0],
        tip_diameter: [Some(127.2e-3), Some(187.2e-3)],
        center_distance: None,
        face_width: 0.025,
        internal: false,
    }
}
