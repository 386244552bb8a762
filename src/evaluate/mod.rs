//! Stage 3, evaluate: computes only what the scene asks for, in plain SI `f64`.
//!
//! The operating points reported in full become [`Case`]s ([`cases`]); at each case the contact state along the
//! line of action is always computed, friction, efficiency and film thickness only when the scene's
//! `analyses` name them ([`laws`]), and the dynamics only when it has a `dynamics` block and asks for
//! them ([`dynamics`]). Report and render read the evaluation; they never recompute physics.

pub mod cases;
pub mod dynamics;
pub mod laws;
pub mod map;
pub mod plan;
pub mod records;
pub mod stream;
pub mod tally;

use rayon::prelude::*;
use serde::Serialize;

use crate::efficiency;
use crate::friction::LawContext;
use crate::geometry::contact::{reduced_modulus, Sharing};
use crate::geometry::{ContactPoint, OperatingState, PairGeometry};
use crate::model::{Formulation, LoadSharing, Scene};
use crate::tribology::{Film, FilmInputs, Tribology};

pub use cases::{
    case_at, cycle_times, pick, state_at, table_positions, Case, ContactCurves, CURVE_SAMPLES, MAX_CURVES,
    TABLE_INTERVALS,
};
pub use laws::{LawCurves, LawEvaluation, ValiditySummary};
pub use plan::{Plan, Shard};
pub use records::{RecordSink, SummaryRow};
pub use tally::Tally;

/// Everything computed for one scene.
#[derive(Debug, Clone)]
pub struct Evaluation {
    /// The operating points reported in full (the plan's detail points), in the order of `points`.
    pub cases: Vec<Case>,
    /// The contact-state table's positions (A..E in equal steps with B, P, D).
    pub table_rows: Vec<(Option<&'static str>, f64)>,
    /// [`Evaluation::curve_positions`], computed once.
    pub positions: Vec<f64>,
    /// Whether an analysis needs the friction laws.
    pub wants_friction: bool,
    pub geometry: PairGeometry,
    /// E' (Pa).
    pub reduced_modulus: f64,
    pub sharing: LoadSharing,
    pub tribology: Tribology,
    /// Ohlendorf's gear loss factor H_V (geometry only).
    pub ohlendorf_loss_factor: f64,
    /// Formulations evaluated (empty when the scene asks for no efficiency).
    pub formulations: Vec<Formulation>,
    /// Film-thickness inputs when the film is computed (α known and asked for or needed).
    pub film_inputs: Option<(FilmInputs, Option<(f64, f64)>)>,
    pub points: Vec<PointEvaluation>,
    pub contact_curves: ContactCurves,
    /// The dynamics, when the scene asks for them.
    pub dynamics: Option<crate::evaluate::dynamics::DynamicsEvaluation>,
    /// The efficiency map, when the scene asks for one.
    pub efficiency_map: Option<map::EfficiencyMap>,
}

/// Everything computed at one operating point.
#[derive(Debug, Clone, Serialize)]
pub struct PointEvaluation {
    /// Index into [`Evaluation::cases`].
    pub case: usize,
    pub state: OperatingState,
    /// T = 2π/(ω1 z1) (s).
    pub mesh_period: f64,
    /// The contact-state table: the named points A B P D E and equal steps between A and E.
    pub table: Vec<(Option<&'static str>, ContactPoint)>,
    /// Film thickness at the table rows, when computed.
    pub film: Option<Vec<Film>>,
    /// One entry per law of the scene, in the scene's order (empty when no analysis needs friction).
    pub laws: Vec<LawEvaluation>,
    /// Whether curves (for plots) were computed at this point.
    pub has_curves: bool,
}

impl Evaluation {
    pub fn sharing(&self) -> Sharing {
        match self.sharing {
            LoadSharing::Equal => Sharing::Equal,
            LoadSharing::None => Sharing::Whole,
        }
    }

    /// The friction-law context at an operating point.
    pub fn law_context(&self, state: OperatingState) -> LawContext<'_> {
        LawContext { geometry: &self.geometry, state, tribology: self.tribology, sharing: self.sharing() }
    }

    /// The loss budget beside the mesh at an operating point, when the scene describes its gearbox
    /// (lowering has checked that it has a lubricant then).
    pub fn loss_budget(&self, scene: &Scene, state: &OperatingState) -> Option<crate::losses::LossBudget> {
        let gearbox = scene.gearbox.as_ref()?;
        let t = &self.tribology;
        let oil = crate::losses::Oil {
            nu: t.kinematic_viscosity.unwrap_or(f64::NAN),
            rho: t.density().unwrap_or(f64::NAN),
            eta: t.dynamic_viscosity,
            mineral: scene
                .lubricant
                .as_ref()
                .and_then(|l| l.kind)
                .is_none_or(|k| k == crate::model::LubricantType::Mineral),
        };
        Some(crate::losses::loss_budget(gearbox, &self.geometry, state.pinion_torque, state.pinion_speed, &oil))
    }

