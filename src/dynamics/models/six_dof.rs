//! The 6-DOF model of a gear pair on bearings with friction off the line of action
//! (He–Cho–Singh eqs 1–9 for spur pairs; He & Singh eqs 1–17 for helical pairs; physics notes,
//! "Multi-DOF models"): θ, the line-of-action (x) and off-line-of-action (y) translations of both
//! gears, built on the SDOF mesh ([`SixDofSystem`]); its periodic response is [`SixDofResponse`].
//! It takes the base and internal formulations (friction acts through the mesh force) and needs
//! the gears' masses and bearings.

use super::gear_dynamics::{DynamicModelId, GearDynamics, ModelFacts, ModelInputs, Wants};
use crate::dynamics::analysis::{FormulationResult, ModelResponse, ResponseCurves};
use crate::dynamics::numerics::{study, Study};
use crate::dynamics::six_dof::{Bearing, SixDofSystem};
use crate::dynamics::six_dof_response::{dynamic_factor, SixDofResponse};
use crate::dynamics::trajectory::Extremum;
use crate::dynamics::{Floquet, PeriodicModel, SdofSystem};

/// The 6-DOF model: the gears' masses [pinion, wheel] (kg) and bearings.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SixDof {
    pub mass: [f64; 2],
    pub bearings: [Bearing; 2],
}

/// The catalogue's constructor: `None` without both masses and the bearings (lowering names the
/// missing key of a scene that asks for dynamics).
pub(crate) fn build(inputs: &ModelInputs) -> Option<Box<dyn GearDynamics>> {
    let [Some(pinion), Some(wheel)] = inputs.mass else { return None };
    Some(Box::new(SixDof { mass: [pinion, wheel], bearings: inputs.bearings? }))
}

impl SixDof {
    fn system<'a>(&self, mesh: SdofSystem<'a>) -> SixDofSystem<'a> {
        SixDofSystem::new(mesh, self.mass, self.bearings)
    }
}

impl GearDynamics for SixDof {
    fn id(&self) -> DynamicModelId {
        DynamicModelId::SixDof
    }

    fn describe(&self, mesh: SdofSystem<'_>) -> ModelFacts {
        let six = self.system(mesh);
        ModelFacts {
            name: six.name(),
            description: six.description(),
            natural_frequencies: six.frequencies.clone(),
            stiffness_ratio: six.stiffness_ratio(),
        }
    }

    /// The free response is the SDOF model's alone: `wants.free` is not used here.
    fn analyse(&self, mesh: SdofSystem<'_>, wants: Wants) -> FormulationResult {
        let f = mesh.formulation;
        let six = self.system(mesh);
        let fl = Floquet::analyse(&six);
        FormulationResult {
            response: if wants.response { SixDofResponse::compute(&six, &fl).map(generic) } else { None },
            ..FormulationResult::of(f, &fl)
        }
    }

    fn stability(&self, mesh: SdofSystem<'_>) -> (f64, Option<f64>) {
        let six = self.system(mesh);
        let fl = Floquet::analyse(&six);
        (fl.spectral_radius, dynamic_factor(&six, &fl))
    }

    fn study(&self, mesh: SdofSystem<'_>) -> Study {
        let six = self.system(mesh);
        let x0 = six.static_state();
        study(&six, x0)
    }
}

/// The 6-DOF response as generic data: the mesh force as the tooth force, the gears' bearings,
/// no pair-resolved curves, no separation intervals or dynamic efficiency (not computed here).
fn generic(x: SixDofResponse) -> ModelResponse {
    let (lo, hi) = (x.friction_force.min, x.friction_force.max);
    let peak = if hi.value.abs() >= lo.value.abs() { hi } else { Extremum { value: lo.value.abs(), time: lo.time } };
    let [tau, dte, pinion, wheel, friction] = x.series;
    let [gear_p, gear_w] = x.gears;
    ModelResponse {
        dte: x.dte,
        tooth_force: x.mesh_force,
        dynamic_factor: x.dynamic_factor,
        separation: Vec::new(),
        mean_dynamic_efficiency: None,
        max_dynamic_efficiency: None,
        peak_friction_force: Some(peak),
        peak_friction_torque: None,
        peak_mu_times_tooth_force: None,
        pair_force_max: Some(x.pair_force_max),
        pair_friction_force_max: Some(x.pair_friction_force_max),
        friction_force_mean: Some(x.friction_force.mean.value),
        gears: vec![("pinion", gear_p), ("wheel", gear_w)],
        curves: ResponseCurves {
            tau,
            dte,
            friction_force: friction,
            pair_force: Vec::new(),
            bearing_force_oloa: vec![("pinion", pinion), ("wheel", wheel)],
        },
    }
}
