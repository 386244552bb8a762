//! The teeth as elastic bodies: each tooth's outline from the generating rack, its compliance by
//! the potential-energy method, a pair's stiffness along the path of contact, and the load a pair
//! carries when pairs share by compatibility of deflections (with tip relief), which gives the
//! static transmission error.

pub mod compliance;
pub(crate) mod compliance_series;
pub mod iso_6336_method_b;
pub mod load_sharing;
pub(crate) mod outline;
pub mod pair_stiffness;
pub mod transmission_error;
