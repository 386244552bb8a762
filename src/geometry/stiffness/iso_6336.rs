//! The ISO 6336-1 (Method B) estimate of the mesh stiffness from the pair's geometry, for the
//! dynamics (`mesh_stiffness = iso_6336`): c' and c_γα per unit face width from
//! [`iso_6336_method_b`] (README, "Mesh stiffness"), with the scene's moduli and root diameters
//! (E/E_st and each gear's C_B).
//!
//! A spur pair gets the rectangular k_n = n c' b; a helical pair a stiffness density whose mean
//! transverse mesh stiffness per unit face width, K̄/b = k cos β_b ε_α, equals ISO's
//! c_γα = c'(0.75 ε_α + 0.25), with c' including cos β.

use super::mesh_stiffness::StiffnessModel;
use super::pairs_in_contact::PairsInContact;
use super::per_length::PerLength;
use crate::geometry::pair::PairGeometry;
use crate::geometry::teeth::iso_6336_method_b::{iso_6336_method_b, IsoStiffness};
use crate::geometry::teeth::pair_stiffness::Bodies;

/// The ISO estimate for the pair `g` with the gear bodies `bodies` (their moduli and root
/// diameters, given or the basic rack's): rectangular (spur) or a stiffness density (helical).
/// The catalogue's constructor.
pub(crate) fn build(g: &PairGeometry, bodies: &Bodies) -> StiffnessModel {
    let iso = method_b(g, bodies);
    // N/(mm·µm) = 1e9 N/m².
    if g.is_helical() {
        let density = iso.c_gamma_alpha * 1e9 / (g.contact_ratio * g.base_helix_angle.cos());
        return StiffnessModel::new(PerLength::on(density, g));
    }
    let k = iso.c_single * 1e9 * g.face_width;
    StiffnessModel::new(PairsInContact { single: k, double: 2.0 * k, triple: 3.0 * k })
}

/// ISO 6336-1 Method B for the pair `g` with the gear bodies' moduli and root radii (given, or the
/// basic rack's): the figures this model is built from, with their readings.
pub(crate) fn method_b(g: &PairGeometry, bodies: &Bodies) -> IsoStiffness {
    iso_6336_method_b(g, bodies.young, [0, 1].map(|i| bodies.radii(g, i).0))
}
