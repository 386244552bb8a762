//! The catalogue of mesh stiffness models: each model's typed identity, the name a scene and the
//! report use, its file, and for a model computed from the geometry alone its constructor.

use super::iso_6336;
use super::mesh_stiffness::StiffnessModel;
use super::pairs_in_contact::PairsInContact;
use super::per_length::PerLength;
use super::potential_energy;
pub use super::stiffness_id::StiffnessId;
use super::table::Table;
use crate::geometry::pair::PairGeometry;
use crate::geometry::teeth::pair_stiffness::Bodies;

impl StiffnessId {
    /// The catalogue entry of this model.
    pub fn entry(self) -> &'static StiffnessEntry {
        &MODELS[self as usize]
    }

    pub fn name(self) -> &'static str {
        self.entry().name
    }
}

/// One model of the catalogue.
#[derive(Debug, Clone, Copy)]
pub struct StiffnessEntry {
    pub id: StiffnessId,
    /// The name a scene writes (`mesh_stiffness = iso_6336`) or the key of its block.
    pub name: &'static str,
    /// Its file in `src/geometry/stiffness/`.
    pub file: &'static str,
    pub title: &'static str,
    /// For a model computed from the geometry alone: its constructor (the scene names it).
    pub from_geometry: Option<fn(&PairGeometry, &Bodies) -> StiffnessModel>,
}

/// Every stiffness model.
pub const MODELS: &[StiffnessEntry] = &[
    StiffnessEntry {
        id: StiffnessId::PairsInContact,
        name: "pairs",
        file: "pairs_in_contact.rs",
        title: "rectangular: k with 1, 2, 3 pairs in contact",
        from_geometry: None,
    },
    StiffnessEntry {
        id: StiffnessId::Table,
        name: "table",
        file: "table.rs",
        title: "values over one mesh cycle, linearly interpolated",
        from_geometry: None,
    },
    StiffnessEntry {
        id: StiffnessId::PerLength,
        name: "per_length",
        file: "per_length.rs",
        title: "constant stiffness density along the contact lines (He & Singh)",
        from_geometry: None,
    },
    StiffnessEntry {
        id: StiffnessId::Iso6336,
        name: "iso_6336",
        file: "iso_6336.rs",
        title: "ISO 6336-1 Method B estimate from c' and c_γα",
        from_geometry: Some(iso_6336::build),
    },
    StiffnessEntry {
        id: StiffnessId::PotentialEnergy,
        name: "potential_energy",
        file: "potential_energy.rs",
        title: "potential-energy method from the teeth (bending, shear, axial, fillet foundation, Hertz)",
        from_geometry: Some(potential_energy::build),
    },
];

/// The models a scene names by keyword (computed from the geometry alone).
pub(crate) fn named_models() -> impl Iterator<Item = &'static StiffnessEntry> {
    MODELS.iter().filter(|m| m.from_geometry.is_some())
}

/// Constructors of the models given by values (the dynamics, tests and benches build them).
impl StiffnessModel {
    /// Rectangular: 1, 2 and 3 pairs in contact (N/m).
    pub fn pairs_in_contact(single: f64, double: f64, triple: f64) -> Self {
        Self::new(PairsInContact { single, double, triple })
    }

    /// Values over one mesh cycle (N/m).
    pub fn table(values: Vec<f64>) -> Self {
        Self::new(Table(values))
    }

    /// A stiffness density k (N/m²) on the pair `g`.
    pub fn per_length(density: f64, g: &PairGeometry) -> Self {
        Self::new(PerLength::on(density, g))
    }

    /// The ISO 6336-1 estimate for the pair `g` with the gear bodies `bodies`.
    pub fn iso_6336(g: &PairGeometry, bodies: &Bodies) -> Self {
        iso_6336::build(g, bodies)
    }
}
