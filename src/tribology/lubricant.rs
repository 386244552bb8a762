//! A lubricant at the oil temperature: kinematic viscosity by ASTM D341 (Walther), density by
//! thermal expansion, the pressure–viscosity coefficient by α = k·ν^s, and ISO/TR 14179-2's
//! lubricant factor X_L; the oil from the ISO VG catalogue ([`catalogue`]) or from measured values.
//!
//! ```
//! use gearloss::tribology::lubricant::{catalogue, BaseOil};
//! let oil = catalogue(100.0, BaseOil::Mineral).unwrap();
//! let at_90 = oil.at_celsius(90.0);
//! // ν40 is the grade; ν at 90 °C follows the Walther line through ν40 and ν100.
//! assert!((oil.kinematic_viscosity_at(40.0 + 273.15) * 1e6 - 100.0).abs() < 1e-9);
//! assert!(at_90.kinematic_viscosity * 1e6 > 13.0 && at_90.kinematic_viscosity * 1e6 < 16.0);
//! ```

use serde::Serialize;

/// The base oil family, for ISO/TR 14179-2's lubricant factor X_L.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BaseOil {
    Mineral,
    Pao,
    PagInsoluble,
    PagSoluble,
    Traction,
    PhosphateEster,
    /// Synthetic (carboxylic) ester.
    Ester,
}

impl BaseOil {
    pub const NAMES: &'static [&'static str] =
        &["mineral", "pao", "pag_insoluble", "pag_soluble", "traction", "phosphate_ester", "ester"];

    pub fn from_name(name: &str) -> Option<Self> {
        Some(match name {
            "mineral" => BaseOil::Mineral,
            "pao" => BaseOil::Pao,
            "pag_insoluble" => BaseOil::PagInsoluble,
            "pag_soluble" => BaseOil::PagSoluble,
            "traction" => BaseOil::Traction,
            "phosphate_ester" => BaseOil::PhosphateEster,
            "ester" => BaseOil::Ester,
            _ => return None,
        })
    }

    /// The name as written in a scene.
    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }

    /// The name in words, for reports.
    pub fn words(self) -> &'static str {
        match self {
            BaseOil::Mineral => "mineral",
            BaseOil::Pao => "PAO",
            BaseOil::PagInsoluble => "PAG, not water-soluble",
            BaseOil::PagSoluble => "PAG, water-soluble",
            BaseOil::Traction => "traction fluid",
            BaseOil::PhosphateEster => "phosphate ester",
            BaseOil::Ester => "synthetic ester",
        }
    }
}

/// 0 °C in kelvin.
pub const CELSIUS_ZERO: f64 = 273.15;
/// Thermal expansion of lubricating oils, ρ(θ) = ρ15 [1 − γ (θ − 15 °C)], γ in 1/K. A typical value
/// for mineral and synthetic gear oils (the ASTM D1250 tables give 6.3–7.2·10⁻⁴ K⁻¹ over the range
/// of lubricant densities); give the density at temperature for a better one.
pub const THERMAL_EXPANSION: f64 = 7.0e-4;
/// ASTM D341's Walther form holds down to this kinematic viscosity (m²/s); below it the report flags the oil.
pub const WALTHER_LOWER_LIMIT: f64 = 2.0e-6;

/// The ISO 3448 viscosity grades: each the midpoint kinematic viscosity at 40 °C in mm²/s.
pub const ISO_VG_GRADES: &[f64] =
    &[2.0, 3.0, 5.0, 7.0, 10.0, 15.0, 22.0, 32.0, 46.0, 68.0, 100.0, 150.0, 220.0, 320.0, 460.0, 680.0, 1000.0, 1500.0];

/// What one base oil contributes to a catalogue oil.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BaseOilData {
    pub base: BaseOil,
    /// Viscosity index of a typical gear oil of this base (ASTM D2270), used to place ν100.
    pub viscosity_index: f64,
    /// Density at 15 °C (kg/m³).
    pub density_15: f64,
    /// ISO/TR 14179-2 lubricant factor X_L, when the report tabulates one for this base.
    pub lubricant_factor: Option<f64>,
    /// α = k ν^s (α in mm²/N, ν in mm²/s at the temperature), when tabulated for this base.
    pub pressure_viscosity: Option<(f64, f64)>,
    /// Where these values come from, as printed in the report.
    pub source: &'static str,
}

