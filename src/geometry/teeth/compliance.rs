//! One tooth's compliance to a unit normal force at a contact point of its involute, per unit face
//! width: bending, shear and axial compression of the tooth as a non-uniform cantilever from the
//! root circle (Tian, "Dynamic simulation for system response of gearbox including localized gear
//! faults", MSc thesis, University of Alberta, 2004, eqs 3.5–3.7; Chen & Shao, "Analytical mesh
//! stiffness calculation of spur gear pairs with tooth root crack", Engineering Failure Analysis 18
//! (2011) 2149–2164, eqs 4–6, over Ma et al.'s (2014) trochoid fillet) and the fillet foundation of
//! Sainsot, Velex & Duverger, "Contribution of gear body to tooth deflections — a new bidimensional
//! analytical formula", J. Mech. Design 126 (2004) 748–752, eq 6 with its Table 1.
//!
//! With y measured along the centreline from the root point (η = y − y_root), I(η) = 2h³b/3,
//! A(η) = 2hb, and the force F at (η_c, h_c) making the angle α₁ = α_c − ψ_c with the normal to the
//! centreline:
//! 1/k_b = ∫₀^{η_c} [(η_c − η) cos α₁ − h_c sin α₁]² / (E I) dη,
//! 1/k_s = ∫₀^{η_c} 1.2 cos² α₁ / (G A) dη, 1/k_a = ∫₀^{η_c} sin² α₁ / (E A) dη, G = E/(2(1 + ν)).
//! Expanding the square, every term is a combination of four moments of the outline,
//! ∫ 3/(2h³) dη, ∫ 3η/(2h³) dη, ∫ 3η²/(2h³) dη and ∫ 1/(2h) dη: over the fillet they are four
//! numbers (adaptive Gauss–Kronrod to 1e-13), along the involute four functions of the contact's
//! roll length ℓ (their Chebyshev series, integrated term by term, of the smallest degree whose
//! integral over the whole involute and over its first half agrees with adaptive Gauss–Kronrod to
//! 1e-12 relative). The difference is kept as the tooth's error estimate.

use std::f64::consts::FRAC_PI_2;

use super::compliance_series::antiderivative;
use super::outline::ToothOutline;
use crate::numerics::chebyshev::{clenshaw, Lobatto, DEGREES};
use crate::numerics::quadrature::integrate_singular_n;

/// Sainsot et al. (2004) Table 1: A, B, C, D, E, F of L*, M*, P*, Q*.
const SAINSOT: [[f64; 6]; 4] = [
    [-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045],
    [60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086],
    [-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236],
    [-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904],
];

/// The range each of L*, M*, P*, Q* takes over the cases Sainsot et al. fitted: where a tooth's
/// h_f and θ_f give a coefficient outside it, the foundation term is extrapolated and the report
/// says so. The ranges are those the ROSS rotordynamics package checks (petrobras/ross,
/// `ross/gear_element.py`, `poly_limits`); the paper itself was not at hand to read them from.
pub const SAINSOT_RANGES: [(f64, f64); 4] = [(6.82, 6.94), (1.08, 3.29), (2.56, 13.47), (0.141, 0.62)];

/// Sainsot et al.'s L*, M*, P*, Q* for h_f = r_f/r_int and θ_f (rad): each
/// A/θ_f² + B h_f² + C h_f/θ_f + D/θ_f + E h_f + F with the coefficients of their Table 1.
///
/// ```
/// use gearloss::geometry::teeth::{sainsot_coefficients, SAINSOT_RANGES};
/// // FZG type C's pinion (h_f = 2.0795, θ_f = 0.18830 rad): inside every range.
/// let c = sainsot_coefficients(2.07951, 0.1883006749);
/// assert!(c.iter().zip(SAINSOT_RANGES).all(|(v, (lo, hi))| (lo..=hi).contains(v)));
/// ```
pub fn sainsot_coefficients(h_f: f64, theta_f: f64) -> [f64; 4] {
    SAINSOT.map(|[a, b, c, d, e, f]| {
        a / (theta_f * theta_f) + b * h_f * h_f + c * h_f / theta_f + d / theta_f + e * h_f + f
    })
}

