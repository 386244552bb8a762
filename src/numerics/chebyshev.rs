//! Chebyshev–Lobatto nodes on [0, 1] and the spectral integration matrix S on them: for the
//! polynomial p of degree ≤ M through the values f_m at the nodes s_m, (S f)_i = ∫₀^{s_i} p(s) ds
//! (Trefethen, *Spectral Methods in MATLAB*, SIAM 2000, ch. 12; the Clenshaw–Curtis weights are its
//! last row). Built once per M from the Chebyshev coefficients of p:
//! c_k = (2/M) Σ″_m f_m T_k(x_m) (halved for k = 0 and k = M), x_m = −cos(π m / M), and
//! ∫T_0 = T_1, ∫T_1 = T_2/4, ∫T_k = T_{k+1}/(2(k+1)) − T_{k−1}/(2(k−1)) (+ constants), taken from
//! x = −1 and halved for the map x = 2s − 1.
//!
//! ```
//! use gearloss::numerics::Lobatto;
//! let c = Lobatto::get(16);
//! // ∫₀^s cos(3u) du = sin(3s)/3 at every node, to rounding.
//! let f: Vec<f64> = c.nodes.iter().map(|s| (3.0 * s).cos()).collect();
//! for (i, s) in c.nodes.iter().enumerate() {
//!     let integral: f64 = (0..=16).map(|m| c.integration[(i, m)] * f[m]).sum();
//!     assert!((integral - (3.0 * s).sin() / 3.0).abs() < 1e-14);
//! }
//! ```

use std::sync::OnceLock;

use nalgebra::DMatrix;

/// The node counts (M + 1 nodes, degree M) for which the nodes and S are kept.
pub(crate) const DEGREES: [usize; 6] = [8, 16, 24, 32, 48, 64];

/// Nodes and integration matrix of degree M on [0, 1].
#[derive(Debug, Clone)]
pub struct Lobatto {
    pub degree: usize,
    /// s_m = (1 − cos(π m / M)) / 2, ascending from 0 to 1.
    pub nodes: Vec<f64>,
    /// S: (M + 1) × (M + 1).
    pub integration: DMatrix<f64>,
    /// The values at the nodes between (the odd nodes of degree 2M) of the polynomial through
    /// unit values at the nodes: (M + 1) × M, column j for the j-th node between (so that the
    /// values there are betweenᵀ f), by the barycentric formula with the weights
    /// (−1)^m, halved at both ends (Berrut & Trefethen, "Barycentric Lagrange interpolation",
    /// SIAM Review 46 (2004) 501–517, eq 5.4).
    pub between: DMatrix<f64>,
}

