//! Stage 3 for the `dynamics` block: the scene's dynamic model (a catalogue row,
//! [`crate::dynamics::models`]) at every operating point and formulation, the
//! stability map and the numerics study — only what the scene's analyses ask for.

use rayon::prelude::*;
use serde::Serialize;

use super::cases::Case;
pub(crate) use crate::dynamics::analysis::FormulationResult;
use crate::dynamics::models::{GearDynamics, ModelInputs, Wants};
use crate::dynamics::numerics::Study;
use crate::dynamics::{DynamicFormulation, SdofSystem, StiffnessModel};
use crate::friction::{FrictionLaw, LawContext};
use crate::geometry::stiffness::{iso_6336, StiffnessId};
use crate::geometry::teeth::iso_6336_method_b::IsoStiffness;
use crate::geometry::{OperatingState, PairGeometry};
use crate::mesh::MeshProblem;
use crate::model::{DynamicsSpec, Solver, StiffnessSpec};
use crate::numerics::roots::brent;

#[derive(Debug, Clone, Serialize)]
pub struct DynamicsPoint {
    /// Index into the evaluation's cases.
    pub case: usize,
    pub state: OperatingState,
    pub mesh_frequency: f64,
    pub results: Vec<FormulationResult>,
}

/// Spectral radius and dynamic factor of each formulation at one speed of the map.
#[derive(Debug, Clone, Serialize)]
pub struct StabilityPoint {
    pub pinion_speed: f64,
    pub spectral_radius: Vec<f64>,
    pub dynamic_factor: Vec<Option<f64>>,
}

#[derive(Debug, Clone)]
pub struct DynamicsEvaluation {
    /// The model that ran ([`crate::dynamics::PeriodicModel::name`]).
    pub model: &'static str,
    /// The model's paragraph for the report ([`crate::dynamics::PeriodicModel::description`]).
    pub description: &'static str,
    pub stiffness: StiffnessModel,
    /// "given", "iso_6336" or "table".
    pub stiffness_source: &'static str,
    /// With `mesh_stiffness = iso_6336`: ISO 6336-1 Method B's figures and readings it is built from.
    pub iso_6336: Option<IsoStiffness>,
    pub damping_ratio: f64,
    pub equivalent_mass: f64,
    pub damping: f64,
    pub mean_stiffness: f64,
    pub natural_frequency: f64,
    /// 6-DOF: the natural frequencies of the mean undamped system (Hz), ascending, and the ratio of
    /// the highest to the lowest (how stiff the system is for an integrator).
    pub natural_frequencies: Vec<f64>,
    pub stiffness_ratio: Option<f64>,
    pub formulations: Vec<DynamicFormulation>,
    /// The friction law diverges at the pitch point (no finite peak friction force).
    pub friction_diverges_at_pitch: bool,
    pub points: Vec<DynamicsPoint>,
    pub stability_map: Option<Vec<StabilityPoint>>,
    /// Per formulation: speed ranges (rad/s) where ρ > 1, their bounds located by Brent's method on
    /// ρ(ω) − 1 between the map's speeds (to 1e-9 relative); a range open at an end of the map ends there.
    pub unstable_ranges: Vec<Vec<(f64, f64)>>,
    /// The formulation and operating point (index) of the numerics study, and the study.
    pub numerics: Option<(DynamicFormulation, usize, Study)>,
}

fn stiffness_model(problem: &MeshProblem, spec: &DynamicsSpec, g: &PairGeometry) -> (StiffnessModel, &'static str) {
    (spec.stiffness.build(g, &problem.gears.bodies()), spec.stiffness.source())
}

fn inertia(problem: &MeshProblem) -> Option<[f64; 2]> {
    let j = |g: &crate::model::Gear| g.inertia.as_ref().map(|j| j.value.value);
    Some([j(&problem.gears.pinion)?, j(&problem.gears.wheel)?])
}

fn system<'a>(
    base: LawContext<'a>,
    spec: &DynamicsSpec,
    stiffness: &StiffnessModel,
    law: Option<&'a dyn FrictionLaw>,
    f: DynamicFormulation,
    state: OperatingState,
    inertia: [f64; 2],
) -> SdofSystem<'a> {
    let ctx = LawContext { state, ..base };
    let law = if f == DynamicFormulation::Base { None } else { law };
    let mut sys = SdofSystem::new(ctx, law, f, stiffness.clone(), inertia, spec.damping_ratio);
    sys.allow_exact = spec.solver == Solver::Auto;
    sys.transmission_error = spec.transmission_error.clone();
    sys
}

