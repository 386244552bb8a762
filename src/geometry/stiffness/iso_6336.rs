//! The ISO 6336-1 (Method B) estimate of the mesh stiffness from the pair's geometry: the
//! single-pair stiffness per face width c' from the flexibility q' of ISO 6336-1 §9 (README,
//! "Mesh stiffness"), q' = 0.04723 + 0.15551/z_n1 + 0.25791/z_n2 − 0.00635 x1 − 0.11654 x1/z_n1
//! − 0.00193 x2 − 0.24188 x2/z_n2 + 0.00529 x1² + 0.00182 x2² (mm·µm/N), c' = C_M C_R C_B / q'
//! with C_M = 0.8, C_R = 1 (solid blanks), C_B = [1 + 0.5(1.2 − h_fP/m)][1 − 0.02(20° − α)].
//!
//! A spur pair gets the rectangular k_n = n c' b; a helical pair a stiffness density whose mean
//! transverse mesh stiffness per unit face width, K̄/b = k cos β_b ε_α, equals ISO's
//! c_γα = c'(0.75 ε_α + 0.25), with c' including cos β.

use super::mesh_stiffness::StiffnessModel;
use super::pairs_in_contact::PairsInContact;
use super::per_length::PerLength;
use crate::geometry::pair::PairGeometry;

/// The ISO 6336-1 single-pair stiffness per face width c' (N/(mm·µm)).
pub fn iso_6336_single_stiffness(g: &PairGeometry) -> f64 {
    let (z1, z2) = (g.teeth[0] as f64, g.teeth[1] as f64);
    let [x1, x2] = g.profile_shift;
    let q = 0.04723 + 0.15551 / z1 + 0.25791 / z2 - 0.00635 * x1 - 0.11654 * x1 / z1 - 0.00193 * x2 - 0.24188 * x2 / z2
        + 0.00529 * x1 * x1
        + 0.00182 * x2 * x2;
    let (c_m, c_r) = (0.8, 1.0);
    let h_fp = 1.25;
    let c_b = (1.0 + 0.5 * (1.2 - h_fp)) * (1.0 - 0.02 * (20.0 - g.pressure_angle.to_degrees()));
    c_m * c_r * c_b / q
}

/// The ISO estimate for the pair `g`: rectangular (spur) or a stiffness density (helical). The
/// catalogue's constructor: the bodies are not read (the estimate takes no material).
pub fn build(g: &PairGeometry, _: &crate::geometry::teeth::pair_stiffness::Bodies) -> StiffnessModel {
    iso_estimate(g)
}

/// The ISO estimate for the pair `g` (materials do not enter it).
pub fn iso_estimate(g: &PairGeometry) -> StiffnessModel {
    if g.is_helical() {
        let c_prime = iso_6336_single_stiffness(g) * g.helix_angle.cos() * 1e9; // N/m²
        let c_gamma = c_prime * (0.75 * g.contact_ratio + 0.25);
        return StiffnessModel::new(PerLength::on(c_gamma / (g.contact_ratio * g.base_helix_angle.cos()), g));
    }
    // c' in N/(mm·µm) times b in mm: N/µm, ×1e6: N/m.
    let k = iso_6336_single_stiffness(g) * g.face_width * 1e3 * 1e6;
    StiffnessModel::new(PairsInContact { single: k, double: 2.0 * k, triple: 3.0 * k })
}
