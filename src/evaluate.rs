//! Stage 3, evaluate: computes only what the scene asks for, in plain SI `f64`.
//!
//! Geometry and the contact state along the line of action are always computed; friction,
//! efficiency and film thickness only when the scene's `analyses` name them.

use rayon::prelude::*;
use serde::Serialize;

use crate::efficiency::{self, EfficiencyResult};
use crate::friction::catalog::LawId;
use crate::friction::{FrictionLaw, LawContext, Parameter, Regime};
use crate::geometry::contact::{reduced_modulus, Sharing};
use crate::geometry::{ContactPoint, OperatingState, SpurGeometry};
use crate::model::{Formulation, LoadSharing, LubricantType, Scene};
use crate::numerics::quadrature::Integral;
use crate::tribology::{Film, FilmInputs, Tribology};

/// Points sampled along the line of action for curves and plots.
pub const CURVE_SAMPLES: usize = 241;
/// Equal intervals of the contact-state table between A and E (B, P and D are added).
pub const TABLE_INTERVALS: usize = 12;

/// One operating point of the scene: the product of its sweeps expanded once, torque-major, with
/// the state in SI and the label in the units the user wrote. Evaluation, report and render all
/// read the cases; none rebuilds them from the scene.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Case {
    /// Index of the torque and of the speed in the scene's sweeps.
    pub torque_index: usize,
    pub speed_index: usize,
    pub state: OperatingState,
    /// `239.3 N*m, 100 rpm`.
    pub label: String,
}

/// The cases of a scene's operating sweeps.
pub fn cases(op: &crate::model::Operating) -> Vec<Case> {
    let mut out = Vec::with_capacity(op.pinion_torque.values.len() * op.pinion_speed.values.len());
    for (ti, torque) in op.pinion_torque.values.iter().enumerate() {
        for (ni, speed) in op.pinion_speed.values.iter().enumerate() {
            out.push(Case {
                torque_index: ti,
                speed_index: ni,
                state: OperatingState { pinion_torque: torque.value, pinion_speed: speed.value },
                label: format!(
                    "{} {}, {} {}",
                    op.pinion_torque.written_values[ti],
                    op.pinion_torque.unit,
                    op.pinion_speed.written_values[ni],
                    op.pinion_speed.unit
                ),
            });
        }
    }
    out
}

/// Contact quantities along the line of action for the contact-state plot: v_s at each plotted speed
/// (first torque), p_H at each plotted torque (first speed), SR at the first operating point.
#[derive(Debug, Clone, Default)]
pub struct ContactCurves {
    /// Positions from T1 (m), [`Evaluation::curve_positions`].
    pub u: Vec<f64>,
    /// (speed as written, v_s in m/s).
    pub sliding_velocity: Vec<(String, Vec<f64>)>,
    pub slide_to_roll: Vec<f64>,
    /// (torque as written, p_H in Pa).
    pub hertz_pressure: Vec<(String, Vec<f64>)>,
}

