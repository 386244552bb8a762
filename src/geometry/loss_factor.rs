//! The gear loss factor H_V: the mean of the sliding speed weighted by each pair's load share
//! over a mesh cycle, per unit friction coefficient, so that the mean mesh loss is P = P_in μ H_V
//! for a constant μ under equal load sharing (a spur pair; a helical pair's transverse slice).
//!
//! Ohlendorf's closed form (H. Ohlendorf, *Verlustleistung und Erwärmung von Stirnrädern*,
//! dissertation, TH München, 1958; quoted in ISO/TR 14179-2:2001 §6.2):
//!
//! H_V = π(u + 1)/(z_1 u cos β_b) · (1 − ε_α + ε_1² + ε_2²),
//!
//! is that mean when the pitch point lies in the zone of single contact (ε_1, ε_2 ≤ 1). Written as
//! the integral it closes, with x the distance from the pitch point along the path in base pitches
//! (from −ε_1 at A to ε_2 at E) and n(x) the number of pairs in contact while one is at x (each
//! carries 1/n of the load):
//!
//! H_V = π(u + 1)/(z_1 u cos β_b) · 2 ∫ |x|/n(x) dx,
//!
//! which holds for every ε_1, ε_2 (a ring mesh whose recess reaches past one pitch, ε_2 = 1.13; a
//! high-contact-ratio pair, ε_α ≥ 2). n(x) = #{j ∈ ℤ : −ε_1 ≤ x + j ≤ ε_2} is constant between the
//! points −ε_1 + k and ε_2 − k, so the integral is a sum of exact pieces. u is signed (negative for
//! an internal pair, where (u + 1)/u = (|u| − 1)/|u|).

use super::pair::PairGeometry;

/// 2 ∫ |x|/n(x) dx over the path −ε_1 … ε_2 (base pitches), exactly: the bracket of Ohlendorf's
/// H_V without his assumption of the pitch point in single contact.
///
/// ```
/// use gearloss::geometry::shared_sliding_integral;
/// // The pitch point in single contact: Ohlendorf's 1 − ε_α + ε_1² + ε_2².
/// let (e1, e2) = (0.8, 0.9);
/// let closed = 1.0 - (e1 + e2) + e1 * e1 + e2 * e2;
/// assert!((shared_sliding_integral(e1, e2) - closed).abs() < 1e-15);
/// ```
pub fn shared_sliding_integral(e1: f64, e2: f64) -> f64 {
    let (start, end) = (-e1, e2);
    let mut cuts = vec![start, 0.0, end];
    let pitches = (e1 + e2).ceil() as i64 + 1;
    for k in 1..=pitches {
        cuts.push(start + k as f64);
        cuts.push(end - k as f64);
    }
    cuts.retain(|x| *x >= start && *x <= end);
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let pairs = |x: f64| ((end - x).floor() - (start - x).ceil() + 1.0).max(1.0);
    let abs_integral = |a: f64, b: f64| (b * b.abs() - a * a.abs()) / 2.0;
    2.0 * cuts.windows(2).map(|w| abs_integral(w[0], w[1]) / pairs(0.5 * (w[0] + w[1]))).sum::<f64>()
}

/// Whether Ohlendorf's closed form holds: the pitch point in single contact (ε_1, ε_2 ≤ 1).
pub fn closed_form_holds(g: &PairGeometry) -> bool {
    let [e1, e2] = g.addendum_contact_ratio;
    e1 <= 1.0 && e2 <= 1.0
}

/// Ohlendorf's closed form H_V = π(u + 1)/(z_1 u cos β_b) · (1 − ε_α + ε_1² + ε_2²), as he wrote it
/// (spur: cos β_b = 1), whether or not its assumption holds (see [`closed_form_holds`]).
pub fn ohlendorf_closed_form(g: &PairGeometry) -> f64 {
    let [e1, e2] = g.addendum_contact_ratio;
    g.to_normal(prefactor(g) * (1.0 - g.contact_ratio + e1 * e1 + e2 * e2))
}

/// The loss factor H_V every mesh loss P_in μ H_V charges: Ohlendorf's closed form where it holds,
/// else the integral it closes ([`shared_sliding_integral`]).
pub(crate) fn loss_factor(g: &PairGeometry) -> f64 {
    if closed_form_holds(g) {
        ohlendorf_closed_form(g)
    } else {
        let [e1, e2] = g.addendum_contact_ratio;
        g.to_normal(prefactor(g) * shared_sliding_integral(e1, e2))
    }
}

/// π(u + 1)/(z_1 u): the sliding speed per unit pitch-line speed per base pitch from the pitch point.
fn prefactor(g: &PairGeometry) -> f64 {
    let u = g.gear_ratio;
    std::f64::consts::PI * (u + 1.0) / (g.teeth[0] as f64 * u)
}

#[cfg(test)]
mod tests {
    use super::shared_sliding_integral;

    /// Limit and closed cases: the closed form wherever the pitch point is in single contact
    /// (1e-15); a recess past one pitch (ε_2 = 1.13, ε_1 = 0.6) by hand: on −0.6…0.13 two pairs,
    /// 0.13…0.4 one, 0.4…1.13 two: 2[(0.36 + 0.0169)/4 + (0.16 − 0.0169)/2 + (1.2769 − 0.16)/4];
    /// ε_α = 2 exactly (ε_1 = ε_2 = 1): two pairs everywhere, 2 · (1 + 1)/4 = 1, the closed form's
    /// 1 − 2 + 1 + 1 = 1 too; three pairs everywhere at ε_1 = ε_2 = 1.5: 2 · 2.25/3.
    #[test]
    fn the_integral_by_hand() {
        for (e1, e2) in [(0.5, 0.7), (1.0, 0.3), (0.95, 0.95), (0.2, 1.0)] {
            let closed = 1.0 - (e1 + e2) + e1 * e1 + e2 * e2;
            assert!((shared_sliding_integral(e1, e2) - closed).abs() < 1e-15, "{e1} {e2}");
        }
        let by_hand = 2.0 * ((0.36 + 0.0169) / 4.0 + (0.16 - 0.0169) / 2.0 + (1.2769 - 0.16) / 4.0);
        assert!((shared_sliding_integral(0.6, 1.13) - by_hand).abs() < 1e-15);
        assert!((shared_sliding_integral(1.0, 1.0) - 1.0).abs() < 1e-15);
        assert!((shared_sliding_integral(1.5, 1.5) - 1.5).abs() < 1e-15);
    }
}
