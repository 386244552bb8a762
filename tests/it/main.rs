//! The one integration test binary (each extra `tests/*.rs` would relink every dependency).

mod cli;
mod dynamics;
mod efficiency;
mod friction;
mod fuzz;
mod geometry;
mod properties;
mod specs;
mod units;

use std::path::{Path, PathBuf};

/// The project root.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Reads a scene and lowers it, panicking with the rendered diagnostics if it fails.
pub fn scene(path: &Path) -> gearloss::Scene {
    let source = std::fs::read_to_string(path).unwrap();
    gearloss::check(&path.display().to_string(), &source).unwrap_or_else(|e| panic!("{}", e.render(false)))
}
