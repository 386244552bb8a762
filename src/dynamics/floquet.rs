//! Floquet analysis of the periodic SDOF system (He & Singh §4; physics notes, "Dynamics"):
//! monodromy Φ(T) = Π Φ_j, multipliers = eig Φ(T), stable while every |λ| < 1, and the periodic
//! forced response directly from (I − Φ(T)) X*(0) = q(T), with no marching through transients.
//! Liouville's formula det Φ(T) = exp(∫₀ᵀ tr A dt) checks the propagators.

use nalgebra::{Matrix2, Vector2};
use serde::Serialize;

use super::propagator::{monodromy, period_segments, Method, Propagation};
use super::sdof::{DynamicFormulation, SdofSystem};
use crate::numerics::quadrature::integrate;

/// A Floquet multiplier.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Multiplier {
    pub re: f64,
    pub im: f64,
}

impl Multiplier {
    pub fn abs(&self) -> f64 {
        self.re.hypot(self.im)
    }
}

/// Stability verdict from the spectral radius ρ.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// ρ < 1 − 1e-9: perturbations decay; the periodic response is the steady state.
    Stable,
    /// |ρ − 1| ≤ 1e-9 (undamped): neither decay nor growth.
    Marginal,
    /// ρ > 1 + 1e-9: parametric instability; no steady state exists in the linear model.
    Unstable,
}

/// Everything Floquet theory gives at one operating point and formulation.
#[derive(Debug, Clone)]
pub struct Floquet {
    pub segments: Vec<Propagation>,
    pub method: Method,
    pub monodromy: Propagation,
    pub multipliers: [Multiplier; 2],
    pub spectral_radius: f64,
    pub verdict: Verdict,
    /// det Φ(T) and exp(∫ tr A) (Liouville).
    pub determinant: f64,
    pub liouville: f64,
    /// X*(0) of the periodic response; None when I − Φ(T) is singular or the system is unstable.
    pub periodic_state: Option<Vector2<f64>>,
}

/// Eigenvalues of a real 2×2 matrix.
pub fn eigenvalues(m: &Matrix2<f64>) -> [Multiplier; 2] {
    let tr = m.trace();
    let det = m.determinant();
    let disc = 0.25 * tr * tr - det;
    if disc >= 0.0 {
        let r = disc.sqrt();
        [Multiplier { re: 0.5 * tr + r, im: 0.0 }, Multiplier { re: 0.5 * tr - r, im: 0.0 }]
    } else {
        let i = (-disc).sqrt();
        [Multiplier { re: 0.5 * tr, im: i }, Multiplier { re: 0.5 * tr, im: -i }]
    }
}

/// exp(∫₀ᵀ tr A(t) dt): tr A = −c/m_e (base, external) or −(1 − f) c/m_e (internal).
pub fn liouville(sys: &SdofSystem) -> f64 {
    let c = sys.damping / sys.equivalent_mass;
    let integral = match sys.formulation {
        DynamicFormulation::Internal => {
            let breaks: Vec<f64> = std::iter::once(0.0).chain(sys.segments.iter().map(|s| s.end)).collect();
            integrate(|t| -(1.0 - sys.friction_term(t)) * c, &breaks, 1e-13).value
        }
        _ => -c * sys.period,
    };
    integral.exp()
}

impl Floquet {
    pub fn analyse(sys: &SdofSystem) -> Floquet {
        let (segments, method) = period_segments(sys);
        let mono = monodromy(&segments);
        let multipliers = eigenvalues(&mono.phi);
        let rho = multipliers[0].abs().max(multipliers[1].abs());
        let verdict = if rho > 1.0 + 1e-9 {
            Verdict::Unstable
        } else if rho >= 1.0 - 1e-9 {
            Verdict::Marginal
        } else {
            Verdict::Stable
        };
        let periodic_state = match verdict {
            Verdict::Unstable => None,
            _ => (Matrix2::identity() - mono.phi)
                .try_inverse()
                .map(|inv| inv * mono.q)
                .filter(|x| x.iter().all(|v| v.is_finite())),
        };
        Floquet {
            determinant: mono.phi.determinant(),
            liouville: liouville(sys),
            segments,
            method,
            monodromy: mono,
            multipliers,
            spectral_radius: rho,
            verdict,
            periodic_state,
        }
    }
}
