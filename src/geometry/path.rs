//! Queries on a computed pair: the named points of the path of contact, how many pairs are in
//! contact at a point, the helical force arms and the axial force, and ISO 21771's tangent form of ε_α.

use std::f64::consts::PI;

use super::pair::PairGeometry;

impl PairGeometry {
    /// The points of A–E where the number of pairs in contact changes, A + k p_b and E − k p_b (k ≥ 1)
    /// strictly inside A–E, sorted, with their names. For 1 < ε_α < 2 these are B = E − p_b and
    /// D = A + p_b, the limits of single contact (A B P D E). For 2 ≤ ε_α < 3 there is no single
    /// contact and the order of E − p_b and A + p_b is reversed, so they are not called B and D: the
    /// names say how each point is built (`E−2pb`, `A+pb`, `E−pb`, `A+2pb`), where 3 ↔ 2 pairs change.
    pub fn pair_change_points(&self) -> Vec<(&'static str, f64)> {
        let (a, e, pb) = (self.points.a, self.points.e, self.base_pitch);
        let tol = 1e-9 * pb;
        let single = self.contact_ratio < 2.0;
        let mut out: Vec<(&'static str, f64)> = [
            (if single { "D" } else { "A+pb" }, a + pb),
            ("A+2pb", a + 2.0 * pb),
            (if single { "B" } else { "E−pb" }, e - pb),
            ("E−2pb", e - 2.0 * pb),
        ]
        .into_iter()
        .filter(|(_, u)| *u > a + tol && *u < e - tol)
        .collect();
        out.sort_by(|x, y| x.1.total_cmp(&y.1));
        out
    }

    /// A, every point where the number of pairs changes, P and E, sorted along the line of action.
    pub fn named_points(&self) -> Vec<(&'static str, f64)> {
        let mut v = vec![("A", self.points.a), ("P", self.points.p), ("E", self.points.e)];
        v.extend(self.pair_change_points());
        v.sort_by(|x, y| x.1.total_cmp(&y.1));
        v
    }

    /// How many pairs are in contact when one of them is at `u` (from T1): the pair itself, plus
    /// every neighbour one or more base pitches away that lies strictly inside (A, E). At the zone
    /// boundaries this gives the single-contact value, so B and D carry the whole load.
    pub fn pairs_in_contact(&self, u: f64) -> usize {
        let pb = self.base_pitch;
        let tol = 1e-9 * pb;
        let mut n = 1;
        for k in 1..4 {
            for sign in [-1.0, 1.0] {
                let v = u + sign * k as f64 * pb;
                if v > self.points.a + tol && v < self.points.e - tol {
                    n += 1;
                }
            }
        }
        n
    }

    /// True when the pair has a helix angle.
    pub fn is_helical(&self) -> bool {
        self.helix_angle != 0.0
    }

    /// The arm of the normal tooth force about gear `i`'s axis, r_b,i cos β_b: the normal force is
    /// inclined by β_b to the transverse plane (He & Singh eq 8; r_b,i for a spur pair).
    ///
    /// Signed as ISO 21771 signs the base radius: a ring's (i = 1 of an internal pair) is negative,
    /// so the efficiency's formulas of an external pair hold for an internal one unchanged.
    pub fn normal_force_arm(&self, i: usize) -> f64 {
        let sign = if i == 1 { self.wheel_sign() } else { 1.0 };
        if self.is_helical() {
            sign * self.base_radius[i] * self.base_helix_angle.cos()
        } else {
            sign * self.base_radius[i]
        }
    }

    /// ISO 21771's sign of the wheel's radii and teeth: −1 for a ring (an internal pair), else +1.
    pub fn wheel_sign(&self) -> f64 {
        super::pair_input::wheel_sign(self.internal)
    }

    /// The centre distance with ISO 21771's sign (negative for an internal pair).
    pub fn signed_center_distance(&self) -> f64 {
        self.wheel_sign() * self.center_distance
    }

    /// A force (or moment) per unit of the transverse force F_bn cos β_b, taken per unit of the normal
    /// force F_bn instead: x / cos β_b (x itself for a spur pair).
    pub fn to_normal(&self, x: f64) -> f64 {
        if self.is_helical() {
            x / self.base_helix_angle.cos()
        } else {
            x
        }
    }

    /// Axial force on the pinion from a pinion torque T_p (N·m): F_a = F_t tan β with
    /// F_t = T_p / r_1 the tangential force at the reference circle (ISO 6336-1 §5; 0 for spur).
    pub fn axial_force(&self, pinion_torque: f64) -> f64 {
        pinion_torque / self.pitch_radius[0] * self.helix_angle.tan()
    }

    /// Involute start (form circle) of gear `i`, as a distance from T1.
    /// A ring's flank is involute from its tip to its root (a pinion-type cutter generates it), so the
    /// path never reaches a start: +∞.
    pub fn involute_start_from_t1(&self, i: usize) -> f64 {
        if i == 0 {
            self.involute_start[0]
        } else if self.internal {
            f64::INFINITY
        } else {
            self.line_of_action_length - self.involute_start[1]
        }
    }

    /// ε_α by ISO 21771's tangent form, ε_α = [z1 (tan α_a1 − tan α_w) + z2 (tan α_a2 − tan α_w)] / 2π
    /// (z2 < 0 for an internal pair),
    /// independent of the line-of-action construction used by [`PairGeometry::compute`].
    pub fn contact_ratio_iso21771(&self) -> f64 {
        let mut sum = 0.0;
        for i in 0..2 {
            // z2 < 0 for a ring (ISO 21771).
            let z = if i == 1 { self.wheel_sign() } else { 1.0 } * self.teeth[i] as f64;
            let alpha_a = (self.base_radius[i] / self.tip_radius[i]).acos();
            sum += z * (alpha_a.tan() - self.operating_pressure_angle.tan());
        }
        sum / (2.0 * PI)
    }
}
