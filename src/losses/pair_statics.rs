//! The statics of a single-stage gearbox's two shafts, each on its bearing places, under the mesh
//! force at the gear's mid-plane (what [`super::budget::loss_budget`] hands the bearings part).
//!
//! Bearing loads come from the mesh force at the gear's mid-plane: the transverse force
//! F_bt = T_1/r_b1 along the line of action (the same on both shafts; tangential part
//! F_t = F_bt cos α_wt, radial part F_r = F_bt sin α_wt) and, for a helical pair, the axial force
//! F_a = F_t tan β_w acting at the working pitch radius r_w. With positions on a shaft of two bearing
//! places, the shaft is a beam on them and [`shaft_reactions`] solves its statics (3 forces, 2
//! moments); without positions each of the shaft's bearings carries F_bt / (number of bearings) and
//! the axial moment is not taken up. The axial force goes to the shaft's first bearing place (the
//! locating bearing), divided by its count.
//!
//! Axial convention: `at` is measured on one common axial direction for both shafts, from the gear
//! mid-plane. The axial mesh force on the pinion points towards increasing `at`, the wheel's (its
//! reaction) towards decreasing `at`. For a pair of the other hand, or turning the other way, the
//! axial forces reverse: mirror the positions (write each `at` with the opposite sign).

use super::bearings::Bearing;

/// The mesh force on one shaft's gear (N) and the radius where the axial part acts (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GearForce {
    pub tangential: f64,
    pub radial: f64,
    /// Along the common axial direction of `at` (+F_a on the pinion, −F_a on the wheel).
    pub axial: f64,
    /// The working pitch radius r_w of this shaft's gear.
    pub radius: f64,
}

/// The reactions [x, y, z] (N) of a shaft's two bearing places at positions p_1 ≠ p_2 (m) on the
/// gear force `f`, by statics of the shaft as a beam. Frame of the shaft: x along the line of
/// centres towards the mesh, y along the tangential force, z the common axial direction of `at`;
/// the gear force (−F_r, F_t, F_a) acts at (r_w, 0, 0). Forces: R_1 + R_2 + F = 0; moments about the
/// gear centre's x and y axes: Σ p_i e_z × R_i + r_w e_x × F = 0 (the z moment is the shaft's torque).
/// The axial reaction is all at the first place.
///
/// ```
/// use gearloss::losses::pair_statics::{shaft_reactions, GearForce};
/// let f = GearForce { tangential: 1000.0, radial: 364.0, axial: 268.0, radius: 0.04 };
/// let [r1, r2] = shaft_reactions(f, [-0.05, 0.05]);
/// // Force balance, and the moment about y: p_1 R_1x + p_2 R_2x = r_w F_a.
/// assert!((r1[0] + r2[0] - 364.0).abs() < 1e-12 && (r1[1] + r2[1] + 1000.0).abs() < 1e-12);
/// assert!((-0.05 * r1[0] + 0.05 * r2[0] - 0.04 * 268.0).abs() < 1e-12);
/// ```
pub fn shaft_reactions(f: GearForce, [p1, p2]: [f64; 2]) -> [[f64; 3]; 2] {
    let span = p2 - p1;
    let x2 = (f.radius * f.axial - p1 * f.radial) / span;
    let y2 = p1 * f.tangential / span;
    [[f.radial - x2, -f.tangential - y2, -f.axial], [x2, y2, 0.0]]
}

/// The [radial, axial] load of one bearing at each bearing place of one shaft (N).
pub(crate) fn place_loads(places: &[Bearing], f: GearForce, f_bt: f64) -> Vec<[f64; 2]> {
    let count: usize = places.iter().map(|b| b.count).sum();
    let axial_at = |i: usize| if i == 0 { f.axial.abs() / places[0].count as f64 } else { 0.0 };
    match places {
        [a, b] if a.position.is_some() && b.position.is_some() => {
            let p = [a.position.unwrap_or(0.0), b.position.unwrap_or(0.0)];
            let r = shaft_reactions(f, p);
            [a.count, b.count]
                .iter()
                .enumerate()
                .map(|(i, &n)| [r[i][0].hypot(r[i][1]) / n as f64, axial_at(i)])
                .collect()
        }
        _ => (0..places.len()).map(|i| [f_bt / count as f64, axial_at(i)]).collect(),
    }
}
