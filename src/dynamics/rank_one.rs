//! The propagator of a segment on which A(t) changes along one row only: A(t) = A0 + w(t) nᵀ with A0
//! and the row n constant on the segment and w(t) any smooth column (the 6-DOF model with friction:
//! f(t) and μ̄(t) scale the mesh force N = nᵀX, whose row holds the constant k and c of the segment).
//! Only the scalar N(t) is solved for, with ~3 nodes per oscillation of the fastest mode, where
//! 6th-order Magnus needs ~12 substeps of an 11 × 11 exponential for the same accuracy.
//!
//! With A0 = V Λ V⁻¹ (modal coordinates z = V⁻¹X, ŵ = V⁻¹w, n̂ = Vᵀn, b̂ = V⁻¹b), variation of constants
//! gives, on a piece [0, h] of the segment,
//!
//! - z_j(τ) = e^{λ_j τ} z_j(0) + ∫₀^τ e^{λ_j (τ−σ)} (ŵ_j(σ) N(σ) + b̂_j(σ)) dσ,
//! - N(τ) = Σ_j n̂_j z_j(τ): a scalar Volterra equation of the second kind for N.
//!
//! It is solved by collocation at the Chebyshev–Lobatto nodes τ_m of the piece with the spectral
//! integration matrix S (Trefethen, *Spectral Methods in MATLAB*, SIAM 2000, ch. 12;
//! [`crate::numerics::chebyshev`]), writing e^{λ(τ_i − σ)} g(σ) = e^{λ τ_i} (e^{−λσ} g(σ)):
//! (I − G) N = R with G_im = S_im Re Σ_j n̂_j e^{λ_j (τ_i − τ_m)} ŵ_j(τ_m), one column of R per unit
//! initial state (the free response Re Σ_j n̂_j e^{λ_j τ_i} (V⁻¹)_jc) and one for b. The end state of
//! every mode then follows from the last row of S (Clenshaw–Curtis). The integrands
//! e^{−λσ} ŵ(σ) N(σ) oscillate up to twice the fastest mode, so a piece is at most
//! [`MAX_PHASE`] radians of that at degree [`PIECE_DEGREE`] (resolved to ~1e-14, measured and tested);
//! a shorter span takes the lowest degree that resolves it.
//!
//! Everything runs on the scaled state X / scale (displacements and velocities of one size) so that V
//! is well conditioned; where A0's eigenvectors are not (cond V > [`MAX_CONDITION`], a defective or
//! nearly defective A0), or A(t) is found not to vary along n alone, no segment is built and the
//! caller keeps Magnus.

use nalgebra::{Complex, SMatrix, SVector};

use super::model::{PeriodicModel, Propagation};
use crate::numerics::chebyshev::{Lobatto, DEGREES};
use crate::numerics::dense::{eigen, solve_dense};

type C64 = Complex<f64>;

/// The largest phase 2 ω_max h (rad) a piece of each degree of [`DEGREES`] resolves to ~1e-14
/// (measured: the integration of cos(w s) on [0, 1]).
pub const MAX_PHASE: [f64; 6] = [0.6, 6.0, 13.0, 22.0, 42.0, 66.0];
/// The largest condition number ‖V‖ ‖V⁻¹‖ (Frobenius) of A0's eigenvectors accepted.
pub const MAX_CONDITION: f64 = 1e6;
/// The degree of a full piece: the cost of a piece grows as its degree cubed (the dense solve) and
/// the pieces needed as 1 / [`MAX_PHASE`]; 24 is the cheapest measured.
pub const PIECE_DEGREE: usize = 24;

/// One mode of A0 (for a conjugate pair, the member with Im λ > 0 stands for both).
#[derive(Debug, Clone)]
struct Mode<const N: usize> {
    lambda: C64,
    /// 2 for a conjugate pair (Re of the sum of both = 2 Re of one), 1 for a real mode.
    weight: f64,
    /// Column of V and row of V⁻¹.
    vector: SVector<C64, N>,
    dual: SVector<C64, N>,
    /// n̂ = nᵀ v.
    n_hat: C64,
    /// Whether the mode enters N at all (|n̂| above rounding).
    drives_mesh: bool,
}

/// One segment's reference matrix, in modal form, and the constant row along which A varies.
#[derive(Debug, Clone)]
pub struct RankOneSegment<const N: usize> {
    pub start: f64,
    pub end: f64,
    scale: SVector<f64, N>,
    /// A0 unscaled, and D² n / |D n|², so that the scaled w = D⁻¹ (A − A0) D² n / |D n|².
    a0: SMatrix<f64, N, N>,
    projector: SVector<f64, N>,
    /// D n: the row in scaled states.
    row: SVector<f64, N>,
    modes: Vec<Mode<N>>,
    /// max |λ| (1/s): sets the piece lengths.
    fastest: f64,
}

