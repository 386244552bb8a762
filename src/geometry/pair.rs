//! Involute pair geometry, spur or helical: radii, operating pressure angle, the points A B P D E on
//! the transverse line of action and the contact ratios (Fernandes et al. §3, Table 1; ISO 21771 for
//! the addendum rule, the involute function, the tooth thickness and the helical relations).
//!
//! Distances along the line of action are measured from T1, the tangency point on the pinion's base
//! circle: `T1 – A – B – P – D – E – T2`. A helical pair is computed in its transverse section
//! (ISO 21771): with the normal module m_n, normal pressure angle α_n and helix angle β at the
//! reference circle, tan α_t = tan α_n / cos β, m_t = m_n / cos β, d = z m_t, d_b = d cos α_t,
//! tan β_b = tan β cos α_t, p_bt = π m_t cos α_t, overlap ratio ε_β = b sin β / (π m_n) and total
//! contact ratio ε_γ = ε_α + ε_β. Profile shifts are normal coefficients (x m_n is the shift). A
//! spur pair is β = 0, where every transverse value equals the normal one.

use std::f64::consts::PI;

use serde::Serialize;

pub(crate) use super::involute::inverse_involute;
pub(crate) use super::involute::involute;
use super::pair_checks::{
    centre_distance, contact_ratios, interference, too_few_teeth, tooth_shapes, trochoid_interference, TeethShape,
};
use super::pair_input::wheel_sign;
pub use super::pair_input::{GeometryProblem, PairInput, PairPart};

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TipSource {
    /// Given in the scene.
    Given,
    /// d_a = m_t z + 2 m_n (1 + x) (spur: m (z + 2 + 2x)).
    AddendumRule,
}

/// The geometry of an external spur pair. Index 0 is the pinion (driving), 1 the wheel.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairGeometry {
    /// Normal module m_n.
    pub module: f64,
    /// Normal pressure angle α_n.
    pub pressure_angle: f64,
    /// β at the reference circle (rad); 0 for a spur pair.
    pub helix_angle: f64,
    /// β_b, tan β_b = tan β cos α_t.
    pub base_helix_angle: f64,
    /// m_t = m_n / cos β.
    pub transverse_module: f64,
    /// α_t, tan α_t = tan α_n / cos β.
    pub transverse_pressure_angle: f64,
    /// ε_β = b sin β / (π m_n).
    pub overlap_ratio: f64,
    /// ε_γ = ε_α + ε_β.
    pub total_contact_ratio: f64,
    pub teeth: [u32; 2],
    pub profile_shift: [f64; 2],
    pub face_width: f64,
    /// u = z2/z1, negative for an internal pair (ISO 21771: z2 < 0).
    pub gear_ratio: f64,
    pub pitch_radius: [f64; 2],
    pub base_radius: [f64; 2],
    pub tip_radius: [f64; 2],
    pub tip_source: [TipSource; 2],
    /// Centre distance used (given, or the zero-backlash one).
    pub center_distance: f64,
    pub center_distance_given: bool,
    /// α_w used: from the centre distance, cos α_w = (r_b1 + r_b2)/a.
    pub operating_pressure_angle: f64,
    /// α_w from inv α_w = inv α + 2 tan α (x1 + x2)/(z1 + z2).
    pub zero_backlash_pressure_angle: f64,
    pub zero_backlash_center_distance: f64,
    pub working_pitch_radius: [f64; 2],
    /// Transverse base pitch p_bt = π m_t cos α_t (p_b = π m cos α for a spur pair).
    pub base_pitch: f64,
    /// T1T2 = a sin α_w; negative for an internal pair (ISO 21771's a < 0: T2 lies on T1's side of P,
    /// beyond T1).
    pub line_of_action_length: f64,
    /// T1A, T1B, T1P, T1D, T1E
    pub points: LoaPoints,
    /// Transverse contact ratio ε_α = AE / p_bt.
    pub contact_ratio: f64,
    /// ε_1 = PE/p_b (pinion addendum, recess), ε_2 = AP/p_b (wheel addendum, approach)
    pub addendum_contact_ratio: [f64; 2],
    /// Transverse tooth thickness at the tip circle, s_a.
    pub tip_thickness: [f64; 2],
    /// Smallest profile shift free of undercut, x_min = 1 − z sin²α / 2 (h_a0* = 1).
    pub undercut_limit: [f64; 2],
    /// An internal pair (the wheel a ring, ISO 21771): `gear_ratio`, `line_of_action_length` and the
    /// wheel's radius of curvature carry ISO's negative sign, every radius and the centre distance
    /// are magnitudes.
    pub internal: bool,
    /// Start of the generated involute (form circle) along the line of action from the gear's own T:
    /// T_iF_i = r_i sin α_t − (1 − x_i) m_n / sin α_t (rack addendum 1·m_n).
    pub involute_start: [f64; 2],
    /// The radius up to which the rack's flank end cuts a gear below its undercut limit
    /// ([`super::undercut::undercut_radius`]); None where the gear is not undercut (and for a ring). An
    /// undercut that reaches the mate's path of contact is refused; one below it is reported.
    pub undercut_radius: [Option<f64>; 2],
}

