//! A checked mesh: one gear pair with the lubricant it runs in (its geometry, its bodies'
//! elasticity, its surfaces and oil), and the problem of one mesh the per-mesh evaluation reads:
//! the mesh over its grid of operating states with the laws, the dynamics and the analyses asked of
//! it. The evaluation of a pair takes a mesh, never the scene: a drive's stages are meshes of their
//! own ([`crate::model::SceneDrive`]), each analysed as a [`MeshProblem`] at the state the drive's
//! power walk gives it (`evaluate::stage_pairs`), a scene of one pair's stage over the scene's grid
//! ([`Scene::pair_alone`]).

use crate::geometry::contact::reduced_modulus;
use crate::geometry::PairGeometry;
use crate::model::{
    Analyses, DynamicsSpec, FrictionLawSpec, GearPair, Lubricant, LubricantType, Operating, Scene, SceneDrive,
};
use crate::tribology::Tribology;

/// One mesh's analysis, what the per-mesh evaluation (`evaluate::prepare`, the stream, the details,
/// the pair's report) reads: the pair with the driving gear in the pinion's place, its oil at the
/// oil temperature, the grid of the pinion's torques and speeds (with the detail points to see in
/// full), the friction laws to compare, the dynamics block and the analyses of one pair.
///
/// What a drive evaluates itself is not here: the gearbox's loss budget, the housing's balance, the
/// duty cycle, the efficiency map, the oil at its balance or over a sweep of temperatures
/// (`operating.oil_temperatures` and `operating.equilibrium` are always None).
///
/// ```
/// let scene = gearloss::check("s.gear", r#"scene "s" {
///     gears { module = 2 mm  pressure_angle = 20 deg  face_width = 20 mm
///             pinion { teeth = 20  material = steel }  wheel { teeth = 40  material = steel } }
///     material steel { youngs_modulus = 210 GPa  poisson_ratio = 0.3 }
///     operating { pinion_torque = [50, 100] N*m  pinion_speed = 1000 rpm }
/// }"#).unwrap();
/// let problem = scene.pair_alone().expect("a scene of one pair");
/// assert_eq!(problem.operating.count(), 2);
/// assert_eq!(problem.gears.wheel.teeth.value, 40);
/// assert!(problem.operating.oil_temperatures.is_none() && problem.operating.equilibrium.is_none());
/// let eval = gearloss::evaluate(&problem);
/// assert_eq!(eval.points.len(), 2);
/// // The same numbers as the scene's own report of its pair (`gearloss::report_of`).
/// let (a, b) = (gearloss::mesh_report(&problem), gearloss::report_of(&scene));
/// assert_eq!(format!("{:?}", a.operating_points), format!("{:?}", b.operating_points));
/// ```
#[derive(Debug, Clone)]
pub struct MeshProblem {
    /// What the mesh's report is titled (the scene's title; a drive's stage mesh adds its stage,
    /// mesh and point).
    pub title: String,
    pub gears: GearPair,
    pub lubricant: Option<Lubricant>,
    pub operating: Operating,
    pub friction: Vec<FrictionLawSpec>,
    pub dynamics: Option<DynamicsSpec>,
    /// The analyses asked: the per-mesh evaluation reads those of one pair and of efficiency.
    pub analyses: Analyses,
}

impl MeshProblem {
    /// The pair with its lubricant: the mesh the evaluation reads.
    pub fn mesh(&self) -> Mesh<'_> {
        Mesh { gears: &self.gears, lubricant: self.lubricant.as_ref() }
    }
}