/// ρ above 1 by more than this is unstable (the verdict's margin, [`Verdict`]).
const UNSTABLE_MARGIN: f64 = 1e-9;

/// The ranges where ρ > 1: between consecutive map speeds whose verdicts differ, the bound is the root
/// of `excess(ω) = ρ(ω) − 1 − margin`, located by Brent's method to 1e-9 of the speed.
fn unstable_ranges(rows: impl Iterator<Item = (f64, f64)>, excess: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    let mut open: Option<f64> = None;
    let mut prev: Option<(f64, bool)> = None;
    for (w, rho) in rows {
        let bad = rho > 1.0 + UNSTABLE_MARGIN;
        match prev {
            None if bad => open = Some(w),
            Some((w0, was_bad)) if was_bad != bad => {
                let bound = brent(&excess, w0, w, 1e-9 * w);
                if bad {
                    open = Some(bound)
                } else if let Some(a) = open.take() {
                    out.push((a, bound))
                }
            }
            _ => {}
        }
        prev = Some((w, bad));
    }
    if let (Some(a), Some((w, _))) = (open, prev) {
        out.push((a, w));
    }
    out
}

/// The dynamic model's fixed inputs for a scene: built once, then analysed at any operating point.
pub(crate) struct DynamicsSetup<'a> {
    base: LawContext<'a>,
    spec: &'a DynamicsSpec,
    stiffness: StiffnessModel,
    source: &'static str,
    inertia: [f64; 2],
    /// The scene's model, from its catalogue row.
    model: Box<dyn GearDynamics>,
}

impl<'a> DynamicsSetup<'a> {
    /// The setup when the mesh's problem has a `dynamics` block and the inputs its model needs (the gears'
    /// inertias, and masses and bearings on bearings: lowering refuses a scene that asks for dynamics
    /// without them); `base` is the law context of the problem's pair (its state is replaced by each
    /// operating point's).
    pub(crate) fn new(problem: &'a MeshProblem, base: LawContext<'a>) -> Option<DynamicsSetup<'a>> {
        let spec = problem.dynamics.as_ref()?;
        let inertia = inertia(problem)?;
        let mass = |g: &crate::model::Gear| g.mass.as_ref().map(|m| m.value.value);
        let inputs = ModelInputs {
            mass: [mass(&problem.gears.pinion), mass(&problem.gears.wheel)],
            bearings: spec.model.bearings,
        };
        let model = (spec.model.id.entry().build)(&inputs)?;
        let (stiffness, source) = stiffness_model(problem, spec, base.geometry);
        Some(DynamicsSetup { base, spec, stiffness, source, inertia, model })
    }

    /// The mesh at one state and formulation (no law for the base formulation).
    fn mesh(&self, law: Option<&'a dyn FrictionLaw>, f: DynamicFormulation, state: OperatingState) -> SdofSystem<'a> {
        system(self.base, self.spec, &self.stiffness, law, f, state, self.inertia)
    }

    /// The formulation at one state: Floquet analysis, and with `with_response` the periodic (and
    /// free) response, by the scene's model.
    fn analyse(
        &self,
        law: Option<&'a dyn FrictionLaw>,
        f: DynamicFormulation,
        state: OperatingState,
        with_response: bool,
    ) -> FormulationResult {
        let wants = Wants { response: with_response, free: self.spec.free_response };
        self.model.analyse(self.mesh(law, f, state), wants)
    }

    /// The spectral radius and (when stable) the dynamic factor at one state, for stability maps.
    fn stability(
        &self,
        law: Option<&'a dyn FrictionLaw>,
        f: DynamicFormulation,
        state: OperatingState,
    ) -> (f64, Option<f64>) {
        self.model.stability(self.mesh(law, f, state))
    }

    fn law_for(&self, state: OperatingState) -> Option<Box<dyn FrictionLaw + 'a>> {
        self.spec.friction.as_ref().map(|l| super::setup::law_at(l, &LawContext { state, ..self.base }))
    }

    /// Every formulation at operating point `case` (its index in the caller's list) with its periodic
    /// response (located extrema, spectrum, series).
    pub(crate) fn point(&self, case: usize, state: OperatingState) -> DynamicsPoint {
        let law = self.law_for(state);
        let results = self
            .spec
            .formulations
            .iter()
            .map(|f| {
                let law = if *f == DynamicFormulation::Base { None } else { law.as_deref() };
                self.analyse(law, *f, state, true)
            })
            .collect();
        DynamicsPoint {
            case,
            state,
            mesh_frequency: state.pinion_speed * self.base.geometry.teeth[0] as f64 / (2.0 * std::f64::consts::PI),
            results,
        }
    }
}

