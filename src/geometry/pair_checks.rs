//! The checks of [`super::pair::PairGeometry::compute`], one per stage of the construction: enough
//! teeth, a centre distance the teeth fit at, teeth that are neither undercut nor pointed nor tipped
//! inside their base circle, tips that stay off the mate's interference point, and contact ratios
//! the mesh model supports (ISO 21771 for the tooth relations).

use std::f64::consts::PI;

use super::involute::involute;
use super::pair_input::{gear_name, GeometryProblem, PairInput, PairPart, MAX_TOTAL_CONTACT_RATIO};

/// A gear needs at least 5 teeth.
pub(super) fn too_few_teeth(input: &PairInput) -> Vec<GeometryProblem> {
    let mut problems: Vec<GeometryProblem> = (0..2)
        .filter(|&i| input.teeth[i] < 5)
        .map(|i| GeometryProblem {
            part: PairPart::Teeth(i),
            reason: format!("{} teeth are too few for an involute gear", input.teeth[i]),
            hint: "a spur gear needs at least 5 teeth".into(),
        })
        .collect();
    if input.internal && input.teeth[1] <= input.teeth[0] {
        problems.push(GeometryProblem {
            part: PairPart::Teeth(1),
            reason: format!(
                "a ring of {} teeth cannot hold a pinion of {}: an internal pair needs more teeth on the ring",
                input.teeth[1], input.teeth[0]
            ),
            hint: "a ring needs at least 10 teeth more than its pinion to clear the tips (z2 − z1 ≥ 10 for 20°)".into(),
        });
    }
    problems
}

