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

/// ASTM D2270's worked examples (§7–8): ν40 = 73.30, ν100 = 8.86 mm²/s → L 119.94, H 69.48 (Table 1
/// between 8.8 and 8.9), VI 92.43, reported 92; ν40 = 22.83, ν100 = 5.05 → H 28.97(5), VI 156.4,
/// reported 156. Interpolation to 1e-9 mm²/s, the VI to 0.01 of the unrounded value.
#[test]
fn viscosity_index_by_the_standard() {
    let (l, h) = crate::tribology::d2270::l_and_h(8.86).unwrap();
    assert!((l - 119.94).abs() < 1e-9 && (h - 69.48).abs() < 1e-9, "{l} {h}");
    let vi = viscosity_index(73.3, 8.86).unwrap();
    assert!((vi - 92.43).abs() < 0.01 && vi.round() == 92.0, "{vi}");
    let (_, h) = crate::tribology::d2270::l_and_h(5.05).unwrap();
    assert!((h - 28.975).abs() < 1e-9, "{h}");
    let vi = viscosity_index(22.83, 5.05).unwrap();
    assert!((vi - 156.42).abs() < 0.01 && vi.round() == 156.0, "{vi}");
    // Table rows are read exactly, the equations take over above 70 mm²/s and are continuous
    // with the table's last row there to the table's rounding (L 4905, H 1558).
    assert_eq!(crate::tribology::d2270::l_and_h(10.0), Some((147.7, 82.87)));
    let (l70, h70) = crate::tribology::d2270::l_and_h(70.0).unwrap();
    let (l, h) = crate::tribology::d2270::l_and_h(70.0 + 1e-9).unwrap();
    assert!((l / l70 - 1.0).abs() < 1e-3 && (h / h70 - 1.0).abs() < 1e-3, "{l70} {l} {h70} {h}");
    assert!(viscosity_index(10.0, 1.99).is_none());
}

/// The table's rows rise in Y, L and H, and L > H (VI 0 above VI 100 at every Y).
#[test]
fn table_1_is_monotone() {
    let t = &crate::tribology::d2270::TABLE_1;
    assert_eq!((t[0].0, t[t.len() - 1].0), (2.0, 70.0));
    for w in t.windows(2) {
        assert!(w[1].0 > w[0].0 && w[1].1 > w[0].1 && w[1].2 > w[0].2, "{w:?}");
    }
    assert!(t.iter().all(|r| r.1 > r.2));
}

/// The catalogue's ν100 gives back the base oil's VI (to 1e-6) for every grade it holds; the grades
/// it refuses are exactly those whose ν100 would lie below ASTM D2270's 2 mm²/s.
#[test]
fn catalogue_round_trip() {
    for &g in ISO_VG_GRADES {
        for b in [BaseOil::Mineral, BaseOil::Pao, BaseOil::PagInsoluble, BaseOil::PagSoluble, BaseOil::Ester] {
            let vi = base_oil(b).unwrap().viscosity_index;
            match catalogue(g, b) {
                Ok(oil) => {
                    assert!((oil.viscosity_index().unwrap() - vi).abs() < 1e-6, "VG {g} {b:?}");
                    assert!(oil.nu_100 < oil.nu_40 && oil.nu_100 >= 2e-6);
                }
                Err(NotInCatalogue::NoNu100(NoNu100::BelowTable)) => {
                    assert!(g <= 5.0 && (g <= 2.0 || viscosity_index(g, 2.0).unwrap() > vi), "VG {g} {b:?}");
                }
                Err(e) => panic!("VG {g} {b:?}: {e:?}"),
            }
        }
    }
    assert_eq!(lowest_grade(BaseOil::Mineral), Some(7.0));
    assert_eq!(catalogue(101.0, BaseOil::Mineral).err(), Some(NotInCatalogue::NotAGrade));
    assert_eq!(catalogue(100.0, BaseOil::Traction).err(), Some(NotInCatalogue::NoSuchBase));
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
