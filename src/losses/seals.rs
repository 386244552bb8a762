//! Radial shaft-seal losses, ISO/TR 14179-2:2001 (after Linke): P_VD = 7.69·10⁻⁶ d_sh² n, P_VD in W,
//! the shaft diameter d_sh in mm and the shaft speed n in rpm (for elastomer lip seals on steel
//! shafts; independent of load and, in this form, of the oil).
//!
//! ```
//! use gearloss::losses::Seal;
//! // A 30 mm seal at 1500 rpm: 7.69e-6 · 900 · 1500 = 10.38 W.
//! let p = Seal { diameter: 0.030, count: 1 }.power_loss(1500.0 * std::f64::consts::PI / 30.0);
//! assert!((p - 10.3815).abs() < 1e-4);
//! ```

/// One or more equal radial lip seals on a shaft.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Seal {
    /// Shaft diameter at the lip (m).
    pub diameter: f64,
    pub count: usize,
}

impl Seal {
    /// P_VD (W) of all `count` seals at shaft speed ω (rad/s).
    pub fn power_loss(&self, omega: f64) -> f64 {
        let d_mm = self.diameter * 1e3;
        let n_rpm = omega * 30.0 / std::f64::consts::PI;
        7.69e-6 * d_mm * d_mm * n_rpm * self.count as f64
    }
}
