//! What every dynamic model gives back for one formulation at one operating point, in terms no
//! model owns: the Floquet numbers, and the periodic response as generic data — the DTE and the
//! total mesh (tooth) force with their located extremes, integrated means and spectra, the friction
//! the model applies, per gear the bearing forces where the model has bearings, and the plot curves.
//!
//! A model's own response type (the SDOF model's [`super::response::PeriodicResponse`], the 6-DOF
//! model's [`super::six_dof_response::SixDofResponse`]) is turned into a [`ModelResponse`] in the
//! model's catalogue file ([`super::models`]); the evaluation, the report and the renderers read
//! only this file's types, so they never name a model.

use serde::Serialize;

use super::floquet::{Floquet, Multiplier, Verdict};
use super::free::FreeResponse;
use super::propagator::Method;
use super::sdof::DynamicFormulation;
use super::trajectory::Extremum;
use crate::numerics::quadrature::Integral;

/// One formulation at one operating point: the Floquet numbers and, when asked for, the periodic
/// (and free) response.
#[derive(Debug, Clone, Serialize)]
pub struct FormulationResult {
    pub formulation: DynamicFormulation,
    pub method: Method,
    pub multipliers: Vec<Multiplier>,
    pub spectral_radius: f64,
    pub verdict: Verdict,
    pub determinant: f64,
    pub liouville: f64,
    /// The periodic steady state (None when unstable or not asked for).
    pub response: Option<ModelResponse>,
    /// The free response from the scene's initial state (detail points, models that have one).
    pub free: Option<FreeResponse>,
}

impl FormulationResult {
    /// The Floquet numbers of a formulation, without any response.
    pub fn of<const N: usize>(formulation: DynamicFormulation, fl: &Floquet<N>) -> FormulationResult {
        FormulationResult {
            formulation,
            method: fl.method,
            multipliers: fl.multipliers.clone(),
            spectral_radius: fl.spectral_radius,
            verdict: fl.verdict,
            determinant: fl.determinant,
            liouville: fl.liouville,
            response: None,
            free: None,
        }
    }
}

/// A located range of one periodic quantity: minimum, maximum (times in mesh periods), the time
/// mean with its error estimate, and the amplitudes of mesh orders 1, 2, ….
#[derive(Debug, Clone, Serialize)]
pub struct Range {
    pub min: Extremum,
    pub max: Extremum,
    pub mean: Integral,
    pub spectrum: Vec<f64>,
}

impl Range {
    pub fn peak_to_peak(&self) -> f64 {
        self.max.value - self.min.value
    }
}

/// One gear on its bearings: bearing forces (K x, K y) and displacements along (x) and off (y)
/// the line of action.
#[derive(Debug, Clone, Serialize)]
pub struct GearResponse {
    pub bearing_force_loa: Range,
    pub bearing_force_oloa: Range,
    pub displacement_loa: [Extremum; 2],
    pub displacement_oloa: [Extremum; 2],
}

/// The periodic response of any model. Extremes carry their time in mesh periods; a quantity a
/// model does not have is None (or empty).
#[derive(Debug, Clone, Serialize)]
pub struct ModelResponse {
    /// The DTE (m): located extremes, integrated mean, spectrum of orders 1, 2, ….
    pub dte: Range,
    /// The total tooth (mesh) force (N), located [min, max].
    pub tooth_force: [Extremum; 2],
    /// max tooth force / static tooth force F0.
    pub dynamic_factor: f64,
    /// Intervals (τ from, τ to) in mesh periods where the tooth force is negative, located.
    pub separation: Vec<(f64, f64)>,
    /// Time mean of the instantaneous efficiency from the tooth force, with its error estimate,
    /// and its largest value.
    pub mean_dynamic_efficiency: Option<Integral>,
    pub max_dynamic_efficiency: Option<f64>,
    /// Peak |friction force the model applies| (N), located; None for a law that diverges at P.
    pub peak_friction_force: Option<Extremum>,
    /// Peak |friction torque| on pinion and wheel (N·m), located.
    pub peak_friction_torque: Option<[Extremum; 2]>,
    /// External formulation: peak |Σ μ_j w_j F| (μ × tooth force, which its equation does not apply).
    pub peak_mu_times_tooth_force: Option<Extremum>,
    /// The largest force on one pair (N), located.
    pub pair_force_max: Option<Extremum>,
    /// The largest friction force on one pair (N), located.
    pub pair_friction_force_max: Option<Extremum>,
    /// The integrated mean of the friction force (N).
    pub friction_force_mean: Option<f64>,
    /// Per gear on bearings (name, response); empty for a model without bearings.
    pub gears: Vec<(&'static str, GearResponse)>,
    /// The plot curves over one mesh period.
    pub curves: ResponseCurves,
}

/// The response's curves over one mesh period, at common times.
#[derive(Debug, Clone, Default, Serialize)]
pub struct ResponseCurves {
    /// Times in mesh periods, [0, 1], sorted.
    pub tau: Vec<f64>,
    /// DTE (m).
    pub dte: Vec<f64>,
    /// The friction force the model applies (N).
    pub friction_force: Vec<f64>,
    /// Tooth force of each pair slot k (the pair that entered k periods ago), NaN out of contact;
    /// empty for a model that does not resolve pairs.
    pub pair_force: Vec<Vec<f64>>,
    /// Off-line-of-action bearing force per gear (name, N); empty without bearings.
    pub bearing_force_oloa: Vec<(&'static str, Vec<f64>)>,
}