/// The centre distance a and the operating pressure angle α_w: the given a (cos α_w = (r_b1 + r_b2)/a)
/// or the zero-backlash one `(a0, α_w0)`. None (with the problem) when a given a does not exceed the
/// sum of the base radii; a given a below a0 is a problem too, but the pair is still computed.
pub(super) fn centre_distance(
    input: &PairInput,
    rb: [f64; 2],
    (a0, alpha_w0): (f64, f64),
    problems: &mut Vec<GeometryProblem>,
) -> Option<(f64, f64)> {
    let Some(a) = input.center_distance else { return Some((a0, alpha_w0)) };
    // |r_b1 + r_b2| with ISO 21771's signed radii: their difference for an internal pair.
    let (span, of) = if input.internal { (rb[1] - rb[0], "difference") } else { (rb[0] + rb[1], "sum") };
    let c = span / a;
    if c >= 1.0 || c <= 0.0 {
        problems.push(GeometryProblem {
            part: PairPart::CenterDistance,
            reason: format!(
                "centre distance {:.4} mm is not larger than the {of} of the base radii {:.4} mm",
                a * 1e3,
                span * 1e3
            ),
            hint: format!("the zero-backlash centre distance of this pair is {:.4} mm", a0 * 1e3),
        });
        return None;
    }
    // Below the zero-backlash centre distance the teeth collide: not a pair that can be
    // assembled. Allowed: 1e-3 m of rounding in the given value (FZG C: 91.5 against 91.5001 mm).
    // An internal pair collides the other way: the pinion moves into the ring's teeth as a grows.
    if input.internal && a > a0 + 1e-3 * input.module {
        problems.push(GeometryProblem {
            part: PairPart::CenterDistance,
            reason: format!(
                "centre distance {:.4} mm of the internal pair is {:.4} mm above the zero-backlash centre distance {:.4} mm (α_w = {:.4}°): the pinion's teeth would cut into the ring's",
                a * 1e3,
                (a - a0) * 1e3,
                a0 * 1e3,
                alpha_w0.to_degrees()
            ),
            hint: format!(
                "give a centre distance of at most {:.4} mm, leave it out for zero backlash, or lower the profile shifts' sum",
                a0 * 1e3
            ),
        });
    }
    if !input.internal && a < a0 - 1e-3 * input.module {
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
    Some((a, c.acos()))
}

/// The transverse tooth as the checks read it.
pub(super) struct TeethShape {
    pub transverse_pressure_angle: f64,
    pub base_radius: [f64; 2],
    pub tip_radius: [f64; 2],
}

/// Each gear's tip thickness s_a = 2 r_a ((π/2 + 2 x tan α_n)/z + inv α_t − inv α_a) (ISO 21771),
/// with the problems of a tip inside the base circle and a pointed tooth (s_a ≤ 0).
pub(super) fn tooth_shapes(input: &PairInput, shape: &TeethShape, problems: &mut Vec<GeometryProblem>) -> [f64; 2] {
    let (x, alpha, alpha_n) = (input.profile_shift, shape.transverse_pressure_angle, input.pressure_angle);
    let (rb, ra) = (shape.base_radius, shape.tip_radius);
    let z = [input.teeth[0] as f64, input.teeth[1] as f64];
    let mut tip_thickness = [0.0; 2];
    for i in 0..2 {
        let ring = i == 1 && input.internal;
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
        // ISO 21771 with a ring's r_a and z negative: s_a2 = 2|r_a2| ((π/2 + 2 x tan α_n)/|z2| − inv α_t + inv α_a2).
        let sign = if ring { -1.0 } else { 1.0 };
        tip_thickness[i] = 2.0
            * ra[i]
            * ((PI / 2.0 + 2.0 * x[i] * alpha_n.tan()) / z[i] + sign * (involute(alpha) - involute(alpha_a)));
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
    tip_thickness
}

/// Each tip circle must end the path before the mate's interference point: A = T1T2 − T2A > 0 (the
/// wheel's tip short of T1) and E = T1E < T1T2 (the pinion's short of T2). For an internal pair
/// T1T2 < 0 and only the ring's tip can reach T1 (involute interference with the pinion's root:
/// √(r_a2² − r_b2²) > |T1T2|); the pinion's tip moves away from T2.
pub(super) fn interference(t1a: f64, t1e: f64, t1t2: f64, rb: [f64; 2], internal: bool) -> Vec<GeometryProblem> {
    let mut problems = Vec::new();
    if internal && t1a <= 0.0 {
        problems.push(GeometryProblem {
            part: PairPart::TipDiameter(1),
            reason: format!(
                "the ring's tip circle reaches {:.4} mm beyond the pinion's interference point T1 (involute interference with the pinion's root)",
                -t1a * 1e3
            ),
            hint: format!("raise the ring's tip diameter above {:.4} mm", 2e3 * (t1t2 * t1t2 + rb[1] * rb[1]).sqrt()),
        });
        return problems;
    }
    if internal {
        return problems;
    }
    if t1a <= 0.0 {
        problems.push(GeometryProblem {
            part: PairPart::TipDiameter(1),
            reason: format!(
                "the wheel tip circle reaches {:.4} mm beyond the pinion's interference point T1",
                -t1a * 1e3
            ),
            hint: format!("reduce the wheel tip diameter below {:.4} mm", 2e3 * (t1t2 * t1t2 + rb[1] * rb[1]).sqrt()),
        });
    }
    if t1e >= t1t2 {
        problems.push(GeometryProblem {
            part: PairPart::TipDiameter(0),
            reason: format!(
                "the pinion tip circle reaches {:.4} mm beyond the wheel's interference point T2",
                (t1e - t1t2) * 1e3
            ),
            hint: format!("reduce the pinion tip diameter below {:.4} mm", 2e3 * (t1t2 * t1t2 + rb[0] * rb[0]).sqrt()),
        });
    }
    problems
}

/// A gear below its undercut limit x_min whose undercut reaches its mate's path of contact (its
/// undercut radius at or above the radius where contact starts on its flank): the contact would
/// meet the cut-away flank (DIN 3960's condition for an undercut that does no harm fails). An
/// undercut below the path is no problem here (the report says it).
pub(super) fn undercut_in_contact(
    input: &PairInput,
    undercut_radius: [Option<f64>; 2],
    active_start: [f64; 2],
    undercut_limit: [f64; 2],
) -> Vec<GeometryProblem> {
    (0..2)
        .filter_map(|i| {
            let ru = undercut_radius[i]?;
            (ru >= active_start[i]).then(|| GeometryProblem {
                part: PairPart::ProfileShift(i),
                reason: format!(
                    "profile shift x = {} undercuts the {} into its path of contact: the rack cuts its involute up to d = {:.4} mm, and contact starts at d = {:.4} mm (z = {} is free of undercut from x = {:.4})",
                    input.profile_shift[i],
                    gear_name(i),
                    2e3 * ru,
                    2e3 * active_start[i],
                    input.teeth[i],
                    undercut_limit[i]
                ),
                hint: format!("raise the profile shift to at least {:.4}, or shorten the mate's tip", undercut_limit[i]),
            })
        })
        .collect()
}

/// The mesh model takes 1 < ε_α < 3 and ε_γ = ε_α + ε_β ≤ [`MAX_TOTAL_CONTACT_RATIO`]: the first
/// of these that fails, if any.
pub(super) fn contact_ratios(eps: f64, overlap: f64) -> Option<GeometryProblem> {
    if eps <= 1.0 || eps >= 3.0 {
        return Some(GeometryProblem {
            part: PairPart::Pair,
            reason: format!("transverse contact ratio ε_α = {eps:.4} is outside (1, 3)"),
            hint: if eps <= 1.0 {
                "with ε_α ≤ 1 the mesh loses contact between pairs; increase the tip diameters or the number of teeth"
                    .into()
            } else {
                "contact ratios of 3 and above (four pairs in contact) are not supported".into()
            },
        });
    }
    (eps + overlap > MAX_TOTAL_CONTACT_RATIO).then(|| GeometryProblem {
        part: PairPart::Pair,
        reason: format!(
            "total contact ratio ε_γ = {:.4} (ε_α {eps:.4} + ε_β {overlap:.4}) is above {}",
            eps + overlap,
            MAX_TOTAL_CONTACT_RATIO
        ),
        hint: "reduce the face width or the helix angle: more than 7 contact lines at once are not supported".into(),
    })
}

/// Trochoid (tip-to-tip) interference of an internal pair: the pinion's tip, leaving contact, must
/// clear the ring's tooth tip. With the magnitudes of the tip radii r_a1, r_a2 and the centre
/// distance a (Stock Drive Products / KHK, *Elements of Metric Gear Technology*, eqs 5-6 to 5-8):
/// θ1 = acos((r_a2² − r_a1² − a²)/(2 a r_a1)) + inv α_a1 − inv α_w,
/// θ2 = acos((a² + r_a2² − r_a1²)/(2 a r_a2)); clear when θ1 z1/z2 + inv α_w − inv α_a2 ≥ θ2.
/// Returns the margin θ1 z1/z2 + inv α_w − inv α_a2 − θ2 (rad, ≥ 0 when clear).
pub fn trochoid_margin(teeth: [u32; 2], rb: [f64; 2], ra: [f64; 2], a: f64, alpha_w: f64) -> f64 {
    let z = teeth.map(f64::from);
    let inv_a1 = involute((rb[0] / ra[0]).acos());
    let inv_a2 = involute((rb[1] / ra[1]).acos());
    let clamp = |c: f64| c.clamp(-1.0, 1.0).acos();
    let theta1 = clamp((ra[1] * ra[1] - ra[0] * ra[0] - a * a) / (2.0 * a * ra[0])) + inv_a1 - involute(alpha_w);
    let theta2 = clamp((a * a + ra[1] * ra[1] - ra[0] * ra[0]) / (2.0 * a * ra[1]));
    theta1 * z[0] / z[1] + involute(alpha_w) - inv_a2 - theta2
}

/// The trochoid interference of an internal pair as a problem, with the margin's numbers.
pub(super) fn trochoid_interference(
    teeth: [u32; 2],
    rb: [f64; 2],
    ra: [f64; 2],
    a: f64,
    alpha_w: f64,
) -> Option<GeometryProblem> {
    let margin = trochoid_margin(teeth, rb, ra, a, alpha_w);
    (margin < 0.0).then(|| GeometryProblem {
        part: PairPart::TipDiameter(1),
        reason: format!(
            "the pinion's tip fouls the ring's tip as it leaves contact (trochoid interference): θ1 z1/z2 + inv α_w − inv α_a2 − θ2 = {:.6} rad < 0 with z1 = {}, z2 = {}",
            margin, teeth[0], teeth[1]
        ),
        hint: "raise the ring's teeth (z2 − z1 ≥ 10 clears a standard 20° pair), raise the ring's tip diameter or lower the pinion's".into(),
    })
}
