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

pub use super::involute::{inverse_involute, involute};

/// Largest ε_γ supported: at most [`super::contact_lines::MAX_LINES`] lines in contact.
pub const MAX_TOTAL_CONTACT_RATIO: f64 = 7.0;

/// What the geometry needs, in SI units (m, rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairInput {
    /// Normal module m_n (the module of a spur pair).
    pub module: f64,
    /// Normal pressure angle α_n.
    pub pressure_angle: f64,
    /// Helix angle β at the reference circle (0 for a spur pair).
    pub helix_angle: f64,
    /// [pinion, wheel]
    pub teeth: [u32; 2],
    pub profile_shift: [f64; 2],
    pub tip_diameter: [Option<f64>; 2],
    pub center_distance: Option<f64>,
    pub face_width: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TipSource {
    /// Given in the scene.
    Given,
    /// d_a = m_t z + 2 m_n (1 + x) (spur: m (z + 2 + 2x)).
    AddendumRule,
}

/// Which gear or quantity a geometry problem is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PairPart {
    Teeth(usize),
    ProfileShift(usize),
    TipDiameter(usize),
    CenterDistance,
    Pair,
}

/// A pair that cannot mesh as specified.
#[derive(Debug, Clone, PartialEq)]
pub struct GeometryProblem {
    pub part: PairPart,
    pub reason: String,
    pub hint: String,
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
    /// u = z2/z1
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
    /// T1T2 = a sin α_w
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
    /// Start of the generated involute (form circle) along the line of action from the gear's own T:
    /// T_iF_i = r_i sin α_t − (1 − x_i) m_n / sin α_t (rack addendum 1·m_n).
    pub involute_start: [f64; 2],
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
        for i in 0..2 {
            if input.teeth[i] < 5 {
                problems.push(GeometryProblem {
                    part: PairPart::Teeth(i),
                    reason: format!("{} teeth are too few for an involute gear", input.teeth[i]),
                    hint: "a spur gear needs at least 5 teeth".into(),
                });
            }
        }
        if !problems.is_empty() {
            return Err(problems);
        }
        let r = [m * z[0] / 2.0, m * z[1] / 2.0];
        let rb = [r[0] * alpha.cos(), r[1] * alpha.cos()];
        let mut tip_source = [TipSource::Given; 2];
        let mut ra = [0.0; 2];
        for i in 0..2 {
            ra[i] = match input.tip_diameter[i] {
                Some(d) => d / 2.0,
                None => {
                    tip_source[i] = TipSource::AddendumRule;
                    if beta == 0.0 {
                        m * (z[i] + 2.0 + 2.0 * x[i]) / 2.0
                    } else {
                        m * z[i] / 2.0 + m_n * (1.0 + x[i])
                    }
                }
            };
        }
        let inv_w0 = involute(alpha) + 2.0 * alpha_n.tan() * (x[0] + x[1]) / (z[0] + z[1]);
        let alpha_w0 = inverse_involute(inv_w0);
        let a0 = (rb[0] + rb[1]) / alpha_w0.cos();
        let (a, alpha_w) = match input.center_distance {
            Some(a) => {
                let c = (rb[0] + rb[1]) / a;
                if c >= 1.0 {
                    problems.push(GeometryProblem {
                        part: PairPart::CenterDistance,
                        reason: format!(
                            "centre distance {:.4} mm is not larger than the sum of the base radii {:.4} mm",
                            a * 1e3,
                            (rb[0] + rb[1]) * 1e3
                        ),
                        hint: format!("the zero-backlash centre distance of this pair is {:.4} mm", a0 * 1e3),
                    });
                    return Err(problems);
                }
                // Below the zero-backlash centre distance the teeth collide: not a pair that can be
                // assembled. Allowed: 1e-3 m of rounding in the given value (FZG C: 91.5 against 91.5001 mm).
                if a < a0 - 1e-3 * m_n {
                    problems.push(GeometryProblem {
                        part: PairPart::CenterDistance,
                        reason: format!(
                            "centre distance {:.4} mm is {:.4} mm below the zero-backlash centre distance {:.4} mm (α_w = {:.4}°): the teeth would collide",
                            a * 1e3,
                            (a0 - a) * 1e3,
                            a0 * 1e3,
                            alpha_w0.to_degrees()
                        ),
                        hint: format!(
                            "give a centre distance of at least {:.4} mm, leave it out for zero backlash, or raise the profile shifts' sum",
                            a0 * 1e3
                        ),
                    });
                }
                (a, c.acos())
            }
            None => (a0, alpha_w0),
        };
        // Rack addendum 1·m_n; in the transverse section x_min = 1 − z sin²α_t / (2 cos β).
        let undercut_limit =
            [1.0 - z[0] * alpha.sin().powi(2) * (m / m_n) / 2.0, 1.0 - z[1] * alpha.sin().powi(2) * (m / m_n) / 2.0];
        let involute_start = [
            r[0] * alpha.sin() - (1.0 - x[0]) * m_n / alpha.sin(),
            r[1] * alpha.sin() - (1.0 - x[1]) * m_n / alpha.sin(),
        ];
        let mut tip_thickness = [0.0; 2];
        for i in 0..2 {
            if x[i] < undercut_limit[i] - 1e-9 {
                problems.push(GeometryProblem {
                    part: PairPart::ProfileShift(i),
                    reason: format!(
                        "profile shift x = {} undercuts the {}: z = {} needs x ≥ {:.4}",
                        x[i],
                        gear_name(i),
                        input.teeth[i],
                        undercut_limit[i]
                    ),
                    hint: format!("raise the profile shift to at least {:.4}", undercut_limit[i]),
                });
            }
            if ra[i] <= rb[i] {
                problems.push(GeometryProblem {
                    part: PairPart::TipDiameter(i),
                    reason: format!(
                        "{} tip diameter {:.4} mm is inside its base circle ({:.4} mm)",
                        gear_name(i),
                        2e3 * ra[i],
                        2e3 * rb[i]
                    ),
                    hint: "the tip diameter must exceed the base diameter d_b = m z cos α".into(),
                });
                continue;
            }
            let alpha_a = (rb[i] / ra[i]).acos();
            tip_thickness[i] =
                2.0 * ra[i] * ((PI / 2.0 + 2.0 * x[i] * alpha_n.tan()) / z[i] + involute(alpha) - involute(alpha_a));
            if tip_thickness[i] <= 0.0 {
                problems.push(GeometryProblem {
                    part: if input.tip_diameter[i].is_some() {
                        PairPart::TipDiameter(i)
                    } else {
                        PairPart::ProfileShift(i)
                    },
                    reason: format!(
                        "the {} tooth is pointed: tip thickness s_a = {:.4} mm",
                        gear_name(i),
                        tip_thickness[i] * 1e3
                    ),
                    hint: "reduce the profile shift or the tip diameter".into(),
                });
            }
        }
        if !problems.is_empty() {
            return Err(problems);
        }
        let t1t2 = a * alpha_w.sin();
        let t1e = (ra[0] * ra[0] - rb[0] * rb[0]).sqrt();
        let t2a = (ra[1] * ra[1] - rb[1] * rb[1]).sqrt();
        let t1a = t1t2 - t2a;
        let t1p = rb[0] * alpha_w.tan();
        let pb = PI * m * alpha.cos();
        if t1a <= 0.0 {
            problems.push(GeometryProblem {
                part: PairPart::TipDiameter(1),
                reason: format!(
                    "the wheel tip circle reaches {:.4} mm beyond the pinion's interference point T1",
                    -t1a * 1e3
                ),
                hint: format!(
                    "reduce the wheel tip diameter below {:.4} mm",
                    2e3 * (t1t2 * t1t2 + rb[1] * rb[1]).sqrt()
                ),
            });
        }
        if t1e >= t1t2 {
            problems.push(GeometryProblem {
                part: PairPart::TipDiameter(0),
                reason: format!(
                    "the pinion tip circle reaches {:.4} mm beyond the wheel's interference point T2",
                    (t1e - t1t2) * 1e3
                ),
                hint: format!(
                    "reduce the pinion tip diameter below {:.4} mm",
                    2e3 * (t1t2 * t1t2 + rb[0] * rb[0]).sqrt()
                ),
            });
        }
        if !problems.is_empty() {
            return Err(problems);
        }
        let eps = (t1e - t1a) / pb;
        if eps <= 1.0 || eps >= 3.0 {
            problems.push(GeometryProblem {
                part: PairPart::Pair,
                reason: format!("transverse contact ratio ε_α = {eps:.4} is outside (1, 3)"),
                hint: if eps <= 1.0 {
                    "with ε_α ≤ 1 the mesh loses contact between pairs; increase the tip diameters or the number of teeth".into()
                } else {
                    "contact ratios of 3 and above (four pairs in contact) are not supported".into()
                },
            });
            return Err(problems);
        }
        let overlap = input.face_width * beta.sin() / (PI * m_n);
        if eps + overlap > MAX_TOTAL_CONTACT_RATIO {
            problems.push(GeometryProblem {
                part: PairPart::Pair,
                reason: format!(
                    "total contact ratio ε_γ = {:.4} (ε_α {eps:.4} + ε_β {overlap:.4}) is above {}",
                    eps + overlap,
                    MAX_TOTAL_CONTACT_RATIO
                ),
                hint: "reduce the face width or the helix angle: more than 7 contact lines at once are not supported"
                    .into(),
            });
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
            gear_ratio: z[1] / z[0],
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
            involute_start,
        })
    }
}

pub(crate) fn gear_name(i: usize) -> &'static str {
    if i == 0 {
        "pinion"
    } else {
        "wheel"
    }
}
