//! The rank-one segment: A0's modes, the varying column w and the structure checks (module docs in
//! [`super`]).

use nalgebra::{SMatrix, SVector};

use super::complex::C64;
use crate::dynamics::model::{just_inside, PeriodicModel};
use crate::numerics::chebyshev::{clenshaw, clenshaw_many, Lobatto};
use crate::numerics::dense::eigen;

/// The largest condition number ‖V‖ ‖V⁻¹‖ (Frobenius) of A0's eigenvectors accepted.
pub(crate) const MAX_CONDITION: f64 = 1e6;
/// How closely (relative to ‖A0‖, scaled) the interpolant of w must reproduce the model between
/// its nodes to stand in for it.
pub(super) const INTERPOLATION_TOLERANCE: f64 = 1e-13;

/// One mode of A0 (for a conjugate pair, the member with Im λ > 0 stands for both).
#[derive(Debug, Clone)]
pub(super) struct Mode<const N: usize> {
    pub(super) lambda: C64,
    /// 2 for a conjugate pair (Re of the sum of both = 2 Re of one), 1 for a real mode.
    pub(super) weight: f64,
    /// Column of V and row of V⁻¹.
    pub(super) vector: SVector<C64, N>,
    pub(super) dual: SVector<C64, N>,
    /// n̂ = nᵀ v.
    pub(super) n_hat: C64,
    /// Whether the mode enters N at all (|n̂| above rounding).
    pub(super) drives_mesh: bool,
    /// b̂ = V⁻¹ b of the segment's constant forcing.
    pub(super) forcing: C64,
    /// For a mode that drives the mesh: ŵ(t) = α φ(t) (0 for the others).
    pub(super) alpha: C64,
}

/// One segment's reference matrix, in modal form, and the constant row along which A varies.
#[derive(Debug, Clone)]
pub struct RankOneSegment<const N: usize> {
    pub start: f64,
    pub end: f64,
    pub(super) scale: SVector<f64, N>,
    /// A0 unscaled, and D² n / |D n|², so that the scaled w = D⁻¹ (A − A0) D² n / |D n|².
    pub(super) a0: SMatrix<f64, N, N>,
    pub(super) projector: SVector<f64, N>,
    /// scale_j / scale_i: D⁻¹ A D = A ∘ ratio; and max |D⁻¹ A0 D|.
    pub(super) ratio: SMatrix<f64, N, N>,
    pub(super) size: f64,
    /// D n: the row in scaled states.
    pub(super) row: SVector<f64, N>,
    /// D⁻¹ b: the forcing, constant on the segment.
    pub(super) forcing: SVector<f64, N>,
    pub(super) modes: Vec<Mode<N>>,
    /// Σ |α_j|² over the modes that drive the mesh.
    pub(super) alpha_norm: f64,
    /// The entries of w not zero at every check node (the accelerations w drives): the only ones
    /// interpolated and projected on the modes.
    pub(super) support: Vec<usize>,
    /// w(t) on the segment, where a Chebyshev interpolant reproduces it (else the model is
    /// evaluated at every node).
    pub(super) interpolant: Option<ColumnInterpolant>,
    /// max |λ| (1/s): sets the piece lengths.
    pub(super) fastest: f64,
}

/// w(s) on a segment (s ∈ [0, 1]) through its values at the Chebyshev–Lobatto nodes of a degree,
/// as one Chebyshev series per entry of the segment's support.
#[derive(Debug, Clone)]
pub(super) struct ColumnInterpolant {
    pub(super) series: Vec<Vec<f64>>,
}

impl ColumnInterpolant {
    pub(super) fn new<const N: usize>(degree: usize, columns: &[SVector<f64, N>], support: &[usize]) -> Self {
        let nodes = Lobatto::get(degree);
        let series =
            support.iter().map(|i| nodes.coefficients(&columns.iter().map(|c| c[*i]).collect::<Vec<_>>())).collect();
        ColumnInterpolant { series }
    }

    /// The support's entries of w at the points `s`: entry x at x · len + m.
    pub(super) fn at_points(&self, s: &[f64], out: &mut [f64]) {
        for (c, out) in self.series.iter().zip(out.chunks_exact_mut(s.len())) {
            clenshaw_many(c, s, out);
        }
    }

    /// w(s).
    pub(super) fn at<const N: usize>(&self, s: f64, support: &[usize]) -> SVector<f64, N> {
        let mut w = SVector::<f64, N>::zeros();
        for (i, c) in support.iter().zip(&self.series) {
            w[*i] = clenshaw(c, s);
        }
        w
    }
}

