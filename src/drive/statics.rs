//! The statics of one shaft: a rigid beam on two bearing places, loaded by every gear on it.
//!
//! Unknowns: the transverse reactions (R_x, R_y) of both places and the axial reaction R_z of the
//! place that locates. Equations (all six of the shaft's equilibrium; the sixth, about the axis,
//! is the torque balance the power walk keeps): ΣF_x = ΣF_y = ΣF_z = 0 and the moments about the
//! x and y axes through the shaft's origin, Σ (y F_z − z F_y) = 0 and Σ (z F_x − x F_z) = 0, the
//! bearings acting on the axis at their positions z_1 ≠ z_2. Solved in closed form:
//! R_2x = (z_1 ΣF_x − M_y)/(z_2 − z_1), R_2y = (z_1 ΣF_y + M_x)/(z_2 − z_1), R_1 = −ΣF − R_2
//! (Niemann & Winter, Maschinenelemente I, the shaft as a beam on two supports; the axial force's
//! moment at the working pitch radius included).
//!
//! ```
//! use gearloss::drive::{statics::{residuals, shaft_reactions}, GearLoad, Member};
//! // Two gears on a lay shaft, bearings at 30 mm and 136 mm, the second place locating.
//! let loads = [
//!     GearLoad { stage: 0, member: Member::Wheel, shaft: 1, point: [-0.052, 0.0, 0.056], force: [1200.0, 3300.0, -1400.0] },
//!     GearLoad { stage: 1, member: Member::Pinion, shaft: 1, point: [0.026, 0.0, 0.103], force: [-4600.0, 12600.0, 4200.0] },
//! ];
//! let r = shaft_reactions(&loads, [0.030, 0.136], 1);
//! assert_eq!(r[0][2], 0.0);
//! assert!(residuals(&loads, [0.030, 0.136], &r).iter().all(|x| x.abs() < 1e-12 * 12600.0));
//! ```

use super::forces::GearLoad;

/// The reactions [[R_x, R_y, R_z]; 2] (N) of the places at `positions` (m), the whole axial
/// reaction at place `locating`, on the gear loads `loads` (all of one shaft).
pub fn shaft_reactions(loads: &[GearLoad], positions: [f64; 2], locating: usize) -> [[f64; 3]; 2] {
    let [z1, z2] = positions;
    let (f, m) = resultant(loads);
    let r2x = (z1 * f[0] - m[1]) / (z2 - z1);
    let r2y = (z1 * f[1] + m[0]) / (z2 - z1);
    let mut out = [[-f[0] - r2x, -f[1] - r2y, 0.0], [r2x, r2y, 0.0]];
    out[locating][2] = -f[2];
    out
}

/// The resultant force ΣF and its moments [M_x, M_y] about the shaft's origin.
fn resultant(loads: &[GearLoad]) -> ([f64; 3], [f64; 2]) {
    let mut f = [0.0; 3];
    let mut m = [0.0; 2];
    for l in loads {
        let ([x, y, z], [fx, fy, fz]) = (l.point, l.force);
        f = [f[0] + fx, f[1] + fy, f[2] + fz];
        m = [m[0] + y * fz - z * fy, m[1] + z * fx - x * fz];
    }
    (f, m)
}

/// The five residuals [ΣF_x, ΣF_y, ΣF_z, M_x, M_y] (N, N·m) of the shaft with its reactions.
pub fn residuals(loads: &[GearLoad], positions: [f64; 2], reactions: &[[f64; 3]; 2]) -> [f64; 5] {
    let (f, m) = resultant(loads);
    let r = reactions;
    [
        f[0] + r[0][0] + r[1][0],
        f[1] + r[0][1] + r[1][1],
        f[2] + r[0][2] + r[1][2],
        m[0] - positions[0] * r[0][1] - positions[1] * r[1][1],
        m[1] + positions[0] * r[0][0] + positions[1] * r[1][0],
    ]
}