/// The base oils of the catalogue.
///
/// - Viscosity index and density: typical values of industrial gear oils of each base (mineral CLP
///   oils VI ≈ 95, ρ15 ≈ 885 kg/m³; PAO VI ≈ 145, ρ15 ≈ 850 kg/m³; PAG VI ≈ 200 with ρ15 ≈ 1000
///   kg/m³ water-insoluble and ≈ 1060 kg/m³ water-soluble; synthetic ester VI ≈ 145, ρ15 ≈ 920
///   kg/m³): a grade's oils scatter around them by a few per cent in ν100 and ρ15. A measured oil
///   (`nu_40`, `nu_100`, `density_15`) replaces them.
/// - X_L: ISO/TR 14179-2:2001 (mineral 1.0, PAO 0.8, PAG water-insoluble 0.7, water-soluble 0.6,
///   traction fluid 1.5, phosphate ester 1.3). It tabulates none for synthetic (carboxylic) esters.
/// - α = k ν^s: AGMA 925-A03 (mineral oil k = 0.010471, s = 0.1348; PAO k = 0.010326,
///   s = 0.0507; α in mm²/N, ν the kinematic viscosity at the temperature in mm²/s), the power-law
///   form of Gold et al. (2001). PAG (both kinds) k = 0.005489, s = 0.1485 and synthetic ester
///   k = 0.007382, s = 0.1335: Gold et al.'s coefficients for their polyglycol and ester oils (α in
///   GPa⁻¹ = 5.489 ν^0.1485 and 7.382 ν^0.1335), as tabulated in the lubricant library of the
///   GEARpie tool by C. M. C. G. Fernandes, where s and t stand with their digits exchanged
///   (s = 1.485, t = 0.5489); read back, its mineral pair (9.904, 0.1390) lies within 5 % of AGMA's
///   over 5 to 500 mm²/s. A scene's `pressure_viscosity` replaces any of them.
pub const BASE_OILS: &[BaseOilData] = &[
    BaseOilData {
        base: BaseOil::Mineral,
        viscosity_index: 95.0,
        density_15: 885.0,
        lubricant_factor: Some(1.0),
        pressure_viscosity: Some((0.010471, 0.1348)),
        source:
            "ISO VG catalogue, mineral: VI 95, ρ15 885 kg/m³ (typical CLP gear oil); X_L ISO/TR 14179-2; α AGMA 925-A03",
    },
    BaseOilData {
        base: BaseOil::Pao,
        viscosity_index: 145.0,
        density_15: 850.0,
        lubricant_factor: Some(0.8),
        pressure_viscosity: Some((0.010326, 0.0507)),
        source:
            "ISO VG catalogue, PAO: VI 145, ρ15 850 kg/m³ (typical PAO gear oil); X_L ISO/TR 14179-2; α AGMA 925-A03",
    },
    BaseOilData {
        base: BaseOil::PagInsoluble,
        viscosity_index: 200.0,
        density_15: 1000.0,
        lubricant_factor: Some(0.7),
        pressure_viscosity: Some((0.005489, 0.1485)),
        source: "ISO VG catalogue, PAG (water-insoluble): VI 200, ρ15 1000 kg/m³ (typical); X_L ISO/TR 14179-2; α Gold et al. (2001)",
    },
    BaseOilData {
        base: BaseOil::PagSoluble,
        viscosity_index: 200.0,
        density_15: 1060.0,
        lubricant_factor: Some(0.6),
        pressure_viscosity: Some((0.005489, 0.1485)),
        source: "ISO VG catalogue, PAG (water-soluble): VI 200, ρ15 1060 kg/m³ (typical); X_L ISO/TR 14179-2; α Gold et al. (2001)",
    },
    BaseOilData {
        base: BaseOil::Ester,
        viscosity_index: 145.0,
        density_15: 920.0,
        lubricant_factor: None,
        pressure_viscosity: Some((0.007382, 0.1335)),
        source:
            "ISO VG catalogue, synthetic ester: VI 145, ρ15 920 kg/m³ (typical); no X_L (not in ISO/TR 14179-2); α Gold et al. (2001)",
    },
];

/// The catalogue's data of a base oil (traction fluids and phosphate esters are not in it).
pub fn base_oil(base: BaseOil) -> Option<&'static BaseOilData> {
    BASE_OILS.iter().find(|b| b.base == base)
}

