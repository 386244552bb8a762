//! The one interface a dynamic model implements for the evaluation: given the mesh at one
//! operating point and formulation (an [`SdofSystem`]: stiffness, friction, damping, inertias), the
//! model builds its own system on it and answers with generic data ([`FormulationResult`]).
//!
//! The trait is object safe: the evaluation holds a `Box<dyn GearDynamics>` built from the scene's
//! catalogue row ([`super::catalog::MODELS`]) and never names a model. A model that wraps another
//! one is a few lines; here one that analyses the SDOF model with the friction law removed:
//!
//! ```
//! use gearloss::dynamics::models::{DynamicModelId, GearDynamics, ModelFacts, Wants};
//! use gearloss::dynamics::models::sdof::Sdof;
//! use gearloss::dynamics::FormulationResult;
//! use gearloss::dynamics::numerics::Study;
//! use gearloss::dynamics::SdofSystem;
//!
//! /// The SDOF model with μ = 0 whatever the scene's law.
//! struct Frictionless;
//!
//! impl GearDynamics for Frictionless {
//!     fn id(&self) -> DynamicModelId { DynamicModelId::Sdof }
//!     fn describe(&self, mesh: SdofSystem<'_>) -> ModelFacts { Sdof.describe(mesh) }
//!     fn analyse(&self, mut mesh: SdofSystem<'_>, wants: Wants) -> FormulationResult {
//!         mesh.law = None;
//!         Sdof.analyse(mesh, wants)
//!     }
//!     fn stability(&self, mut mesh: SdofSystem<'_>) -> (f64, Option<f64>) {
//!         mesh.law = None;
//!         Sdof.stability(mesh)
//!     }
//!     fn study(&self, mut mesh: SdofSystem<'_>) -> Study {
//!         mesh.law = None;
//!         Sdof.study(mesh)
//!     }
//! }
//!
//! // Without friction the external formulation is the base one: the same ρ (to rounding).
//! use gearloss::dynamics::{DynamicFormulation, StiffnessModel};
//! use gearloss::friction::Coulomb;
//! use gearloss::geometry::OperatingState;
//! let text = include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/specs/fzg_type_c.gear"));
//! let scene = gearloss::check("fzg_type_c.gear", text).unwrap().pair_alone().unwrap();
//! let eval = gearloss::evaluate(&scene);
//! let ctx = eval.law_context(OperatingState { pinion_torque: 239.3, pinion_speed: 300.0 });
//! let law = Coulomb { mu: 0.08 };
//! let k = StiffnessModel::pairs_in_contact(1.96e8, 3.92e8, 5.88e8);
//! let mesh = |f| SdofSystem::new(ctx, Some(&law), f, k.clone(), [3.45e-4, 15.24e-4], 0.05);
//! let base = Frictionless.stability(mesh(DynamicFormulation::Base)).0;
//! let external = Frictionless.stability(mesh(DynamicFormulation::External)).0;
//! assert!((base - external).abs() < 1e-12 && base < 1.0);
//! ```

use crate::dynamics::analysis::FormulationResult;
use crate::dynamics::free::FreeResponseSpec;
use crate::dynamics::numerics::Study;
use crate::dynamics::sdof::SdofSystem;
use crate::dynamics::six_dof::Bearing;

pub(crate) use super::model_id::DynamicModelId;

/// What a model's constructor is given beyond the mesh.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModelInputs {
    /// The gears' masses [pinion, wheel] (kg), where the scene gives them.
    pub mass: [Option<f64>; 2],
    /// The gears' bearings, for a model on bearings.
    pub bearings: Option<[Bearing; 2]>,
}

/// What an analysis asks of a model beyond the Floquet numbers.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Wants {
    /// The periodic response (located extremes, means, spectra, curves).
    pub response: bool,
    /// The free response from these initial conditions (for models that have one).
    pub free: Option<FreeResponseSpec>,
}

impl Wants {
    /// The Floquet numbers alone (ρ for a stability bound).
    pub const FLOQUET: Wants = Wants { response: false, free: None };
}

/// What the report says of the model at the scene's first operating point.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelFacts {
    /// The model's name ([`crate::dynamics::PeriodicModel::name`]).
    pub name: &'static str,
    /// Its paragraph for the report ([`crate::dynamics::PeriodicModel::description`]).
    pub description: &'static str,
    /// The natural frequencies of the mean undamped system (Hz), ascending, where the model
    /// computes more than the mesh's own.
    pub natural_frequencies: Vec<f64>,
    /// The highest over the lowest of them (how stiff the system is for an integrator).
    pub stiffness_ratio: Option<f64>,
}

/// A dynamic model of the catalogue.
pub trait GearDynamics: Sync {
    /// Its catalogue row.
    fn id(&self) -> DynamicModelId;
    /// Name, description and natural frequencies, on the mesh at one operating point.
    fn describe(&self, mesh: SdofSystem<'_>) -> ModelFacts;
    /// Floquet analysis of the model built on `mesh`, and what `wants` asks for.
    fn analyse(&self, mesh: SdofSystem<'_>, wants: Wants) -> FormulationResult;
    /// The spectral radius and, when stable, the dynamic factor (located max tooth force / F0).
    fn stability(&self, mesh: SdofSystem<'_>) -> (f64, Option<f64>);
    /// The error-against-run-time study of every solver, from the static state.
    fn study(&self, mesh: SdofSystem<'_>) -> Study;
    /// The spectral radius alone.
    fn spectral_radius(&self, mesh: SdofSystem<'_>) -> f64 {
        self.analyse(mesh, Wants::FLOQUET).spectral_radius
    }
}
