//! The scene at its first operating point's thermal balance (`oil_temperature = equilibrium`):
//! the evaluation is prepared once at ambient to find it.

use crate::efficiency::Formulation;
use crate::model::Scene;

/// At `oil_temperature = equilibrium`: the scene with its lubricant at the balance of its first
/// operating point (first law, first formulation), where its tables, curves, film and dynamics are
/// read; the scene itself otherwise, or when that point finds no balance.
pub(crate) fn at_first_balance(scene: &Scene) -> std::borrow::Cow<'_, Scene> {
    use std::borrow::Cow;
    let (Some(span), Some(housing), Some(spec)) =
        (scene.operating.equilibrium, scene.housing.as_ref(), scene.friction.first())
    else {
        return Cow::Borrowed(scene);
    };
    let plan = super::plan::Plan::new(&scene.operating, None, &[]);
    let eval = super::prepare::prepare(scene, &plan);
    let Some(losses) = super::thermal::Losses::new(scene, &eval) else { return Cow::Borrowed(scene) };
    let f = eval.formulations.first().copied().unwrap_or(Formulation::External);
    let state = super::cases::state_at(&scene.operating, 0);
    let Some(t) = crate::thermal::balance(|t| losses.at(spec, f, state, t).total(), housing).temperature else {
        return Cow::Borrowed(scene);
    };
    Cow::Owned(scene.at_balance_of_point_1(t, span))
}
