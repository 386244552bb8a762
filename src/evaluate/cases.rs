//! The operating points of a scene expanded once into cases, and the fixed sample sets of the
//! report: the contact-state table positions, the curve positions and cycle times, the picked
//! operating points whose curves are plotted.

use serde::Serialize;

use crate::geometry::{OperatingState, PairGeometry};

/// One operating point of the scene: the product of its sweeps expanded once, torque-major, with
/// the state in SI and the label in the units the user wrote. Evaluation, report and render all
/// read the cases; none rebuilds them from the scene.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Case {
    /// The operating point's number in the sweep, 0-based, torque-major.
    pub index: usize,
    /// Index of the torque and of the speed in the scene's sweeps.
    pub torque_index: usize,
    pub speed_index: usize,
    pub state: OperatingState,
    /// `239.3 N*m, 100 rpm`.
    pub label: String,
}

/// Operating point `k` (0-based, torque-major) of a scene's sweeps, built on its own so that a
/// sweep of any size is never expanded in memory.
pub fn case_at(op: &crate::model::Operating, k: usize) -> Case {
    let (ti, ni) = (k / op.pinion_speed.values.len(), k % op.pinion_speed.values.len());
    Case {
        index: k,
        torque_index: ti,
        speed_index: ni,
        state: state_at(op, k),
        label: format!("{}, {}", op.pinion_torque.point_label(ti), op.pinion_speed.point_label(ni)),
    }
}

/// The operating state of point `k` (no label: the inner loop of a sweep).
pub fn state_at(op: &crate::model::Operating, k: usize) -> OperatingState {
    let (ti, ni) = (k / op.pinion_speed.values.len(), k % op.pinion_speed.values.len());
    OperatingState { pinion_torque: op.pinion_torque.values[ti].value, pinion_speed: op.pinion_speed.values[ni].value }
}

/// Table positions: A..E in equal steps, with B, P and D inserted, each labelled where it is a named point.
pub fn table_positions(g: &PairGeometry) -> Vec<(Option<&'static str>, f64)> {
    let p = &g.points;
    let mut rows: Vec<(Option<&'static str>, f64)> =
        (0..=TABLE_INTERVALS).map(|i| (None, p.a + (p.e - p.a) * i as f64 / TABLE_INTERVALS as f64)).collect();
    for (name, u) in g.named_points() {
        let tol = 1e-9 * (p.e - p.a);
        match rows.iter_mut().find(|(_, v)| (*v - u).abs() < tol) {
            Some(row) => *row = (Some(name), u),
            None => rows.push((Some(name), u)),
        }
    }
    rows.sort_by(|a, b| a.1.total_cmp(&b.1));
    rows
}

/// Times in the mesh cycle (in periods) at which η(τ) curves are sampled.
pub fn cycle_times() -> Vec<f64> {
    (0..CURVE_SAMPLES).map(|i| i as f64 / (CURVE_SAMPLES - 1) as f64 * (1.0 - 1e-9)).collect()
}

/// At most this many curves of one kind are plotted (evenly picked from a sweep).
pub const MAX_CURVES: usize = 6;

/// Indices of at most `MAX_CURVES` values evenly picked from `n`.
pub fn pick(n: usize) -> Vec<usize> {
    evenly(n, MAX_CURVES)
}

/// Indices of at most `max` values evenly picked from `n` (the first and the last included).
pub fn evenly(n: usize, max: usize) -> Vec<usize> {
    if n <= max {
        return (0..n).collect();
    }
    if max < 2 {
        return vec![0];
    }
    let mut v: Vec<usize> = (0..max).map(|i| i * (n - 1) / (max - 1)).collect();
    v.dedup();
    v
}

/// Points sampled along the line of action for curves and plots.
pub const CURVE_SAMPLES: usize = 241;

/// Equal intervals of the contact-state table between A and E (B, P and D are added).
pub const TABLE_INTERVALS: usize = 12;
