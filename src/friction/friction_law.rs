//! The [`FrictionLaw`] trait every law of the catalogue implements, the parameters and regimes a
//! law reports, and the sign convention all of them share ([`signed`]).

use serde::Serialize;

use super::law_id::LawId;
use crate::geometry::ContactPoint;

/// A lubrication regime of the composite law (Model V).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Regime {
    /// Λ < 1: smoothed Coulomb (Model IV).
    Boundary,
    /// 1 ≤ Λ < 4: Benedict–Kelley (Model II).
    Mixed,
    /// Λ ≥ 4: Xu et al. (Model III).
    FullFilm,
}

/// A parameter of a law as it was used (SI value and unit), for reports.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Parameter {
    pub name: &'static str,
    pub value: f64,
    pub unit: &'static str,
}

/// A coefficient-of-friction law along the line of action.
pub trait FrictionLaw: Send + Sync {
    /// The law's identity in the catalogue.
    fn id(&self) -> LawId;
    /// Signed μ at a contact; 0 at s = 0 exactly.
    fn mu(&self, c: &ContactPoint) -> f64;
    /// `Err(reason)` where the contact lies outside the law's stated validity range.
    fn validity(&self, _c: &ContactPoint) -> Result<(), &'static str> {
        Ok(())
    }
    /// True when |μ| → ∞ at the pitch point (integrable).
    /// The largest |μ| this law can plausibly give in a lubricated steel contact. Above it a number
    /// is flagged as outside validity. Default 0.3: lubricated steel gears stay below about 0.15 even
    /// in boundary lubrication, and dry steel on steel is 0.5–0.8, so |μ| > 0.3 means the law has
    /// been pushed (by a viscosity, speed or load far outside its data) beyond the physics it fits.
    fn plausible_max(&self) -> f64 {
        0.3
    }
    /// True when |μ| is the same at every contact off the pitch point (Coulomb, ISO/TR 14179-2): then
    /// the friction forcing of the external formulation is piecewise affine in time.
    fn constant_magnitude(&self) -> bool {
        false
    }
    fn diverges_at_pitch(&self) -> bool {
        false
    }
    /// The lubrication regime, for laws that switch between regimes.
    fn regime(&self, _c: &ContactPoint) -> Option<Regime> {
        None
    }
    /// Positions along the line of action (from T1) where the law switches regime.
    fn switch_points(&self) -> Vec<f64> {
        Vec::new()
    }
    /// The parameters as used, SI.
    fn parameters(&self) -> Vec<Parameter> {
        Vec::new()
    }
    /// Notes the report must carry whenever this law is used (low confidence, unit readings, clamps).
    fn notes(&self) -> Vec<String> {
        Vec::new()
    }
}

/// The Benedict–Kelley forms take log10 of an argument that must exceed 1 (else μ ≤ 0, clamped to 0).
pub(crate) fn log_argument_validity(c: &ContactPoint, argument: f64) -> Result<(), &'static str> {
    if c.s != 0.0 && argument <= 1.0 {
        Err("log argument ≤ 1: μ would be ≤ 0 and is clamped to 0")
    } else {
        Ok(())
    }
}

/// sgn(s) · magnitude, with 0 at s = 0 (the sliding direction reverses at P) whatever the
/// magnitude there (laws that diverge at P give ±∞ or NaN at s = 0, never returned).
pub fn signed(magnitude: f64, s: f64) -> f64 {
    if s > 0.0 {
        magnitude
    } else if s < 0.0 {
        -magnitude
    } else {
        0.0
    }
}
