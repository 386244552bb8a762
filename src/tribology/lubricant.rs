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

/// The oil temperature (°C) above which a base oil ages fast in service: a typical upper limit for
/// continuous operation of gear oils (mineral 100 °C; PAO, PAG and synthetic esters 130 °C; the
/// fluids not in the catalogue none). Oxidation roughly doubles per 10 K (Arrhenius' rule), so the
/// oil's life halves for every 10 K above it.
pub fn service_limit_celsius(base: BaseOil) -> Option<f64> {
    match base {
        BaseOil::Mineral => Some(100.0),
        BaseOil::Pao | BaseOil::PagInsoluble | BaseOil::PagSoluble | BaseOil::Ester => Some(130.0),
        BaseOil::Traction | BaseOil::PhosphateEster => None,
    }
}

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

/// The viscosity index of an oil from ν40 = u and ν100 = y (mm²/s), ASTM D2270 §5 with L and H of
/// its Table 1 (`super::d2270`): VI ≤ 100: 100 (L − U)/(L − H); above: N = (log H − log U)/log Y,
/// VI = (10^N − 1)/0.00715 + 100. `None` below ν100 = 2 mm²/s, where the standard defines none.
pub fn viscosity_index(u: f64, y: f64) -> Option<f64> {
    let (l, h) = super::d2270::l_and_h(y)?;
    Some(if u >= h {
        100.0 * (l - u) / (l - h)
    } else {
        let n = (h.log10() - u.log10()) / y.log10();
        (10f64.powf(n) - 1.0) / 0.00715 + 100.0
    })
}

/// Why [`nu_100_for_index`] finds no ν100.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NoNu100 {
    /// Even ν100 = 2 mm²/s, the lowest ASTM D2270 tabulates, gives a VI above the one asked for
    /// (or ν40 itself is at most 2 mm²/s): the oil's ν100 would lie below the standard's range.
    BelowTable,
    /// ν100 = ν40 still gives a VI below the one asked for.
    AboveNu40,
}

/// ν100 (mm²/s) of the oil with ν40 = u and viscosity index `vi`: the root of
/// [`viscosity_index`](u, y) = vi, which rises with y (a flatter viscosity–temperature line), by
/// bisection on [2, u] to 1e-12 relative.
pub fn nu_100_for_index(u: f64, vi: f64) -> Result<f64, NoNu100> {
    let lowest = super::d2270::LOWEST_NU_100;
    let f = |y: f64| viscosity_index(u, y).map_or(f64::INFINITY, |x| x - vi);
    let (mut lo, mut hi) = (lowest, u);
    if f(lo) > 0.0 || u <= lowest {
        return Err(NoNu100::BelowTable);
    }
    if f(hi) < 0.0 {
        return Err(NoNu100::AboveNu40);
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
    Ok(0.5 * (lo + hi))
}

/// Why the catalogue holds no oil of a grade and base.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NotInCatalogue {
    /// Not an ISO 3448 grade.
    NotAGrade,
    /// The base oil is not in the catalogue (traction fluids, phosphate esters).
    NoSuchBase,
    /// The base oil's VI puts ν100 outside ASTM D2270's range (below 2 mm²/s, for the lowest grades).
    NoNu100(NoNu100),
}

/// The catalogue oil of ISO VG `grade` on `base`: ν40 the grade (ISO 3448 midpoint), ν100 from the
/// base oil's viscosity index (ASTM D2270), ρ15 of the base oil. `None` when the grade is not an
/// ISO 3448 grade, the base oil is not in the catalogue, or no ν100 in ASTM D2270's range gives
/// the base oil's VI at that grade.
pub fn catalogue(grade: f64, base: BaseOil) -> Result<OilData, NotInCatalogue> {
    let b = base_oil(base).ok_or(NotInCatalogue::NoSuchBase)?;
    ISO_VG_GRADES.iter().find(|g| (**g - grade).abs() < 1e-9).ok_or(NotInCatalogue::NotAGrade)?;
    let nu_100 = nu_100_for_index(grade, b.viscosity_index).map_err(NotInCatalogue::NoNu100)?;
    Ok(OilData {
        base,
        nu_40: grade * 1e-6,
        nu_100: nu_100 * 1e-6,
        density_15: b.density_15,
        source: format!("ISO VG {grade} {}: {}", base.name(), b.source),
    })
}

/// The lowest ISO VG grade the catalogue holds on `base` (the grades below put ν100 under
/// ASTM D2270's 2 mm²/s at the base oil's VI); `None` for a base not in the catalogue.
pub fn lowest_grade(base: BaseOil) -> Option<f64> {
    ISO_VG_GRADES.iter().copied().find(|&g| catalogue(g, base).is_ok())
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

    /// The viscosity index (ASTM D2270); `None` for ν100 below 2 mm²/s.
    pub fn viscosity_index(&self) -> Option<f64> {
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
