//! Helical pairs (He & Singh): geometry, contact lines, efficiency along the lines, effective
//! stiffness and Floquet stability, against the paper, closed forms and the spur limit.

use gearloss::geometry::{LineEnd::*, PitchSide::*};
use gearloss::geometry::{PairGeometry, PairInput};

use crate::root;

/// The NASA-ART pair (He & Singh §2) with `beta` as the reference helix angle (m_n = m_t cos β,
/// tan α_n = tan α_t cos β, so that the transverse values stay those of the paper).
pub(crate) fn nasa_art(beta_deg: f64) -> PairGeometry {
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
        internal: false,
    })
    .unwrap()
}

/// The reference helix angle whose base helix angle is `beta_b_deg` (tan β = tan β_b / cos α_t).
pub(crate) fn reference_for_base(beta_b_deg: f64) -> f64 {
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
    let table =
        [vec![z1, z2, z5], vec![z1, z2, z7], vec![z1, z4, z7], vec![z1, z5, z7], vec![z2, z5, z7], vec![z2, z5]];
    let regions = g.cycle_regions();
    let found: Vec<Vec<_>> = regions.iter().map(|r| r.lines.iter().map(|l| (l.ends, l.side)).collect()).collect();
    assert_eq!(found, table.to_vec(), "regions {regions:#?}");
}

#[test]
fn contact_length_is_exact_and_its_mean_is_eps_alpha_b_over_cos_beta_b() {
    let g = nasa_art(21.5);
    // L̄ = ε_α b / cos β_b; L(τ) is piecewise linear between the break times, so the trapezoid rule
    // on the breaks is exact (to 1e-12 relative).
    let breaks = g.cycle_break_times(&[]);
    let mean: f64 = breaks
        .windows(2)
        .map(|w| 0.5 * (w[1] - w[0]) * (g.contact_length(w[0] + 1e-13) + g.contact_length(w[1] - 1e-13)))
        .sum();
    assert!((mean / g.mean_contact_length() - 1.0).abs() < 1e-9, "{mean} vs {}", g.mean_contact_length());
    // dL/dτ from the geometry equals the slope between breaks (to 1e-9 relative).
    for w in breaks.windows(2) {
        let (a, b) = (w[0] + 0.25 * (w[1] - w[0]), w[0] + 0.75 * (w[1] - w[0]));
        let slope = (g.contact_length(b) - g.contact_length(a)) / (b - a);
        let rate = g.contact_length_rate(0.5 * (a + b));
        assert!((slope - rate).abs() <= 1e-9 * g.mean_contact_length(), "{slope} vs {rate}");
    }
}

