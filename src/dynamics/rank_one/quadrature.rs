//! The quadrature of a [`super::RankOneSegment`]'s pieces: the integrals of the Volterra equation
//! and of the end states on the Lobatto nodes of twice the piece's degree.

use nalgebra::DMatrix;

use super::complex::C64;
use crate::numerics::chebyshev::Lobatto;

/// The integrals of a piece on the Lobatto nodes of twice its degree: the products
/// e^{λ(τ−σ)} g(σ) of the Volterra integrals, g = φN or ŵ_k N taken as the polynomial through its
/// values at the piece's nodes (Lobatto's `between` gives g at the nodes between), oscillate up to
/// 2 ω_max, which the finer nodes resolve where the piece's own would not. The fine nodes are kept
/// in the order even (the piece's own nodes), then odd.
pub(super) struct Quadrature {
    degree: usize,
    /// e^{−λ_k σ_q} at the fine nodes: Re in column k, Im in column r + k.
    decays: DMatrix<f64>,
    /// Column i: the fine integration matrix's row 2i (from 0 to the piece's node i), times h.
    integration: DMatrix<f64>,
    /// ∫₀^{τ_i} e^{−λ_k σ} dσ: Re at (i, k), Im at (i, r + k).
    integrals: DMatrix<f64>,
}

impl Quadrature {
    /// e^{−λ σ_q} by the exponential on the first half of the nodes and
    /// e^{−λ (h − σ)} = e^{−λ h} / e^{−λ σ} on the second (the nodes are symmetric).
    pub(super) fn new(lambdas: &[C64], degree: usize, h: f64) -> Self {
        let fine = Lobatto::get(2 * degree);
        let (r, count) = (lambdas.len(), degree + 1);
        // Fine node q at row: even q first, then odd.
        let row = |q: usize| if q.is_multiple_of(2) { q / 2 } else { count + q / 2 };
        let mut decays = DMatrix::zeros(2 * degree + 1, 2 * r);
        for (k, lambda) in lambdas.iter().enumerate() {
            let end = (-lambda * h).exp();
            let half: Vec<C64> = fine.nodes[..=degree].iter().map(|s| (-lambda * (s * h)).exp()).collect();
            for q in 0..=2 * degree {
                let z = if q <= degree { half[q] } else { end / half[2 * degree - q] };
                (decays[(row(q), k)], decays[(row(q), r + k)]) = (z.re, z.im);
            }
        }
        let integration = DMatrix::from_fn(2 * degree + 1, count, |x, i| {
            let q = if x < count { 2 * x } else { 2 * (x - count) + 1 };
            fine.integration[(2 * i, q)] * h
        });
        let integrals = integration.transpose() * &decays;
        Quadrature { degree, decays, integration, integrals }
    }

    /// e^{−λ_k τ_i} at the piece's node i.
    pub(super) fn decay(&self, k: usize, i: usize) -> C64 {
        let r = self.decays.ncols() / 2;
        C64::new(self.decays[(i, k)], self.decays[(i, r + k)])
    }

    /// ∫₀^{τ_i} e^{−λ_k σ} dσ.
    pub(super) fn integral(&self, k: usize, i: usize) -> C64 {
        let r = self.decays.ncols() / 2;
        C64::new(self.integrals[(i, k)], self.integrals[(i, r + k)])
    }

    /// The collocation kernel, row-major:
    /// M_im = Σ_q S′_{2i,q} Re Σ_j c_j e^{λ_j τ_i} e^{−λ_j σ_q} P_qm over the (mode j, c_j) of
    /// `coefficients`, P the values at the fine nodes of the polynomial through unit values at the
    /// piece's (the identity at the even ones, `between` at the odd); `e` holds e^{λ_k τ_i} at
    /// i r + k.
    pub(super) fn kernel(&self, cheb: &Lobatto, e: &[C64], coefficients: &[(usize, C64)]) -> Vec<f64> {
        let (degree, r) = (self.degree, self.decays.ncols() / 2);
        let fine_count = 2 * degree + 1;
        let decays = self.decays.as_slice();
        let mut products = self.integration.clone();
        let mut kernel = vec![0.0; fine_count];
        for (i, column) in products.as_mut_slice().chunks_exact_mut(fine_count).enumerate() {
            kernel.fill(0.0);
            for (k, c) in coefficients {
                let a = c * e[i * r + k];
                let re = &decays[k * fine_count..(k + 1) * fine_count];
                let im = &decays[(r + k) * fine_count..(r + k + 1) * fine_count];
                for ((out, re), im) in kernel.iter_mut().zip(re).zip(im) {
                    *out += a.re * re - a.im * im;
                }
            }
            for (out, k) in column.iter_mut().zip(kernel.iter()) {
                *out *= k;
            }
        }
        with_between(&products, cheb)
    }

