//! Load-independent gear losses P_VZ0: churning of dip-lubricated gears (ISO/TR 14179-2:2001 after
//! Mauz), and for injection lubrication the jet's impulse loss and the gears' windage.
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
//! Injection lubrication: the oil jet of flow Q and speed v_j meets the teeth head-on (aimed against
//! their motion) and is brought to the pitch-line speed v_t at the working pitch circle; the
//! momentum flux ρ Q (v_t + v_j) taken at v_t costs P_VZ0 = ρ Q v_t (v_t + v_j) (the impulse loss of
//! Ariura et al. 1973). A jet into the mesh entry, moving with the teeth, would cost the smaller
//! ρ Q v_t (v_t − v_j); this reading takes the head-on, conservative one. Each gear spinning in the housing's air–oil mist adds
//! its windage, by Anderson & Loewenthal (N. E. Anderson, S. H. Loewenthal, *Spur-gear-system
//! efficiency at part and full load*, NASA TP-1622, 1980; and *Design of spur gears for improved
//! efficiency*, ASME J. Mech. Des. 104 (1982) 767–774):
//!
//! P_W = 2.82·10⁻⁷ (1 + 2.3 b/R) n^2.8 R^4.6 (0.028 η + 0.019)^0.2  (kW),
//!
//! n the gear's speed (rpm), R its pitch radius (m; their "pitch radius" read as the working pitch
//! radius r_w, which differs from the reference m_t z/2 where x_1 + x_2 ≠ 0: by 2 % on FZG C14), b the face width (m) and η the oil's dynamic
//! viscosity at the oil temperature (cP = mPa·s): 0.028 η + 0.019 is their viscosity of the mist,
//! air's 0.019 cP plus a share of the oil's (their fit to NASA's jet-lubricated spur-gear tests).
//! Dip lubrication does not add it: Mauz's measured torque contains the windage of the dipping
//! gears.
//!
//! ```
//! use gearloss::losses::mauz_dip_torque;
//! // FZG-like: e1 = 0, e2 = 30 mm, h_c = 80 mm, l_h = 200 mm, b = 14 mm at 8.3 m/s.
//! let t = mauz_dip_torque([0.0, 0.030], 0.080, 0.200, 0.014, 8.3);
//! let (c_sp, c1, c2) = ((4.0 * 30.0 / 240.0f64).powf(1.5) * 160.0 / 200.0, 0.063 * 3.0 + 0.0128 * 1.4f64.powi(3), 30.0 / 800.0 + 0.2);
//! assert!((t - c_sp * c1 * (c2 * 0.83f64).exp()).abs() < 1e-12);
//! ```

/// How the gears are lubricated.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub enum Lubrication {
    /// Dip (splash) lubrication: immersion depths [pinion, wheel], wheel-axis height h_c and inner
    /// housing width l_h (m).
    Dip { immersion: [f64; 2], axis_height: f64, housing_width: f64 },
    /// Injection: flow Q (m³/s) and jet speed v_j (m/s).
    Injection { flow: f64, jet_speed: f64 },
}

/// Mauz's highest tested pitch-line speed (m/s).
pub(crate) const MAUZ_SPEED_LIMIT: f64 = 60.0;

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
pub(crate) fn injection_impulse_loss(density: f64, flow: f64, v_t: f64, jet_speed: f64) -> f64 {
    density * flow * v_t * (v_t + jet_speed)
}

/// P_W (W) of one gear by Anderson & Loewenthal: speed n (rpm), pitch radius R (m), face width b
/// (m), the oil's dynamic viscosity η (Pa·s).
pub fn windage_loss(n_rpm: f64, r: f64, b: f64, eta: f64) -> f64 {
    let eta_cp = eta * 1e3;
    2.82e-7 * (1.0 + 2.3 * b / r) * n_rpm.powf(2.8) * r.powf(4.6) * (0.028 * eta_cp + 0.019).powf(0.2) * 1e3
}

/// The two gears as the load-independent losses read them (SI): speeds [ω_1, ω_2] (rad/s), working
/// pitch radii (m) and face width (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GearsRunning {
    pub omega: [f64; 2],
    pub pitch_radius: [f64; 2],
    pub face_width: f64,
}

impl Lubrication {
    /// P_VZ0 (W) of the two gears in `oil`; `None` for injection lubrication of an oil without a
    /// density (lowering refuses that scene).
    pub fn power_loss(&self, g: &GearsRunning, oil: &super::oil::Oil) -> Option<f64> {
        self.power_loss_by_gear(g, oil).map(|[own, other]| own + other)
    }

