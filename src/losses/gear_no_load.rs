//! Load-independent gear losses P_VZ0: churning of dip-lubricated gears (ISO/TR 14179-2:2001 after
//! Mauz) and the impulse loss of injection lubrication.
//!
//! Dip lubrication, the hydraulic loss torque of the stage (Mauz 1987, ISO/TR 14179-2:2001):
//!
//! T_H = C_Sp · C_1 · exp(C_2 · v_t / v_t0)  (N·m),
//! C_Sp = (4 e_max / (3 h_c))^1.5 · 2 h_c / l_h,
//! C_1 = 0.063 (e_1 + e_2)/e_0 + 0.0128 (b/b_0)³,
//! C_2 = (e_1 + e_2)/(80 e_0) + 0.2,
//!
//! e_1, e_2 the immersion depths of pinion and wheel (the depth of the tip circle below the oil
//! level, 0 for a gear above it), e_max the larger, h_c the height of the wheel axis above the
//! housing floor, l_h the inner width of the housing, b the face width, v_t the pitch-line speed,
//! e_0 = b_0 = 10 mm, v_t0 = 10 m/s. The torque is read at the pinion shaft, P_VZ0 = T_H ω_1. Mauz's
//! tests cover pitch-line speeds up to 60 m/s; his fit carries no viscosity term (his oils gave
//! splash losses nearly independent of viscosity in the dip-lubricated range); beyond 60 m/s the
//! report flags the value.
//!
//! Injection lubrication: the oil jet of flow Q and speed v_j, aimed into the mesh entry against
//! the teeth, is brought to the pitch-line speed; the momentum flux ρ Q (v_t + v_j) taken at v_t
//! costs P_VZ0 = ρ Q v_t (v_t + v_j) (the impulse loss of Ariura et al. 1973, as ISO/TR 14179-2's
//! FZG method uses it for jets into the mesh). Windage of injection-lubricated gears is not included.
//!
//! ```
//! use gearloss::losses::gear_no_load::mauz_dip_torque;
//! // FZG-like: e1 = 0, e2 = 30 mm, h_c = 80 mm, l_h = 200 mm, b = 14 mm at 8.3 m/s.
//! let t = mauz_dip_torque([0.0, 0.030], 0.080, 0.200, 0.014, 8.3);
//! let (c_sp, c1, c2) = ((4.0 * 30.0 / 240.0f64).powf(1.5) * 160.0 / 200.0, 0.063 * 3.0 + 0.0128 * 1.4f64.powi(3), 30.0 / 800.0 + 0.2);
//! assert!((t - c_sp * c1 * (c2 * 0.83f64).exp()).abs() < 1e-12);
//! ```

/// How the gears are lubricated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Lubrication {
    /// Dip (splash) lubrication: immersion depths [pinion, wheel], wheel-axis height h_c and inner
    /// housing width l_h (m).
    Dip { immersion: [f64; 2], axis_height: f64, housing_width: f64 },
    /// Injection: flow Q (m³/s) and jet speed v_j (m/s).
    Injection { flow: f64, jet_speed: f64 },
}

/// Mauz's highest tested pitch-line speed (m/s).
pub const MAUZ_SPEED_LIMIT: f64 = 60.0;

/// T_H (N·m) of ISO/TR 14179-2 (Mauz) for immersion depths `e` [pinion, wheel], h_c, l_h, face
/// width b (all m) and pitch-line speed v_t (m/s).
pub fn mauz_dip_torque(e: [f64; 2], h_c: f64, l_h: f64, b: f64, v_t: f64) -> f64 {
    const E0: f64 = 0.010;
    const B0: f64 = 0.010;
    const VT0: f64 = 10.0;
    let e_max = e[0].max(e[1]);
    let c_sp = (4.0 * e_max / (3.0 * h_c)).powf(1.5) * 2.0 * h_c / l_h;
    let c1 = 0.063 * (e[0] + e[1]) / E0 + 0.0128 * (b / B0).powi(3);
    let c2 = (e[0] + e[1]) / (80.0 * E0) + 0.2;
    c_sp * c1 * (c2 * v_t / VT0).exp()
}

/// The impulse loss P (W) of an injection jet: ρ Q v_t (v_t + v_j).
pub fn injection_impulse_loss(density: f64, flow: f64, v_t: f64, jet_speed: f64) -> f64 {
    density * flow * v_t * (v_t + jet_speed)
}

impl Lubrication {
    /// P_VZ0 (W) at pinion speed ω1 (rad/s), pitch-line speed v_t (m/s), face width b (m) and oil
    /// density ρ (kg/m³).
    pub fn power_loss(&self, omega_1: f64, v_t: f64, b: f64, density: f64) -> f64 {
        match *self {
            Lubrication::Dip { immersion, axis_height, housing_width } => {
                mauz_dip_torque(immersion, axis_height, housing_width, b, v_t) * omega_1
            }
            Lubrication::Injection { flow, jet_speed } => injection_impulse_loss(density, flow, v_t, jet_speed),
        }
    }

    /// A note when the pitch-line speed v_t (m/s) is outside the model's tested range.
    pub fn note(&self, v_t: f64) -> Option<String> {
        match self {
            Lubrication::Dip { .. } if v_t > MAUZ_SPEED_LIMIT => Some(format!(
                "gear churning: the fastest pitch-line speed, v_t = {v_t:.1} m/s, is above the 60 m/s of Mauz's tests; P_VZ0 is extrapolated there"
            )),
            _ => None,
        }
    }

    pub fn name(&self) -> &'static str {
        match self {
            Lubrication::Dip { .. } => "dip",
            Lubrication::Injection { .. } => "injection",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// By hand: e1 = 20, e2 = 40 mm, h_c = 60 mm, l_h = 150 mm, b = 20 mm, v_t = 10 m/s:
    /// C_Sp = (160/180)^1.5 · 120/150 = 0.670 432..., C_1 = 0.063·6 + 0.0128·8 = 0.4804,
    /// C_2 = 60/800 + 0.2 = 0.275, T_H = C_Sp C_1 e^0.275.
    #[test]
    fn mauz_by_hand() {
        let c_sp = (160.0f64 / 180.0).powf(1.5) * 120.0 / 150.0;
        let expected = c_sp * 0.4804 * 0.275f64.exp();
        let t = mauz_dip_torque([0.020, 0.040], 0.060, 0.150, 0.020, 10.0);
        assert!((t - expected).abs() < 1e-12 * expected, "{t} vs {expected}");
        // Out of the oil, only the face-width term of C_1 is left, times C_Sp = 0.
        assert_eq!(mauz_dip_torque([0.0, 0.0], 0.060, 0.150, 0.020, 10.0), 0.0);
    }

    /// ρ Q v_t (v_t + v_j): 870 kg/m³, 2 l/min, 10 m/s, jet 20 m/s → 870 · 3.333e-5 · 10 · 30 = 8.7 W.
    #[test]
    fn injection_by_hand() {
        let p = Lubrication::Injection { flow: 2e-3 / 60.0, jet_speed: 20.0 }.power_loss(100.0, 10.0, 0.02, 870.0);
        assert!((p - 8.7).abs() < 1e-12, "{p}");
    }
}