impl Lobatto {
    /// The nodes and S for a degree of `DEGREES` (built on first use).
    pub fn get(degree: usize) -> &'static Lobatto {
        static CACHE: [OnceLock<Lobatto>; DEGREES.len()] = [const { OnceLock::new() }; DEGREES.len()];
        let i = DEGREES.iter().position(|d| *d == degree).expect("a degree of DEGREES");
        CACHE[i].get_or_init(|| Lobatto::new(degree))
    }

    fn new(m: usize) -> Self {
        let pi = std::f64::consts::PI;
        let nodes: Vec<f64> = (0..=m).map(|i| 0.5 * (1.0 - (pi * i as f64 / m as f64).cos())).collect();
        // T_k(x_i) with x_i = −cos(π i/M) = cos(π − π i/M), for k up to M + 1 (tabulated once).
        let table: Vec<f64> = (0..=m + 1)
            .flat_map(|k| (0..=m).map(move |i| (k as f64 * (pi - pi * i as f64 / m as f64)).cos()))
            .collect();
        let t = |k: usize, i: usize| table[k * (m + 1) + i];
        let mut s = DMatrix::zeros(m + 1, m + 1);
        for col in 0..=m {
            // Coefficients of the polynomial through the unit vector e_col.
            let end = if col == 0 || col == m { 0.5 } else { 1.0 };
            let c: Vec<f64> = (0..=m)
                .map(|k| {
                    let half = if k == 0 || k == m { 0.5 } else { 1.0 };
                    half * 2.0 / m as f64 * end * t(k, col)
                })
                .collect();
            // Coefficients of its antiderivative (degree M + 1).
            let d = integrated_series(&c);
            let at_minus_one: f64 = d.iter().enumerate().map(|(k, dk)| if k % 2 == 0 { *dk } else { -dk }).sum();
            for i in 0..=m {
                let value: f64 = d.iter().enumerate().map(|(k, dk)| dk * t(k, i)).sum();
                // dx = 2 ds.
                s[(i, col)] = 0.5 * (value - at_minus_one);
            }
        }
        let weight = |l: usize| if l.is_multiple_of(2) { 1.0 } else { -1.0 } * if l == 0 || l == m { 0.5 } else { 1.0 };
        let between = DMatrix::from_fn(m + 1, m, |l, j| {
            let x = 0.5 * (1.0 - (pi * (2 * j + 1) as f64 / (2 * m) as f64).cos());
            let sum: f64 = nodes.iter().enumerate().map(|(k, s)| weight(k) / (x - s)).sum();
            weight(l) / (x - nodes[l]) / sum
        });
        Lobatto { degree: m, nodes, integration: s, between }
    }

    /// The Chebyshev coefficients c_k of the polynomial through the values f_j at the nodes,
    /// p = Σ_k c_k T_k(2s − 1): c_k = (2/M) Σ″_j f_j T_k(x_j), halved for k = 0 and k = M
    /// (Trefethen, *Approximation Theory and Approximation Practice*, SIAM 2013, ch. 3).
    pub fn coefficients(&self, values: &[f64]) -> Vec<f64> {
        let (m, pi) = (self.degree, std::f64::consts::PI);
        // T_k(x_j) = cos(k π (M − j) / M) = cos(π n / M) with n = k (M − j) mod 2M.
        let cosines: Vec<f64> = (0..2 * m).map(|n| (pi * n as f64 / m as f64).cos()).collect();
        (0..=m)
            .map(|k| {
                let half = if k == 0 || k == m { 0.5 } else { 1.0 };
                let sum: f64 = values
                    .iter()
                    .enumerate()
                    .map(|(j, f)| {
                        let end = if j == 0 || j == m { 0.5 } else { 1.0 };
                        end * f * cosines[k * (m - j) % (2 * m)]
                    })
                    .sum();
                half * 2.0 / m as f64 * sum
            })
            .collect()
    }
}

/// The coefficients (in x, up to a constant) of an antiderivative of Σ_k c_k T_k(x): ∫T_0 = T_1,
/// ∫T_1 = T_2/4, ∫T_k = T_{k+1}/(2(k+1)) − T_{k−1}/(2(k−1)); one longer than `c`.
pub(crate) fn integrated_series(c: &[f64]) -> Vec<f64> {
    let m = c.len() - 1;
    let mut d = vec![0.0; m + 2];
    d[1] += c[0];
    if m >= 1 {
        d[2] += 0.25 * c[1];
    }
    for (k, ck) in c.iter().enumerate().skip(2) {
        d[k + 1] += ck / (2.0 * (k + 1) as f64);
        d[k - 1] -= ck / (2.0 * (k - 1) as f64);
    }
    d
}

/// Σ_k c_k T_k(2s − 1) by Clenshaw's recurrence b_k = c_k + 2x b_{k+1} − b_{k+2}, p = c_0 + x b_1 − b_2
/// (Clenshaw, "A note on the summation of Chebyshev series", MTAC 9 (1955) 118–120).
pub(crate) fn clenshaw(coefficients: &[f64], s: f64) -> f64 {
    let x = 2.0 * s - 1.0;
    let (mut b1, mut b2) = (0.0, 0.0);
    for c in coefficients[1..].iter().rev() {
        (b1, b2) = (c + 2.0 * x * b1 - b2, b1);
    }
    coefficients[0] + x * b1 - b2
}

