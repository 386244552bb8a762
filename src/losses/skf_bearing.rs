//! The SKF model of a rolling bearing's frictional moment, for a bearing given with its SKF geometry
//! constants (SKF Group, *Rolling bearings*, catalogue PUB BU/P1 17000/1 EN, 2018, section
//! "Friction", "The SKF model for calculating the frictional moment"):
//!
//! - M = M_rr + M_sl (N·mm; d, D, d_m = (d + D)/2 in mm, n in rpm, ν the oil's kinematic viscosity
//!   at the oil temperature in mm²/s, loads in N);
//! - rolling: M_rr = φ_ish φ_rs G_rr (ν n)^0.6, with the inlet shear heating reduction
//!   φ_ish = 1/(1 + 1.84·10⁻⁹ (n d_m)^1.28 ν^0.64) and the kinematic replenishment/starvation
//!   reduction φ_rs = 1/exp(K_rs ν n (d + D) √(K_Z/(2(D − d)))), K_rs = 3·10⁻⁸ (low oil bath level
//!   and oil jet, the gearbox's two methods);
//! - sliding: M_sl = μ_sl G_sl, μ_sl = φ_bl μ_bl + (1 − φ_bl) μ_EHL, φ_bl = 1/exp(2.6·10⁻⁸ (n ν)^1.4 d_m),
//!   μ_bl = 0.15 (boundary, SKF's approximate value) and μ_EHL = 0.02 (cylindrical roller),
//!   0.002 (tapered roller), 0.05 (ball bearings in mineral oil) or 0.04 (in synthetic oil).
//!
//! G_rr and G_sl by type, with the geometry constants R1, R2, S1, S2 of the bearing's series from
//! SKF's tables (the user gives them; no table is built in):
//!
//! | type | K_Z | G_rr | G_sl |
//! |---|---|---|---|
//! | deep groove ball, F_a = 0 | 3.1 | R1 d_m^1.96 F_r^0.54 | S1 d_m^−0.26 F_r^(5/3) |
//! | deep groove ball, F_a > 0 | 3.1 | R1 d_m^1.96 (F_r + R2 F_a / sin α_F)^0.54 | S1 d_m^−0.145 (F_r⁵ + S2 d_m^1.5 F_a⁴ / sin α_F)^(1/3) |
//! | cylindrical roller | 5.1 | R1 d_m^2.41 F_r^0.31 | S1 d_m^0.9 F_a + S2 d_m F_r |
//! | tapered roller | 6.0 | R1 d_m^2.38 (F_r + R2 Y F_a)^0.31 | S1 d_m^0.82 (F_r + S2 Y F_a) |
//!
//! with α_F = 24.6 (F_a/C_0)^0.24 degrees and Y the tapered roller bearing's axial load factor.
//! Left out: the seal moment M_seal (the budget counts the shaft seals on their own) and the drag
//! moment M_drag of a bearing running submerged in the oil bath (it needs SKF's drag diagram).
//!
//! ```
//! use gearloss::losses::{SkfConstants, skf_moments};
//! use gearloss::losses::BearingType;
//! // A 61806-size deep groove ball bearing (d = 30, D = 42 mm) with SKF's 618-series constants,
//! // 1 kN radial, 3000 rpm, ν = 20 mm²/s: the sliding moment is μ_sl S1 d_m^-0.26 F_r^(5/3).
//! let k = SkfConstants { r1: 4.7e-7, r2: 1.7, s1: 6.5e-3, s2: 0.78, y: 1.6, mu_bl: 0.15, mu_ehl: None };
//! let (m_rr, m_sl) = skf_moments(BearingType::DeepGrooveBall, &k, 30.0, 42.0, None, 1000.0, 0.0, 20.0, 3000.0, true).unwrap();
//! let phi_bl = (-2.6e-8 * (3000.0f64 * 20.0).powf(1.4) * 36.0).exp();
//! let mu_sl = phi_bl * 0.15 + (1.0 - phi_bl) * 0.05;
//! assert!((m_sl - mu_sl * 6.5e-3 * 36f64.powf(-0.26) * 1000f64.powf(5.0 / 3.0)).abs() < 1e-12);
//! assert!(m_rr > 0.0);
//! ```

use super::bearing_type::BearingType;

/// K_rs for a low oil bath level and for oil jet lubrication (SKF).
pub(crate) const K_RS: f64 = 3e-8;
/// SKF's approximate boundary friction coefficient μ_bl.
pub(crate) const MU_BOUNDARY: f64 = 0.15;

/// The SKF geometry constants of one bearing and the friction coefficients that may override SKF's.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SkfConstants {
    pub r1: f64,
    /// Not used by cylindrical roller bearings.
    pub r2: f64,
    pub s1: f64,
    pub s2: f64,
    /// The tapered roller bearing's axial load factor Y.
    pub y: f64,
    pub mu_bl: f64,
    /// μ_EHL when given; otherwise SKF's value for the type and oil.
    pub mu_ehl: Option<f64>,
}

