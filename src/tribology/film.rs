//! EHL line-contact film thickness and the film parameter Λ along the line of action.
//!
//! - Central film, Dowson–Toyoda: H_c = 3.06 G^0.56 U^0.69 W^−0.10 (He–Cho–Singh eq 21c; physics notes, Model V).
//! - Minimum film, Dowson–Higginson: H_min = 2.65 U^0.70 G^0.54 W^−0.13 (physics notes, Matsumoto).
//! - Groups: U = η U_e/(E' R), G = α E', W = w/(E' R); h = H R.
//! - Λ_HCS = h_c / R_comp · sqrt(L_x / (2 b_H)) (He–Cho–Singh eq 21a, with their mm/µm factor 10³ absorbed by SI
//!   units): their film parameter, the central film over the composite roughness filtered at the cut-off L_x.
//!   The composite law picks its regime by it.
//! - λ = h_min / σ, σ = sqrt(Rq1² + Rq2²): the specific film thickness of the EHL literature (Tallian; ISO/TR 15144-1
//!   reads the same ratio with Ra), the minimum film over the unfiltered composite roughness. Xu's validity reads it.
//!   The two are different numbers of the same contact (Λ_HCS / λ = (h_c/h_min) √(L_x/(2 b_H)), typically 2–3
//!   at gear contact widths): a report names each.

use serde::Serialize;

use crate::geometry::ContactPoint;

/// Lubricant and surface data the film formulas need (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmInputs {
    pub dynamic_viscosity: f64,
    pub pressure_viscosity: f64,
    pub reduced_modulus: f64,
}

/// Film thickness at one contact (m) and Λ when the roughness is known.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Film {
    pub central: f64,
    pub minimum: f64,
    /// He–Cho–Singh's Λ_HCS (needs R_comp and the filter cut-off).
    pub lambda: Option<f64>,
    /// The specific film thickness λ = h_min / σ (needs σ = R_comp).
    pub specific: Option<f64>,
}

impl FilmInputs {
    /// The dimensionless groups (U, G, W) at a contact.
    pub fn groups(&self, c: &ContactPoint) -> (f64, f64, f64) {
        let r = c.reduced_radius;
        let u = self.dynamic_viscosity * c.entrainment_velocity / (self.reduced_modulus * r);
        let g = self.pressure_viscosity * self.reduced_modulus;
        let w = c.load_per_width / (self.reduced_modulus * r);
        (u, g, w)
    }

    /// Dowson–Toyoda central film thickness h_c (m).
    pub fn central(&self, c: &ContactPoint) -> f64 {
        let (u, g, w) = self.groups(c);
        3.06 * g.powf(0.56) * u.powf(0.69) * w.powf(-0.10) * c.reduced_radius
    }

    /// Dowson–Higginson minimum film thickness h_min (m).
    pub fn minimum(&self, c: &ContactPoint) -> f64 {
        let (u, g, w) = self.groups(c);
        2.65 * u.powf(0.70) * g.powf(0.54) * w.powf(-0.13) * c.reduced_radius
    }

    /// Λ_HCS = h_c / R_comp · sqrt(L_x / (2 b_H)) (He–Cho–Singh eq 21a).
    pub fn lambda(&self, c: &ContactPoint, rq_composite: f64, filter_cutoff: f64) -> f64 {
        self.central(c) / rq_composite * (filter_cutoff / (2.0 * c.hertz_half_width)).sqrt()
    }

    pub fn film(&self, c: &ContactPoint, lambda_inputs: Option<(f64, f64)>) -> Film {
        let minimum = self.minimum(c);
        Film {
            central: self.central(c),
            minimum,
            lambda: lambda_inputs.map(|(rq, lx)| self.lambda(c, rq, lx)),
            specific: lambda_inputs.map(|(rq, _)| minimum / rq),
        }
    }
}
