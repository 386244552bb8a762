//! Stage 3, evaluate: computes only what the scene asks for, in plain SI `f64`.
//!
//! The operating points reported in full become [`Case`]s ([`cases`]); at each case the contact state along the
//! line of action is always computed, friction, efficiency and film thickness only when the scene's
//! `analyses` name them ([`laws`]), and the dynamics only when it has a `dynamics` block and asks for
//! them ([`dynamics`]). Report and render read the evaluation; they never recompute physics.

pub mod cases;
pub mod contact_curves;
pub mod dynamics;
pub mod evaluation;
pub mod laws;
pub mod map;
pub mod plan;
pub mod records;
pub mod setup;
pub mod stages;
pub mod stream;
pub mod tally;
pub mod teeth;
pub mod thermal;

use rayon::prelude::*;

use crate::efficiency;
use crate::geometry::contact::reduced_modulus;
use crate::geometry::OperatingState;
use crate::model::Scene;
use crate::tribology::FilmInputs;

pub use cases::{
    case_at, cycle_times, pick, state_at, table_positions, Case, CURVE_SAMPLES, MAX_CURVES, TABLE_INTERVALS,
};
pub use contact_curves::ContactCurves;
pub use evaluation::{Evaluation, PointEvaluation};
pub use laws::{LawCurves, LawEvaluation, ValiditySummary};
pub use plan::{Plan, Shard};
pub use records::{RecordSink, SummaryRow};
pub use setup::{contact_table, tribology, Setup};
pub use tally::Tally;

/// Evaluates a lowered scene in full: every operating point in detail (small scenes, tests and
/// benches; a run over a sweep uses [`prepare`], [`stream::evaluate_records`] and [`evaluate_details`]).
pub fn evaluate_scene(scene: &Scene) -> Evaluation {
    let plan = Plan::new(&scene.operating, None, &[]);
    let mut eval = prepare(scene, &plan);
    evaluate_details(scene, &mut eval, &plan, &[], &|| {});
    eval
}

/// Everything but the operating points: geometry, materials, lubricant, the fixed sample positions.
/// Lowering has checked the geometry, so this cannot fail on a lowered scene.
pub fn prepare(scene: &Scene, plan: &Plan) -> Evaluation {
    let geometry = scene.gears.geometry().expect("lowering refuses pairs whose geometry fails");
    let p = &scene.gears.pinion.material;
    let w = &scene.gears.wheel.material;
    let e_r = reduced_modulus(
        [p.youngs_modulus.value.value, w.youngs_modulus.value.value],
        [p.poisson_ratio.value, w.poisson_ratio.value],
    );
    let tribology = tribology(scene, e_r);
    let analyses = &scene.analyses;
    let film_inputs = tribology.pressure_viscosity.filter(|_| analyses.film).map(|alpha| {
        let inputs = FilmInputs {
            dynamic_viscosity: tribology.dynamic_viscosity,
            pressure_viscosity: alpha,
            reduced_modulus: e_r,
        };
        let cutoff = scene.friction.iter().find_map(|l| l.argument("filter_cutoff")).unwrap_or(0.8e-3);
        (inputs, tribology.rq_composite.map(|rq| (rq, cutoff)))
    });
    let mut setup = Setup {
        cases: plan.detail_cases(&scene.operating),
        ohlendorf_loss_factor: 0.0,
        table_rows: table_positions(&geometry),
        positions: Vec::new(),
        geometry,
        reduced_modulus: e_r,
        sharing: scene.gears.load_sharing,
        stiffness_sharing: (scene.gears.load_sharing == crate::model::LoadSharing::Stiffness)
            .then(|| {
                scene.gears.pair_stiffness().map(|stiffness| crate::geometry::teeth::load_sharing::LoadSharing {
                    stiffness,
                    reliefs: scene.gears.reliefs(),
                })
            })
            .flatten(),
        tribology,
        formulations: analyses.efficiency.clone().unwrap_or_default(),
        film_inputs,
        wants_friction: analyses.friction_along_loa || analyses.efficiency.is_some(),
    };
    setup.positions = setup.curve_positions();
    setup.ohlendorf_loss_factor =
        efficiency::ohlendorf_loss_factor(&setup.law_context(OperatingState { pinion_torque: 1.0, pinion_speed: 1.0 }));
    Evaluation {
        setup,
        points: Vec::new(),
        contact_curves: ContactCurves::default(),
        dynamics: None,
        efficiency_map: None,
        thermal: None,
        teeth: None,
    }
}

/// The detail points of the plan in full (tables, film, laws, curves), the contact curves and the
/// dynamics; `tick` is called once per detail point.
/// `known` are dynamics the sweep's stream already computed (by point number), reused as they are.
pub fn evaluate_details(
    scene: &Scene,
    eval: &mut Evaluation,
    plan: &Plan,
    known: &[(usize, dynamics::DynamicsPoint)],
    tick: &(dyn Fn() + Sync),
) {
    let points: Vec<PointEvaluation> = eval
        .cases
        .par_iter()
        .enumerate()
        .map(|(i, case)| {
            let state = case.state;
            let table = contact_table(eval, &state);
            let film =
                eval.film_inputs.map(|(inputs, lambda)| table.iter().map(|(_, c)| inputs.film(c, lambda)).collect());
            let curves = plan.curves.binary_search(&case.index).is_ok();
            let laws = if eval.wants_friction {
                scene.friction.iter().map(|spec| laws::evaluate_law(eval, spec, state, &table, true, curves)).collect()
            } else {
                Vec::new()
            };
            tick();
            let mesh_period = eval.geometry.mesh_period(state.pinion_speed);
            PointEvaluation { case: i, state, mesh_period, table, film, laws, has_curves: curves }
        })
        .collect();
    eval.points = points;
    eval.contact_curves = contact_curves::contact_curves(scene, eval);
    eval.dynamics = dynamics::evaluate_dynamics(scene, &eval.cases, eval.law_context(eval.cases[0].state), known);
    eval.efficiency_map = map::evaluate_map(scene, eval);
    eval.thermal = thermal::thermal_details(scene, eval);
    eval.teeth = teeth::teeth_details(scene, &eval.geometry);
}