/// The equal pieces of a propagation: their starts and their common nodes.
struct PiecePlan {
    starts: Vec<f64>,
    nodes: PieceNodes,
}

/// A piece's nodes: times, S scaled to its length, e^{λ τ_m} per mode.
struct PieceNodes {
    tau: Vec<f64>,
    /// S scaled to the piece, row-major.
    s: Vec<f64>,
    /// [m][mode] row-major: e^{λ τ_m} and e^{−λ τ_m}.
    e: Vec<C64>,
    back: Vec<C64>,
}

impl<const N: usize> RankOneSegment<N> {
    /// The segment [start, end] of `model`, whose A(t) varies along `row` only (in unscaled states).
    /// None when A0 has no well-conditioned eigenbasis or A(t) − A0 is not w nᵀ at the segment's
    /// Chebyshev nodes (to 1e-10 of ‖A0‖).
    pub fn new<M: PeriodicModel<N> + ?Sized>(model: &M, start: f64, end: f64, row: SVector<f64, N>) -> Option<Self> {
        let scale = model.state_scale();
        let a0 = model.system(0.5 * (start + end)).0;
        let a0_scaled = scaled(&a0, &scale);
        let row_scaled = row.component_mul(&scale);
        let (lambda, v) = eigen(&a0_scaled)?;
        let v_inv = v.clone().try_inverse()?;
        if v.norm() * v_inv.norm() > MAX_CONDITION * N as f64 {
            return None;
        }
        let mut modes = Vec::with_capacity(N);
        let mut j = 0;
        while j < N {
            let vector = SVector::<C64, N>::from_fn(|i, _| v[(i, j)]);
            let n_hat = (0..N).map(|i| vector[i] * row_scaled[i]).sum();
            let weight = if lambda[j].im > 0.0 { 2.0 } else { 1.0 };
            let dual = SVector::<C64, N>::from_fn(|i, _| v_inv[(j, i)]);
            modes.push(Mode { lambda: lambda[j], weight, vector, dual, n_hat, drives_mesh: true });
            j += if weight == 2.0 { 2 } else { 1 };
        }
        let largest = modes.iter().map(|m| m.n_hat.norm() * m.dual.norm()).fold(0.0, f64::max);
        for m in &mut modes {
            m.drives_mesh = m.n_hat.norm() * m.dual.norm() > 1e-14 * largest;
        }
        let fastest = lambda.iter().map(|l| l.norm()).fold(0.0, f64::max);
        let projector = row_scaled.component_mul(&scale) / row_scaled.norm_squared();
        RankOneSegment { start, end, scale, a0, projector, row: row_scaled, modes, fastest }.checked(model)
    }

    /// The same reference A0 and row used on another segment [start, end] (where A differs from A0
    /// along the row as well: the other side of the pitch point); None if it does not.
    pub fn moved<M: PeriodicModel<N> + ?Sized>(&self, model: &M, start: f64, end: f64) -> Option<Self> {
        RankOneSegment { start, end, ..self.clone() }.checked(model)
    }

    /// Self if A(t) − A0 = w nᵀ at the Chebyshev nodes of the segment (to 1e-10 of ‖A0‖).
    fn checked<M: PeriodicModel<N> + ?Sized>(self, model: &M) -> Option<Self> {
        let size = scaled(&self.a0, &self.scale).abs().max();
        for s in &Lobatto::get(8).nodes {
            let a = model.system(self.inside(self.start + s * (self.end - self.start))).0;
            let w = self.column(&a);
            if (scaled(&(a - self.a0), &self.scale) - w * self.row.transpose()).abs().max() > 1e-10 * size {
                return None;
            }
        }
        Some(self)
    }

    /// t moved just inside the segment: A and b at its ends are one-sided limits.
    fn inside(&self, t: f64) -> f64 {
        let d = 1e-12 * (self.end - self.start);
        t.clamp(self.start + d, self.end - d)
    }

    /// The scaled w of A(t): D⁻¹ (A − A0) D² n / |D n|².
    fn column(&self, a: &SMatrix<f64, N, N>) -> SVector<f64, N> {
        ((a - self.a0) * self.projector).component_div(&self.scale)
    }

    /// The propagation from `from` over `h` inside the segment, in equal pieces short enough for
    /// their degree. (Run in parallel, the pieces gained ~5 %: waking the threads costs about what
    /// a piece does.)
    pub fn propagate<M: PeriodicModel<N> + ?Sized>(&self, model: &M, from: f64, h: f64) -> Propagation<N> {
        let plan = self.plan(from, h);
        (0..plan.starts.len()).fold(Propagation::identity(), |acc, k| acc.then(&self.piece(model, &plan, k)))
    }

