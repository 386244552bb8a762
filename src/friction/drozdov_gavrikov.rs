//! Drozdov–Gavrikov, **low confidence**: Bernard et al. (Table 1) print it garbled as
//! μ = (1/V) / (0.4 R g sqrt(ν_k + φ + 13.4/V)), φ = 0.47 − 0.13e−4 P_max − 0.4e−4 ν_k,
//! with validity ν_k ∈ [4, 500] cSt, V_s ≤ 15 m/s, V_r ∈ [3, 20] m/s, P_max ∈ [4000, 20000].
//!
//! Reading used here (stated in every report that uses it): V is the **sliding** velocity in m/s,
//! since Bernard state that the law peaks at the pitch point, where only the sliding velocity
//! vanishes; the stray `g` is dropped; R is in mm; P_max in kgf/cm² (the validity range 4000–20000
//! is 0.39–1.96 GPa in those units). With these readings μ ≈ 0.02–0.1 on Bernard's Table 2 data.
//! It diverges at P as V_s^−1/2 (integrable). Never used inside Model V.

use super::friction_law::{signed, FrictionLaw, Parameter};
use super::needs::Needs;
use crate::geometry::ContactPoint;
use crate::tribology::{units, Tribology};

/// Pa → kgf/cm².
const KGF_PER_CM2_PER_PA: f64 = 1.0 / 98_066.5;

#[derive(Debug, Clone, Copy)]
pub(crate) struct DrozdovGavrikov {
    pub kinematic_viscosity_cst: f64,
}

impl DrozdovGavrikov {
    pub(crate) fn new(t: &Tribology) -> Result<Self, Needs> {
        Ok(DrozdovGavrikov {
            kinematic_viscosity_cst: Needs::KinematicViscosity.of(t.kinematic_viscosity)? * units::CST_PER_M2_S,
        })
    }

    pub(crate) fn magnitude(&self, c: &ContactPoint) -> f64 {
        let nu = self.kinematic_viscosity_cst;
        let p = c.hertz_pressure * KGF_PER_CM2_PER_PA;
        let phi = 0.47 - 0.13e-4 * p - 0.4e-4 * nu;
        let v = c.sliding_velocity;
        (1.0 / v) / (0.4 * c.reduced_radius * units::MM_PER_M * (nu + phi + 13.4 / v).sqrt())
    }
}

impl FrictionLaw for DrozdovGavrikov {
    fn id(&self) -> super::law_id::LawId {
        super::law_id::LawId::DrozdovGavrikov
    }
    fn mu(&self, c: &ContactPoint) -> f64 {
        signed(self.magnitude(c), c.s)
    }
    fn validity(&self, c: &ContactPoint) -> Result<(), &'static str> {
        let p = c.hertz_pressure * KGF_PER_CM2_PER_PA;
        if !(4.0..=500.0).contains(&self.kinematic_viscosity_cst) {
            Err("ν_k outside 4–500 cSt")
        } else if c.sliding_velocity > 15.0 {
            Err("sliding velocity above 15 m/s")
        } else if !(3.0..=20.0).contains(&c.entrainment_velocity) {
            Err("rolling velocity outside 3–20 m/s")
        } else if !(4000.0..=20000.0).contains(&p) {
            Err("P_max outside 4000–20000 kgf/cm²")
        } else {
            Ok(())
        }
    }
    fn diverges_at_pitch(&self) -> bool {
        true
    }
    fn parameters(&self) -> Vec<Parameter> {
        vec![Parameter {
            name: "kinematic_viscosity",
            value: self.kinematic_viscosity_cst / units::CST_PER_M2_S,
            unit: "m^2/s",
        }]
    }
    fn notes(&self) -> Vec<String> {
        vec!["drozdov_gavrikov: LOW CONFIDENCE — the formula is printed garbled in Bernard et al.; read with V = sliding velocity (m/s), R in mm, P_max in kgf/cm², the stray g dropped".into()]
    }
}
