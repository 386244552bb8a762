//! The contact state at a point of the line of action: radii of curvature, velocities, slide-to-roll
//! ratio, load share, load per unit face width and Hertzian pressure (physics notes, "Geometry and
//! names"; Hertz line contact as in He–Cho–Singh §2 and Johnson, Contact Mechanics, eq 4.45).

use serde::Serialize;

pub use super::elastic::reduced_modulus;
use super::pair::PairGeometry;
pub use super::sharing::Sharing;

/// One operating point in SI: pinion torque (N·m) and pinion speed (rad/s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct OperatingState {
    pub pinion_torque: f64,
    pub pinion_speed: f64,
}

/// The contact state at one point; SI units throughout.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Default)]
pub struct ContactPoint {
    /// Distance from T1 (m).
    pub u: f64,
    /// s = u − T1P: negative in approach, positive in recess (m).
    pub s: f64,
    /// ρ1 = u, ρ2 = T1T2 − u (m).
    pub radius_of_curvature: [f64; 2],
    /// R = ρ1ρ2/(ρ1 + ρ2) (m).
    pub reduced_radius: f64,
    /// v_i = ω_i ρ_i (m/s).
    pub rolling_velocity: [f64; 2],
    /// v_s = |v1 − v2| (m/s).
    pub sliding_velocity: f64,
    /// v_Σ = v1 + v2 (m/s).
    pub sum_velocity: f64,
    /// U = v_Σ / 2 (m/s).
    pub entrainment_velocity: f64,
    /// SR = v_s / U.
    pub slide_to_roll: f64,
    pub pairs_in_contact: usize,
    /// The share of the normal load the friction law and the Hertz formulas see: 1/n (`equal`) or 1
    /// (`none`, He–Cho–Singh's reading: each contact sees the whole load F_bn/b).
    pub load_share: f64,
    /// The share of F_bn this contact carries in the torque and power balance: always 1/n, so the
    /// forces of the n pairs in contact add up to F_bn whatever `load_share` is.
    pub force_share: f64,
    /// w = share · F_bn / b (N/m).
    pub load_per_width: f64,
    /// p_H = sqrt(w E' / (2π R)) (Pa).
    pub hertz_pressure: f64,
    /// b_H = sqrt(8 w R / (π E')) (m).
    pub hertz_half_width: f64,
}

impl PairGeometry {
    /// Normal load, F_bn = T_p / (r_b1 cos β_b) (N); T_p / r_b1 along the line of action of a spur pair.
    pub fn normal_load(&self, op: &OperatingState) -> f64 {
        op.pinion_torque / self.normal_force_arm(0)
    }

    /// The transverse force along the line of action the shares by stiffness are read at,
    /// T_p / r_b1 (N); 1 N at zero torque, where they are read at a vanishing load.
    pub fn sharing_force(&self, op: &OperatingState) -> f64 {
        let f = op.pinion_torque / self.base_radius[0];
        if f > 0.0 {
            f
        } else {
            1.0
        }
    }

    /// Wheel speed ω2 = ω1 z1/z2 (rad/s).
    pub fn wheel_speed(&self, op: &OperatingState) -> f64 {
        op.pinion_speed / self.gear_ratio
    }

    /// [load share the law sees, force share in the balance] of the pair at `s` (from P) when `n`
    /// pairs are in contact: 1/n and 1/n (`equal`); 1 and 1/n (`none`); by stiffness, the pair's
    /// own F_j/F_bn for both, F_j from the compatibility of the deflections at this torque.
    pub fn shares(&self, s: f64, n: usize, op: &OperatingState, sharing: Sharing) -> [f64; 2] {
        let equal = if n > 0 { 1.0 / n as f64 } else { 0.0 };
        match sharing {
            Sharing::Equal => [equal, equal],
            Sharing::Whole => [1.0, equal],
            Sharing::Stiffness(model) => {
                // Positions from A along the path.
                let share = model.spur_share(s + (self.points.p - self.points.a), self.sharing_force(op));
                [share, share]
            }
        }
    }

    /// The contact state at `u` (from T1) for an operating point, with reduced modulus E'; the
    /// number of pairs in contact is [`PairGeometry::pairs_in_contact`].
    pub fn contact_at(&self, u: f64, op: &OperatingState, reduced_modulus: f64, sharing: Sharing) -> ContactPoint {
        self.contact_with_pairs(u, op, reduced_modulus, sharing, self.pairs_in_contact(u))
    }

    /// The contact state at `u` when `n` pairs are in contact (known from the mesh cycle).
    pub fn contact_with_pairs(
        &self,
        u: f64,
        op: &OperatingState,
        reduced_modulus: f64,
        sharing: Sharing,
        n: usize,
    ) -> ContactPoint {
        self.contact_exact(u, u - self.points.p, op, reduced_modulus, sharing, n)
    }

    /// The contact state at `u` whose distance from the pitch point `s` is known more exactly than
    /// `u − T1P` (near P, where u cannot resolve s): the sliding velocity and the sign use `s`.
    pub fn contact_exact(
        &self,
        u: f64,
        s: f64,
        op: &OperatingState,
        reduced_modulus: f64,
        sharing: Sharing,
        n: usize,
    ) -> ContactPoint {
        let shares = self.shares(s, n, op, sharing);
        let w = shares[0] * self.normal_load(op) / self.face_width;
        self.contact_with_load(u, s, op, reduced_modulus, w, shares, n)
    }

    /// The contact state at `u` (s = u − T1P, exact) under a load per unit contact length `w`
    /// (N/m), with `shares` = [load share the law sees, force share in the balance] and `n` pairs or
    /// lines in contact. For a helical pair the radii of curvature are those of the normal section,
    /// ρ_i / cos β_b, as ISO/TR 14179-2 and ISO 6336-2 take them; the velocities are the transverse
    /// ones (physics notes, "Helical pairs").
    #[allow(clippy::too_many_arguments)]
    pub fn contact_with_load(
        &self,
        u: f64,
        s: f64,
        op: &OperatingState,
        reduced_modulus: f64,
        w: f64,
        shares: [f64; 2],
        n: usize,
    ) -> ContactPoint {
        let transverse = [u, self.line_of_action_length - u];
        let rho = if self.is_helical() {
            let c = self.base_helix_angle.cos();
            [transverse[0] / c, transverse[1] / c]
        } else {
            transverse
        };
        let r = rho[0] * rho[1] / (rho[0] + rho[1]);
        let v = [op.pinion_speed * transverse[0], self.wheel_speed(op) * transverse[1]];
        // v_s = |v1 − v2| = ω1 (1 + z1/z2) |s| (physics notes), written without the cancellation of
        // v1 − v2 near the pitch point.
        let vs = op.pinion_speed * (1.0 + 1.0 / self.gear_ratio) * s.abs();
        let vsum = v[0] + v[1];
        let ue = vsum / 2.0;
        ContactPoint {
            u,
            s,
            radius_of_curvature: rho,
            reduced_radius: r,
            rolling_velocity: v,
            sliding_velocity: vs,
            sum_velocity: vsum,
            entrainment_velocity: ue,
            slide_to_roll: if ue > 0.0 { vs / ue } else { 0.0 },
            pairs_in_contact: n,
            load_share: shares[0],
            force_share: shares[1],
            load_per_width: w,
            hertz_pressure: (w * reduced_modulus / (2.0 * std::f64::consts::PI * r)).sqrt(),
            hertz_half_width: (8.0 * w * r / (std::f64::consts::PI * reduced_modulus)).sqrt(),
        }
    }
}
