//! Stage 3's set-up: everything of a scene's evaluation but its operating points.

use super::cases::table_positions;
use super::contact_curves::ContactCurves;
use super::evaluation::Evaluation;
use super::plan::Plan;
use super::setup::Setup;
use crate::efficiency;
use crate::geometry::OperatingState;
use crate::mesh::MeshProblem;
use crate::tribology::FilmInputs;

/// Everything but the operating points: geometry, materials, lubricant, the fixed sample positions.
/// Lowering has checked the geometry, so this cannot fail on a lowered mesh.
pub fn prepare(problem: &MeshProblem, plan: &Plan) -> Evaluation {
    let mesh = problem.mesh();
    let geometry = mesh.geometry();
    let e_r = mesh.reduced_modulus();
    let tribology = mesh.tribology(e_r);
    let analyses = &problem.analyses;
    let film_inputs = tribology.pressure_viscosity.filter(|_| analyses.film).map(|alpha| {
        let inputs = FilmInputs {
            dynamic_viscosity: tribology.dynamic_viscosity,
            pressure_viscosity: alpha,
            reduced_modulus: e_r,
        };
        let cutoff = problem.friction.iter().find_map(|l| l.argument("filter_cutoff")).unwrap_or(0.8e-3);
        (inputs, tribology.rq_composite.map(|rq| (rq, cutoff)))
    });
    let mut setup = Setup {
        cases: plan.detail_cases(&problem.operating),
        ohlendorf_loss_factor: 0.0,
        table_rows: table_positions(&geometry),
        positions: Vec::new(),
        geometry,
        reduced_modulus: e_r,
        sharing: problem.gears.load_sharing,
        stiffness_sharing: (problem.gears.load_sharing == crate::model::LoadSharing::Stiffness)
            .then(|| {
                problem.gears.pair_stiffness().map(|stiffness| crate::geometry::teeth::load_sharing::LoadSharing {
                    stiffness,
                    reliefs: problem.gears.reliefs(),
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
    Evaluation { setup, points: Vec::new(), contact_curves: ContactCurves::default(), dynamics: None, teeth: None }
}