/// The "done when": the committed NASA-ART report (kept up to date by
/// `specs::committed_reports_are_up_to_date`) carries the helical geometry fields, efficiency
/// records and the dynamics records with their located numbers.
#[test]
fn helical_report_carries_the_required_fields() {
    let text =
        std::fs::read_to_string(root().join("reports/nasa_art_helical_pair_he_singh/stages/pair/report.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let g = &v["geometry"];
    assert_eq!(g["helix_angle"]["unit"], "rad");
    assert!((g["helix_angle"]["value"].as_f64().unwrap() - 21.5f64.to_radians()).abs() < 1e-9);
    let eps_a = g["transverse_contact_ratio"].as_f64().unwrap();
    let eps_b = g["overlap_ratio"].as_f64().unwrap();
    assert_eq!(g["contact_ratio"].as_f64().unwrap(), eps_a);
    assert!((g["total_contact_ratio"].as_f64().unwrap() - (eps_a + eps_b)).abs() < 1e-9);
    assert!((g["total_contact_ratio"].as_f64().unwrap() - 2.7425).abs() < 5e-5);
    assert!(!v["efficiency"].as_array().unwrap().is_empty());
    let points = v["dynamics"]["points"].as_array().unwrap();
    let first = &points[0]["formulations"][0];
    for key in ["spectral_radius", "floquet_multipliers", "dte_peak_to_peak", "dte_mean", "dynamic_factor"] {
        assert!(!first[key].is_null(), "{key} missing");
    }
    // 18 000 rpm stable, 19 000 rpm unstable in every formulation (Figs 8–9).
    for f in points[1]["formulations"].as_array().unwrap() {
        assert!(f["spectral_radius"].as_f64().unwrap() <= 1.0 + 1e-9);
    }
    for f in points[2]["formulations"].as_array().unwrap() {
        assert!(f["spectral_radius"].as_f64().unwrap() > 1.01);
    }
}

mod free_response {
    use gearloss::dynamics::free_response;
    use gearloss::dynamics::{DynamicFormulation, Floquet};
    use gearloss::friction::Coulomb;

    /// He & Singh after Fig. 6 and Fig. 7: the free response at 1000 rpm (x0 = 2e-6 in, v0 = 20 in/s,
    /// μ = 0.2, undamped) is dominated by f_n ≈ 9.5 f_mesh with sidebands at 8.5 and 10.5 f_mesh:
    /// the three largest lines lie within 0.05 orders of 9.5, 8.5 and 10.5; growth |λ| = 1 (to 1e-9).
    #[test]
    fn sidebands_at_8_5_and_10_5_mesh_orders() {
        let g = super::nasa_art(21.5);
        let law = Coulomb { mu: 0.2 };
        let sys = crate::helical_physics::system_at(&g, 1000.0, Some(&law), DynamicFormulation::Internal);
        let fl = Floquet::analyse(&sys);
        let r = free_response(&sys, &fl, [2e-6 * 0.0254, 20.0 * 0.0254], 20);
        let orders: Vec<f64> = r.lines.iter().map(|l| l.order).collect();
        println!("{:?}", r.lines);
        assert!((orders[0] - 9.5).abs() < 0.05, "{orders:?}");
        let mut side = [orders[1], orders[2]];
        side.sort_by(f64::total_cmp);
        assert!((side[0] - 8.5).abs() < 0.05 && (side[1] - 10.5).abs() < 0.05, "{orders:?}");
        assert!(r.lines.iter().all(|l| (l.growth - 1.0).abs() < 1e-9));
        // The lines add up to the response: x(0) = Σ amplitudes × cos(phase) cannot be checked without
        // phases, but the peak over the window is bounded by their sum (to 1e-9 relative).
        let sum: f64 = r.lines.iter().map(|l| l.amplitude).sum();
        assert!(r.peak.value <= sum * (1.0 + 1e-6) + 1e-12, "{} vs {sum}", r.peak.value);
    }
}

mod closed_form {
    use gearloss::dynamics::magnus_adaptive;
    use gearloss::dynamics::{airy_propagation, linear_on_segments};
    use gearloss::dynamics::{DynamicFormulation, PeriodicModel};
    use gearloss::friction::Coulomb;

    /// He & Singh eqs 28–35: where K_e is linear in t (μ = 0, and the eq-25 chord with friction) the
    /// undamped segment has the Airy closed form; it agrees with adaptive 4th-order Magnus on every
    /// segment of the NASA-ART cycle to 1e-9 (Φ, relative to ‖Φ‖; q, relative to ‖q‖).
    #[test]
    fn airy_closed_form_equals_magnus_on_every_segment() {
        let g = super::nasa_art(21.5);
        let law = Coulomb { mu: 0.2 };
        for (f, l) in [
            (DynamicFormulation::Base, None),
            (DynamicFormulation::InternalChord, Some(&law as &dyn gearloss::friction::FrictionLaw)),
        ] {
            let sys = crate::helical_physics::system_at(&g, 1000.0, l, f);
            assert!(linear_on_segments(&sys), "{f:?}");
            for s in sys.segments() {
                let h = s.end - s.start;
                let a = airy_propagation(&sys, s.start, s.end, h).expect("closed form applies");
                let (m, _) = magnus_adaptive(&sys, s.start, h);
                let dphi = (a.phi - m.phi).norm() / m.phi.norm();
                let dq = (a.q - m.q).norm() / m.q.norm().max(1e-300);
                assert!(dphi < 1e-9 && dq < 1e-9, "{f:?} segment {s:?}: Φ {dphi:e}, q {dq:e}");
            }
        }
    }
}
