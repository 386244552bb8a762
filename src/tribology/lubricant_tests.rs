//! Tests of the lubricant catalogue: ASTM D341, D2270, density, α, by hand.

use super::*;

/// ASTM D341 by hand for ν40 = 100, ν100 = 11 mm²/s at 90 °C:
/// W(ν) = log10 log10(ν + 0.7); B = (W40 − W100)/(log 373.15 − log 313.15); A = W40 + B log 313.15.
#[test]
fn walther_by_hand() {
    let w40 = (100.7f64).log10().log10();
    let w100 = (11.7f64).log10().log10();
    let b = (w40 - w100) / (373.15f64.log10() - 313.15f64.log10());
    let a = w40 + b * 313.15f64.log10();
    let by_hand = 10f64.powf(10f64.powf(a - b * 363.15f64.log10())) - 0.7;
    let oil =
        OilData { base: BaseOil::Mineral, nu_40: 100e-6, nu_100: 11e-6, density_15: 885.0, source: String::new() };
    let nu = oil.kinematic_viscosity_at(363.15) * 1e6;
    assert!((nu - by_hand).abs() < 1e-6 * by_hand, "{nu} vs {by_hand}");
    // And the line passes through both of its points exactly.
    assert!((oil.kinematic_viscosity_at(373.15) * 1e6 - 11.0).abs() < 1e-9);
}

/// ASTM D2270's Table 1 values at y = 10 (L 147.7, H 82.87) and y = 50 (L 2618, H 919.6) from the
/// fits, within 0.05 %; VI of the standard's examples: ν40 = 22.83, ν100 = 5.05
/// → VI 156 and ν40 = 73.3, ν100 = 8.86 → VI 92.6 (its §8 examples, rounded there).
#[test]
fn viscosity_index_fits_the_table() {
    let (l, h) = d2270_l_h(10.0);
    assert!((l - 147.7).abs() < 0.05 && (h - 82.87).abs() < 0.005, "{l} {h}");
    let (l, h) = d2270_l_h(50.0);
    assert!((l / 2618.0 - 1.0).abs() < 5e-4 && (h / 919.6 - 1.0).abs() < 5e-4, "{l} {h}");
    assert!((viscosity_index(22.83, 5.05) - 156.0).abs() < 0.5, "{}", viscosity_index(22.83, 5.05));
    assert!((viscosity_index(73.3, 8.86) - 92.6).abs() < 0.5, "{}", viscosity_index(73.3, 8.86));
}

/// The catalogue's ν100 gives back the base oil's VI (to 1e-6) for every grade from 32 to 680.
#[test]
fn catalogue_round_trip() {
    for &g in &ISO_VG_GRADES[7..16] {
        for b in [BaseOil::Mineral, BaseOil::Pao, BaseOil::PagInsoluble, BaseOil::PagSoluble, BaseOil::Ester] {
            let oil = catalogue(g, b).unwrap();
            let vi = base_oil(b).unwrap().viscosity_index;
            assert!((oil.viscosity_index() - vi).abs() < 1e-6, "VG {g} {b:?}: {}", oil.viscosity_index());
            assert!(oil.nu_100 < oil.nu_40);
        }
    }
    assert!(catalogue(101.0, BaseOil::Mineral).is_none());
    assert!(catalogue(100.0, BaseOil::Traction).is_none());
}

/// Density by hand: 885 (1 − 7e-4 · 75) = 838.5375 kg/m³ at 90 °C; α at 90 °C by hand from
/// AGMA 925's mineral coefficients; η = ρ ν.
#[test]
fn density_alpha_and_dynamic_viscosity() {
    let oil = catalogue(100.0, BaseOil::Mineral).unwrap();
    let at = oil.at_celsius(90.0);
    assert!((at.density - 838.5375).abs() < 1e-9);
    let nu = at.kinematic_viscosity * 1e6;
    let alpha = 0.010471 * nu.powf(0.1348) * 1e-6;
    assert!((at.pressure_viscosity.unwrap() - alpha).abs() < 1e-15);
    assert!((at.dynamic_viscosity - at.density * at.kinematic_viscosity).abs() < 1e-15);
}

/// α of the synthetic bases by hand in Gold et al.'s GPa⁻¹ form: ester 7.382 ν^0.1335, PAG
/// 5.489 ν^0.1485 (to 1e-12 relative); at 100 mm²/s ester ≈ 13.65 and PAG ≈ 10.88 GPa⁻¹, below
/// mineral oil's ≈ 19.6 as Gold et al. measured.
#[test]
fn synthetic_pressure_viscosity() {
    for (b, s, t) in
        [(BaseOil::Ester, 7.382, 0.1335), (BaseOil::PagInsoluble, 5.489, 0.1485), (BaseOil::PagSoluble, 5.489, 0.1485)]
    {
        let at = catalogue(220.0, b).unwrap().at_celsius(70.0);
        let by_hand = s * (at.kinematic_viscosity * 1e6).powf(t) * 1e-9;
        assert!((at.pressure_viscosity.unwrap() / by_hand - 1.0).abs() < 1e-12, "{b:?}");
    }
    let nu100 = |b: BaseOil| {
        let (k, s) = base_oil(b).unwrap().pressure_viscosity.unwrap();
        k * 100f64.powf(s) * 1e3
    };
    assert!((nu100(BaseOil::Ester) - 13.65).abs() < 0.01 && (nu100(BaseOil::PagSoluble) - 10.88).abs() < 0.01);
    assert!(nu100(BaseOil::Mineral) > nu100(BaseOil::Ester));
}
