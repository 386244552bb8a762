//! Helical pairs (He & Singh): geometry, contact lines, efficiency along the lines, effective
//! stiffness and Floquet stability, against the paper, closed forms and the spur limit.

use gearloss::geometry::regions::{LineEnd::*, PitchSide::*};
use gearloss::geometry::{PairGeometry, PairInput};

use crate::{root, scene};

/// The NASA-ART pair (He & Singh §2) with `beta` as the reference helix angle (m_n = m_t cos β,
/// tan α_n = tan α_t cos β, so that the transverse values stay those of the paper).
fn nasa_art(beta_deg: f64) -> PairGeometry {
    let beta = beta_deg.to_radians();
    let m_t = 25.4e-3 / 8.0;
    PairGeometry::compute(&PairInput {
        module: m_t * beta.cos(),
        pressure_angle: (25f64.to_radians().tan() * beta.cos()).atan(),
        helix_angle: beta,
        teeth: [25, 31],
        profile_shift: [0.0, 0.0],
        tip_diameter: [Some(3.38 * 25.4e-3), Some(4.13 * 25.4e-3)],
        center_distance: Some(3.5 * 25.4e-3),
        face_width: 1.25 * 25.4e-3,
    })
    .unwrap()
}

/// The reference helix angle whose base helix angle is `beta_b_deg` (tan β = tan β_b / cos α_t).
fn reference_for_base(beta_b_deg: f64) -> f64 {
    (beta_b_deg.to_radians().tan() / 25f64.to_radians().cos()).atan().to_degrees()
}

#[test]
fn nasa_art_contact_ratios() {
    let g = nasa_art(21.5);
    // Transverse values are the paper's whatever β: m_t 3.175 mm, α_t 25° (to 1e-12).
    assert!((g.transverse_module - 3.175e-3).abs() < 1e-15);
    assert!((g.transverse_pressure_angle.to_degrees() - 25.0).abs() < 1e-12);
    // ε_γ "around 2.7": 2.7425 with 21.5° as the reference helix angle (to 5e-5).
    assert!((g.total_contact_ratio - 2.7425).abs() < 5e-5, "ε_γ = {}", g.total_contact_ratio);
    // ε_β = b sin β/(π m_n) = b tan β_b / p_bt (ISO 21771, two routes to 1e-12).
    let other = g.face_width * g.base_helix_angle.tan() / g.base_pitch;
    assert!((g.overlap_ratio - other).abs() < 1e-12);
    // Two or three lines in contact over the cycle.
    let counts: Vec<usize> = (0..1000).map(|i| g.pairs_at((i as f64 + 0.5) / 1000.0)).collect();
    assert_eq!(*counts.iter().min().unwrap(), 2);
    assert_eq!(*counts.iter().max().unwrap(), 3);
    // With 21.5° read as the base helix angle, ε_γ = 2.872 (physics notes).
    let b = nasa_art(reference_for_base(21.5));
    assert!((b.base_helix_angle.to_degrees() - 21.5).abs() < 1e-9);
    assert!((b.total_contact_ratio - 2.872).abs() < 5e-4, "ε_γ = {}", b.total_contact_ratio);
}

#[test]
fn nasa_art_regions_are_table_1_with_the_base_reading() {
    // He & Singh Table 1 (β_b = 21.5°): six regions, zones per pair #0, #1, #2 as line states.
    let g = nasa_art(reference_for_base(21.5));
    let z1 = ([StartOfContact, FaceEdge], Approach);
    let z2 = ([StartOfContact, FaceEdge], Both); // Z2 and Z3 are one state split by the period
    let z4 = ([FaceEdge, FaceEdge], Both);
    let z5 = ([FaceEdge, EndOfContact], Both); // Z5 and Z6 likewise
    let z7 = ([FaceEdge, EndOfContact], Recess);
    let table = [
        vec![z1, z2, z5],
        vec![z1, z2, z7],
        vec![z1, z4, z7],
        vec![z1, z5, z7],
        vec![z2, z5, z7],
        vec![z2, z5],
    ];
    let regions = g.cycle_regions();
    let found: Vec<Vec<_>> =
        regions.iter().map(|r| r.lines.iter().map(|l| (l.ends, l.side)).collect()).collect();
    assert_eq!(found, table.to_vec(), "regions {regions:#?}");
}

#[test]
fn contact_length_is_exact_and_its_mean_is_eps_alpha_b_over_cos_beta_b() {
    let g = nasa_art(21.5);
    // L̄ = ε_α b / cos β_b; L(τ) is piecewise linear between the break times, so the trapezoid rule
    // on the breaks is exact (to 1e-12 relative).
    let breaks = g.cycle_break_times(&[]);
    let mean: f64 = breaks.windows(2).map(|w| 0.5 * (w[1] - w[0]) * (g.contact_length(w[0] + 1e-13) + g.contact_length(w[1] - 1e-13))).sum();
    assert!((mean / g.mean_contact_length() - 1.0).abs() < 1e-9, "{mean} vs {}", g.mean_contact_length());
    // dL/dτ from the geometry equals the slope between breaks (to 1e-9 relative).
    for w in breaks.windows(2) {
        let (a, b) = (w[0] + 0.25 * (w[1] - w[0]), w[0] + 0.75 * (w[1] - w[0]));
        let slope = (g.contact_length(b) - g.contact_length(a)) / (b - a);
        let rate = g.contact_length_rate(0.5 * (a + b));
        assert!((slope - rate).abs() <= 1e-9 * g.mean_contact_length(), "{slope} vs {rate}");
    }
}

#[test]
fn helical_spec_runs_end_to_end() {
    let path = root().join("specs/nasa_art_helical.gear");
    let _ = scene(&path);
    let source = std::fs::read_to_string(&path).unwrap();
    let r = gearloss::run_to_files("nasa_art_helical.gear", &source).unwrap_or_else(|e| panic!("{e:?}"));
    let json = &r.files.iter().find(|(n, _)| n == "report.json").unwrap().1;
    let v: serde_json::Value = serde_json::from_str(json).unwrap();
    println!("{}", serde_json::to_string_pretty(&v["geometry"]).unwrap());
}
