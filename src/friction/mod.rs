//! Friction laws along the line of action: one file per law behind the small [`FrictionLaw`] trait.
//!
//! A law is built for one operating point ([`LawContext`]) from the scene's `friction { ... }` entry and
//! then gives the **signed** coefficient of friction at any contact: positive in recess (s > 0),
//! negative in approach (s < 0), and 0 exactly at the pitch point, where the sliding direction
//! reverses (physics notes, "Friction laws"). Laws that diverge at P say so; callers never put their
//! value at P into a table, plot or mean, and integrate the (integrable) singularity instead.
//!
//! ```
//! use gearloss::friction::{Coulomb, FrictionLaw};
//! # use gearloss::geometry::ContactPoint;
//! # let mut c: ContactPoint = gearloss::friction::testing::contact();
//! let law = Coulomb { mu: 0.05 };
//! c.s = -1e-3; // approach
//! assert_eq!(law.mu(&c), -0.05);
//! c.s = 2e-3; // recess
//! assert_eq!(law.mu(&c), 0.05);
//! ```

mod benedict_kelley;
pub(crate) mod benedict_kelley_bernard;
pub mod catalog;
mod composite;
mod coulomb;
pub(crate) mod drozdov_gavrikov;
mod friction_law;
mod iso_14179_2;
mod law_context;
pub(crate) mod law_id;
mod matsumoto;
mod misharin;
pub(crate) mod needs;
mod odonoghue_cameron;
mod smoothed_coulomb;
#[doc(hidden)]
pub mod testing;
mod xu;

pub use friction_law::{signed, FrictionLaw, Parameter, Regime};
pub use law_context::LawContext;
pub use law_id::LawId;

pub use benedict_kelley::BenedictKelley;
pub use composite::Composite;
pub use coulomb::Coulomb;
pub use iso_14179_2::Iso14179_2;
pub use matsumoto::Matsumoto;
pub use misharin::Misharin;
pub use odonoghue_cameron::ODonoghueCameron;
pub use smoothed_coulomb::SmoothedCoulomb;
pub use xu::Xu;
