//! Rolling-bearing losses by Palmgren's moments, the bearing model of ISO/TR 14179-2:2001:
//!
//! - load-independent: M_0 = 10⁻⁷ f_0 (ν n)^(2/3) d_m³ for ν n ≥ 2000, M_0 = 160·10⁻⁷ f_0 d_m³
//!   below (N·mm; ν the oil's kinematic viscosity in mm²/s at the oil temperature, n in rpm, d_m
//!   the mean diameter (d + D)/2 in mm);
//! - load-dependent: M_1 = f_1 P_1 d_m (N·mm, P_1 in N);
//! - P_VL = (M_0 + M_1) ω per bearing.
//!
//! f_0, f_1 and P_1 by bearing type (Palmgren 1959; the values of SKF's General Catalogue 4000 E,
//! 1989, for oil-bath lubrication, as ISO/TR 14179-2 tabulates them; a middle value where the
//! catalogue gives a range by series):
//!
//! | type | f_0 | f_1 | P_1 |
//! |---|---|---|---|
//! | deep_groove_ball | 2.0 | 0.0007 (P_0/C_0)^0.5 | max(3F_a − 0.1F_r, F_r) |
//! | angular_contact_ball | 2.0 | 0.001 (P_0/C_0)^0.33 | max(F_a − 0.1F_r, F_r) |
//! | cylindrical_roller | 2.5 | 0.0003 | F_r |
//! | tapered_roller | 4.5 | 0.0004 | max(2 Y F_a, F_r), Y = `y` or [`TAPERED_Y`] |
//! | spherical_roller | 5.0 | 0.0005 (P_0/C_0)^0.33 | max(F_r + 2.5 F_a, F_r) |
//!
//! with P_0 = max(0.6 F_r + 0.5 F_a, F_r) the static equivalent load and C_0 the static load rating
//! (needed by the ball and spherical roller types). `f0` and `f1` given on a bearing replace the
//! table's. The angular-contact (2.0) and tapered (4.5) f_0 could not be traced to a primary table
//! here; README says so and points to `f0`.
//!
//! A bearing given with its SKF geometry constants is computed by the SKF model instead
//! ([`super::skf_bearing`]): its rolling moment M_rr takes the place of M_0 and its sliding moment
//! M_sl that of M_1 in the budget (both grow with the load there; M_rr carries the viscous, speed-
//! governed part as M_0 does).
//!
//! ```
//! use gearloss::losses::{Bearing, BearingType};
//! let b = Bearing { kind: BearingType::CylindricalRoller, mean_diameter: 0.060, count: 1,
//!                   static_load_rating: None, f0: None, f1: None, y: None, position: None, skf: None };
//! // ν = 14 mm²/s, n = 1500 rpm: ν n = 21 000 ≥ 2000, M_0 = 1e-7 · 2.5 · 21000^(2/3) · 60³ N·mm.
//! let m0 = 1e-7 * 2.5 * 21000f64.powf(2.0 / 3.0) * 216000.0 * 1e-3;
//! assert!((b.no_load_moment(14e-6, 1500.0 * std::f64::consts::PI / 30.0) - m0).abs() < 1e-12);
//! // 5 kN radial: M_1 = 0.0003 · 5000 · 60 N·mm = 0.09 N·m.
//! assert!((b.load_moment(5000.0, 0.0).unwrap() - 0.09).abs() < 1e-12);
//! ```

pub use super::bearing_type::BearingType;
pub(crate) use super::bearing_type::TAPERED_Y;

/// One bearing position on a shaft (`count` equal bearings there), in SI.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Bearing {
    pub kind: BearingType,
    /// d_m = (d + D)/2 (m).
    pub mean_diameter: f64,
    pub count: usize,
    /// C_0 (N).
    pub static_load_rating: Option<f64>,
    pub f0: Option<f64>,
    pub f1: Option<f64>,
    /// The axial load factor Y of a tapered roller bearing (its catalogue's Y for F_a/F_r > e), for
    /// P_1 = max(2 Y F_a, F_r); `TAPERED_Y` when not given.
    pub y: Option<f64>,
    /// Axial position along the shaft from the gear's mid-plane (m), for the lever rule.
    pub position: Option<f64>,
    /// The SKF model's constants with the bore d and outside diameter D (m) it needs.
    pub skf: Option<(super::skf_bearing::SkfConstants, [f64; 2])>,
}