impl Scene {
    /// The scene's pair with its lubricant (a drive's: its first stage's pair).
    pub fn mesh(&self) -> Mesh<'_> {
        Mesh { gears: &self.gears, lubricant: self.lubricant.as_ref() }
    }

    /// A scene of one pair's pair alone, as a drive's stage mesh is analysed (what
    /// `gearloss::report_of` reports): its gears, oil at the scene's oil temperature, operating
    /// grid and detail points, laws, dynamics and every analysis; what its one-stage drive
    /// evaluates itself (the gearbox's budget, the housing's balance, the duty cycle, the oil at its
    /// balance or over a sweep) left to the drive. None for a drive written with `stage` blocks:
    /// its operating block is at the drive's ends, and each of its meshes is analysed at the state
    /// the drive's walk gives it (`gearloss::evaluate::stage_pairs`).
    pub fn pair_alone(&self) -> Option<MeshProblem> {
        if self.drive.as_ref().is_some_and(|d| !d.one_pair) {
            return None;
        }
        Some(MeshProblem {
            title: self.title.clone(),
            gears: self.gears.clone(),
            lubricant: self.lubricant.clone(),
            operating: Operating { oil_temperatures: None, equilibrium: None, ..self.operating.clone() },
            friction: self.friction.clone(),
            dynamics: self.dynamics.clone(),
            analyses: self.analyses.clone(),
        })
    }
}

/// One pair and its lubricant.
#[derive(Debug, Clone, Copy)]
pub struct Mesh<'a> {
    pub gears: &'a GearPair,
    pub lubricant: Option<&'a Lubricant>,
}

impl SceneDrive {
    /// Stage `k`'s pair in `lubricant`: the mesh its evaluation reads.
    pub fn mesh<'a>(&'a self, k: usize, lubricant: Option<&'a Lubricant>) -> Mesh<'a> {
        Mesh { gears: &self.pairs[k], lubricant }
    }

    /// Mesh `mesh` of stage `k` as a pair: 0 the stage's own pair, 1, 2, … its further meshes (a
    /// planetary stage's planet–ring pair is its mesh 1). The mesh numbers are the stage kind's
    /// (`StageModel::mesh_gears`), which lowering gave a pair each.
    pub fn mesh_pair(&self, k: usize, mesh: usize) -> &GearPair {
        match mesh {
            0 => &self.pairs[k],
            n => &self.further_pairs[k][n - 1],
        }
    }

    /// Stage `k`'s further mesh `n` (1, 2, …) in `lubricant`, if the stage has it.
    pub fn further_mesh<'a>(&'a self, k: usize, n: usize, lubricant: Option<&'a Lubricant>) -> Option<Mesh<'a>> {
        let gears = self.further_pairs[k].get(n.checked_sub(1)?)?;
        Some(Mesh { gears, lubricant })
    }
}

impl Mesh<'_> {
    /// The pair's geometry; lowering has checked it, so a lowered mesh always has one.
    pub fn geometry(&self) -> PairGeometry {
        self.gears.geometry().expect("lowering refuses pairs whose geometry fails")
    }

    /// E' (Pa) of the two gears' materials (Hertz).
    pub fn reduced_modulus(&self) -> f64 {
        let p = &self.gears.pinion.material;
        let w = &self.gears.wheel.material;
        reduced_modulus(
            [p.youngs_modulus.value.value, w.youngs_modulus.value.value],
            [p.poisson_ratio.value, w.poisson_ratio.value],
        )
    }

    /// The lubricant and surface data in SI, with E' = `reduced_modulus`.
    pub fn tribology(&self, reduced_modulus: f64) -> Tribology {
        let g = self.gears;
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
        let l = self.lubricant;
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

    /// The oil as the losses beside the mesh read it, from the tribology at the oil temperature
    /// (ρ = η/ν; a lubricant of unknown base counts as mineral).
    pub fn budget_oil(&self, t: &Tribology) -> crate::losses::Oil {
        crate::losses::Oil {
            nu: t.kinematic_viscosity,
            rho: t.density(),
            eta: t.dynamic_viscosity,
            mineral: self.lubricant.and_then(|l| l.kind).is_none_or(|k| k == LubricantType::Mineral),
        }
    }
}
