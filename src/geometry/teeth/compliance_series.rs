//! Term-by-term calculus of Chebyshev series on an interval (Mason & Handscomb, *Chebyshev
//! Polynomials*, Chapman & Hall 2003, §2.4.4–2.4.5).

/// Coefficients of the antiderivative of Σ c_k T_k(2s − 1) over s ∈ [0, 1] scaled to a length
/// `span`, zero at s = 0 (∫T_0 = T_1, ∫T_1 = T_2/4, ∫T_k = T_{k+1}/(2(k+1)) − T_{k−1}/(2(k−1))).
pub(crate) fn antiderivative(c: &[f64], span: f64) -> Vec<f64> {
    let mut d = crate::numerics::chebyshev::integrated_series(c);
    // dℓ = span ds = span/2 dx; make the value at x = −1 zero.
    let at_minus_one: f64 = d.iter().enumerate().map(|(k, v)| if k % 2 == 0 { *v } else { -v }).sum();
    d[0] -= at_minus_one;
    d.iter_mut().for_each(|v| *v *= 0.5 * span);
    d
}

/// Coefficients of d/ds of Σ c_k T_k(2s/g − 1) (per unit s): c'_{k−1} = c'_{k+1} + 2k c_k, ×2/g.
pub(crate) fn derivative(c: &[f64], span: f64) -> Vec<f64> {
    let n = c.len();
    let mut d = vec![0.0; n + 1];
    for k in (1..n).rev() {
        d[k - 1] = d[k + 1] + 2.0 * k as f64 * c[k];
    }
    d[0] *= 0.5;
    d.truncate(n.max(1));
    d.iter_mut().for_each(|v| *v *= 2.0 / span);
    d
}