impl Bearing {
    /// The loss model: "skf" for a bearing given with SKF constants, else "palmgren".
    pub fn model_name(&self) -> &'static str {
        if self.skf.is_some() {
            "skf"
        } else {
            "palmgren"
        }
    }

    /// M_0 (N·m) of one bearing at the oil's kinematic viscosity ν (m²/s) and shaft speed ω (rad/s).
    pub fn no_load_moment(&self, nu: f64, omega: f64) -> f64 {
        let f0 = self.f0.unwrap_or(self.kind.f0());
        let nu_n = nu * 1e6 * omega * 30.0 / std::f64::consts::PI;
        let dm3 = (self.mean_diameter * 1e3).powi(3);
        let n_mm = if nu_n >= 2000.0 { 1e-7 * f0 * nu_n.powf(2.0 / 3.0) * dm3 } else { 160e-7 * f0 * dm3 };
        n_mm * 1e-3
    }

    /// The shaft speed ω (rad/s) at which this bearing's model changes form at the oil's ν (m²/s):
    /// Palmgren's ν n = 2000 mm²/s·rpm, where M_0 steps from 160·10⁻⁷ f_0 d_m³ to
    /// 10⁻⁷ f_0 (ν n)^(2/3) d_m³ (a 0.8 % jump); `None` for the SKF model (smooth in n).
    pub fn switch_speed(&self, nu: f64) -> Option<f64> {
        (self.skf.is_none() && nu > 0.0).then(|| 2000.0 / (nu * 1e6) * std::f64::consts::PI / 30.0)
    }

    /// M_1 (N·m) of one bearing under F_r, F_a (N); `None` when f_1 needs a C_0 the bearing lacks.
    pub fn load_moment(&self, fr: f64, fa: f64) -> Option<f64> {
        let f1 = match self.f1 {
            Some(f) => f,
            None => self.kind.f1(fr, fa, self.static_load_rating)?,
        };
        Some(f1 * self.kind.p1(fr, fa, self.y.unwrap_or(TAPERED_Y)) * self.mean_diameter)
    }

    /// The two moments (N·m) of one bearing under F_r, F_a (N) at ν (m²/s) and ω (rad/s): Palmgren's
    /// M_0 and M_1, or the SKF model's M_rr and M_sl for a bearing given with SKF constants (in a
    /// mineral oil or not). The second is `None` when the bearing lacks a C_0 its model needs.
    pub fn moments(&self, fr: f64, fa: f64, nu: f64, omega: f64, mineral: bool) -> (f64, Option<f64>) {
        match &self.skf {
            Some((k, [d, big_d])) => {
                let n = omega * 30.0 / std::f64::consts::PI;
                let c0 = self.static_load_rating;
                match super::skf_bearing::skf_moments(
                    self.kind,
                    k,
                    d * 1e3,
                    big_d * 1e3,
                    c0,
                    fr,
                    fa,
                    nu * 1e6,
                    n,
                    mineral,
                ) {
                    Some((rr, sl)) => (rr * 1e-3, Some(sl * 1e-3)),
                    None => (0.0, None),
                }
            }
            None => (self.no_load_moment(nu, omega), self.load_moment(fr, fa)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ball(c0: Option<f64>) -> Bearing {
        Bearing {
            kind: BearingType::DeepGrooveBall,
            mean_diameter: 0.045,
            count: 1,
            static_load_rating: c0,
            f0: None,
            f1: None,
            y: None,
            position: None,
            skf: None,
        }
    }

    /// Below ν n = 2000 the no-load moment is 160e-7 f0 d_m³ (N·mm), and continuous at 2000:
    /// 2000^(2/3) = 158.74, so the two forms differ by 0.8 % there (Palmgren's own rounding).
    #[test]
    fn no_load_branches() {
        let b = ball(None);
        let omega = |n_rpm: f64| n_rpm * std::f64::consts::PI / 30.0;
        let low = b.no_load_moment(10e-6, omega(100.0));
        assert!((low - 160e-7 * 2.0 * 45f64.powi(3) * 1e-3).abs() < 1e-15);
        let high = b.no_load_moment(10e-6, omega(200.0));
        assert!((high / low - 2000f64.powf(2.0 / 3.0) / 160.0).abs() < 1e-12);
    }

    /// Deep groove ball: F_r = 2 kN, F_a = 1 kN, C_0 = 20 kN: P_0 = max(1.7, 2) kN = 2 kN,
    /// f_1 = 0.0007 √0.1, P_1 = max(3 − 0.2, 2) kN = 2.8 kN, M_1 = f_1 P_1 d_m.
    #[test]
    fn ball_load_moment_by_hand() {
        let m1 = ball(Some(20e3)).load_moment(2e3, 1e3).unwrap();
        let expected = 0.0007 * 0.1f64.sqrt() * 2800.0 * 0.045;
        assert!((m1 - expected).abs() < 1e-15, "{m1} vs {expected}");
        assert!(ball(None).load_moment(2e3, 1e3).is_none());
        let given = Bearing { f1: Some(0.001), ..ball(None) };
        assert!((given.load_moment(2e3, 0.0).unwrap() - 0.001 * 2000.0 * 0.045).abs() < 1e-15);
    }

    /// Tapered roller: P_1 = max(2 Y F_a, F_r), Y = 1.6 by default or the bearing's `y`; at F_r = 3 kN,
    /// F_a = 1.2 kN: 2 · 1.6 · 1.2 = 3.84 kN, with y = 1.0: F_r = 3 kN governs.
    #[test]
    fn tapered_axial_factor() {
        let b = Bearing { kind: BearingType::TaperedRoller, ..ball(None) };
        let m1 = b.load_moment(3e3, 1.2e3).unwrap();
        assert!((m1 - 0.0004 * 3840.0 * 0.045).abs() < 1e-12, "{m1}");
        let own = Bearing { y: Some(1.0), ..b };
        assert!((own.load_moment(3e3, 1.2e3).unwrap() - 0.0004 * 3000.0 * 0.045).abs() < 1e-12);
    }
}