/// Evaluates the dynamics the mesh's problem asks for at the given cases (the detail points), the stability
/// map and the numerics study; None when it asks for none.
/// `base` is the law context of the problem's pair (its state is replaced by each operating point's).
/// `known` holds dynamics already computed by the sweep's stream, by point number (0-based); the
/// cases among them are not computed again.
pub(crate) fn evaluate_dynamics(
    problem: &MeshProblem,
    cases: &[Case],
    base: LawContext,
    known: &[(usize, DynamicsPoint)],
) -> Option<DynamicsEvaluation> {
    let setup = DynamicsSetup::new(problem, base)?;
    let a = &problem.analyses;
    if !(a.dynamics || a.stability_map.is_some() || a.numerics) {
        return None;
    }
    let spec = setup.spec;
    let probe_state = cases[0].state;
    let probe = setup.mesh(None, DynamicFormulation::Base, probe_state);
    let law_for = |state: OperatingState| setup.law_for(state);
    let points = if a.dynamics {
        cases
            .par_iter()
            .enumerate()
            .map(|(k, case)| match known.iter().find(|(i, _)| *i == case.index) {
                Some((_, p)) => DynamicsPoint { case: k, ..p.clone() },
                None => setup.point(k, case.state),
            })
            .collect()
    } else {
        Vec::new()
    };
    let stability_map: Option<Vec<StabilityPoint>> = a.stability_map.as_ref().map(|speeds| {
        speeds
            .values
            .par_iter()
            .map(|w| {
                let state = OperatingState { pinion_torque: probe_state.pinion_torque, pinion_speed: w.value };
                let law = law_for(state);
                let results: Vec<(f64, Option<f64>)> = spec
                    .formulations
                    .iter()
                    .map(|f| {
                        let law = if *f == DynamicFormulation::Base { None } else { law.as_deref() };
                        setup.stability(law, *f, state)
                    })
                    .collect();
                StabilityPoint {
                    pinion_speed: w.value,
                    spectral_radius: results.iter().map(|r| r.0).collect(),
                    dynamic_factor: results.iter().map(|r| r.1).collect(),
                }
            })
            .collect()
    });
    let unstable_ranges = match &stability_map {
        None => Vec::new(),
        Some(rows) => (0..spec.formulations.len())
            .map(|i| {
                let rho = |w: f64| {
                    let state = OperatingState { pinion_torque: probe_state.pinion_torque, pinion_speed: w };
                    let law = law_for(state);
                    let f = spec.formulations[i];
                    let law = if f == DynamicFormulation::Base { None } else { law.as_deref() };
                    let rho = setup.model.spectral_radius(setup.mesh(law, f, state));
                    rho - (1.0 + UNSTABLE_MARGIN)
                };
                unstable_ranges(rows.iter().map(|r| (r.pinion_speed, r.spectral_radius[i])), rho)
            })
            .collect(),
    };
    let numerics = a.numerics.then(|| {
        let f = if spec.formulations.contains(&DynamicFormulation::External) {
            DynamicFormulation::External
        } else {
            spec.formulations[0]
        };
        let law = law_for(probe_state);
        let law = if f == DynamicFormulation::Base { None } else { law.as_deref() };
        (f, 0, setup.model.study(setup.mesh(law, f, probe_state)))
    });
    let facts = setup.model.describe(setup.mesh(None, DynamicFormulation::Base, probe_state));
    Some(DynamicsEvaluation {
        model: facts.name,
        description: facts.description,
        stiffness: setup.stiffness.clone(),
        stiffness_source: setup.source,
        iso_6336: matches!(spec.stiffness, StiffnessSpec::Named(StiffnessId::Iso6336))
            .then(|| iso_6336::method_b(setup.base.geometry, &problem.gears.bodies())),
        damping_ratio: spec.damping_ratio,
        equivalent_mass: probe.equivalent_mass,
        damping: probe.damping,
        mean_stiffness: probe.mean_stiffness,
        natural_frequency: probe.natural_frequency(),
        natural_frequencies: facts.natural_frequencies,
        stiffness_ratio: facts.stiffness_ratio,
        formulations: spec.formulations.clone(),
        friction_diverges_at_pitch: law_for(probe_state).is_some_and(|l| l.diverges_at_pitch()),
        points,
        stability_map,
        unstable_ranges,
        numerics,
    })
}
