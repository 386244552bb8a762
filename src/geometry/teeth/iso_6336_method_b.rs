//! ISO 6336-1:2019 Method B (§9): the single-pair stiffness c' and the mesh stiffness c_γα per unit
//! face width, to set beside the potential-energy method's figures.
//!
//! q′ = C1 + C2/z_n1 + C3/z_n2 + C4 x1 + C5 x1/z_n1 + C6 x2 + C7 x2/z_n2 + C8 x1² + C9 x2²
//! (mm·µm/N, Table 2), z_n = z/cos³β; c′_th = 1/q′; c′ = c′_th C_M C_R C_B cos β (E/E_st) with
//! C_M = 0.8, C_R = 1 (solid blanks), C_B = (C_B1 + C_B2)/2, C_Bi = [1 + 0.5(1.2 − h_fPi/m_n)]
//! [1 − 0.02(20° − α_n)] with each gear's own rack dedendum, E = 2E₁E₂/(E₁ + E₂), E_st = 206 GPa;
//! c_γα = c′ (0.75 ε_α + 0.25). The standard gives them for F_t/b ≥ 100 N/mm.

use crate::geometry::pair::PairGeometry;

const C: [f64; 9] = [0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182];

/// c' and c_γα in N/(mm·µm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IsoStiffness {
    pub c_single: f64,
    pub c_gamma_alpha: f64,
}

/// ISO 6336-1 Method B for the pair `g`, with E of both gears and each gear's root radius.
pub fn iso_6336_method_b(g: &PairGeometry, young: [f64; 2], root_radius: [f64; 2]) -> IsoStiffness {
    let cos_b = g.helix_angle.cos();
    let zn = [g.teeth[0] as f64 / cos_b.powi(3), g.teeth[1] as f64 / cos_b.powi(3)];
    let [x1, x2] = g.profile_shift;
    let q = C[0]
        + C[1] / zn[0]
        + C[2] / zn[1]
        + C[3] * x1
        + C[4] * x1 / zn[0]
        + C[5] * x2
        + C[6] * x2 / zn[1]
        + C[7] * x1 * x1
        + C[8] * x2 * x2;
    let c_b = |i: usize| {
        let h_fp = g.pitch_radius[i] - root_radius[i] + g.profile_shift[i] * g.module;
        (1.0 + 0.5 * (1.2 - h_fp / g.module)) * (1.0 - 0.02 * (20.0 - g.pressure_angle.to_degrees()))
    };
    let e = 2.0 * young[0] * young[1] / (young[0] + young[1]);
    let c_single = 0.8 * 0.5 * (c_b(0) + c_b(1)) * cos_b * (e / 206e9) / q;
    IsoStiffness { c_single, c_gamma_alpha: c_single * (0.75 * g.contact_ratio + 0.25) }
}
