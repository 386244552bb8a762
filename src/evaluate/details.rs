//! Stage 3's detail points: the plan's points in full, the contact curves, the dynamics, the map,
//! the thermal balance and the teeth, each only when the scene asks for it.

use rayon::prelude::*;

use super::evaluation::{Evaluation, PointEvaluation};
use super::plan::Plan;
use super::setup::contact_table;
use super::{contact_curves, dynamics, laws, teeth};
use crate::mesh::MeshProblem;

/// The detail points of the plan in full (tables, film, laws, curves), the contact curves and the
/// dynamics; `tick` is called once per detail point.
/// `known` is what the sweep's stream already computed (dynamics by point number, the teeth),
/// reused as it is.
pub fn evaluate_details(
    problem: &MeshProblem,
    eval: &mut Evaluation,
    plan: &Plan,
    known: &super::stream::Streamed,
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
                problem
                    .friction
                    .iter()
                    .map(|spec| laws::evaluate_law(eval, spec, state, &table, true, curves))
                    .collect()
            } else {
                Vec::new()
            };
            tick();
            let mesh_period = eval.geometry.mesh_period(state.pinion_speed);
            PointEvaluation { case: i, state, mesh_period, table, film, laws, has_curves: curves }
        })
        .collect();
    eval.points = points;
    eval.contact_curves = contact_curves::contact_curves(problem, eval);
    eval.dynamics = dynamics::evaluate_dynamics(
        problem,
        &eval.cases,
        eval.law_context(eval.cases[0].state),
        &known.detail_dynamics,
    );
    eval.teeth = known.teeth.clone().or_else(|| teeth::teeth_details(problem, &eval.geometry));
}
