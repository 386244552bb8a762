//! What a friction law reads at one operating point: the pair, the state, the lubricant and
//! surfaces, and how the load is shared.

use crate::geometry::contact::Sharing;
use crate::geometry::{ContactPoint, Mesh, OperatingState, PairGeometry};
use crate::tribology::Tribology;

/// Everything a law may read at one operating point.
#[derive(Debug, Clone, Copy)]
pub struct LawContext<'a> {
    pub geometry: &'a PairGeometry,
    pub state: OperatingState,
    pub tribology: Tribology,
    pub sharing: Sharing<'a>,
}

impl LawContext<'_> {
    /// The pair at this operating point: the contact states of its mesh cycle.
    pub fn mesh(&self) -> Mesh<'_> {
        Mesh {
            pair: self.geometry,
            state: self.state,
            reduced_modulus: self.tribology.reduced_modulus,
            sharing: self.sharing,
        }
    }

    /// The contact state at `u` (from T1).
    pub fn contact_at(&self, u: f64) -> ContactPoint {
        self.mesh().contact_at(u)
    }

    /// The contact state at distance `s` from the pitch point, with `s` exact (for integrands near P).
    pub fn contact_at_offset(&self, s: f64) -> ContactPoint {
        self.mesh().contact_at_offset(s)
    }
}