    /// P_VZ0 (W) split by where it acts, [pinion's shaft, wheel's shaft]: Mauz's T_H and the jet's
    /// impulse are the mesh's and act where Mauz read his torque, at the pinion shaft (T_H ω_1);
    /// each gear's windage is its own and acts on its own gear's shaft.
    pub fn power_loss_by_gear(&self, g: &GearsRunning, oil: &super::oil::Oil) -> Option<[f64; 2]> {
        self.parts(g, oil).map(|(mesh, windage)| [mesh + windage[0], windage[1]])
    }

    /// The mesh's part (churning or the jet's impulse, W) and each gear's windage (W).
    fn parts(&self, g: &GearsRunning, oil: &super::oil::Oil) -> Option<(f64, [f64; 2])> {
        let v_t = g.omega[0] * g.pitch_radius[0];
        match *self {
            Lubrication::Dip { immersion, axis_height, housing_width } => {
                Some((mauz_dip_torque(immersion, axis_height, housing_width, g.face_width, v_t) * g.omega[0], [0.0; 2]))
            }
            Lubrication::Injection { flow, jet_speed } => {
                let windage = |i: usize| {
                    windage_loss(g.omega[i] * 30.0 / std::f64::consts::PI, g.pitch_radius[i], g.face_width, oil.eta)
                };
                Some((injection_impulse_loss(oil.rho?, flow, v_t, jet_speed), [windage(0), windage(1)]))
            }
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

    /// ρ Q v_t (v_t + v_j): 870 kg/m³, 2 l/min, 10 m/s, jet 20 m/s → 870 · 3.333e-5 · 10 · 30 = 8.7 W,
    /// plus both gears' windage (pinion R = 0.1 m at 100 rad/s, wheel R = 0.2 m at 50 rad/s).
    #[test]
    fn injection_by_hand() {
        let oil = crate::losses::oil::Oil { nu: Some(1e-5), rho: Some(870.0), eta: 8.7e-3, mineral: true };
        let g = GearsRunning { omega: [100.0, 50.0], pitch_radius: [0.1, 0.2], face_width: 0.02 };
        let p = Lubrication::Injection { flow: 2e-3 / 60.0, jet_speed: 20.0 }.power_loss(&g, &oil).unwrap();
        let rpm = |w: f64| w * 30.0 / std::f64::consts::PI;
        let w = windage_loss(rpm(100.0), 0.1, 0.02, 8.7e-3) + windage_loss(rpm(50.0), 0.2, 0.02, 8.7e-3);
        assert!((p - 8.7 - w).abs() < 1e-12, "{p}");
        // The wheel's windage is the wheel's own; the jet and the pinion's windage the pinion's.
        let by_gear =
            Lubrication::Injection { flow: 2e-3 / 60.0, jet_speed: 20.0 }.power_loss_by_gear(&g, &oil).unwrap();
        assert!((by_gear[1] - windage_loss(rpm(50.0), 0.2, 0.02, 8.7e-3)).abs() < 1e-15, "{by_gear:?}");
        assert!((by_gear[0] - 8.7 - windage_loss(rpm(100.0), 0.1, 0.02, 8.7e-3)).abs() < 1e-12, "{by_gear:?}");
        let no_density = crate::losses::oil::Oil { rho: None, ..oil };
        assert_eq!(Lubrication::Injection { flow: 2e-3 / 60.0, jet_speed: 20.0 }.power_loss(&g, &no_density), None);
    }

    /// Anderson–Loewenthal by hand (values from Python): n = 3000 rpm, R = 0.1 m, b = 0.02 m,
    /// η = 10 cP: 2.82e-7 · 1.46 · 3000^2.8 · 0.1^4.6 · 0.299^0.2 kW = 44.23 W; the speed exponent
    /// 2.8 and the radius exponent 4.6 (tolerance 1e-12 relative).
    #[test]
    fn windage_by_hand() {
        let p = windage_loss(3000.0, 0.1, 0.02, 10e-3);
        let expected = 2.82e-7 * 1.46 * 3000f64.powf(2.8) * 0.1f64.powf(4.6) * 0.299f64.powf(0.2) * 1e3;
        assert!((p / expected - 1.0).abs() < 1e-12, "{p} vs {expected}");
        assert!((p - 44.226).abs() < 0.001, "{p}");
        assert!((windage_loss(6000.0, 0.1, 0.02, 10e-3) / p - 2f64.powf(2.8)).abs() < 1e-12);
        let r2 = windage_loss(3000.0, 0.2, 0.04, 10e-3) / p;
        assert!((r2 - 2f64.powf(4.6)).abs() < 1e-12, "{r2}");
    }
}
