//! Sizes of the rolling bearings a REXS model names by designation only (Bearinx exports give no
//! diameters): the ISO bore code gives the bore d (ISO 15 and ISO 355: the designation's last two
//! digits × 5 mm from 04; 00, 01, 02, 03 are 10, 12, 15, 17 mm), and this table the outside
//! diameter D and the static load rating C₀ of the designations it knows (the bearing makers'
//! catalogues: FAG/Schaeffler and SKF list the same D for these ISO dimension series; C₀ of the
//! deep groove ball bearing 6210 from the SKF catalogue). A needle roller cage `K Fw×Ew×B` gives
//! its raceway diameters in its name.

/// d, D (mm) and C₀ (kN, when the table has it) of a designation.
pub(crate) struct Sizes {
    pub bore: f64,
    pub outside: f64,
    pub static_load_rating: Option<f64>,
}

/// (designation stem, D mm, C₀ kN): catalogue values that stand before the dimension plans.
const TABLE: &[(&str, f64, Option<f64>)] = &[
    // ISO 15 dimension series 02 (deep groove ball 62xx).
    ("6210", 90.0, Some(23.2)),
    // ISO 355 series 330 (tapered roller 330xx).
    ("33012", 95.0, None),
    ("33014", 110.0, None),
    ("33016", 125.0, None),
];

/// The outside diameter D (mm) of each bore d (mm) in ISO 15's diameter series 0, 2 and 3 (the
/// general plan for radial bearings, which ISO 355 follows for the metric tapered roller
/// bearings of those series): (d, D₀, D₂, D₃).
const DIAMETER_SERIES: &[(f64, f64, f64, f64)] = &[
    (10.0, 26.0, 30.0, 35.0),
    (12.0, 28.0, 32.0, 37.0),
    (15.0, 32.0, 35.0, 42.0),
    (17.0, 35.0, 40.0, 47.0),
    (20.0, 42.0, 47.0, 52.0),
    (25.0, 47.0, 52.0, 62.0),
    (30.0, 55.0, 62.0, 72.0),
    (35.0, 62.0, 72.0, 80.0),
    (40.0, 68.0, 80.0, 90.0),
    (45.0, 75.0, 85.0, 100.0),
    (50.0, 80.0, 90.0, 110.0),
    (55.0, 90.0, 100.0, 120.0),
    (60.0, 95.0, 110.0, 130.0),
    (65.0, 100.0, 120.0, 140.0),
    (70.0, 110.0, 125.0, 150.0),
    (75.0, 115.0, 130.0, 160.0),
    (80.0, 125.0, 140.0, 170.0),
    (85.0, 130.0, 150.0, 180.0),
    (90.0, 140.0, 160.0, 190.0),
    (95.0, 145.0, 170.0, 200.0),
    (100.0, 150.0, 180.0, 215.0),
    (105.0, 160.0, 190.0, 225.0),
    (110.0, 170.0, 200.0, 240.0),
    (120.0, 180.0, 215.0, 260.0),
    (130.0, 200.0, 230.0, 280.0),
    (140.0, 210.0, 250.0, 300.0),
    (150.0, 225.0, 270.0, 320.0),
    (160.0, 240.0, 290.0, 340.0),
];

/// The bore from the ISO bore code of `stem`'s last two digits.
fn bore(stem: &str) -> Option<f64> {
    let code: u32 = stem.get(stem.len().checked_sub(2)?..)?.parse().ok()?;
    match code {
        0 => Some(10.0),
        1 => Some(12.0),
        2 => Some(15.0),
        3 => Some(17.0),
        4..=96 => Some(5.0 * code as f64),
        _ => None,
    }
}

/// The letters before a designation's digits (`NU`, `NJ`, `QJ`, …) and its digit stem.
fn split(designation: &str) -> (String, String) {
    let d = designation.trim();
    let prefix: String = d.chars().take_while(|c| c.is_ascii_alphabetic()).collect();
    let stem: String = d[prefix.len()..].trim_start().chars().take_while(|c| c.is_ascii_digit()).collect();
    (prefix.to_ascii_uppercase(), stem)
}

/// D from the dimension plan: the digit before the bore code is the diameter series (6210: 2,
/// 16008: 0, 30212: 2, NU 310: 3); series 0, 2 and 3 are known.
fn planned_outside(stem: &str, d: f64) -> Option<f64> {
    let series = stem.chars().rev().nth(2)?.to_digit(10)?;
    let row = DIAMETER_SERIES.iter().find(|r| r.0 == d)?;
    match series {
        0 => Some(row.1),
        2 => Some(row.2),
        3 => Some(row.3),
        _ => None,
    }
}

/// The sizes of `designation` (`6210-2Z`, `33014`, `30212-A`, `NU 2210`, `K 50x58x25`), None when
/// unknown: the table's, else the bore code and the diameter series' D (C₀ then unknown).
pub(crate) fn sizes(designation: &str) -> Option<Sizes> {
    let d = designation.trim();
    if let Some(rest) = d.strip_prefix("K ") {
        let parts: Vec<f64> = rest.split(['x', 'X', '×']).filter_map(|p| p.trim().parse().ok()).collect();
        if let [fw, ew, _] = parts[..] {
            return (ew > fw).then_some(Sizes { bore: fw, outside: ew, static_load_rating: None });
        }
        return None;
    }
    let (_, stem) = split(d);
    if stem.len() < 3 {
        return None;
    }
    let bore = bore(&stem)?;
    if let Some((_, outside, c0)) = TABLE.iter().find(|(s, _, _)| *s == stem) {
        return Some(Sizes { bore, outside: *outside, static_load_rating: *c0 });
    }
    Some(Sizes { bore, outside: planned_outside(&stem, bore)?, static_load_rating: None })
}