/// [`clenshaw`] at many points at once, `out[m]` = the sum at `s[m]`: the recurrences of 16 points
/// run side by side, so that neither waits on the other's last step.
pub(crate) fn clenshaw_many(coefficients: &[f64], s: &[f64], out: &mut [f64]) {
    const LANES: usize = 16;
    for (points, out) in s.chunks(LANES).zip(out.chunks_mut(LANES)) {
        let (mut x, mut b1, mut b2) = ([0.0; LANES], [0.0; LANES], [0.0; LANES]);
        for (x, s) in x.iter_mut().zip(points) {
            *x = 2.0 * s - 1.0;
        }
        for c in coefficients[1..].iter().rev() {
            for l in 0..LANES {
                (b1[l], b2[l]) = (c + 2.0 * x[l] * b1[l] - b2[l], b1[l]);
            }
        }
        for (l, out) in out.iter_mut().enumerate() {
            *out = coefficients[0] + x[l] * b1[l] - b2[l];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The coefficients and Clenshaw's sum reproduce a polynomial of degree M between the nodes
    /// (to 1e-13 of its largest value), and sin(5s) from degree 24 on (to 1e-13).
    #[test]
    fn interpolation_is_exact_for_polynomials() {
        for &m in &DEGREES {
            let c = Lobatto::get(m);
            let p = |s: f64| (0..=m).map(|k| (0.3 * k as f64 - 1.0) * (2.0 * s - 1.0).powi(k as i32)).sum::<f64>();
            let q = |s: f64| (5.0 * s).sin();
            let series = |f: &dyn Fn(f64) -> f64| c.coefficients(&c.nodes.iter().map(|s| f(*s)).collect::<Vec<_>>());
            let (a, b) = (series(&p), series(&q));
            let size = c.nodes.iter().fold(1.0f64, |acc, s| acc.max(p(*s).abs()));
            for s in [0.0, 0.013, 0.25, 0.5, 0.62, 0.999, 1.0] {
                assert!((clenshaw(&a, s) - p(s)).abs() < 1e-13 * size, "M {m} s {s}");
                let mut many = [0.0; 20];
                clenshaw_many(&a, &[s; 20], &mut many);
                assert!(many.iter().all(|v| *v == clenshaw(&a, s)), "M {m} s {s}: many");
                if m >= 24 {
                    assert!((clenshaw(&b, s) - q(s)).abs() < 1e-13, "M {m} s {s}: sin");
                }
            }
        }
    }

    /// The values between the nodes reproduce a polynomial of degree M at the odd nodes of degree
    /// 2M (to 1e-13 of its largest value), and every row sums to 1 (to 1e-14).
    #[test]
    fn values_between_the_nodes() {
        for m in [8, 16, 24, 32] {
            let (c, fine) = (Lobatto::get(m), Lobatto::get(2 * m));
            let p = |s: f64| (0..=m).map(|k| (0.3 * k as f64 - 1.0) * (2.0 * s - 1.0).powi(k as i32)).sum::<f64>();
            let values: Vec<f64> = c.nodes.iter().map(|s| p(*s)).collect();
            let size = values.iter().fold(1.0f64, |acc, v| acc.max(v.abs()));
            for (j, s) in fine.nodes.iter().skip(1).step_by(2).enumerate() {
                let v: f64 = values.iter().enumerate().map(|(l, f)| c.between[(l, j)] * f).sum();
                assert!((v - p(*s)).abs() < 1e-13 * size, "M {m} node {j}: {:e}", (v - p(*s)).abs() / size);
                assert!((c.between.column(j).sum() - 1.0).abs() < 1e-14, "M {m} node {j}: sum");
            }
        }
    }

    /// Exact for polynomials of degree ≤ M (tolerance 1e-14): ∫₀^s u^k du = s^(k+1)/(k+1).
    #[test]
    fn exact_for_polynomials() {
        for &m in &DEGREES {
            let c = Lobatto::get(m);
            for k in [0, 1, 2, m / 2, m] {
                for (i, s) in c.nodes.iter().enumerate() {
                    let v: f64 = (0..=m).map(|j| c.integration[(i, j)] * c.nodes[j].powi(k as i32)).sum();
                    assert!((v - s.powi(k as i32 + 1) / (k + 1) as f64).abs() < 1e-14, "M {m} k {k}");
                }
            }
        }
    }
}
