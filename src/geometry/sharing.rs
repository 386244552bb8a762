//! How the normal load is shared between the pairs (or lines) in contact: equally, wholly, or by
//! the compatibility of the teeth's deflections ([`LoadSharing`], from their stiffness and relief).

use super::teeth::load_sharing::LoadSharing;

/// How the normal load is shared between pairs in contact.
#[derive(Debug, Clone, Copy)]
pub enum Sharing<'a> {
    /// 1/n of the load on each of n pairs in contact.
    Equal,
    /// Every contact carries the whole load.
    Whole,
    /// Pair j carries k_j max(0, δ − e_j), δ closing the balance (`load_sharing = stiffness`).
    Stiffness(&'a LoadSharing),
}

impl Sharing<'_> {
    /// The rule's name in the scene language.
    pub fn name(&self) -> &'static str {
        match self {
            Sharing::Equal => "equal",
            Sharing::Whole => "none",
            Sharing::Stiffness(_) => "stiffness",
        }
    }
}