/// Whether the SKF model is available for `kind` here.
pub(crate) fn supports(kind: BearingType) -> bool {
    matches!(kind, BearingType::DeepGrooveBall | BearingType::CylindricalRoller | BearingType::TaperedRoller)
}

/// SKF's K_Z and μ_EHL of a type (`None` for the types left out).
fn type_constants(kind: BearingType, mineral: bool) -> Option<(f64, f64)> {
    match kind {
        BearingType::DeepGrooveBall => Some((3.1, if mineral { 0.05 } else { 0.04 })),
        BearingType::CylindricalRoller => Some((5.1, 0.02)),
        BearingType::TaperedRoller => Some((6.0, 0.002)),
        _ => None,
    }
}

/// G_rr and G_sl of the table (N·mm-scaled base values) at d_m (mm), F_r, F_a (N) and C_0 (N).
fn base_values(kind: BearingType, k: &SkfConstants, dm: f64, fr: f64, fa: f64, c0: Option<f64>) -> Option<(f64, f64)> {
    Some(match kind {
        BearingType::DeepGrooveBall if fa > 0.0 => {
            let sin_af = (24.6 * (fa / c0?).powf(0.24)).to_radians().sin();
            (
                k.r1 * dm.powf(1.96) * (fr + k.r2 / sin_af * fa).powf(0.54),
                k.s1 * dm.powf(-0.145) * (fr.powi(5) + k.s2 * dm.powf(1.5) / sin_af * fa.powi(4)).cbrt(),
            )
        }
        BearingType::DeepGrooveBall => {
            (k.r1 * dm.powf(1.96) * fr.powf(0.54), k.s1 * dm.powf(-0.26) * fr.powf(5.0 / 3.0))
        }
        BearingType::CylindricalRoller => {
            (k.r1 * dm.powf(2.41) * fr.powf(0.31), k.s1 * dm.powf(0.9) * fa + k.s2 * dm * fr)
        }
        BearingType::TaperedRoller => {
            (k.r1 * dm.powf(2.38) * (fr + k.r2 * k.y * fa).powf(0.31), k.s1 * dm.powf(0.82) * (fr + k.s2 * k.y * fa))
        }
        _ => return None,
    })
}

