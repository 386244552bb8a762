//! Profile shifts the model does not give, from its centre distance: the sum Σx from the
//! working transverse pressure angle (ISO 21771:2007, eq. 62 and 66), split by a stated rule.
//!
//! α_t = atan(tan α_n / cos β), a = m_n (z₁ + z₂)/(2 cos β), cos α_wt = a cos α_t / a_w,
//! Σx = (inv α_wt − inv α_t)(z₁ + z₂)/(2 tan α_n), inv α = tan α − α. One gear given: the other is
//! Σx less it. Neither: the pinion takes Σx z₂/(z₁ + z₂), the wheel Σx z₁/(z₁ + z₂) (the pinion,
//! with fewer teeth, the larger share; chosen, said).

use super::error::describe;
use super::model::Component;
use super::stage_data::GearData;

fn inv(a: f64) -> f64 {
    a.tan() - a
}

/// Σx of a pair of `teeth` with normal module `m_n` (mm), α_n and β (deg) at centre distance
/// `a_w` (mm); None when the centre distance cannot be reached (|cos α_wt| > 1).
pub(crate) fn sum_of_shifts(teeth: [u32; 2], m_n: f64, alpha_n: f64, beta: f64, a_w: f64) -> Option<f64> {
    let (an, b) = (alpha_n.to_radians(), beta.abs().to_radians());
    let at = (an.tan() / b.cos()).atan();
    let z = f64::from(teeth[0] + teeth[1]);
    let a = m_n * z / (2.0 * b.cos());
    let cos_wt = a * at.cos() / a_w;
    (cos_wt.abs() < 1.0).then(|| (inv(cos_wt.acos()) - inv(at)) * z / (2.0 * an.tan()))
}

/// Fills in the shifts of `gears` ([pinion, wheel]) the model left out, from the stage `stage`'s
/// centre distance; says what it derived. Without a centre distance they stay 0, said.
pub(crate) fn derive_missing(
    stage: &Component,
    gears: &mut [GearData; 2],
    a_w: Option<f64>,
    warnings: &mut Vec<String>,
) {
    let given = [gears[0].profile_shift_given, gears[1].profile_shift_given];
    if given == [true, true] {
        return;
    }
    let [p, w] = &*gears;
    let sum = a_w.and_then(|a| sum_of_shifts([p.teeth, w.teeth], p.module, p.pressure_angle, p.helix_angle, a));
    let Some(sum) = sum else {
        warnings.push(format!(
            "{}: a gear gives no `addendum_modification_coefficient` and the stage no usable centre distance: x = 0 (chosen)",
            describe(stage)
        ));
        for g in gears.iter_mut().filter(|g| !g.profile_shift_given) {
            g.profile_shift_note = Some("x = 0, the model gives none".into());
        }
        return;
    };
    let z = [f64::from(p.teeth), f64::from(w.teeth)];
    let shares = match given {
        [true, false] => [p.profile_shift, sum - p.profile_shift],
        [false, true] => [sum - w.profile_shift, w.profile_shift],
        _ => [sum * z[1] / (z[0] + z[1]), sum * z[0] / (z[0] + z[1])],
    };
    for (g, x) in gears.iter_mut().zip(shares) {
        if !g.profile_shift_given {
            g.profile_shift = x;
            g.profile_shift_note =
                Some(format!("x from the centre distance (Σx = {})", crate::numerics::rounding::sig(sum)));
        }
    }
    warnings.push(format!(
        "{}: profile shifts the model does not give follow from its centre distance: Σx = {} ({}; chosen)",
        describe(stage),
        crate::numerics::rounding::sig(sum),
        if given == [false, false] {
            "split pinion z₂/(z₁+z₂), wheel z₁/(z₁+z₂)"
        } else {
            "the other gear's given x taken off"
        }
    ));
}

#[cfg(test)]
mod tests {
    use super::sum_of_shifts;

    /// At the reference centre distance a = m_n (z₁ + z₂)/(2 cos β) the shifts add up to 0 (1e-12);
    /// a wider one needs a positive sum, and one beyond reach (cos α_wt > 1) gives none.
    #[test]
    fn the_reference_centre_distance_needs_no_shift() {
        let a = 4.5 * 78.0 / (2.0 * 21f64.to_radians().cos());
        assert!(sum_of_shifts([27, 51], 4.5, 20.0, 21.0, a).unwrap().abs() < 1e-12);
        assert!(sum_of_shifts([27, 51], 4.5, 20.0, 21.0, a + 1.0).unwrap() > 0.0);
        assert!(sum_of_shifts([27, 51], 4.5, 20.0, 21.0, 0.5 * a).is_none());
    }
}