/// Tolerance of the quadratures behind a tooth's compliance.
const QUADRATURE_TOLERANCE: f64 = 1e-13;
/// Agreement asked of the Chebyshev series with the quadrature.
const SERIES_TOLERANCE: f64 = 1e-12;

/// The four moments of the outline at a point of the tooth.
type Moments = [f64; 4];

fn moments_integrand(eta: f64, h: f64, dy: f64) -> Moments {
    let inv_i = 1.5 / (h * h * h);
    [inv_i * dy, inv_i * eta * dy, inv_i * eta * eta * dy, 0.5 / h * dy]
}

/// A tooth with its material and foundation, ready to give its compliance at any contact.
#[derive(Debug, Clone)]
pub struct ToothCompliance {
    pub outline: ToothOutline,
    pub young: f64,
    pub poisson: f64,
    pub bore_radius: f64,
    /// The moments over the whole fillet.
    fillet: Moments,
    /// Chebyshev coefficients of the moments' antiderivatives along the involute, in s ∈ [0, 1]
    /// over [ℓ_form, ℓ_tip], zero at s = 0.
    involute: [Vec<f64>; 4],
    /// Degree of the series used.
    pub degree: usize,
    /// The largest relative difference between series and quadrature found, plus the quadratures'
    /// own estimates: the tooth's relative error estimate.
    pub relative_error: f64,
    /// Sainsot's L*, M*, P*, Q* for this tooth's θ_f and h_f = r_f/r_int.
    foundation: [f64; 4],
}

/// The parts of a tooth's compliance at a contact, per unit face width (m/N · m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToothParts {
    pub bending: f64,
    pub shear: f64,
    pub axial: f64,
    pub foundation: f64,
}

impl ToothParts {
    pub fn total(&self) -> f64 {
        self.bending + self.shear + self.axial + self.foundation
    }
}

impl ToothCompliance {
    /// The compliance of a tooth of `outline` in a material (E, ν) on a body with a bore of
    /// `bore_radius` (m).
    pub fn new(outline: ToothOutline, young: f64, poisson: f64, bore_radius: f64) -> Self {
        let y0 = outline.root_y();
        let alpha = outline.input.pressure_angle;
        // The fillet from the root (γ = π/2) up to the form circle (γ = α): dη = dy/dγ dγ, run from
        // π/2 down to α, so the integral over [α, π/2] changes sign.
        let fillet = integrate_singular_n(
            |g, _| {
                let p = outline.fillet_point(g);
                moments_integrand(p.y - y0, p.h, -p.dy)
            },
            &[alpha, FRAC_PI_2],
            &[],
            QUADRATURE_TOLERANCE,
        );
        let [l0, l1] = outline.involute_rolls();
        let on_involute = |l: f64| {
            let p = outline.involute_point(l);
            moments_integrand(p.y - y0, p.h, p.dy)
        };
        let reference = |end: f64| integrate_singular_n(|l, _| on_involute(l), &[l0, end], &[], QUADRATURE_TOLERANCE);
        let (whole, half) = (reference(l1), reference(0.5 * (l0 + l1)));
        let mut chosen = None;
        for &degree in &DEGREES[1..] {
            let lobatto = Lobatto::get(degree);
            let values: Vec<Moments> = lobatto.nodes.iter().map(|s| on_involute(l0 + (l1 - l0) * s)).collect();
            let series: [Vec<f64>; 4] = std::array::from_fn(|k| {
                let column: Vec<f64> = values.iter().map(|v| v[k]).collect();
                antiderivative(&lobatto.coefficients(&column), l1 - l0)
            });
            let mut worst = 0.0f64;
            for k in 0..4 {
                for (s, r) in [(1.0, whole[k]), (0.5, half[k])] {
                    let diff = (clenshaw(&series[k], s) - r.value).abs();
                    worst = worst.max((diff + r.error) / r.value.abs());
                }
            }
            let done = worst < SERIES_TOLERANCE || degree == *DEGREES.last().unwrap();
            chosen = Some((series, degree, worst));
            if done {
                break;
            }
        }
        let (involute, degree, worst) = chosen.expect("at least one degree");
        let fillet_error = fillet.iter().map(|f| f.error / f.value.abs()).fold(0.0, f64::max);
        let theta_f = outline.root_angle();
        let h_f = outline.input.root_radius / bore_radius;
        let foundation = sainsot_coefficients(h_f, theta_f);
        ToothCompliance {
            outline,
            young,
            poisson,
            bore_radius,
            fillet: fillet.map(|f| f.value),
            involute,
            degree,
            relative_error: worst + fillet_error,
            foundation,
        }
    }

