//! Stage 3, evaluate: computes only what the scene asks for, in plain SI `f64`.
//!
//! Geometry and the contact state along the line of action are always computed; friction,
//! efficiency and film thickness only when the scene's `analyses` name them.

use serde::Serialize;

use crate::geometry::contact::{reduced_modulus, Sharing};
use crate::geometry::{ContactPoint, OperatingState, SpurGeometry};
use crate::model::{LoadSharing, Scene};

/// Points sampled along the line of action for curves and plots.
pub const CURVE_SAMPLES: usize = 241;
/// Equal intervals of the contact-state table between A and E (B, P and D are added).
pub const TABLE_INTERVALS: usize = 12;

/// Everything computed for one scene.
#[derive(Debug, Clone, Serialize)]
pub struct Evaluation {
    pub geometry: SpurGeometry,
    /// E' (Pa).
    pub reduced_modulus: f64,
    pub sharing: LoadSharing,
    pub points: Vec<PointEvaluation>,
}

/// Everything computed at one operating point.
#[derive(Debug, Clone, Serialize)]
pub struct PointEvaluation {
    /// (torque index, speed index) into the scene's sweeps.
    pub index: (usize, usize),
    pub state: OperatingState,
    /// The contact-state table: the named points A B P D E and equal steps between A and E.
    pub table: Vec<(Option<&'static str>, ContactPoint)>,
}

impl Evaluation {
    pub fn sharing(&self) -> Sharing {
        match self.sharing {
            LoadSharing::Equal => Sharing::Equal,
            LoadSharing::None => Sharing::Whole,
        }
    }

    /// The contact state at `u` for an operating point.
    pub fn contact_at(&self, u: f64, state: &OperatingState) -> ContactPoint {
        self.geometry
            .contact_at(u, state, self.reduced_modulus, self.sharing())
    }

    /// Evenly spaced positions from A to E for curves, with B and D taken from both sides so that
    /// the jumps of the load share are drawn vertical.
    pub fn curve_positions(&self) -> Vec<f64> {
        let p = &self.geometry.points;
        let eps = 1e-9 * (p.e - p.a);
        let mut u: Vec<f64> = (0..CURVE_SAMPLES)
            .map(|i| p.a + (p.e - p.a) * i as f64 / (CURVE_SAMPLES - 1) as f64)
            .collect();
        u.extend([p.b - eps, p.b, p.p, p.d, p.d + eps]);
        u.sort_by(f64::total_cmp);
        u
    }
}

/// Table positions: A..E in equal steps, with B, P and D inserted, each labelled where it is a named point.
pub fn table_positions(g: &SpurGeometry) -> Vec<(Option<&'static str>, f64)> {
    let p = &g.points;
    let mut rows: Vec<(Option<&'static str>, f64)> = (0..=TABLE_INTERVALS)
        .map(|i| (None, p.a + (p.e - p.a) * i as f64 / TABLE_INTERVALS as f64))
        .collect();
    for (name, u) in p.named() {
        let tol = 1e-9 * (p.e - p.a);
        match rows.iter_mut().find(|(_, v)| (*v - u).abs() < tol) {
            Some(row) => *row = (Some(name), u),
            None => rows.push((Some(name), u)),
        }
    }
    rows.sort_by(|a, b| a.1.total_cmp(&b.1));
    rows
}

/// Evaluates a lowered scene. Lowering has checked the geometry, so this cannot fail on a lowered scene.
pub fn evaluate_scene(scene: &Scene) -> Evaluation {
    let geometry = scene
        .gears
        .geometry()
        .expect("lowering refuses pairs whose geometry fails");
    let p = &scene.gears.pinion.material;
    let w = &scene.gears.wheel.material;
    let e_r = reduced_modulus(
        [p.youngs_modulus.value.value, w.youngs_modulus.value.value],
        [p.poisson_ratio.value, w.poisson_ratio.value],
    );
    let mut eval = Evaluation {
        geometry,
        reduced_modulus: e_r,
        sharing: scene.gears.load_sharing,
        points: Vec::new(),
    };
    let rows = table_positions(&eval.geometry);
    let op = &scene.operating;
    eval.points = op
        .points()
        .into_iter()
        .map(|(ti, ni)| {
            let state = OperatingState {
                pinion_torque: op.pinion_torque.values[ti].value,
                pinion_speed: op.pinion_speed.values[ni].value,
            };
            let table = rows
                .iter()
                .map(|(name, u)| (*name, eval.contact_at(*u, &state)))
                .collect();
            PointEvaluation {
                index: (ti, ni),
                state,
                table,
            }
        })
        .collect();
    eval
}