/// ISO/TR 14179-2's X_L for a base oil, where it gives one.
pub fn iso_lubricant_factor(base: BaseOil) -> Option<f64> {
    match base {
        BaseOil::Traction => Some(1.5),
        BaseOil::PhosphateEster => Some(1.3),
        b => base_oil(b).and_then(|d| d.lubricant_factor),
    }
}

/// An oil known by ν40, ν100 and ρ15: everything at any temperature follows.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OilData {
    pub base: BaseOil,
    /// Kinematic viscosity at 40 °C and at 100 °C (m²/s).
    pub nu_40: f64,
    pub nu_100: f64,
    /// Density at 15 °C (kg/m³).
    pub density_15: f64,
    /// Where the values come from.
    pub source: String,
}

/// The oil's properties at one temperature, in SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct OilAtTemperature {
    /// θ (K).
    pub temperature: f64,
    /// ν (m²/s), ASTM D341.
    pub kinematic_viscosity: f64,
    /// ρ (kg/m³).
    pub density: f64,
    /// η = ρ ν (Pa·s).
    pub dynamic_viscosity: f64,
    /// α (1/Pa), when known for the base oil.
    pub pressure_viscosity: Option<f64>,
}

/// The constants (A, B) of ASTM D341's Walther line log10 log10(ν + 0.7) = A − B log10 T through
/// two points (ν in mm²/s, T in K).
pub fn walther_line((t1, nu1): (f64, f64), (t2, nu2): (f64, f64)) -> (f64, f64) {
    let w = |nu: f64| (nu + 0.7).log10().log10();
    let b = (w(nu1) - w(nu2)) / (t2.log10() - t1.log10());
    (w(nu1) + b * t1.log10(), b)
}

/// ν (mm²/s) on the Walther line (A, B) at T (K): ν = 10^(10^(A − B log10 T)) − 0.7
/// (ASTM D341-93 eq 1, for ν ≥ 2 mm²/s).
pub fn walther_viscosity((a, b): (f64, f64), t: f64) -> f64 {
    10f64.powf(10f64.powf(a - b * t.log10())) - 0.7
}

/// ASTM D2270 L and H (mm²/s) at ν100 = y (mm²/s), by the quadratic fits of its Appendix X2
/// (Table X2.1), which reproduce Table 1 within 0.05 % for 2 ≤ y ≤ 70 and extend it above.
fn d2270_l_h(y: f64) -> (f64, f64) {
    // (upper end of the range, a, b, c, d, e, f): L = a y² + b y + c, H = d y² + e y + f.
    const FITS: [(f64, [f64; 6]); 16] = [
        (3.8, [1.14673, 1.7576, -0.109, 0.84155, 1.5521, -0.077]),
        (4.4, [3.38095, -15.4952, 33.196, 0.78571, 1.7929, -0.183]),
        (5.0, [2.5, -7.2143, 13.812, 0.82143, 1.5679, 0.119]),
        (6.4, [0.101, 16.635, -45.469, 0.04985, 9.1613, -18.557]),
        (7.0, [3.35714, -23.5643, 78.466, 0.22619, 7.7369, -16.656]),
        (7.7, [0.01191, 21.475, -72.87, 0.79762, -0.7321, 14.61]),
        (9.0, [0.41858, 16.1558, -56.04, 0.05794, 10.5156, -28.24]),
        (12.0, [0.88779, 7.5527, -16.6, 0.26665, 6.7015, -10.81]),
        (15.0, [0.7672, 10.7972, -38.18, 0.20073, 8.4658, -22.49]),
        (18.0, [0.97305, 5.3135, -2.2, 0.28889, 5.9741, -4.93]),
        (22.0, [0.97256, 5.25, -0.98, 0.24504, 7.416, -16.73]),
        (28.0, [0.91413, 7.4759, -21.82, 0.20323, 9.1267, -34.23]),
        (40.0, [0.87031, 9.7157, -50.77, 0.18411, 10.1015, -46.75]),
        (55.0, [0.84703, 12.6752, -133.31, 0.17029, 11.4866, -80.62]),
        (70.0, [0.85921, 11.1009, -83.19, 0.1713, 11.368, -76.94]),
        (f64::INFINITY, [0.83531, 14.6731, -216.246, 0.16841, 11.8493, -96.947]),
    ];
    let (_, [a, b, c, d, e, f]) = FITS.iter().find(|(hi, _)| y <= *hi).copied().unwrap_or(FITS[15]);
    (a * y * y + b * y + c, d * y * y + e * y + f)
}

