//! Gauss collocation (the implicit Runge–Kutta methods of Butcher's "Implicit Runge–Kutta
//! processes", Math. Comp. 18 (1964) 50–64): s stages at the Gauss–Legendre nodes c, weights b,
//! a_ij = ∫₀^{c_i} ℓ_j(x) dx with ℓ_j the Lagrange basis on the nodes; order 2s. Its quadrature of
//! a time-dependent integrand is the Gauss–Legendre rule itself, and it keeps every linear
//! invariant of the system exactly (an energy balance among the states holds to rounding).
//!
//! ```
//! use gearloss::numerics::Collocation;
//! // y' = y from y(0) = 1 over one step of 1: 3-stage Gauss collocation gives the [3/3] Padé
//! // approximant of e (Butcher 1964), 2.71831, to rounding.
//! let g = Collocation::new(3);
//! let mut y = vec![1.0; 3];
//! for _ in 0..40 {
//!     y = (0..3).map(|i| 1.0 + (0..3).map(|j| g.a[i][j] * y[j]).sum::<f64>()).collect();
//! }
//! let end = 1.0 + (0..3).map(|j| g.b[j] * y[j]).sum::<f64>();
//! let pade = (1.0 + 1.0 / 2.0 + 1.0 / 10.0 + 1.0 / 120.0) / (1.0 - 1.0 / 2.0 + 1.0 / 10.0 - 1.0 / 120.0);
//! assert!((end - pade).abs() < 1e-14);
//! ```

/// The Butcher tableau of s-stage Gauss collocation on [0, 1].
#[derive(Debug, Clone, PartialEq)]
pub struct Collocation {
    pub c: Vec<f64>,
    pub b: Vec<f64>,
    pub a: Vec<Vec<f64>>,
}

impl Collocation {
    pub fn new(s: usize) -> Collocation {
        let (c, b) = super::quadrature::gauss_legendre(s);
        let basis = |j: usize, x: f64| (0..s).filter(|&m| m != j).map(|m| (x - c[m]) / (c[j] - c[m])).product::<f64>();
        // ∫₀^{c_i} ℓ_j: ℓ_j has degree s − 1, so the s-point rule on [0, c_i] is exact.
        let a = c
            .iter()
            .map(|&ci| (0..s).map(|j| c.iter().zip(&b).map(|(x, w)| ci * w * basis(j, ci * x)).sum()).collect())
            .collect();
        Collocation { c, b, a }
    }

    /// y'(x) of the collocation polynomial at x ∈ [0, 1] (per unit step) from the stage slopes.
    pub fn slope_at(&self, slopes: &[f64], x: f64) -> f64 {
        let s = self.c.len();
        (0..s)
            .map(|j| {
                slopes[j]
                    * (0..s).filter(|&m| m != j).map(|m| (x - self.c[m]) / (self.c[j] - self.c[m])).product::<f64>()
            })
            .sum()
    }

    /// y(x) − y(0) of the collocation polynomial at x ∈ [0, 1] (per unit step) from the stage slopes.
    pub fn rise_to(&self, slopes: &[f64], x: f64) -> f64 {
        // ∫₀ˣ of the degree-(s−1) interpolant of the slopes: exact with the s-point rule on [0, x].
        self.c.iter().zip(&self.b).map(|(node, w)| x * w * self.slope_at(slopes, x * node)).sum()
    }
}