    /// The contact state at `u` for an operating point.
    pub fn contact_at(&self, u: f64, state: &OperatingState) -> ContactPoint {
        self.geometry.contact_at(u, state, self.reduced_modulus, self.sharing())
    }

    /// Evenly spaced positions from A to E for curves, with every point where the number of pairs
    /// changes (B and D for ε_α < 2) taken from both sides so that the jumps of the load share are
    /// drawn vertical.
    pub fn curve_positions(&self) -> Vec<f64> {
        let p = &self.geometry.points;
        let eps = 1e-9 * (p.e - p.a);
        let mut u: Vec<f64> =
            (0..CURVE_SAMPLES).map(|i| p.a + (p.e - p.a) * i as f64 / (CURVE_SAMPLES - 1) as f64).collect();
        u.push(p.p);
        let g = &self.geometry;
        for (_, c) in g.pair_change_points() {
            u.push(c);
            // The side on which the number of pairs differs from the point itself (B: before, D: after).
            u.extend([c - eps, c + eps].into_iter().filter(|v| g.pairs_in_contact(*v) != g.pairs_in_contact(c)));
        }
        u.sort_by(f64::total_cmp);
        u
    }
}

/// The lubricant and surface data in SI.
pub fn tribology(scene: &Scene, reduced_modulus: f64) -> Tribology {
    let g = &scene.gears;
    let mean = |f: fn(&crate::model::Gear) -> Option<f64>| match (f(&g.pinion), f(&g.wheel)) {
        (Some(a), Some(b)) => Some(0.5 * (a + b)),
        _ => None,
    };
    let ra = mean(|g| g.roughness_ra.as_ref().map(|r| r.value.value));
    let rq = mean(|g| g.roughness_rq.as_ref().map(|r| r.value.value));
    let rz = mean(|g| g.roughness_rz.as_ref().map(|r| r.value.value));
    let rq_composite = match (&g.pinion.roughness_rq, &g.wheel.roughness_rq) {
        (Some(a), Some(b)) => Some(a.value.value.hypot(b.value.value)),
        _ => None,
    };
    let l = scene.lubricant.as_ref();
    let (x_l, family) = match l.and_then(|l| l.kind) {
        None => (1.0, "mineral (default)"),
        Some(base) => match crate::tribology::lubricant::iso_lubricant_factor(base) {
            Some(x) => (x, base.words()),
            None => (1.0, "synthetic ester (no ISO/TR 14179-2 X_L: 1.0)"),
        },
    };
    Tribology {
        dynamic_viscosity: l.map_or(0.0, |l| l.dynamic_viscosity.value.value),
        kinematic_viscosity: l.and_then(|l| l.kinematic_viscosity_si()),
        pressure_viscosity: l.and_then(|l| l.pressure_viscosity.as_ref().map(|a| a.value.value)),
        ra_mean: ra,
        rq_mean: rq,
        rq_composite,
        rz_mean: rz,
        reduced_modulus,
        lubricant_factor: x_l,
        lubricant_family: family,
    }
}

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
    let mut eval = Evaluation {
        cases: plan.detail_cases(&scene.operating),
        ohlendorf_loss_factor: 0.0,
        table_rows: table_positions(&geometry),
        positions: Vec::new(),
        geometry,
        reduced_modulus: e_r,
        sharing: scene.gears.load_sharing,
        tribology,
        formulations: analyses.efficiency.clone().unwrap_or_default(),
        film_inputs,
        wants_friction: analyses.friction_along_loa || analyses.efficiency.is_some(),
        points: Vec::new(),
        contact_curves: ContactCurves::default(),
        dynamics: None,
        efficiency_map: None,
    };
    eval.positions = eval.curve_positions();
    eval.ohlendorf_loss_factor =
        efficiency::ohlendorf_loss_factor(&eval.law_context(OperatingState { pinion_torque: 1.0, pinion_speed: 1.0 }));
    eval
}

/// The contact-state table of one operating point.
pub fn contact_table(eval: &Evaluation, state: &OperatingState) -> Vec<(Option<&'static str>, ContactPoint)> {
    eval.table_rows.iter().map(|(name, u)| (*name, eval.contact_at(*u, state))).collect()
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
    eval.contact_curves = cases::contact_curves(scene, eval);
    eval.dynamics =
        crate::evaluate::dynamics::evaluate_dynamics(scene, &eval.cases, eval.law_context(eval.cases[0].state), known);
    eval.efficiency_map = map::evaluate_map(scene, eval);
}
