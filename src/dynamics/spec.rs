//! The lowered `dynamics` block: the model and its parameters, the formulations, how the mesh
//! stiffness is given, the solver, the static transmission error and the free response asked for.

use crate::diagnostics::Span;
use crate::friction::catalog::FrictionLawSpec;
use crate::geometry::stiffness::{StiffnessId, StiffnessModel};
use crate::geometry::PairGeometry;

pub use super::free::FreeResponseSpec;

/// How the mesh stiffness k(t) is given: by values in a `mesh_stiffness { ... }` block, or by
/// the name of a catalogue model computed from the geometry ([`crate::geometry::stiffness::MODELS`]).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub enum StiffnessSpec {
    /// Rectangular, with one, two (and three) pairs in contact (N/m); triple defaults to 3/2 double.
    Pairs { single: f64, double: f64, triple: Option<f64> },
    /// A model computed from the geometry alone (`mesh_stiffness = iso_6336`, the default).
    Named(StiffnessId),
    /// Values over one mesh cycle (N/m), equally spaced, t = 0 when a pair enters at A.
    Table(Vec<f64>),
    /// Stiffness density k along the contact lines (N/m²), He & Singh's k: k(t) = k cos²β_b L(t)
    /// along the transverse line of action (k × face width per pair for a spur pair).
    PerLength(f64),
}

impl StiffnessSpec {
    /// The model on the pair `g`.
    pub fn build(&self, g: &PairGeometry, bodies: &crate::geometry::teeth::pair_stiffness::Bodies) -> StiffnessModel {
        match self {
            StiffnessSpec::Pairs { single, double, triple } => {
                StiffnessModel::pairs_in_contact(*single, *double, triple.unwrap_or(1.5 * double))
            }
            StiffnessSpec::Named(id) => {
                (id.entry().from_geometry.expect("lowering names only models built from the geometry"))(g, bodies)
            }
            StiffnessSpec::Table(v) => StiffnessModel::table(v.clone()),
            StiffnessSpec::PerLength(k) => StiffnessModel::per_length(*k, g),
        }
    }

    /// Whether the stiffness is computed from the teeth (the scene's teeth must then be checked).
    pub fn is_potential_energy(&self) -> bool {
        matches!(self, StiffnessSpec::Named(StiffnessId::PotentialEnergy))
    }

    /// Where the values come from, as the report says it (`given`, `table`, `per_length` or the
    /// named model's name).
    pub fn source(&self) -> &'static str {
        match self {
            StiffnessSpec::Pairs { .. } => "given",
            StiffnessSpec::Named(id) => id.name(),
            StiffnessSpec::Table(_) => "table",
            StiffnessSpec::PerLength(_) => "per_length",
        }
    }
}

/// The solver of the periodic response.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Solver {
    /// The exact propagator where it applies, 4th-order Magnus elsewhere.
    Auto,
    /// 4th-order Magnus everywhere.
    Magnus,
}

/// Which dynamic model, with the parameters its catalogue row asks for.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct DynamicModel {
    /// The catalogue row ([`crate::dynamics::models::MODELS`]).
    pub id: crate::dynamics::models::DynamicModelId,
    /// The gears' bearings, [pinion, wheel], for a model on bearings.
    pub bearings: Option<[crate::dynamics::six_dof::Bearing; 2]>,
}

/// The `dynamics` block.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DynamicsSpec {
    pub model: DynamicModel,
    pub formulations: Vec<crate::dynamics::DynamicFormulation>,
    pub stiffness: StiffnessSpec,
    pub damping_ratio: f64,
    pub friction: Option<FrictionLawSpec>,
    pub solver: Solver,
    /// Static transmission error harmonics (amplitude m, phase rad) in mesh orders 1, 2, …
    pub transmission_error: Vec<(f64, f64)>,
    /// `free_response { x0 = .. v0 = .. periods = .. }`: initial DTE (m), its rate (m/s), periods.
    pub free_response: Option<FreeResponseSpec>,
    pub span: Span,
}
