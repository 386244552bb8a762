//! A checked mesh: one gear pair with the lubricant it runs in, what a per-mesh evaluation reads
//! (its geometry, its bodies' elasticity, its surfaces and oil). The evaluation of a pair takes a
//! mesh, never the scene: a drive's stages are meshes of their own ([`crate::model::SceneDrive`]).

use crate::geometry::contact::reduced_modulus;
use crate::geometry::PairGeometry;
use crate::model::{GearPair, Lubricant, LubricantType, Scene, SceneDrive};
use crate::tribology::Tribology;

/// One pair and its lubricant.
#[derive(Debug, Clone, Copy)]
pub struct Mesh<'a> {
    pub gears: &'a GearPair,
    pub lubricant: Option<&'a Lubricant>,
}

impl Scene {
    /// The scene's pair with its lubricant: the mesh the pair's evaluation reads.
    pub fn mesh(&self) -> Mesh<'_> {
        Mesh { gears: &self.gears, lubricant: self.lubricant.as_ref() }
    }
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
