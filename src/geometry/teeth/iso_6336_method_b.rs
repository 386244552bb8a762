//! ISO 6336-1:2019 Method B (§9): the single-pair stiffness c' and the mesh stiffness c_γα per unit
//! face width, the one implementation that the report sets beside the potential-energy method and
//! that the dynamics' `mesh_stiffness = iso_6336` builds its model from.
//!
//! q′ = C1 + C2/z_n1 + C3/z_n2 + C4 x1 + C5 x1/z_n1 + C6 x2 + C7 x2/z_n2 + C8 x1² + C9 x2²
//! (mm·µm/N, Table 2) with the virtual numbers of teeth z_n = z/(cos²β_b cos β) (ISO 21771, as
//! ISO 6336-1 uses them; z/cos³β is an approximation 0.9 % high at β = 15.8°); c′_th = 1/q′;
//! c′ = c′_th C_M C_R C_B cos β (E/E_st) with C_M = 0.8, C_R = 1 (solid blanks),
//! C_B = (C_B1 + C_B2)/2, C_Bi = [1 + 0.5(1.2 − h_fPi/m_n)][1 − 0.02(20° − α_n)] with each gear's
//! own rack dedendum h_fPi = r_i − r_fi + x_i m_n, E = 2E₁E₂/(E₁ + E₂), E_st = 206 GPa;
//! c_γα = c′ (0.75 ε_α + 0.25). The standard gives them for F_t/b ≥ 100 N/mm.
//!
//! Checked against the standard's own worked example, ISO/TR 6336-30:2017 example 1 (z 17/103,
//! m_n 8 mm, β 15.8°, x 0.145/0, ISO 53 rack D): c′_th 17.85584, c′ 12.37047 N/(mm·µm)
//! (test `iso_tr_6336_30_example_1`).
//!
//! ```
//! use gearloss::geometry::teeth::{virtual_teeth, single_pair_flexibility};
//! // ISO/TR 6336-30 example 1: z_n = 18.905 and 114.543, q′ = 1/17.85584 mm·µm/N.
//! let (beta, beta_b) = (15.8f64.to_radians(), (15.8f64.to_radians().sin() * 20f64.to_radians().cos()).asin());
//! let zn = [virtual_teeth(17, beta, beta_b), virtual_teeth(103, beta, beta_b)];
//! assert!((zn[0] - 18.905).abs() < 1e-3 && (zn[1] - 114.543).abs() < 1e-3);
//! assert!((1.0 / single_pair_flexibility(zn, [0.145, 0.0]) - 17.85584).abs() < 1e-3);
//! ```

use crate::geometry::pair::PairGeometry;

/// C1…C9 of ISO 6336-1 Table 2 (mm·µm/N).
const C: [f64; 9] = [0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182];
/// C_M: the standard's factor from the theoretical to measured solid-disc teeth.
pub const C_M: f64 = 0.8;
/// E_st: the modulus of the standard's steel (Pa).
const E_STEEL: f64 = 206e9;

/// c' and c_γα in N/(mm·µm), with the readings they rest on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IsoStiffness {
    pub c_single: f64,
    pub c_gamma_alpha: f64,
    /// z_n of pinion and wheel.
    pub virtual_teeth: [f64; 2],
    /// c′_th = 1/q′ (N/(mm·µm)).
    pub c_theoretical: f64,
    /// C_B, the mean of both gears' basic-rack factors.
    pub basic_rack_factor: f64,
    /// E/E_st with E = 2E₁E₂/(E₁ + E₂).
    pub modulus_ratio: f64,
    /// cos β and ε_α of the pair.
    pub cos_helix: f64,
    pub contact_ratio: f64,
}

/// The virtual number of teeth z_n = z/(cos²β_b cos β) (ISO 21771).
pub fn virtual_teeth(z: u32, helix: f64, base_helix: f64) -> f64 {
    z as f64 / (base_helix.cos().powi(2) * helix.cos())
}

/// The minimum flexibility q′ of a single tooth pair (mm·µm/N) for virtual teeth `zn` and normal
/// profile shifts `x` (ISO 6336-1 eq. (9.3) with Table 2).
pub fn single_pair_flexibility(zn: [f64; 2], x: [f64; 2]) -> f64 {
    let [x1, x2] = x;
    C[0] + C[1] / zn[0]
        + C[2] / zn[1]
        + C[3] * x1
        + C[4] * x1 / zn[0]
        + C[5] * x2
        + C[6] * x2 / zn[1]
        + C[7] * x1 * x1
        + C[8] * x2 * x2
}

/// ISO 6336-1 Method B for the pair `g`, with E of both gears and each gear's root radius.
pub fn iso_6336_method_b(g: &PairGeometry, young: [f64; 2], root_radius: [f64; 2]) -> IsoStiffness {
    let zn = [0, 1].map(|i| virtual_teeth(g.teeth[i], g.helix_angle, g.base_helix_angle));
    let q = single_pair_flexibility(zn, g.profile_shift);
    let c_b = |i: usize| {
        let h_fp = g.pitch_radius[i] - root_radius[i] + g.profile_shift[i] * g.module;
        (1.0 + 0.5 * (1.2 - h_fp / g.module)) * (1.0 - 0.02 * (20.0 - g.pressure_angle.to_degrees()))
    };
    let modulus_ratio = 2.0 * young[0] * young[1] / (young[0] + young[1]) / E_STEEL;
    let basic_rack_factor = 0.5 * (c_b(0) + c_b(1));
    let c_single = C_M * basic_rack_factor * g.helix_angle.cos() * modulus_ratio / q;
    IsoStiffness {
        c_single,
        c_gamma_alpha: c_single * (0.75 * g.contact_ratio + 0.25),
        virtual_teeth: zn,
        c_theoretical: 1.0 / q,
        basic_rack_factor,
        modulus_ratio,
        cos_helix: g.helix_angle.cos(),
        contact_ratio: g.contact_ratio,
    }
}
