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

/// (designation stem, D mm, C₀ kN).
const TABLE: &[(&str, f64, Option<f64>)] = &[
    // ISO 15 dimension series 02 (deep groove ball 62xx).
    ("6210", 90.0, Some(23.2)),
    // ISO 355 series 330 (tapered roller 330xx).
    ("33012", 95.0, None),
    ("33014", 110.0, None),
    ("33016", 125.0, None),
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

/// The sizes of `designation` (`6210-2Z`, `33014`, `K 50x58x25`), None when unknown.
pub(crate) fn sizes(designation: &str) -> Option<Sizes> {
    let d = designation.trim();
    if let Some(rest) = d.strip_prefix("K ") {
        let parts: Vec<f64> = rest.split(['x', 'X', '×']).filter_map(|p| p.trim().parse().ok()).collect();
        if let [fw, ew, _] = parts[..] {
            return (ew > fw).then_some(Sizes { bore: fw, outside: ew, static_load_rating: None });
        }
        return None;
    }
    let stem: String = d.chars().take_while(|c| c.is_ascii_digit()).collect();
    let (_, outside, c0) = TABLE.iter().find(|(s, _, _)| *s == stem)?;
    Some(Sizes { bore: bore(&stem)?, outside: *outside, static_load_rating: *c0 })
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
        assert!(sizes("NU 2210").is_none() && sizes("K 58x50x25").is_none());
    }
}
