//! A planetary stage in the drive: the stage at one operating point from its two meshes'
//! efficiencies ([`flow`]), the forces on its members and planet bearings ([`loads`]) and what the
//! report reads ([`point`]). Its kinematics and layout are the catalogue's
//! [`super::kinematics::planetary`] entry; what the walk charges for it is
//! [`super::planetary_charges`].

pub(crate) mod flow;
pub(crate) mod loads;
pub(crate) mod point;

pub(crate) use crate::drive::kinematics::planetary::PlanetaryLayout;
pub(crate) use flow::{PlanetMesh, PlanetaryState};
pub(crate) use point::PlanetaryPoint;