    /// How [from, from + h] is cut: pieces of at most [`MAX_PHASE`] at [`PIECE_DEGREE`], a single
    /// piece of the lowest degree that resolves it when shorter.
    fn plan(&self, from: f64, h: f64) -> PiecePlan {
        let phase = 2.0 * self.fastest * h;
        let top = DEGREES.iter().position(|d| *d == PIECE_DEGREE).unwrap_or(DEGREES.len() - 1);
        let pieces = (phase / MAX_PHASE[top]).ceil().max(1.0) as usize;
        let degree = DEGREES[MAX_PHASE.iter().position(|p| phase / pieces as f64 <= *p).unwrap_or(top)];
        let dt = h / pieces as f64;
        PiecePlan { starts: (0..pieces).map(|k| from + k as f64 * dt).collect(), nodes: self.nodes(degree, dt) }
    }

    fn nodes(&self, degree: usize, h: f64) -> PieceNodes {
        let cheb = Lobatto::get(degree);
        let tau: Vec<f64> = cheb.nodes.iter().map(|x| x * h).collect();
        let e: Vec<C64> = tau.iter().flat_map(|t| self.modes.iter().map(move |m| (m.lambda * *t).exp())).collect();
        let back = e.iter().map(|x| x.inv()).collect();
        let n = tau.len();
        PieceNodes { s: (0..n * n).map(|x| cheb.integration[(x / n, x % n)] * h).collect(), tau, e, back }
    }

