//! The teeth as elastic bodies: each tooth's outline from the generating rack, its compliance by
//! the potential-energy method, a pair's stiffness along the path of contact, and the load a pair
//! carries when pairs share by compatibility of deflections (with tip relief), which gives the
//! static transmission error.

pub(crate) mod compliance;
pub(crate) mod compliance_series;
pub(crate) mod iso_6336_method_b;
pub(crate) mod load_sharing;
pub(crate) mod outline;
pub(crate) mod pair_stiffness;
pub(crate) mod transmission_error;
pub use compliance::{sainsot_coefficients, SAINSOT_RANGES};
pub use iso_6336_method_b::{iso_6336_method_b, single_pair_flexibility, virtual_teeth, C_M};
pub use load_sharing::{LoadSharing, ReliefShape, Reliefs, TipRelief};
pub use pair_stiffness::{Bodies, PairStiffness};
pub use transmission_error::SERIES_POINTS;
