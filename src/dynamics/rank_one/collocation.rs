//! The pieces of a [`RankOneSegment`]'s propagation: the Chebyshev–Lobatto collocation of the
//! scalar Volterra equation for the mesh force N on each piece, and every mode's end state
//! (module docs of [`super`]).

use nalgebra::{SMatrix, SVector};

use super::complex::{re_mul, C64};
use super::quadrature::Quadrature;
use super::segment::RankOneSegment;
use crate::dynamics::model::{PeriodicModel, Propagation};
use crate::numerics::chebyshev::Lobatto;
use crate::numerics::dense::Augmented;

/// The degrees a piece may have (each with twice the degree in [`crate::numerics::chebyshev::DEGREES`]
/// for its quadrature).
pub(crate) const PIECE_DEGREES: [usize; 4] = [8, 16, 24, 32];
/// The largest phase ω_max h (rad) over a piece of each degree of [`PIECE_DEGREES`] at which the
/// polynomial through the nodes reproduces cos(w s + θ) on [0, 1] to 1e-13 (measured, and tested
/// below): N oscillates with the modes, up to ω_max.
pub(crate) const MAX_PHASE: [f64; 4] = [0.5, 4.5, 11.5, 20.5];
/// The degree of a full piece: the cost of a piece grows as its degree cubed (the dense solve) and
/// the pieces needed as 1 / [`MAX_PHASE`]; 24 is the cheapest measured.
pub(crate) const PIECE_DEGREE: usize = 24;

/// The equal pieces of a propagation: their starts and their common nodes.
struct PiecePlan<const N: usize> {
    starts: Vec<f64>,
    nodes: PieceNodes<N>,
}

/// What all pieces of one length share: the nodes, the collocation kernel, the free response and
/// the quadrature weights of the end state.
struct PieceNodes<const N: usize> {
    tau: Vec<f64>,
    /// M_im = Σ_q S′_{2i,q} Re Σ_j weight n̂_j α_j e^{λ_j (τ_i − σ_q)} P_qm over the modes driving
    /// the mesh, row-major ([`Quadrature::kernel`]): the system of a piece is I − M diag(φ).
    kernel: Vec<f64>,
    /// The right-hand sides, count × live columns: Re Σ_j weight n̂_j e^{λ_j τ_i} (V⁻¹)_jc for the
    /// unit initial states that reach N, and the free response to the forcing (column N).
    free: Vec<f64>,
    /// The columns (0..N initial states, N the forcing) that reach N.
    live: Vec<usize>,
    /// E_km = Σ_q S′_{last,q} e^{−λ_k σ_q} P_qm: the end state's quadrature of e^{−λσ} ŵ N from
    /// the values of ŵ N at the nodes, mode k at k count + m ([`Quadrature::ends`]).
    ends_re: Vec<f64>,
    ends_im: Vec<f64>,
    /// (V⁻¹)_ki of every mode k on the segment's support of w (entry x at k support + x), and
    /// conj α_k: ŵ and φ = Re Σ_k conj α_k ŵ_k / Σ |α|² at the nodes from the support's entries of w.
    duals: Vec<C64>,
    shares: Vec<C64>,
    /// The piece's map without the variation (A0 and the forcing alone), scaled states.
    free_map: Propagation<N>,
    /// weight e^{λ_k h} v_k per mode, (Re, Im): turns the modes' end corrections into states.
    end_vectors: Vec<[SVector<f64, N>; 2]>,
}

/// The buffers one propagation's pieces share.
struct Workspace {
    system: Augmented,
    /// E_km ŵ_k(τ_m) at k count + m.
    weights_re: Vec<f64>,
    weights_im: Vec<f64>,
    /// N at x count + m (live column x).
    mesh: Vec<f64>,
    /// The nodes as fractions of the segment, and the support's entries of w there (entry x at
    /// x count + m).
    points: Vec<f64>,
    columns: Vec<f64>,
    phi: Vec<f64>,
    /// ŵ_k at the nodes, one mode at a time.
    hat_re: Vec<f64>,
    hat_im: Vec<f64>,
    /// Σ_m E_km ŵ_k(τ_m) N_c(τ_m): mode k, live column x at k · live + x.
    z_re: Vec<f64>,
    z_im: Vec<f64>,
}

impl<const N: usize> RankOneSegment<N> {
    /// The propagation from `from` over `h` inside the segment, in equal pieces short enough for
    /// their degree.
    pub fn propagate<M: PeriodicModel<N> + ?Sized>(&self, model: &M, from: f64, h: f64) -> Propagation<N> {
        let plan = self.plan(from, h);
        let (count, r, live) = (plan.nodes.tau.len(), self.modes.len(), plan.nodes.live.len());
        let mut ws = Workspace {
            system: Augmented::zeros(count, live),
            weights_re: vec![0.0; count * r],
            weights_im: vec![0.0; count * r],
            mesh: vec![0.0; count * live],
            points: vec![0.0; count],
            columns: vec![0.0; count * self.support.len()],
            phi: vec![0.0; count],
            hat_re: vec![0.0; count],
            hat_im: vec![0.0; count],
            z_re: vec![0.0; r * live],
            z_im: vec![0.0; r * live],
        };
        let scaled = (0..plan.starts.len())
            .fold(Propagation::identity(), |acc, k| acc.then(&self.piece(model, &plan, k, &mut ws)));
        Propagation {
            phi: SMatrix::from_fn(|i, j| scaled.phi[(i, j)] * self.scale[i] / self.scale[j]),
            q: scaled.q.component_mul(&self.scale),
        }
    }

