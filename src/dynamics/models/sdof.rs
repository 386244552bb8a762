//! The SDOF torsional model along the line of action (Fernandes et al. eqs 3–20; physics notes,
//! "Dynamics"): x = DTE = R_p θ_p − R_w θ_w, m_e ẍ + c ẋ + k(t) x = F0 + friction terms, in the
//! base, external, internal and internal-chord formulations. The system is the mesh itself
//! ([`SdofSystem`]); its periodic response is [`PeriodicResponse`], its free response
//! `crate::dynamics::free`.

use super::gear_dynamics::{DynamicModelId, GearDynamics, ModelFacts, ModelInputs, Wants};
use crate::dynamics::analysis::{FormulationResult, ModelResponse, Range, ResponseCurves};
use crate::dynamics::free::free_response;
use crate::dynamics::numerics::{study, Study};
use crate::dynamics::response::PeriodicResponse;
use crate::dynamics::{Floquet, PeriodicModel, SdofSystem};

/// The SDOF model (no parameters beyond the mesh).
#[derive(Debug, Clone, Copy, Default)]
pub struct Sdof;

/// The catalogue's constructor.
pub fn build(_: &ModelInputs) -> Option<Box<dyn GearDynamics>> {
    Some(Box::new(Sdof))
}

impl GearDynamics for Sdof {
    fn id(&self) -> DynamicModelId {
        DynamicModelId::Sdof
    }

    fn describe(&self, mesh: SdofSystem<'_>) -> ModelFacts {
        ModelFacts {
            name: mesh.name(),
            description: mesh.description(),
            natural_frequencies: Vec::new(),
            stiffness_ratio: None,
        }
    }

    fn analyse(&self, mesh: SdofSystem<'_>, wants: Wants) -> FormulationResult {
        let fl = Floquet::analyse(&mesh);
        FormulationResult {
            response: if wants.response { PeriodicResponse::compute(&mesh, &fl).map(generic) } else { None },
            free: wants.free.map(|fr| free_response(&mesh, &fl, [fr.x0, fr.v0], fr.periods)),
            ..FormulationResult::of(mesh.formulation, &fl)
        }
    }

    fn stability(&self, mesh: SdofSystem<'_>) -> (f64, Option<f64>) {
        let fl = Floquet::analyse(&mesh);
        (fl.spectral_radius, PeriodicResponse::dynamic_factor(&mesh, &fl))
    }

    fn study(&self, mesh: SdofSystem<'_>) -> Study {
        study(&mesh, mesh.static_state())
    }
}

/// The SDOF response as generic data: no bearings, pair forces resolved.
fn generic(r: PeriodicResponse) -> ModelResponse {
    let s = r.series;
    ModelResponse {
        dte: Range {
            min: r.dte_min,
            max: r.dte_max,
            mean: r.dte_mean,
            spectrum: r.spectrum.iter().map(|(_, a)| *a).collect(),
        },
        tooth_force: [r.tooth_force_min, r.tooth_force_max],
        dynamic_factor: r.dynamic_factor,
        separation: r.separation,
        mean_dynamic_efficiency: r.mean_dynamic_efficiency,
        max_dynamic_efficiency: r.max_dynamic_efficiency,
        peak_friction_force: r.peak_friction_force,
        peak_friction_torque: r.peak_friction_torque,
        peak_mu_times_tooth_force: r.peak_mu_times_tooth_force,
        pair_force_max: None,
        pair_friction_force_max: None,
        friction_force_mean: None,
        gears: Vec::new(),
        curves: ResponseCurves {
            tau: s.tau,
            dte: s.dte,
            friction_force: s.friction_force,
            pair_force: s.pair_force,
            bearing_force_oloa: Vec::new(),
        },
    }
}