    /// E_km = Σ_q S′_{last,q} e^{−λ_k σ_q} P_qm, column-major count × 2r: Re of mode k in column
    /// k, Im in r + k.
    pub(super) fn ends(&self, cheb: &Lobatto) -> Vec<f64> {
        let mut weighted = self.decays.clone();
        let last = self.integration.column(self.degree);
        for mut column in weighted.column_iter_mut() {
            column.component_mul_assign(&last);
        }
        with_between(&weighted, cheb)
    }
}

/// Pᵀ F for F given at the fine nodes (even rows first, then odd): even + between · odd,
/// column-major.
fn with_between(fine: &DMatrix<f64>, cheb: &Lobatto) -> Vec<f64> {
    let count = cheb.degree + 1;
    let mut out = fine.rows(0, count).into_owned();
    out.gemm(1.0, &cheb.between, &fine.rows(count, cheb.degree), 1.0);
    out.data.into()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::rank_one::collocation::{MAX_PHASE, PIECE_DEGREE, PIECE_DEGREES};

    /// The polynomial through cos(w s + θ) at the nodes of each degree of [`PIECE_DEGREES`]
    /// reproduces it at the nodes between to 1e-13 for w up to the degree's [`MAX_PHASE`]: the
    /// resolution the piece lengths are chosen by.
    #[test]
    fn every_degree_resolves_its_phase() {
        for (degree, w) in PIECE_DEGREES.iter().zip(MAX_PHASE) {
            let (c, fine) = (Lobatto::get(*degree), Lobatto::get(2 * degree));
            for theta in [0.0, 0.7, 1.9] {
                let f = |s: f64| (w * s + theta).cos();
                let values: Vec<f64> = c.nodes.iter().map(|s| f(*s)).collect();
                for (j, s) in fine.nodes.iter().skip(1).step_by(2).enumerate() {
                    let v: f64 = values.iter().enumerate().map(|(l, f)| c.between[(l, j)] * f).sum();
                    assert!((v - f(*s)).abs() < 1e-13, "degree {degree}, w {w}: {:e}", (v - f(*s)).abs());
                }
            }
        }
    }

    /// At the largest phase of a full piece (ω h = MAX_PHASE at PIECE_DEGREE, a damped mode
    /// λ = (−0.05 + i) ω), the end weights integrate e^{−λσ} cos(ωσ) over the piece and the
    /// kernel's row i integrates Re e^{λ(τ_i − σ)} cos(ωσ) from 0 to τ_i, both from the values of
    /// cos(ωσ) at the piece's nodes, against the closed forms to 1e-13 of h.
    #[test]
    fn fine_quadrature_against_closed_forms() {
        let top = PIECE_DEGREES.iter().position(|d| *d == PIECE_DEGREE).unwrap();
        let (h, omega) = (2e-4, MAX_PHASE[top] / 2e-4);
        let lambda = C64::new(-0.05 * omega, omega);
        let cheb = Lobatto::get(PIECE_DEGREE);
        let quadrature = Quadrature::new(&[lambda], PIECE_DEGREE, h);
        let count = PIECE_DEGREE + 1;
        let g: Vec<f64> = cheb.nodes.iter().map(|s| (omega * s * h).cos()).collect();
        // ∫₀^t e^{aσ} cos(ωσ) dσ = ½ Σ± (e^{(a ± iω) t} − 1)/(a ± iω).
        let closed = |a: C64, t: f64| {
            let half = |b: C64| ((b * t).exp() - 1.0) / b * 0.5;
            half(a + C64::new(0.0, omega)) + half(a - C64::new(0.0, omega))
        };
        let ends = quadrature.ends(cheb);
        let end = C64::new((0..count).map(|m| ends[m] * g[m]).sum(), (0..count).map(|m| ends[count + m] * g[m]).sum());
        assert!((end - closed(-lambda, h)).norm() < 1e-13 * h, "ends: {:e}", (end - closed(-lambda, h)).norm() / h);
        let e: Vec<C64> = (0..count).map(|i| quadrature.decay(0, i).inv()).collect();
        let kernel = quadrature.kernel(cheb, &e, &[(0, C64::new(1.0, 0.0))]);
        for (i, s) in cheb.nodes.iter().enumerate() {
            let t = s * h;
            let row: f64 = (0..count).map(|m| kernel[i * count + m] * g[m]).sum();
            let exact = ((lambda * t).exp() * closed(-lambda, t)).re;
            assert!((row - exact).abs() < 1e-13 * h, "node {i}: {:e}", (row - exact).abs() / h);
        }
    }
}