impl<const N: usize> RankOneSegment<N> {
    /// The segment [start, end] of `model`, whose A(t) varies along `row` only (in unscaled states).
    /// None when A0 has no well-conditioned eigenbasis or the structures of the module docs fail.
    pub fn new<M: PeriodicModel<N> + ?Sized>(model: &M, start: f64, end: f64, row: SVector<f64, N>) -> Option<Self> {
        let scale = model.state_scale();
        let (a0, b0) = model.system(0.5 * (start + end));
        let ratio = SMatrix::<f64, N, N>::from_fn(|i, j| scale[j] / scale[i]);
        let a0_scaled = a0.component_mul(&ratio);
        let size = a0_scaled.abs().max();
        let row_scaled = row.component_mul(&scale);
        let forcing = b0.component_div(&scale);
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
            let forcing = modal(&dual, &forcing);
            let alpha = C64::default();
            modes.push(Mode { lambda: lambda[j], weight, vector, dual, n_hat, drives_mesh: true, forcing, alpha });
            j += if weight == 2.0 { 2 } else { 1 };
        }
        let largest = modes.iter().map(|m| m.n_hat.norm() * m.dual.norm()).fold(0.0, f64::max);
        for m in &mut modes {
            m.drives_mesh = m.n_hat.norm() * m.dual.norm() > 1e-14 * largest;
        }
        let fastest = lambda.iter().map(|l| l.norm()).fold(0.0, f64::max);
        let projector = row_scaled.component_mul(&scale) / row_scaled.norm_squared();
        RankOneSegment {
            start,
            end,
            scale,
            a0,
            projector,
            ratio,
            size,
            row: row_scaled,
            forcing,
            modes,
            alpha_norm: 0.0,
            support: Vec::new(),
            interpolant: None,
            fastest,
        }
        .checked(model)
    }

    /// The same reference A0 and row used on another segment [start, end] (where A differs from A0
    /// along the row as well: the other side of the pitch point); None if it does not.
    pub fn moved<M: PeriodicModel<N> + ?Sized>(&self, model: &M, start: f64, end: f64) -> Option<Self> {
        RankOneSegment { start, end, ..self.clone() }.checked(model)
    }

    /// Self, with the modal direction α of the varying column and its interpolant, if at the
    /// Chebyshev nodes of the segment (17, or 33 where w needs the finer interpolant)
    /// A(t) − A0 = w(t) nᵀ (to 1e-10 of ‖A0‖), b(t) is the constant b (to 1e-12), and the part of w
    /// that drives the mesh keeps one modal direction, ŵ_j(t) = α_j φ(t) (to 1e-9): true of the
    /// gear models, where w is f(t) times a fixed column on the torsional and line-of-action
    /// states (μ̄(t) moves only the states off the line of action, which do not feed back into N).
    /// Then the collocation kernel is the same for every piece of a segment.
    ///
    /// w is interpolated at degree 16 where the degree-8 interpolant through every other node
    /// already reproduces the nodes between to [`INTERPOLATION_TOLERANCE`], else at degree 32
    /// where the degree-16 one does at the 16 nodes between; else every node evaluates the model.
    pub(super) fn checked<M: PeriodicModel<N> + ?Sized>(mut self, model: &M) -> Option<Self> {
        let coarse: Vec<SVector<f64, N>> =
            Lobatto::get(16).nodes.iter().map(|s| self.sample(model, *s)).collect::<Option<_>>()?;
        self.support = support_of(&coarse);
        self.set_direction(&coarse)?;
        let even: Vec<_> = coarse.iter().step_by(2).copied().collect();
        let odd: Vec<_> = coarse.iter().skip(1).step_by(2).copied().collect();
        self.interpolant = if self.reproduces(8, &even, 16, &odd) {
            Some(ColumnInterpolant::new(16, &coarse, &self.support))
        } else {
            let fine = Lobatto::get(32);
            let between: Vec<_> =
                fine.nodes.iter().skip(1).step_by(2).map(|s| self.sample(model, *s)).collect::<Option<_>>()?;
            self.check_direction(&between)?;
            let all: Vec<_> = (0..=32).map(|j| if j % 2 == 0 { coarse[j / 2] } else { between[j / 2] }).collect();
            self.support = support_of(&all);
            self.reproduces(16, &coarse, 32, &between).then(|| ColumnInterpolant::new(32, &all, &self.support))
        };
        Some(self)
    }

    /// The scaled w at s ∈ [0, 1] of the segment; None where A − A0 is not w nᵀ or b is not the
    /// segment's constant forcing.
    pub(super) fn sample<M: PeriodicModel<N> + ?Sized>(&self, model: &M, s: f64) -> Option<SVector<f64, N>> {
        let (a, b) = model.system(self.inside(self.start + s * (self.end - self.start)));
        let w = self.column(&a);
        let mut off = 0.0f64;
        for j in 0..N {
            for i in 0..N {
                off = off.max(((a[(i, j)] - self.a0[(i, j)]) * self.ratio[(i, j)] - w[i] * self.row[j]).abs());
            }
        }
        let rank_one = off <= 1e-10 * self.size;
        let forced = (b.component_div(&self.scale) - self.forcing).abs().max() <= 1e-12 * self.forcing.abs().max();
        (rank_one && forced).then_some(w)
    }

    /// α from the largest of `columns` in the modes that drive the mesh; None unless every column
    /// is along it ([`RankOneSegment::check_direction`]).
    pub(super) fn set_direction(&mut self, columns: &[SVector<f64, N>]) -> Option<()> {
        let hats: Vec<Vec<C64>> = columns.iter().map(|w| self.driving_hats(w)).collect();
        let norm = |h: &Vec<C64>| h.iter().map(|c| c.norm_sqr()).sum::<f64>();
        let largest = hats.iter().max_by(|a, b| norm(a).total_cmp(&norm(b)))?;
        self.alpha_norm = norm(largest);
        for (m, a) in self.modes.iter_mut().zip(largest) {
            m.alpha = *a;
        }
        hats.iter().all(|h| self.along_direction(h)).then_some(())
    }

    /// Whether the modal columns that drive the mesh are α φ (to 1e-9 of |α|).
    pub(super) fn check_direction(&self, columns: &[SVector<f64, N>]) -> Option<()> {
        columns.iter().all(|w| self.along_direction(&self.driving_hats(w))).then_some(())
    }

    pub(super) fn along_direction(&self, hats: &[C64]) -> bool {
        let phi = self.direction_share(hats);
        let off: f64 = hats.iter().zip(&self.modes).map(|(h, m)| (h - m.alpha * phi).norm_sqr()).sum();
        off <= 1e-18 * self.alpha_norm
    }

    /// ŵ_j = (V⁻¹ w)_j of the modes that drive the mesh, 0 for the others.
    pub(super) fn driving_hats(&self, w: &SVector<f64, N>) -> Vec<C64> {
        self.modes.iter().map(|m| if m.drives_mesh { modal(&m.dual, w) } else { C64::default() }).collect()
    }

    /// Whether the interpolant of `degree` through `columns` reproduces `between`, the columns at
    /// the odd nodes of `finer` (= 2 degree), to [`INTERPOLATION_TOLERANCE`] of ‖A0‖.
    pub(super) fn reproduces(
        &self,
        degree: usize,
        columns: &[SVector<f64, N>],
        finer: usize,
        between: &[SVector<f64, N>],
    ) -> bool {
        let interpolant = ColumnInterpolant::new(degree, columns, &self.support);
        let size = self.size / self.row.norm();
        let nodes = Lobatto::get(finer).nodes.iter().skip(1).step_by(2);
        nodes
            .zip(between)
            .all(|(s, w)| (interpolant.at::<N>(*s, &self.support) - w).abs().max() <= INTERPOLATION_TOLERANCE * size)
    }

    /// φ = Re Σ_j conj(α_j) ŵ_j / Σ |α_j|² from the modal column ŵ of every mode.
    pub(super) fn direction_share(&self, hats: &[C64]) -> f64 {
        if self.alpha_norm == 0.0 {
            return 0.0;
        }
        self.modes.iter().zip(hats).map(|(m, h)| (m.alpha.conj() * h).re).sum::<f64>() / self.alpha_norm
    }

    /// t moved just inside the segment ([`just_inside`]).
    pub(super) fn inside(&self, t: f64) -> f64 {
        just_inside(self.start, self.end, t)
    }

    /// The scaled w of A(t): D⁻¹ (A − A0) D² n / |D n|².
    pub(super) fn column(&self, a: &SMatrix<f64, N, N>) -> SVector<f64, N> {
        ((a - self.a0) * self.projector).component_div(&self.scale)
    }
}

/// The entries not zero in any of `columns`.
pub(super) fn support_of<const N: usize>(columns: &[SVector<f64, N>]) -> Vec<usize> {
    (0..N).filter(|i| columns.iter().any(|c| c[*i] != 0.0)).collect()
}

/// dual · w for a real w, skipping its zeros (w and b are sparse in the gear models: accelerations
/// only).
pub(super) fn modal<const N: usize>(dual: &SVector<C64, N>, w: &SVector<f64, N>) -> C64 {
    let mut sum = C64::default();
    for i in 0..N {
        if w[i] != 0.0 {
            sum += dual[i] * w[i];
        }
    }
    sum
}
