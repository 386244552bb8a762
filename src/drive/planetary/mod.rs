//! A planetary stage in the drive: its sizes and parts ([`layout`]), the stage at one operating
//! point from its two meshes' efficiencies ([`flow`]) and the forces on its members and planet
//! bearings ([`loads`]). Its kinematics is the catalogue's [`super::kinematics::planetary`] entry.

pub mod charges;
pub mod flow;
pub mod layout;
pub mod loads;
pub mod point;

pub use flow::{planetary_state, PlanetMesh, PlanetaryState};
pub use layout::PlanetaryLayout;
pub use point::PlanetaryPoint;
