//! Stage 3 for the `dynamics` block: the SDOF model at every operating point and formulation, the
//! stability map and the numerics study — only what the scene's analyses ask for.

use rayon::prelude::*;
use serde::Serialize;

use super::cases::Case;
use crate::dynamics::floquet::Verdict;
use crate::dynamics::numerics::{study, Study};
use crate::dynamics::propagator::Method;
use crate::dynamics::response::PeriodicResponse;
use crate::dynamics::six_dof::SixDofSystem;
use crate::dynamics::six_dof_response::{self, SixDofResponse};
use crate::dynamics::{DynamicFormulation, Floquet, Multiplier, PeriodicModel, SdofSystem, StiffnessModel};
use crate::friction::{FrictionLaw, LawContext};
use crate::geometry::{OperatingState, PairGeometry};
use crate::model::{DynamicModel, DynamicsSpec, Scene, Solver};
use crate::numerics::roots::brent;

/// One formulation at one operating point.
#[derive(Debug, Clone, Serialize)]
pub struct FormulationResult {
    pub formulation: DynamicFormulation,
    pub method: Method,
    pub multipliers: Vec<Multiplier>,
    pub spectral_radius: f64,
    pub verdict: Verdict,
    pub determinant: f64,
    pub liouville: f64,
    pub response: Option<PeriodicResponse>,
    /// The free response from the scene's initial state (detail points only).
    pub free: Option<crate::dynamics::free::FreeResponse>,
    /// The 6-DOF model's periodic response (`model = six_dof`; then `response` is None).
    pub six_dof: Option<SixDofResponse>,
}

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

fn stiffness_model(scene: &Scene, spec: &DynamicsSpec, g: &PairGeometry) -> (StiffnessModel, &'static str) {
    (spec.stiffness.build(g, &scene.gears.bodies()), spec.stiffness.source())
}

fn inertia(scene: &Scene) -> [f64; 2] {
    let j = |g: &crate::model::Gear| g.inertia.as_ref().map_or(f64::NAN, |j| j.value.value);
    [j(&scene.gears.pinion), j(&scene.gears.wheel)]
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

impl FormulationResult {
    /// The Floquet numbers of a formulation, without any response.
    fn of<const N: usize>(formulation: DynamicFormulation, fl: &Floquet<N>) -> FormulationResult {
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
            six_dof: None,
        }
    }
}

fn analyse(sys: &SdofSystem, with_response: bool, free: Option<crate::model::FreeResponseSpec>) -> FormulationResult {
    let fl = Floquet::analyse(sys);
    FormulationResult {
        response: if with_response { PeriodicResponse::compute(sys, &fl) } else { None },
        free: free.map(|fr| crate::dynamics::free::free_response(sys, &fl, [fr.x0, fr.v0], fr.periods)),
        ..FormulationResult::of(sys.formulation, &fl)
    }
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

/// The SDOF model's fixed inputs for a scene: built once, then analysed at any operating point.
pub struct DynamicsSetup<'a> {
    base: LawContext<'a>,
    spec: &'a DynamicsSpec,
    stiffness: StiffnessModel,
    source: &'static str,
    inertia: [f64; 2],
    /// Masses and bearings for `model = six_dof`.
    six: Option<([f64; 2], [crate::dynamics::six_dof::Bearing; 2])>,
}

