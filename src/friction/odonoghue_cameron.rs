//! O'Donoghue–Cameron (Bernard et al., Table 1):
//! μ = 0.6 (S + 22)/35 · 0.756 / (ν^{1/8} SR^{1/3} U^{1/2} R^{1/2}),
//! S = mean Ra in µm, ν in cSt, U in m/s. The paper does not state the unit of R: R in metres gives
//! μ ≈ 1–4 (implausible), R in millimetres 0.03–0.1, so **R is taken in mm** and every report says so.
//! Diverges at P as SR^−1/3 (integrable).

use super::friction_law::{signed, FrictionLaw, Parameter};
use super::needs::Needs;
use crate::geometry::ContactPoint;
use crate::tribology::{units, Tribology};

#[derive(Debug, Clone, Copy)]
pub struct ODonoghueCameron {
    pub roughness_um: f64,
    pub kinematic_viscosity_cst: f64,
}

impl ODonoghueCameron {
    pub fn new(t: &Tribology) -> Result<Self, Needs> {
        Ok(ODonoghueCameron {
            roughness_um: Needs::RoughnessRa.of(t.ra_mean)? * units::UM_PER_M,
            kinematic_viscosity_cst: Needs::KinematicViscosity.of(t.kinematic_viscosity)? * units::CST_PER_M2_S,
        })
    }

    /// |μ| with R in the given unit (1e3 for mm, 1 for m).
    pub fn magnitude_with_radius_scale(&self, c: &ContactPoint, per_metre: f64) -> f64 {
        0.6 * (self.roughness_um + 22.0) / 35.0 * 0.756
            / (self.kinematic_viscosity_cst.powf(0.125)
                * c.slide_to_roll.powf(1.0 / 3.0)
                * c.entrainment_velocity.sqrt()
                * (c.reduced_radius * per_metre).sqrt())
    }
}

impl FrictionLaw for ODonoghueCameron {
    fn id(&self) -> super::law_id::LawId {
        super::law_id::LawId::ODonoghueCameron
    }
    fn mu(&self, c: &ContactPoint) -> f64 {
        signed(self.magnitude_with_radius_scale(c, units::MM_PER_M), c.s)
    }
    fn diverges_at_pitch(&self) -> bool {
        true
    }
    fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter { name: "roughness_ra_mean", value: self.roughness_um / units::UM_PER_M, unit: "m" },
            Parameter {
                name: "kinematic_viscosity",
                value: self.kinematic_viscosity_cst / units::CST_PER_M2_S,
                unit: "m^2/s",
            },
        ]
    }
    fn notes(&self) -> Vec<String> {
        vec!["odonoghue_cameron: R is taken in mm (the paper states no unit); R in m would give μ ≈ 1–4, which is implausible".into()]
    }
}
