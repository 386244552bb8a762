//! The typed identity of each mesh stiffness model of the catalogue.

/// The typed identity of a stiffness model of the catalogue.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
pub enum StiffnessId {
    PairsInContact,
    Table,
    PerLength,
    Iso6336,
    PotentialEnergy,
}
