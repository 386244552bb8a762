//! The mesh stiffness of a pair over one mesh cycle, as a catalogue: each model is one file
//! implementing [`MeshStiffness`] and one row of [`catalog::MODELS`].
//!
//! Today: rectangular (one value per number of pairs in contact, `pairs_in_contact`), a table
//! over the cycle (`table`), a stiffness density along the contact lines (`per_length`) and
//! the ISO 6336-1 estimate, which builds one of the first and third from the geometry
//! (`iso_6336`). A model computed from the geometry alone is named in a scene by its catalogue
//! name (`mesh_stiffness = iso_6336`): adding one is its file, its [`StiffnessId`] and its row.
//! The dynamics read k(τ) through [`StiffnessModel`], a shared handle on the model.

pub(crate) mod catalog;
pub(crate) mod iso_6336;
pub(crate) mod mesh_stiffness;
pub(crate) mod pairs_in_contact;
pub(crate) mod per_length;
pub(crate) mod potential_energy;
pub(crate) mod stiffness_id;
pub(crate) mod table;

pub use catalog::{StiffnessEntry, StiffnessId, MODELS};
pub use mesh_stiffness::{MeshStiffness, StiffnessModel, StiffnessShape};
pub use pairs_in_contact::PairsInContact;