    /// How [from, from + h] is cut: pieces of at most [`MAX_PHASE`] at [`PIECE_DEGREE`], a single
    /// piece of the lowest degree that resolves it when shorter. Where w comes from the model at
    /// every node (no series of the segment reproduces it), its own variation is not known: the
    /// pieces are then kept half as long.
    fn plan(&self, from: f64, h: f64) -> PiecePlan<N> {
        let phase = self.fastest * h * if self.interpolant.is_some() { 1.0 } else { 2.0 };
        let top = PIECE_DEGREES.iter().position(|d| *d == PIECE_DEGREE).unwrap_or(PIECE_DEGREES.len() - 1);
        let pieces = (phase / MAX_PHASE[top]).ceil().max(1.0) as usize;
        let degree = PIECE_DEGREES[MAX_PHASE.iter().position(|p| phase / pieces as f64 <= *p).unwrap_or(top)];
        let dt = h / pieces as f64;
        PiecePlan { starts: (0..pieces).map(|k| from + k as f64 * dt).collect(), nodes: self.nodes(degree, dt) }
    }

    /// The nodes, kernel, free response and end weights of a piece of length h at `degree`.
    fn nodes(&self, degree: usize, h: f64) -> PieceNodes<N> {
        let cheb = Lobatto::get(degree);
        let (count, r) = (degree + 1, self.modes.len());
        let tau: Vec<f64> = cheb.nodes.iter().map(|x| x * h).collect();
        let lambdas: Vec<C64> = self.modes.iter().map(|m| m.lambda).collect();
        let quadrature = Quadrature::new(&lambdas, degree, h);
        // e^{λ τ_i} at the piece's nodes (every other fine node): node i, mode k at i r + k.
        let e: Vec<C64> =
            (0..count).flat_map(|i| (0..r).map(move |k| (i, k))).map(|(i, k)| quadrature.decay(k, i).inv()).collect();
        let driving: Vec<usize> = (0..r).filter(|k| self.modes[*k].drives_mesh).collect();
        let mut all = vec![0.0; count * (N + 1)];
        for i in 0..count {
            for k in &driving {
                let mode = &self.modes[*k];
                // weight n̂ e^{λ τ_i}: the mesh force's share of the mode.
                let p = mode.n_hat * mode.weight * e[i * r + k];
                for c in 0..N {
                    all[i * (N + 1) + c] += re_mul(p, mode.dual[c]);
                }
                all[i * (N + 1) + N] += re_mul(p * mode.forcing, quadrature.integral(*k, i));
            }
        }
        // Initial states that do not reach N (the OLOA states of the gear models) leave it at 0:
        // only the other columns are solved for.
        let size = all.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let live: Vec<usize> =
            (0..=N).filter(|c| (0..count).any(|i| all[i * (N + 1) + c].abs() > 1e-15 * size)).collect();
        let free =
            (0..count).flat_map(|i| live.iter().map(move |c| (i, *c))).map(|(i, c)| all[i * (N + 1) + c]).collect();
        let coefficients: Vec<(usize, C64)> =
            driving.iter().map(|k| (*k, self.modes[*k].n_hat * self.modes[*k].weight * self.modes[*k].alpha)).collect();
        let kernel = quadrature.kernel(cheb, &e, &coefficients);
        let mut ends_re = quadrature.ends(cheb);
        let ends_im = ends_re.split_off(r * count);
        let duals = self.modes.iter().flat_map(|m| self.support.iter().map(|i| m.dual[*i])).collect();
        let shares = self.modes.iter().map(|m| m.alpha.conj()).collect();
        let mut free_map = Propagation::<N> { phi: SMatrix::zeros(), q: SVector::zeros() };
        let mut end_vectors = Vec::with_capacity(r);
        for (k, mode) in self.modes.iter().enumerate() {
            let v = mode.vector * (e[(count - 1) * r + k] * mode.weight);
            let forced = mode.forcing * quadrature.integral(k, count - 1);
            for i in 0..N {
                for c in 0..N {
                    free_map.phi[(i, c)] += re_mul(v[i], mode.dual[c]);
                }
                free_map.q[i] += re_mul(v[i], forced);
            }
            end_vectors.push([v.map(|x| x.re), v.map(|x| x.im)]);
        }
        PieceNodes { tau, kernel, free, live, ends_re, ends_im, duals, shares, free_map, end_vectors }
    }