impl<'a> DynamicsSetup<'a> {
    /// The setup when the scene has a `dynamics` block; `base` is the law context of the scene's pair
    /// (its state is replaced by each operating point's).
    pub fn new(scene: &'a Scene, base: LawContext<'a>) -> Option<DynamicsSetup<'a>> {
        let spec = scene.dynamics.as_ref()?;
        let (stiffness, source) = stiffness_model(scene, spec, base.geometry);
        let six = match spec.model {
            DynamicModel::SixDof { bearings } => {
                let m = |g: &crate::model::Gear| g.mass.as_ref().map_or(f64::NAN, |m| m.value.value);
                Some(([m(&scene.gears.pinion), m(&scene.gears.wheel)], bearings))
            }
            DynamicModel::Sdof => None,
        };
        Some(DynamicsSetup { base, spec, stiffness, source, inertia: inertia(scene), six })
    }

    fn sdof(&self, law: Option<&'a dyn FrictionLaw>, f: DynamicFormulation, state: OperatingState) -> SdofSystem<'a> {
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
        let sys = self.sdof(law, f, state);
        let Some((mass, bearings)) = self.six else {
            return analyse(&sys, with_response, self.spec.free_response);
        };
        let six = SixDofSystem::new(sys, mass, bearings);
        let fl = Floquet::analyse(&six);
        FormulationResult {
            six_dof: if with_response { SixDofResponse::compute(&six, &fl) } else { None },
            ..FormulationResult::of(f, &fl)
        }
    }

    /// The spectral radius and (when stable) the dynamic factor at one state, for stability maps.
    fn stability(
        &self,
        law: Option<&'a dyn FrictionLaw>,
        f: DynamicFormulation,
        state: OperatingState,
    ) -> (f64, Option<f64>) {
        let sys = self.sdof(law, f, state);
        match self.six {
            None => {
                let fl = Floquet::analyse(&sys);
                (fl.spectral_radius, PeriodicResponse::dynamic_factor(&sys, &fl))
            }
            Some((mass, bearings)) => {
                let six = SixDofSystem::new(sys, mass, bearings);
                let fl = Floquet::analyse(&six);
                (fl.spectral_radius, six_dof_response::dynamic_factor(&six, &fl))
            }
        }
    }

    fn law_for(&self, state: OperatingState) -> Option<Box<dyn FrictionLaw + 'a>> {
        self.spec.friction.as_ref().map(|l| l.build(&LawContext { state, ..self.base }))
    }

    /// Every formulation at operating point `case` (its index in the caller's list) with its periodic
    /// response (located extrema, spectrum, series).
    pub fn point(&self, case: usize, state: OperatingState) -> DynamicsPoint {
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

/// Evaluates the dynamics the scene asks for at the given cases (the detail points), the stability
/// map and the numerics study; None when it asks for none.
/// `base` is the law context of the scene's pair (its state is replaced by each operating point's).
/// `known` holds dynamics already computed by the sweep's stream, by point number (0-based); the
/// cases among them are not computed again.
pub fn evaluate_dynamics(
    scene: &Scene,
    cases: &[Case],
    base: LawContext,
    known: &[(usize, DynamicsPoint)],
) -> Option<DynamicsEvaluation> {
    let setup = DynamicsSetup::new(scene, base)?;
    let a = &scene.analyses;
    if !(a.dynamics || a.stability_map.is_some() || a.numerics) {
        return None;
    }
    let spec = setup.spec;
    let (stiffness, source, j) = (&setup.stiffness, setup.source, setup.inertia);
    let probe_state = cases[0].state;
    let probe = system(base, spec, stiffness, None, DynamicFormulation::Base, probe_state, j);
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
                    let rho = match setup.six {
                        None => Floquet::analyse(&system(base, spec, stiffness, law, f, state, j)).spectral_radius,
                        Some((mass, bearings)) => {
                            let six =
                                SixDofSystem::new(system(base, spec, stiffness, law, f, state, j), mass, bearings);
                            Floquet::analyse(&six).spectral_radius
                        }
                    };
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
        let sys = system(base, spec, stiffness, law, f, probe_state, j);
        match setup.six {
            None => (f, 0, study(&sys, sys.static_state())),
            Some((mass, bearings)) => {
                let six = SixDofSystem::new(sys, mass, bearings);
                let x0 = six.static_state();
                (f, 0, study(&six, x0))
            }
        }
    });
    let six_probe = setup.six.map(|(mass, bearings)| {
        SixDofSystem::new(system(base, spec, stiffness, None, DynamicFormulation::Base, probe_state, j), mass, bearings)
    });
    Some(DynamicsEvaluation {
        model: six_probe.as_ref().map_or(probe.name(), |s| s.name()),
        description: six_probe.as_ref().map_or(probe.description(), |s| s.description()),
        stiffness: stiffness.clone(),
        stiffness_source: source,
        damping_ratio: spec.damping_ratio,
        equivalent_mass: probe.equivalent_mass,
        damping: probe.damping,
        mean_stiffness: probe.mean_stiffness,
        natural_frequency: probe.natural_frequency(),
        natural_frequencies: six_probe.as_ref().map_or_else(Vec::new, |s| s.frequencies.clone()),
        stiffness_ratio: six_probe.as_ref().map(|s| s.stiffness_ratio()),
        formulations: spec.formulations.clone(),
        friction_diverges_at_pitch: law_for(probe_state).is_some_and(|l| l.diverges_at_pitch()),
        points,
        stability_map,
        unstable_ranges,
        numerics,
    })
}