/// Positions along the line of action, measured from T1 (m).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LoaPoints {
    pub a: f64,
    pub b: f64,
    pub p: f64,
    pub d: f64,
    pub e: f64,
}

impl LoaPoints {
    /// The named points in order, with their letters.
    pub fn named(&self) -> [(&'static str, f64); 5] {
        [("A", self.a), ("B", self.b), ("P", self.p), ("D", self.d), ("E", self.e)]
    }
}

impl PairGeometry {
    /// Computes the pair's geometry and refuses pairs that cannot mesh, with every problem found.
    pub fn compute(input: &PairInput) -> Result<PairGeometry, Vec<GeometryProblem>> {
        let mut problems = Vec::new();
        let m_n = input.module;
        let alpha_n = input.pressure_angle;
        let beta = input.helix_angle;
        // Transverse section (ISO 21771). For β = 0, cos β = 1 and atan(tan α) = α exactly, so a
        // spur pair gets its normal values unchanged.
        let m = if beta == 0.0 { m_n } else { m_n / beta.cos() };
        let alpha = if beta == 0.0 { alpha_n } else { (alpha_n.tan() / beta.cos()).atan() };
        let beta_b = (beta.tan() * alpha.cos()).atan();
        let z = [input.teeth[0] as f64, input.teeth[1] as f64];
        let x = input.profile_shift;
        // ISO 21771's sign of the wheel: a ring's teeth, diameters and centre distance are negative.
        let s2 = wheel_sign(input.internal);
        problems.extend(too_few_teeth(input));
        if !problems.is_empty() {
            return Err(problems);
        }
        let r = [m * z[0] / 2.0, m * z[1] / 2.0];
        let rb = [r[0] * alpha.cos(), r[1] * alpha.cos()];
        let (ra, tip_source) = tip_radii(input, m, z);
        let inv_w0 = involute(alpha) + 2.0 * alpha_n.tan() * (x[0] + x[1]) / (z[0] + s2 * z[1]);
        let alpha_w0 = inverse_involute(inv_w0);
        // |a| = |r_b1 + r_b2| / cos α_w with the signed radii: r_b2 − r_b1 for a ring.
        let a0 = (rb[0] + s2 * rb[1]).abs() / alpha_w0.cos();
        let Some((a, alpha_w)) = centre_distance(input, rb, (a0, alpha_w0), &mut problems) else {
            return Err(problems);
        };
        // Rack addendum 1·m_n; in the transverse section x_min = 1 − z sin²α_t / (2 cos β).
        let undercut_limit =
            [1.0 - z[0] * alpha.sin().powi(2) * (m / m_n) / 2.0, 1.0 - z[1] * alpha.sin().powi(2) * (m / m_n) / 2.0];
        let involute_start = [
            r[0] * alpha.sin() - (1.0 - x[0]) * m_n / alpha.sin(),
            r[1] * alpha.sin() - (1.0 - x[1]) * m_n / alpha.sin(),
        ];
        let shape = TeethShape { transverse_pressure_angle: alpha, base_radius: rb, tip_radius: ra };
        let tip_thickness = tooth_shapes(input, &shape, &mut problems);
        let undercut_radius = [0, 1].map(|i| {
            let ring = i == 1 && input.internal;
            let h = (1.0 - x[i]) * m_n;
            if ring {
                None
            } else {
                super::undercut::undercut_radius(r[i], alpha, h)
            }
        });
        if !problems.is_empty() {
            return Err(problems);
        }
        // Signed along the line of action (ISO 21771): a ring's T2 and its tip's point A lie on the
        // T1 side of P, so T1T2 and T2A are negative and T1A = T1T2 − T2A = √(r_a2² − r_b2²) − |a| sin α_w.
        let t1t2 = s2 * a * alpha_w.sin();
        let t1e = (ra[0] * ra[0] - rb[0] * rb[0]).sqrt();
        let t2a = s2 * (ra[1] * ra[1] - rb[1] * rb[1]).sqrt();
        let t1a = t1t2 - t2a;
        let t1p = rb[0] * alpha_w.tan();
        let pb = PI * m * alpha.cos();
        problems.extend(interference(t1a, t1e, t1t2, rb, input.internal));
        // The lowest points of the gears' flanks in contact: the pinion's at A, the wheel's at E.
        let active_start = [(rb[0] * rb[0] + t1a * t1a).sqrt(), (rb[1] * rb[1] + (t1t2 - t1e).powi(2)).sqrt()];
        problems.extend(super::pair_checks::undercut_in_contact(input, undercut_radius, active_start, undercut_limit));
        if input.internal && problems.is_empty() {
            problems.extend(trochoid_interference(input.teeth, rb, ra, a, alpha_w));
        }
        if !problems.is_empty() {
            return Err(problems);
        }
        let eps = (t1e - t1a) / pb;
        let overlap = input.face_width * beta.sin() / (PI * m_n);
        problems.extend(contact_ratios(eps, overlap));
        if !problems.is_empty() {
            return Err(problems);
        }
        Ok(PairGeometry {
            module: m_n,
            pressure_angle: alpha_n,
            helix_angle: beta,
            base_helix_angle: beta_b,
            transverse_module: m,
            transverse_pressure_angle: alpha,
            overlap_ratio: overlap,
            total_contact_ratio: eps + overlap,
            teeth: input.teeth,
            profile_shift: x,
            face_width: input.face_width,
            gear_ratio: s2 * z[1] / z[0],
            pitch_radius: r,
            base_radius: rb,
            tip_radius: ra,
            tip_source,
            center_distance: a,
            center_distance_given: input.center_distance.is_some(),
            operating_pressure_angle: alpha_w,
            zero_backlash_pressure_angle: alpha_w0,
            zero_backlash_center_distance: a0,
            working_pitch_radius: [rb[0] / alpha_w.cos(), rb[1] / alpha_w.cos()],
            base_pitch: pb,
            line_of_action_length: t1t2,
            points: LoaPoints { a: t1a, b: t1e - pb, p: t1p, d: t1a + pb, e: t1e },
            contact_ratio: eps,
            addendum_contact_ratio: [(t1e - t1p) / pb, (t1p - t1a) / pb],
            tip_thickness,
            undercut_limit,
            internal: input.internal,
            involute_start,
            undercut_radius,
        })
    }
}

/// The tip radii, given or by the addendum rule d_a = m_t z + 2 m_n (1 + x) (spur: m (z + 2 + 2x)),
/// and where each came from; `m` is the transverse module.
fn tip_radii(input: &PairInput, m: f64, z: [f64; 2]) -> ([f64; 2], [TipSource; 2]) {
    let (beta, x) = (input.helix_angle, input.profile_shift);
    let mut tip_source = [TipSource::Given; 2];
    let mut ra = [0.0; 2];
    for i in 0..2 {
        ra[i] = match input.tip_diameter[i] {
            Some(d) => d / 2.0,
            None => {
                tip_source[i] = TipSource::AddendumRule;
                // ISO 21771 with signed diameters, d_a = d + 2 m_n (1 + x): a ring's tip lies inside its
                // reference circle, |d_a2| = |d2| − 2 m_n (1 + x2).
                let sign = if i == 1 { wheel_sign(input.internal) } else { 1.0 };
                if beta == 0.0 {
                    m * (z[i] + sign * (2.0 + 2.0 * x[i])) / 2.0
                } else {
                    m * z[i] / 2.0 + sign * input.module * (1.0 + x[i])
                }
            }
        };
    }
    (ra, tip_source)
}