/// (M_rr, M_sl) in N·mm of one bearing of type `kind` with bore d and outside diameter D (mm),
/// static load rating C_0 (N, needed by a deep groove ball bearing under axial load), loads F_r,
/// F_a (N), the oil's ν (mm²/s), speed n (rpm) and whether the oil is mineral; `None` for a type
/// the model does not cover here or a missing C_0.
#[allow(clippy::too_many_arguments)]
pub fn skf_moments(
    kind: BearingType,
    k: &SkfConstants,
    bore: f64,
    outside: f64,
    c0: Option<f64>,
    fr: f64,
    fa: f64,
    nu: f64,
    n: f64,
    mineral: bool,
) -> Option<(f64, f64)> {
    let (k_z, mu_ehl_skf) = type_constants(kind, mineral)?;
    let dm = 0.5 * (bore + outside);
    let (g_rr, g_sl) = base_values(kind, k, dm, fr, fa, c0)?;
    let phi_ish = 1.0 / (1.0 + 1.84e-9 * (n * dm).powf(1.28) * nu.powf(0.64));
    let phi_rs = (-K_RS * nu * n * (bore + outside) * (k_z / (2.0 * (outside - bore))).sqrt()).exp();
    let m_rr = phi_ish * phi_rs * g_rr * (nu * n).powf(0.6);
    let phi_bl = (-2.6e-8 * (n * nu).powf(1.4) * dm).exp();
    let mu_sl = phi_bl * k.mu_bl + (1.0 - phi_bl) * k.mu_ehl.unwrap_or(mu_ehl_skf);
    Some((m_rr, mu_sl * g_sl))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn consts() -> SkfConstants {
        SkfConstants { r1: 1.09e-6, r2: 0.0, s1: 0.16, s2: 0.0015, y: 1.6, mu_bl: MU_BOUNDARY, mu_ehl: None }
    }

    /// Cylindrical roller NJ 406 size (d = 30, D = 90 mm, d_m = 60 mm) under F_r = 5 kN, F_a = 0 at
    /// 1500 rpm in ν = 14 mm²/s, by hand (values computed independently, in Python):
    /// φ_ish = 1/(1 + 1.84e-9 · 90000^1.28 · 14^0.64) = 0.978 601 9…, φ_rs = exp(−3e-8 · 14 · 1500 ·
    /// 120 · √(5.1/120)) = 0.984 535 5…, G_rr = 1.09e-6 · 60^2.41 · 5000^0.31, (νn)^0.6 = 21000^0.6;
    /// φ_bl = exp(−2.6e-8 · 21000^1.4 · 60) = 0.172 939…, μ_sl = 0.15 φ_bl + 0.02 (1 − φ_bl),
    /// G_sl = 0.0015 · 60 · 5000 = 450. Relative tolerance 1e-12 (the same arithmetic).
    #[test]
    fn cylindrical_roller_by_hand() {
        let (m_rr, m_sl) =
            skf_moments(BearingType::CylindricalRoller, &consts(), 30.0, 90.0, None, 5000.0, 0.0, 14.0, 1500.0, true)
                .unwrap();
        let phi_ish = 1.0 / (1.0 + 1.84e-9 * 90000f64.powf(1.28) * 14f64.powf(0.64));
        let phi_rs = (-3e-8 * 14.0 * 1500.0 * 120.0 * (5.1f64 / 120.0).sqrt()).exp();
        assert!((phi_ish - 0.97860185).abs() < 1e-8 && (phi_rs - 0.98453548).abs() < 1e-8, "{phi_ish} {phi_rs}");
        let g_rr = 1.09e-6 * 60f64.powf(2.41) * 5000f64.powf(0.31);
        let expected_rr = phi_ish * phi_rs * g_rr * 21000f64.powf(0.6);
        assert!((m_rr / expected_rr - 1.0).abs() < 1e-12, "{m_rr} vs {expected_rr}");
        let phi_bl = (-2.6e-8 * 21000f64.powf(1.4) * 60.0).exp();
        assert!((phi_bl - 0.17293904).abs() < 1e-8, "{phi_bl}");
        let expected_sl = (0.15 * phi_bl + 0.02 * (1.0 - phi_bl)) * 450.0;
        assert!((m_sl / expected_sl - 1.0).abs() < 1e-12, "{m_sl} vs {expected_sl}");
    }

    /// Limits: at rest (n → 0) the sliding coefficient is the boundary one and the rolling moment
    /// vanishes; at high ν n it tends to μ_EHL; no load, no moment.
    #[test]
    fn limits() {
        let k = consts();
        let (rr, sl) =
            skf_moments(BearingType::CylindricalRoller, &k, 30.0, 90.0, None, 5000.0, 0.0, 14.0, 1e-9, true).unwrap();
        assert!(rr < 1e-3 && (sl / 450.0 - 0.15).abs() < 1e-9, "{rr} {sl}");
        let (_, sl) =
            skf_moments(BearingType::CylindricalRoller, &k, 30.0, 90.0, None, 5000.0, 0.0, 100.0, 10000.0, true)
                .unwrap();
        assert!((sl / 450.0 - 0.02).abs() < 1e-9, "{sl}");
        let (rr, sl) =
            skf_moments(BearingType::CylindricalRoller, &k, 30.0, 90.0, None, 0.0, 0.0, 14.0, 1500.0, true).unwrap();
        assert_eq!((rr, sl), (0.0, 0.0));
    }

    /// Deep groove ball under axial load, by hand: C_0 = 10 kN, F_a = 500 N → α_F = 24.6 · 0.05^0.24
    /// degrees; tapered roller G_sl linear in F_r + S2 Y F_a. A type left out gives `None`.
    #[test]
    fn axial_branches_by_hand() {
        let k = SkfConstants { r1: 4.4e-7, r2: 1.7, s1: 2e-3, s2: 100.0, y: 1.6, mu_bl: 0.15, mu_ehl: Some(0.05) };
        let nu_n: f64 = 10.0 * 1000.0;
        let phi_bl = (-2.6e-8 * nu_n.powf(1.4) * 40.0).exp();
        let mu_sl = 0.15 * phi_bl + 0.05 * (1.0 - phi_bl);
        let (_, sl) =
            skf_moments(BearingType::DeepGrooveBall, &k, 25.0, 55.0, Some(10e3), 2000.0, 500.0, 10.0, 1000.0, true)
                .unwrap();
        let sin_af = (24.6 * 0.05f64.powf(0.24)).to_radians().sin();
        let g_sl =
            2e-3 * 40f64.powf(-0.145) * (2000f64.powi(5) + 100.0 * 40f64.powf(1.5) / sin_af * 500f64.powi(4)).cbrt();
        assert!((sl / (mu_sl * g_sl) - 1.0).abs() < 1e-12);
        assert!(
            skf_moments(BearingType::DeepGrooveBall, &k, 25.0, 55.0, None, 2000.0, 500.0, 10.0, 1000.0, true).is_none()
        );
        let t = SkfConstants { r1: 1.76e-6, r2: 10.9, s1: 0.017, s2: 2.0, ..k };
        let (_, a) =
            skf_moments(BearingType::TaperedRoller, &t, 25.0, 52.0, None, 3000.0, 0.0, 10.0, 1000.0, true).unwrap();
        let (_, b) =
            skf_moments(BearingType::TaperedRoller, &t, 25.0, 52.0, None, 3000.0, 100.0, 10.0, 1000.0, true).unwrap();
        assert!((b / a - (3000.0 + 2.0 * 1.6 * 100.0) / 3000.0).abs() < 1e-12);
        assert!(skf_moments(BearingType::SphericalRoller, &t, 25.0, 52.0, None, 1.0, 0.0, 10.0, 1000.0, true).is_none());
    }
}