    /// One piece [a, a + h] (scaled states): φ at the nodes, the collocation system
    /// (I − M diag φ) N = R, then every mode's end state
    /// z(h) = e^{λh} (z(0) + b̂ ∫₀^h e^{−λσ} dσ + Σ_m E_m ŵ(τ_m) N(τ_m)):
    /// the map of A0 and b alone ([`PieceNodes::free_map`]) plus the last sum's share.
    fn piece<M: PeriodicModel<N> + ?Sized>(
        &self,
        model: &M,
        plan: &PiecePlan<N>,
        k: usize,
        ws: &mut Workspace,
    ) -> Propagation<N> {
        self.variation_at_nodes(model, plan.starts[k], &plan.nodes, ws);
        Self::assemble(&plan.nodes, ws);
        ws.system.solve();
        Self::end_map(&plan.nodes, ws)
    }

    /// φ and E_km ŵ_k at the nodes of the piece from `a`: the support's entries of w
    /// at every node (interpolated, or from the model), then mode by mode along the nodes.
    fn variation_at_nodes<M: PeriodicModel<N> + ?Sized>(
        &self,
        model: &M,
        a: f64,
        nodes: &PieceNodes<N>,
        ws: &mut Workspace,
    ) {
        let (count, support) = (nodes.tau.len(), self.support.len());
        match &self.interpolant {
            Some(p) => {
                for (s, t) in ws.points.iter_mut().zip(&nodes.tau) {
                    *s = ((a + t - self.start) / (self.end - self.start)).clamp(0.0, 1.0);
                }
                p.at_points(&ws.points, &mut ws.columns);
            }
            None => {
                for (m, t) in nodes.tau.iter().enumerate() {
                    let w = self.column(&model.system(self.inside(a + t)).0);
                    for (x, i) in self.support.iter().enumerate() {
                        ws.columns[x * count + m] = w[*i];
                    }
                }
            }
        }
        ws.phi.fill(0.0);
        let (hat_re, hat_im) = (&mut ws.hat_re[..count], &mut ws.hat_im[..count]);
        for (k, share) in nodes.shares.iter().enumerate() {
            hat_re.fill(0.0);
            hat_im.fill(0.0);
            for (d, w) in nodes.duals[k * support..(k + 1) * support].iter().zip(ws.columns.chunks_exact(count)) {
                for ((re, im), w) in hat_re.iter_mut().zip(hat_im.iter_mut()).zip(w) {
                    *re += d.re * w;
                    *im += d.im * w;
                }
            }
            let (e_re, e_im) = (&nodes.ends_re[k * count..(k + 1) * count], &nodes.ends_im[k * count..(k + 1) * count]);
            let (out_re, out_im) =
                (&mut ws.weights_re[k * count..(k + 1) * count], &mut ws.weights_im[k * count..(k + 1) * count]);
            for m in 0..count {
                out_re[m] = e_re[m] * hat_re[m] - e_im[m] * hat_im[m];
                out_im[m] = e_re[m] * hat_im[m] + e_im[m] * hat_re[m];
                ws.phi[m] += share.re * hat_re[m] - share.im * hat_im[m];
            }
        }
        let norm = self.alpha_norm;
        ws.phi.iter_mut().for_each(|p| *p = if norm == 0.0 { 0.0 } else { *p / norm });
    }

    /// [I − M diag φ | R].
    fn assemble(nodes: &PieceNodes<N>, ws: &mut Workspace) {
        let (count, live) = (nodes.tau.len(), nodes.live.len());
        let offset = ws.system.b_offset();
        for i in 0..count {
            let row = ws.system.row_mut(i);
            for ((out, kernel), phi) in row.iter_mut().zip(&nodes.kernel[i * count..(i + 1) * count]).zip(&ws.phi) {
                *out = -kernel * phi;
            }
            row[count..offset].fill(0.0);
            row[i] += 1.0;
            row[offset..offset + live].copy_from_slice(&nodes.free[i * live..(i + 1) * live]);
            row[offset + live..].fill(0.0);
        }
    }

    /// The piece's map from the solved N: the free map plus every mode's end correction.
    fn end_map(nodes: &PieceNodes<N>, ws: &mut Workspace) -> Propagation<N> {
        let (count, live) = (nodes.tau.len(), nodes.live.len());
        let r = nodes.end_vectors.len();
        for m in 0..count {
            for (x, n) in ws.system.x_row(m).iter().enumerate() {
                ws.mesh[x * count + m] = *n;
            }
        }
        for k in 0..r {
            let (re, im) = (&ws.weights_re[k * count..(k + 1) * count], &ws.weights_im[k * count..(k + 1) * count]);
            for x in 0..live {
                let n = &ws.mesh[x * count..(x + 1) * count];
                ws.z_re[k * live + x] = re.iter().zip(n).map(|(a, b)| a * b).sum();
                ws.z_im[k * live + x] = im.iter().zip(n).map(|(a, b)| a * b).sum();
            }
        }
        let mut map = nodes.free_map;
        for (x, c) in nodes.live.iter().enumerate() {
            let mut column = SVector::<f64, N>::zeros();
            for (k, [v_re, v_im]) in nodes.end_vectors.iter().enumerate() {
                column += v_re * ws.z_re[k * live + x] - v_im * ws.z_im[k * live + x];
            }
            if *c < N {
                let mut target = map.phi.column_mut(*c);
                target += column;
            } else {
                map.q += column;
            }
        }
        map
    }
}