/// The gearloss type a designation names (`6…`/`16…` deep groove ball, `7…` angular contact
/// ball, `NU`/`NJ`/`NUP`/`N`… cylindrical roller, `3` + four digits tapered roller, `2` + four
/// digits spherical roller, `QJ` four-point), None when it names none.
pub(crate) fn type_of(designation: &str) -> Option<&'static str> {
    let (prefix, stem) = split(designation);
    match (prefix.as_str(), stem.len(), stem.chars().next()?) {
        ("K", _, _) => Some("cylindrical_roller"),
        ("N" | "NU" | "NJ" | "NUP" | "NF" | "NN" | "NNU", _, _) => Some("cylindrical_roller"),
        ("QJ", _, _) => Some("angular_contact_ball"),
        ("", 4, '6') | ("", 5, '1') => Some("deep_groove_ball"),
        ("", 4, '7') => Some("angular_contact_ball"),
        ("", 5, '3') => Some("tapered_roller"),
        ("", 5, '2') => Some("spherical_roller"),
        _ => None,
    }
}

/// A static load rating C₀ (kN) estimated where the model and the table give none (chosen, said):
/// ISO 76's C₀ = f₀ Z D_w² of a ball bearing with f₀ = 13, the ball D_w ≈ 0.3 (D − d) and Z ≈
/// π d_m/(1.5 D_w) balls (the 6210: 22.8 kN, its catalogue 23.2; the 6205: 8.5, catalogue 7.8); a
/// spherical roller bearing 4 times that (about the catalogues' ratio of a 222xx to a 62xx of one
/// bore).
pub(crate) fn estimated_static_rating(kind: &str, bore: f64, outside: f64) -> f64 {
    let dw = 0.3 * (outside - bore);
    let dm = 0.5 * (outside + bore);
    let z = std::f64::consts::PI * dm / (1.5 * dw);
    let ball = 13.0 * z * dw * dw / 1e3;
    if kind == "spherical_roller" {
        4.0 * ball
    } else {
        ball
    }
}

/// The smallest bore of ISO 15's plan not below `d` (mm) and its outside diameter D in diameter
/// series 2 (the medium series, the usual choice in a gear unit); None beyond the plan (160 mm).
pub(crate) fn series_2_outside(d: f64) -> Option<(f64, f64)> {
    DIAMETER_SERIES.iter().find(|r| r.0 >= d - 1e-9).map(|r| (r.0, r.2))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ISO bore code (10, 12, 15, 17 mm for 00–03, then × 5 mm) and the table's D and C₀.
    #[test]
    fn bore_codes_and_the_table() {
        assert_eq!(
            [bore("6000"), bore("6201"), bore("6302"), bore("6203"), bore("6210"), bore("33014")],
            [Some(10.0), Some(12.0), Some(15.0), Some(17.0), Some(50.0), Some(70.0)]
        );
        let s = sizes("6210-2Z").unwrap();
        assert_eq!((s.bore, s.outside, s.static_load_rating), (50.0, 90.0, Some(23.2)));
        let k = sizes("K 50x58x25").unwrap();
        assert_eq!((k.bore, k.outside), (50.0, 58.0));
        assert!(sizes("K 58x50x25").is_none());
    }

    /// The dimension plans against catalogue sizes (SKF and Schaeffler list these): 6305-2Z 25/62,
    /// 16008 40/68, 30212-A 60/110, 32010 50/80, NU 2210 50/90, NU 310 50/110, 7208 B 40/80,
    /// 22216 E 80/140; a diameter series not in the plan (61810, series 8) is unknown.
    #[test]
    fn the_dimension_plans() {
        for (name, d, big) in [
            ("6305-2Z", 25.0, 62.0),
            ("16008", 40.0, 68.0),
            ("30212-A", 60.0, 110.0),
            ("32010 X", 50.0, 80.0),
            ("NU 2210 ECP", 50.0, 90.0),
            ("NU310", 50.0, 110.0),
            ("7208 B", 40.0, 80.0),
            ("22216 E", 80.0, 140.0),
        ] {
            let s = sizes(name).unwrap_or_else(|| panic!("{name}"));
            assert_eq!((s.bore, s.outside), (d, big), "{name}");
        }
        assert!(sizes("61810").is_none());
        assert_eq!(
            ["6305-2Z", "16008", "30212-A", "NU 2210", "7208 B", "22216 E", "QJ 310"].map(type_of),
            [
                Some("deep_groove_ball"),
                Some("deep_groove_ball"),
                Some("tapered_roller"),
                Some("cylindrical_roller"),
                Some("angular_contact_ball"),
                Some("spherical_roller"),
                Some("angular_contact_ball")
            ]
        );
    }

    /// The estimate against the catalogue's C₀ of the 6210 (23.2 kN) and the 6205 (7.8 kN): within 10 %.
    #[test]
    fn the_static_rating_estimate() {
        for (d, big, c0) in [(50.0, 90.0, 23.2), (25.0, 52.0, 7.8)] {
            let e = estimated_static_rating("deep_groove_ball", d, big);
            assert!((e / c0 - 1.0).abs() < 0.1, "{d}/{big}: {e} vs {c0}");
        }
    }
}