    /// The compliance parts at the contact of roll length ℓ, per unit face width.
    pub fn at(&self, roll: f64) -> ToothParts {
        let o = &self.outline;
        let [l0, l1] = o.involute_rolls();
        let s = (roll - l0) / (l1 - l0);
        let m: Moments = std::array::from_fn(|k| self.fillet[k] + clenshaw(&self.involute[k], s));
        let p = o.involute_point(roll);
        let eta_c = p.y - o.root_y();
        let load_angle = (roll / o.base_radius).atan() - o.half_angle(roll);
        let (sa, ca) = load_angle.sin_cos();
        let arm = ca * eta_c - p.h * sa;
        let e = self.young;
        let g = e / (2.0 * (1.0 + self.poisson));
        let bending = (arm * arm * m[0] - 2.0 * ca * arm * m[1] + ca * ca * m[2]) / e;
        let shear = 1.2 * ca * ca * m[3] / g;
        let axial = sa * sa * m[3] / e;
        // Sainsot: where the force line meets the centreline, above the root circle's crossing.
        let r_f = o.input.root_radius;
        let s_f = 2.0 * r_f * o.root_angle();
        let u = (p.y - p.h * sa / ca - r_f) / s_f;
        let [l, mm, pp, q] = self.foundation;
        let foundation = ca * ca / e * (l * u * u + mm * u + pp * (1.0 + q * (sa / ca).powi(2)));
        ToothParts { bending, shear, axial, foundation }
    }

    /// Sainsot's h_f = r_f/r_int and θ_f, to compare with the range of the fit.
    pub fn foundation_parameters(&self) -> (f64, f64) {
        (self.outline.input.root_radius / self.bore_radius, self.outline.root_angle())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::teeth::outline::ToothInput;

    fn tooth(z: u32, x: f64) -> ToothCompliance {
        let m = 4.5e-3;
        let r = m * z as f64 / 2.0;
        let outline = ToothOutline::new(ToothInput {
            teeth: z,
            transverse_module: m,
            normal_module: m,
            pressure_angle: 20f64.to_radians(),
            shift: x * m,
            tip_radius: r + m * (1.0 + x),
            root_radius: r - (1.25 * m - x * m),
        })
        .unwrap();
        let rf = outline.input.root_radius;
        ToothCompliance::new(outline, 206e9, 0.3, 0.5 * rf)
    }

    /// The series meets its tolerance below the largest degree, and the involute's moments agree
    /// with an independent adaptive quadrature at an interior roll length (1e-11 relative).
    #[test]
    fn series_converged() {
        let t = tooth(16, 0.1817);
        assert!(t.relative_error < 1e-11, "{}", t.relative_error);
        let [l0, l1] = t.outline.involute_rolls();
        let l = l0 + 0.37 * (l1 - l0);
        let y0 = t.outline.root_y();
        let direct = integrate_singular_n(
            |v, _| {
                let p = t.outline.involute_point(v);
                moments_integrand(p.y - y0, p.h, p.dy)
            },
            &[l0, l],
            &[],
            1e-13,
        );
        for (k, d) in direct.iter().enumerate() {
            let series = clenshaw(&t.involute[k], 0.37);
            assert!((series - d.value).abs() < 1e-11 * d.value.abs(), "moment {k}");
        }
    }

    /// Every part is positive and the bending compliance grows monotonically from root to tip.
    #[test]
    fn compliance_grows_towards_the_tip() {
        let t = tooth(24, 0.0);
        let [l0, l1] = t.outline.involute_rolls();
        let mut last = 0.0;
        for i in 0..=10 {
            let p = t.at(l0 + (l1 - l0) * (0.05 + 0.95 * i as f64 / 10.0));
            assert!(p.bending > last && p.shear > 0.0 && p.axial > 0.0 && p.foundation > 0.0, "{p:?}");
            last = p.bending;
        }
    }
}
