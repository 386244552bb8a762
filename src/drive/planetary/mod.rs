//! A planetary stage in the drive: the stage at one operating point from its two meshes'
//! efficiencies ([`flow`]), the forces on its members and planet bearings ([`loads`]) and what the
//! report reads ([`point`]). Its kinematics and layout are the catalogue's
//! [`super::kinematics::planetary`] entry; what the walk charges for it is
//! [`super::planetary_charges`].

pub mod flow;
pub mod loads;
pub mod point;

pub use crate::drive::kinematics::planetary::PlanetaryLayout;
pub use flow::{planetary_state, PlanetMesh, PlanetaryState};
pub use point::PlanetaryPoint;