/// Everything computed for one scene.
#[derive(Debug, Clone)]
pub struct Evaluation {
    /// The operating points, in the order of `points`.
    pub cases: Vec<Case>,
    pub geometry: SpurGeometry,
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
    pub dynamics: Option<crate::evaluate_dynamics::DynamicsEvaluation>,
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

/// Where a law left its validity range along the line of action.
#[derive(Debug, Clone, Serialize)]
pub struct ValiditySummary {
    pub samples: usize,
    pub outside: usize,
    /// (from, to) along the line of action from T1 (m), with the first reason met there.
    pub intervals: Vec<(f64, f64, &'static str)>,
}

/// One friction law at one operating point.
#[derive(Debug, Clone, Serialize)]
pub struct LawEvaluation {
    pub id: LawId,
    pub title: &'static str,
    pub parameters: Vec<Parameter>,
    pub notes: Vec<String>,
    pub diverges_at_pitch: bool,
    /// Signed μ at the table rows; None where the law diverges (at P).
    pub table: Vec<Option<f64>>,
    /// Regime at the table rows (composite law only).
    pub regimes: Option<Vec<Regime>>,
    pub switch_points: Vec<f64>,
    /// Regime bands along the line of action between A, the switch points and E (composite only).
    pub regime_bands: Vec<(f64, f64, Regime)>,
    pub mean_abs_mu: Integral,
    pub validity: ValiditySummary,
    pub efficiency: Vec<EfficiencyResult>,
    /// 1 − μ̄ H_V with μ̄ = mean |μ| over A–E (Ohlendorf's cross-check).
    pub ohlendorf_efficiency: f64,
    /// Where the internal formulation caps |μ| at [`efficiency::INTERNAL_MU_CAP`] (from, to from T1).
    pub internal_cap_band: Option<(f64, f64)>,
    pub curves: Option<LawCurves>,
}

/// Sampled curves of one law for plots.
#[derive(Debug, Clone, Serialize)]
pub struct LawCurves {
    /// Signed μ at `Evaluation::curve_positions` (NaN where it diverges).
    pub mu: Vec<f64>,
    /// Local friction power loss at the same positions (W).
    pub power_loss: Vec<f64>,
    /// η(τ) at `cycle_times` for each formulation.
    pub efficiency: Vec<(Formulation, Vec<f64>)>,
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

/// Table positions: A..E in equal steps, with B, P and D inserted, each labelled where it is a named point.
pub fn table_positions(g: &SpurGeometry) -> Vec<(Option<&'static str>, f64)> {
    let p = &g.points;
    let mut rows: Vec<(Option<&'static str>, f64)> =
        (0..=TABLE_INTERVALS).map(|i| (None, p.a + (p.e - p.a) * i as f64 / TABLE_INTERVALS as f64)).collect();
    for (name, u) in g.named_points() {
        let tol = 1e-9 * (p.e - p.a);
        match rows.iter_mut().find(|(_, v)| (*v - u).abs() < tol) {
            Some(row) => *row = (Some(name), u),
            None => rows.push((Some(name), u)),
        }
    }
    rows.sort_by(|a, b| a.1.total_cmp(&b.1));
    rows
}

/// Times in the mesh cycle (in periods) at which η(τ) curves are sampled.
pub fn cycle_times() -> Vec<f64> {
    (0..CURVE_SAMPLES).map(|i| i as f64 / (CURVE_SAMPLES - 1) as f64 * (1.0 - 1e-9)).collect()
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
        Some(LubricantType::Mineral) => (1.0, "mineral"),
        Some(LubricantType::Pao) => (0.8, "PAO"),
        Some(LubricantType::PagInsoluble) => (0.7, "PAG, not water-soluble"),
        Some(LubricantType::PagSoluble) => (0.6, "PAG, water-soluble"),
        Some(LubricantType::Traction) => (1.5, "traction fluid"),
        Some(LubricantType::PhosphateEster) => (1.3, "phosphate ester"),
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

/// Evaluates a lowered scene. Lowering has checked the geometry, so this cannot fail on a lowered scene.
pub fn evaluate_scene(scene: &Scene) -> Evaluation {
    evaluate_scene_with_progress(scene, &|| {})
}

/// As [`evaluate_scene`], calling `tick` once per operating point evaluated (from any thread).
pub fn evaluate_scene_with_progress(scene: &Scene, tick: &(dyn Fn() + Sync)) -> Evaluation {
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
        cases: cases(&scene.operating),
        ohlendorf_loss_factor: 0.0,
        geometry,
        reduced_modulus: e_r,
        sharing: scene.gears.load_sharing,
        tribology,
        formulations: analyses.efficiency.clone().unwrap_or_default(),
        film_inputs,
        points: Vec::new(),
        contact_curves: ContactCurves::default(),
        dynamics: None,
    };
    let rows = table_positions(&eval.geometry);
    let with_curves = pick(eval.cases.len());
    let wants_friction = analyses.friction_along_loa || analyses.efficiency.is_some();
    let points: Vec<PointEvaluation> = eval
        .cases
        .par_iter()
        .enumerate()
        .map(|(k, case)| {
            let state = case.state;
            let table: Vec<(Option<&'static str>, ContactPoint)> =
                rows.iter().map(|(name, u)| (*name, eval.contact_at(*u, &state))).collect();
            let film =
                eval.film_inputs.map(|(inputs, lambda)| table.iter().map(|(_, c)| inputs.film(c, lambda)).collect());
            let curves = with_curves.contains(&k);
            let laws = if wants_friction {
                scene.friction.iter().map(|spec| evaluate_law(&eval, spec, state, &table, curves)).collect()
            } else {
                Vec::new()
            };
            tick();
            let mesh_period = eval.geometry.mesh_period(state.pinion_speed);
            PointEvaluation { case: k, state, mesh_period, table, film, laws, has_curves: curves }
        })
        .collect();
    eval.points = points;
    eval.contact_curves = contact_curves(scene, &eval);
    eval.dynamics =
        crate::evaluate_dynamics::evaluate_dynamics(scene, &eval.cases, eval.law_context(eval.cases[0].state));
    eval.ohlendorf_loss_factor =
        efficiency::ohlendorf_loss_factor(&eval.law_context(OperatingState { pinion_torque: 1.0, pinion_speed: 1.0 }));
    eval
}

/// The contact curves of the contact-state plot.
fn contact_curves(scene: &Scene, eval: &Evaluation) -> ContactCurves {
    let u = eval.curve_positions();
    let op = &scene.operating;
    let torque0 = op.pinion_torque.values[0].value;
    let speed0 = op.pinion_speed.values[0].value;
    let at = |t: f64, n: f64| -> Vec<ContactPoint> {
        let state = OperatingState { pinion_torque: t, pinion_speed: n };
        u.iter().map(|x| eval.contact_at(*x, &state)).collect()
    };
    let sliding_velocity = pick(op.pinion_speed.values.len())
        .into_iter()
        .map(|i| {
            let label = format!("{} {}", op.pinion_speed.written_values[i], op.pinion_speed.unit);
            (label, at(torque0, op.pinion_speed.values[i].value).iter().map(|c| c.sliding_velocity).collect())
        })
        .collect();
    let hertz_pressure = pick(op.pinion_torque.values.len())
        .into_iter()
        .map(|i| {
            let label = format!("{} {}", op.pinion_torque.written_values[i], op.pinion_torque.unit);
            (label, at(op.pinion_torque.values[i].value, speed0).iter().map(|c| c.hertz_pressure).collect())
        })
        .collect();
    let slide_to_roll = at(torque0, speed0).iter().map(|c| c.slide_to_roll).collect();
    ContactCurves { u, sliding_velocity, slide_to_roll, hertz_pressure }
}

fn validity_summary(law: &dyn FrictionLaw, contacts: &[ContactPoint]) -> ValiditySummary {
    let mut intervals: Vec<(f64, f64, &'static str)> = Vec::new();
    let mut outside = 0;
    let mut open: Option<(f64, f64, &'static str)> = None;
    let diverges = law.diverges_at_pitch();
    for c in contacts {
        let verdict = law.validity(c).and_then(|()| {
            // At P a divergent law is reported as `diverges`, not as implausible.
            let at_pitch = diverges && c.s == 0.0;
            if at_pitch || law.mu(c).abs() <= law.plausible_max() {
                Ok(())
            } else {
                Err("|μ| above the law's plausible bound for a lubricated contact")
            }
        });
        match verdict {
            Err(reason) => {
                outside += 1;
                open = Some(match open {
                    Some((from, _, r)) => (from, c.u, r),
                    None => (c.u, c.u, reason),
                });
            }
            Ok(()) => {
                if let Some(i) = open.take() {
                    intervals.push(i);
                }
            }
        }
    }
    if let Some(i) = open {
        intervals.push(i);
    }
    ValiditySummary { samples: contacts.len(), outside, intervals }
}

/// The regime between consecutive switch points (A, switches…, E), for laws that have regimes.
fn regime_bands(ctx: &LawContext, law: &dyn FrictionLaw) -> Vec<(f64, f64, Regime)> {
    let p = ctx.geometry.points;
    let mut edges = vec![p.a];
    edges.extend(law.switch_points());
    edges.push(p.e);
    edges.windows(2).filter_map(|w| law.regime(&ctx.contact_at(0.5 * (w[0] + w[1]))).map(|r| (w[0], w[1], r))).collect()
}

fn evaluate_law(
    eval: &Evaluation,
    spec: &crate::model::FrictionLawSpec,
    state: OperatingState,
    table: &[(Option<&'static str>, ContactPoint)],
    curves: bool,
) -> LawEvaluation {
    let ctx = eval.law_context(state);
    let law = spec.build(&ctx);
    let law = law.as_ref();
    let diverges = law.diverges_at_pitch();
    let value_at = |c: &ContactPoint| -> Option<f64> { (!(diverges && c.s == 0.0)).then(|| law.mu(c)) };
    let positions = eval.curve_positions();
    let contacts: Vec<ContactPoint> = positions.iter().map(|u| ctx.contact_at(*u)).collect();
    let taus = cycle_times();
    let efficiency = efficiency::evaluate_efficiencies(&ctx, law, &eval.formulations);
    let mean_abs_mu = efficiency::mean_abs_mu(&ctx, law);
    LawEvaluation {
        id: spec.law,
        title: spec.law.entry().title,
        parameters: law.parameters(),
        notes: law.notes(),
        diverges_at_pitch: diverges,
        table: table.iter().map(|(_, c)| value_at(c)).collect(),
        regimes: law.regime(&table[0].1).map(|_| table.iter().filter_map(|(_, c)| law.regime(c)).collect()),
        switch_points: law.switch_points(),
        regime_bands: regime_bands(&ctx, law),
        ohlendorf_efficiency: 1.0 - mean_abs_mu.value * efficiency::ohlendorf_loss_factor(&ctx),
        internal_cap_band: if eval.formulations.contains(&Formulation::Internal) {
            efficiency::internal_cap_band(&ctx, law)
        } else {
            None
        },
        mean_abs_mu,
        validity: validity_summary(law, &contacts),
        efficiency,
        curves: curves.then(|| LawCurves {
            mu: contacts.iter().map(|c| value_at(c).unwrap_or(f64::NAN)).collect(),
            power_loss: contacts
                .iter()
                .map(|c| if diverges && c.s == 0.0 { 0.0 } else { efficiency::local_power_loss(&ctx, law, c) })
                .collect(),
            efficiency: eval
                .formulations
                .iter()
                .map(|f| (*f, taus.iter().map(|t| efficiency::efficiency_at(&ctx, law, *f, *t)).collect()))
                .collect(),
        }),
    }
}

/// At most this many curves of one kind are plotted (evenly picked from a sweep).
pub const MAX_CURVES: usize = 6;

/// Indices of at most `MAX_CURVES` values evenly picked from `n`.
pub fn pick(n: usize) -> Vec<usize> {
    if n <= MAX_CURVES {
        return (0..n).collect();
    }
    let mut v: Vec<usize> = (0..MAX_CURVES).map(|i| i * (n - 1) / (MAX_CURVES - 1)).collect();
    v.dedup();
    v
}
