//! Xu et al., Model III (He–Cho–Singh eq 18; Bernard §2.2):
//! μ = exp(f) p_H^b2 |SR|^b3 U^b6 η^b7 R^b8,
//! f = b1 + b4 |SR| p_H log10 η + b5 exp(−|SR| p_H log10 η) + b9 exp(S),
//! p_H in GPa, U (entrainment) in m/s, η in cP, R in metres, S = mean Ra in µm. Both papers print
//! b5 as the exponent of U: it is b6 (physics notes). μ → 0 at P (|SR|^b3).
//!
//! ```
//! use gearloss::friction::{FrictionLaw, Xu};
//! let law = Xu::from_units(95.0, 0.3);
//! let mut c = gearloss::friction::testing::contact();
//! c.slide_to_roll = 0.0;
//! assert_eq!(law.magnitude(&c), 0.0);
//! ```

use super::friction_law::{signed, FrictionLaw, Parameter};
use super::needs::Needs;
use crate::geometry::ContactPoint;
use crate::tribology::{units, FilmInputs, Tribology};

/// b1 … b9 of Xu (2005), as printed by both papers.
pub(super) const B: [f64; 9] =
    [-8.916465, 1.03303, 1.036077, -0.354068, 2.812084, -0.100601, 0.752755, -0.390958, 0.620305];

#[derive(Debug, Clone, Copy)]
pub struct Xu {
    pub viscosity_cp: f64,
    pub roughness_um: f64,
    /// log10 η, and exp(b1 + b9 e^S) η^b7: the parts that do not change along the line of action.
    log_viscosity: f64,
    constant: f64,
    /// Film inputs and composite roughness σ = sqrt(Rq1² + Rq2²) when the scene gives them: the
    /// regression is a full-film fit, so a contact with h_min/σ < 1 (Dowson–Higginson minimum film;
    /// boundary lubrication) is outside it.
    pub film: Option<(FilmInputs, f64)>,
}

impl Xu {
    pub fn new(t: &Tribology) -> Result<Self, Needs> {
        let mut law = Xu::from_units(
            t.dynamic_viscosity * units::CP_PER_PA_S,
            Needs::RoughnessRa.of(t.ra_mean)? * units::UM_PER_M,
        );
        if let (Some(alpha), Some(sigma)) = (t.pressure_viscosity, t.rq_composite) {
            let inputs = FilmInputs {
                dynamic_viscosity: t.dynamic_viscosity,
                pressure_viscosity: alpha,
                reduced_modulus: t.reduced_modulus,
            };
            law.film = Some((inputs, sigma));
        }
        Ok(law)
    }

    /// From η in cP and S (mean Ra) in µm.
    pub fn from_units(viscosity_cp: f64, roughness_um: f64) -> Self {
        Xu {
            viscosity_cp,
            roughness_um,
            log_viscosity: viscosity_cp.log10(),
            constant: (B[0] + B[8] * roughness_um.exp()).exp() * viscosity_cp.powf(B[6]),
            film: None,
        }
    }

    pub fn magnitude(&self, c: &ContactPoint) -> f64 {
        let ph = c.hertz_pressure * units::GPA_PER_PA;
        let sr = c.slide_to_roll.abs();
        if sr == 0.0 {
            return 0.0;
        }
        let l = sr * ph * self.log_viscosity;
        // exp(f) p_H^b2 |SR|^b3 U^b6 η^b7 R^b8 with the constant factors folded in at construction.
        self.constant
            * (B[3] * l
                + B[4] * (-l).exp()
                + B[1] * ph.ln()
                + B[2] * sr.ln()
                + B[5] * c.entrainment_velocity.ln()
                + B[7] * c.reduced_radius.ln())
            .exp()
    }
}

impl FrictionLaw for Xu {
    fn id(&self) -> super::law_id::LawId {
        super::law_id::LawId::Xu
    }
    fn mu(&self, c: &ContactPoint) -> f64 {
        signed(self.magnitude(c), c.s)
    }
    /// The approximate span of the twin-disc data behind the regression (Xu 2005): p_H 0.5–2.5 GPa,
    /// entrainment velocity 0.5–25 m/s.
    fn validity(&self, c: &ContactPoint) -> Result<(), &'static str> {
        let ph = c.hertz_pressure * units::GPA_PER_PA;
        if !(0.5..=2.5).contains(&ph) {
            Err("p_H outside 0.5–2.5 GPa")
        } else if !(0.5..=25.0).contains(&c.entrainment_velocity) {
            Err("entrainment velocity outside 0.5–25 m/s")
        } else if self.film.is_some_and(|(f, sigma)| f.minimum(c) / sigma < 1.0) {
            Err("specific film λ = h_min/σ < 1: a full-film fit used in boundary lubrication")
        } else {
            Ok(())
        }
    }
    fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter { name: "viscosity", value: self.viscosity_cp / units::CP_PER_PA_S, unit: "Pa*s" },
            Parameter { name: "roughness_ra_mean", value: self.roughness_um / units::UM_PER_M, unit: "m" },
        ]
    }
}
