//! Friction laws along the line of action: one file per law behind the small [`FrictionLaw`] trait.
//!
//! A law is built for one operating point ([`LawContext`]) from the scene's `friction { ... }` entry and
//! then gives the **signed** coefficient of friction at any contact: positive in recess (s > 0),
//! negative in approach (s < 0), and 0 exactly at the pitch point, where the sliding direction
//! reverses (physics notes, "Friction laws"). Laws that diverge at P say so; callers never put their
//! value at P into a table, plot or mean, and integrate the (integrable) singularity instead.
//!
//! ```
//! use gearloss::friction::{FrictionLaw, coulomb::Coulomb};
//! # use gearloss::geometry::ContactPoint;
//! # let mut c: ContactPoint = gearloss::friction::testing::contact();
//! let law = Coulomb { mu: 0.05 };
//! c.s = -1e-3; // approach
//! assert_eq!(law.mu(&c), -0.05);
//! c.s = 2e-3; // recess
//! assert_eq!(law.mu(&c), 0.05);
//! ```

pub mod benedict_kelley;
pub mod benedict_kelley_bernard;
pub mod catalog;
pub mod composite;
pub mod coulomb;
pub mod drozdov_gavrikov;
pub mod iso_14179_2;
pub mod law_id;
pub mod matsumoto;
pub mod misharin;
pub mod needs;
pub mod odonoghue_cameron;
pub mod smoothed_coulomb;
pub mod xu;

use serde::Serialize;

pub use law_id::LawId;

use crate::geometry::contact::Sharing;
use crate::geometry::{ContactPoint, Mesh, OperatingState, PairGeometry};
use crate::tribology::Tribology;

/// Everything a law may read at one operating point.
#[derive(Debug, Clone, Copy)]
pub struct LawContext<'a> {
    pub geometry: &'a PairGeometry,
    pub state: OperatingState,
    pub tribology: Tribology,
    pub sharing: Sharing<'a>,
}

impl LawContext<'_> {
    /// The pair at this operating point: the contact states of its mesh cycle.
    pub fn mesh(&self) -> Mesh<'_> {
        Mesh {
            pair: self.geometry,
            state: self.state,
            reduced_modulus: self.tribology.reduced_modulus,
            sharing: self.sharing,
        }
    }

    /// The contact state at `u` (from T1).
    pub fn contact_at(&self, u: f64) -> ContactPoint {
        self.mesh().contact_at(u)
    }

    /// The contact state at distance `s` from the pitch point, with `s` exact (for integrands near P).
    pub fn contact_at_offset(&self, s: f64) -> ContactPoint {
        self.mesh().contact_at_offset(s)
    }
}

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

/// A contact state for examples and tests: FZG type C near the start of contact at 1000 rpm, 302 N·m.
#[doc(hidden)]
pub mod testing {
    use crate::geometry::ContactPoint;

    pub fn contact() -> ContactPoint {
        ContactPoint {
            u: 6.0e-3,
            s: -7.97e-3,
            radius_of_curvature: [6.0e-3, 28.9e-3],
            reduced_radius: 4.97e-3,
            rolling_velocity: [0.628, 2.02],
            sliding_velocity: 1.39,
            sum_velocity: 2.65,
            entrainment_velocity: 1.325,
            slide_to_roll: 1.05,
            pairs_in_contact: 2,
            load_share: 0.5,
            force_share: 0.5,
            load_per_width: 3.19e5,
            hertz_pressure: 1.52e9,
            hertz_half_width: 1.34e-4,
        }
    }
}