    /// One piece [a, a + h] by collocation at `nodes`. Complex products are split into real ones
    /// (Re(p w) = Re p Re w − Im p Im w) on flat row-major arrays whose inner loops run along
    /// contiguous rows: the systems are small, and a general matrix product's set-up would cost
    /// more than the arithmetic.
    fn piece<M: PeriodicModel<N> + ?Sized>(&self, model: &M, plan: &PiecePlan, k: usize) -> Propagation<N> {
        let (a, nodes) = (plan.starts[k], &plan.nodes);
        let (count, r) = (nodes.tau.len(), self.modes.len());
        let s = &nodes.s;
        let last = count - 1;
        let driving: Vec<usize> = (0..r).filter(|k| self.modes[*k].drives_mesh).collect();
        let nd = driving.len();
        // Per node m and mode k: e^{−λτ_m} ŵ(τ_m) and e^{−λτ_m} b̂(τ_m), the integrands of S.
        let mut w_hat = vec![C64::default(); count * r];
        let mut b_hat = vec![C64::default(); count * r];
        for (m, t) in nodes.tau.iter().enumerate() {
            let (a_t, b_t) = model.system(self.inside(a + t));
            let w = self.column(&a_t);
            let b = b_t.component_div(&self.scale);
            for (k, mode) in self.modes.iter().enumerate() {
                // w and b are sparse in the gear models (accelerations only): skip their zeros.
                let (mut wk, mut bk) = (C64::default(), C64::default());
                for i in 0..N {
                    if w[i] != 0.0 {
                        wk += mode.dual[i] * w[i];
                    }
                    if b[i] != 0.0 {
                        bk += mode.dual[i] * b[i];
                    }
                }
                let back = nodes.back[m * r + k];
                w_hat[m * r + k] = wk * back;
                b_hat[m * r + k] = bk * back;
            }
        }
        // Rows 2x, 2x + 1 over the nodes: (Re, Im) of ŵ and b̂ of the x-th driving mode, and
        // (Re, −Im) of P = weight n̂ e^{λτ} (so that Re(P ŵ) = Σ over both rows).
        let split = |values: &[C64], sign: f64| -> Vec<f64> {
            let mut out = vec![0.0; 2 * nd * count];
            for (x, k) in driving.iter().enumerate() {
                for m in 0..count {
                    let v = values[m * r + k];
                    out[2 * x * count + m] = v.re;
                    out[(2 * x + 1) * count + m] = sign * v.im;
                }
            }
            out
        };
        let (wt, bt) = (split(&w_hat, 1.0), split(&b_hat, 1.0));
        let p_values: Vec<C64> = (0..count * r)
            .map(|x| {
                let mode = &self.modes[x % r];
                mode.n_hat * nodes.e[x] * mode.weight
            })
            .collect();
        let pt = split(&p_values, -1.0);
        // I − G with G_im = S_im Re Σ_k P_ik ŵ_k(τ_m); right-hand sides: the free response of every
        // initial state, Re Σ_k P_ik (V⁻¹)_kc, and the forcing Σ_m S_im Re Σ_k P_ik b̂_k(τ_m).
        let mut system = vec![0.0; count * count];
        let mut rhs = vec![0.0; count * (N + 1)];
        let (mut g, mut f) = (vec![0.0; count], vec![0.0; count]);
        for i in 0..count {
            g.fill(0.0);
            f.fill(0.0);
            for y in 0..2 * nd {
                let c = pt[y * count + i];
                for ((gm, fm), (w, b)) in g
                    .iter_mut()
                    .zip(f.iter_mut())
                    .zip(wt[y * count..(y + 1) * count].iter().zip(&bt[y * count..(y + 1) * count]))
                {
                    *gm += c * w;
                    *fm += c * b;
                }
            }
            let row = &s[i * count..(i + 1) * count];
            for ((out, sim), gm) in system[i * count..(i + 1) * count].iter_mut().zip(row).zip(&g) {
                *out = -sim * gm;
            }
            system[i * count + i] += 1.0;
            let out = &mut rhs[i * (N + 1)..(i + 1) * (N + 1)];
            out[N] = row.iter().zip(&f).map(|(a, b)| a * b).sum();
            for (x, k) in driving.iter().enumerate() {
                let (pr, pi) = (pt[2 * x * count + i], pt[(2 * x + 1) * count + i]);
                for (o, d) in out[..N].iter_mut().zip(self.modes[*k].dual.iter()) {
                    *o += pr * d.re + pi * d.im;
                }
            }
        }
        // Initial states that do not reach N (the OLOA states of the gear models) leave it at 0:
        // only the other columns are solved for.
        let size = rhs.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let live: Vec<usize> =
            (0..=N).filter(|c| (0..count).any(|i| rhs[i * (N + 1) + c].abs() > 1e-15 * size)).collect();
        let compact: Vec<f64> =
            (0..count).flat_map(|i| live.iter().map(move |c| (i, *c))).map(|(i, c)| rhs[i * (N + 1) + c]).collect();
        let solved = solve_dense(system, count, compact, live.len());
        let mut mesh = vec![0.0; count * (N + 1)];
        for i in 0..count {
            for (x, c) in live.iter().enumerate() {
                mesh[i * (N + 1) + c] = solved[i * live.len() + x];
            }
        }
        // Every mode at the end: z(h) = e^{λh} (z(0) + Σ_m S_Mm (e^{−λτ_m} ŵ N + e^{−λτ_m} b̂)).
        let ends = &s[last * count..];
        let mut x = SMatrix::<f64, N, N>::zeros();
        let mut q = SVector::<f64, N>::zeros();
        let (mut zr, mut zi) = (vec![0.0; N + 1], vec![0.0; N + 1]);
        for (k, mode) in self.modes.iter().enumerate() {
            zr.fill(0.0);
            zi.fill(0.0);
            let mut forced = C64::default();
            for m in 0..count {
                let alpha = w_hat[m * r + k] * ends[m];
                forced += b_hat[m * r + k] * ends[m];
                for ((a, b), n) in zr.iter_mut().zip(zi.iter_mut()).zip(&mesh[m * (N + 1)..(m + 1) * (N + 1)]) {
                    *a += alpha.re * n;
                    *b += alpha.im * n;
                }
            }
            let end = nodes.e[last * r + k] * mode.weight;
            for c in 0..=N {
                let z = (C64::new(zr[c], zi[c]) + if c < N { mode.dual[c] } else { forced }) * end;
                for i in 0..N {
                    let value = re_mul(mode.vector[i], z);
                    if c < N {
                        x[(i, c)] += value;
                    } else {
                        q[i] += value;
                    }
                }
            }
        }
        Propagation {
            phi: SMatrix::from_fn(|i, j| x[(i, j)] * self.scale[i] / self.scale[j]),
            q: q.component_mul(&self.scale),
        }
    }
}

/// D⁻¹ A D: A on the scaled state X / scale.
fn scaled<const N: usize>(a: &SMatrix<f64, N, N>, scale: &SVector<f64, N>) -> SMatrix<f64, N, N> {
    SMatrix::from_fn(|i, j| a[(i, j)] * scale[j] / scale[i])
}

/// Re(a b).
fn re_mul(a: C64, b: C64) -> f64 {
    a.re * b.re - a.im * b.im
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each degree integrates cos(w s) on [0, 1] to 1e-13 (absolute, at every node) for w up to its
    /// [`MAX_PHASE`]: the resolution the piece lengths are chosen by.
    #[test]
    fn every_degree_resolves_its_phase() {
        for (degree, w) in DEGREES.iter().zip(MAX_PHASE) {
            let c = Lobatto::get(*degree);
            for (i, s) in c.nodes.iter().enumerate() {
                let v: f64 = c.nodes.iter().enumerate().map(|(m, x)| c.integration[(i, m)] * (w * x).cos()).sum();
                assert!(
                    (v - (w * s).sin() / w).abs() < 1e-13,
                    "degree {degree}, w {w}: {:e}",
                    (v - (w * s).sin() / w).abs()
                );
            }
        }
    }
}