/// The viscosity index of an oil from ν40 = u and ν100 = y (mm²/s), ASTM D2270 §5 (VI ≤ 100:
/// 100 (L − U)/(L − H); above: N = (log H − log U)/log Y, VI = (10^N − 1)/0.00715 + 100).
pub fn viscosity_index(u: f64, y: f64) -> f64 {
    let (l, h) = d2270_l_h(y);
    if u >= h {
        100.0 * (l - u) / (l - h)
    } else {
        let n = (h.log10() - u.log10()) / y.log10();
        (10f64.powf(n) - 1.0) / 0.00715 + 100.0
    }
}

/// ν100 (mm²/s) of the oil with ν40 = u and viscosity index `vi`: the root of
/// [`viscosity_index`](u, y) = vi, which rises with y (a flatter viscosity–temperature line), by
/// bisection on [2, u].
pub fn nu_100_for_index(u: f64, vi: f64) -> Option<f64> {
    let f = |y: f64| viscosity_index(u, y) - vi;
    let (mut lo, mut hi) = (2.0, u);
    if f(lo) > 0.0 || f(hi) < 0.0 {
        return None;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo < 1e-12 * hi {
            break;
        }
    }
    Some(0.5 * (lo + hi))
}

/// The catalogue oil of ISO VG `grade` on `base`: ν40 the grade (ISO 3448 midpoint), ν100 from the
/// base oil's viscosity index (ASTM D2270), ρ15 of the base oil. `None` when the grade is not an
/// ISO 3448 grade or the base oil is not in the catalogue.
pub fn catalogue(grade: f64, base: BaseOil) -> Option<OilData> {
    let b = base_oil(base)?;
    ISO_VG_GRADES.iter().find(|g| (**g - grade).abs() < 1e-9)?;
    let nu_100 = nu_100_for_index(grade, b.viscosity_index)?;
    Some(OilData {
        base,
        nu_40: grade * 1e-6,
        nu_100: nu_100 * 1e-6,
        density_15: b.density_15,
        source: format!("ISO VG {grade} {}: {}", base.name(), b.source),
    })
}

impl OilData {
    /// The Walther line through ν40 and ν100 (mm²/s, K).
    pub fn walther(&self) -> (f64, f64) {
        walther_line((40.0 + CELSIUS_ZERO, self.nu_40 * 1e6), (100.0 + CELSIUS_ZERO, self.nu_100 * 1e6))
    }

    /// ν (m²/s) at T (K), ASTM D341.
    pub fn kinematic_viscosity_at(&self, t: f64) -> f64 {
        walther_viscosity(self.walther(), t) * 1e-6
    }

    /// ρ (kg/m³) at T (K): ρ15 [1 − γ (θ − 15 °C)], γ = [`THERMAL_EXPANSION`].
    pub fn density_at(&self, t: f64) -> f64 {
        self.density_15 * (1.0 - THERMAL_EXPANSION * (t - CELSIUS_ZERO - 15.0))
    }

    /// The viscosity index (ASTM D2270).
    pub fn viscosity_index(&self) -> f64 {
        viscosity_index(self.nu_40 * 1e6, self.nu_100 * 1e6)
    }

    /// Everything at T (K).
    pub fn at(&self, t: f64) -> OilAtTemperature {
        let nu = self.kinematic_viscosity_at(t);
        let rho = self.density_at(t);
        let alpha = base_oil(self.base).and_then(|b| b.pressure_viscosity).map(|(k, s)| k * (nu * 1e6).powf(s) * 1e-6);
        OilAtTemperature {
            temperature: t,
            kinematic_viscosity: nu,
            density: rho,
            dynamic_viscosity: rho * nu,
            pressure_viscosity: alpha,
        }
    }

    /// Everything at θ (°C).
    pub fn at_celsius(&self, theta: f64) -> OilAtTemperature {
        self.at(theta + CELSIUS_ZERO)
    }
}

#[cfg(test)]
#[path = "lubricant_tests.rs"]
mod tests;
