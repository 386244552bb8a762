//! Load sharing by compatibility of deflections, with tip relief, and the static transmission
//! error (physics: README, "Mesh stiffness from the teeth").
//!
//! The pairs in contact all close the same gap δ along the line of action; pair j, whose teeth are
//! relieved by e_j at its contact, carries F_j = k_j max(0, δ − e_j), and δ solves Σ F_j = F_bn,
//! F_bn = T_p / r_b1 (along the transverse line of action). For a spur pair that sum is piecewise
//! linear in δ and is solved exactly (the pairs taken in the order of their relief); without relief
//! δ = F_bn/K and w_j = k_j/K. For a helical pair each line's load is the integral over its
//! transverse positions q of k_w(q) max(0, δ − e(q)) dq / tan β_b, in closed form (e is a
//! polynomial of degree ≤ 2 between the relief starts, cut where e = δ, against the series of
//! ∫ q^p k_w), and δ is found by Brent's method to 1e-15 of its size. δ is
//! the static transmission error (STE), positive when the wheel lags.
//!
//! Tip relief of one gear: amount C_a at its tip, length L_a along the line of action from where
//! its tip circle meets the path (the pinion's at E, s = g_α; the wheel's at A, s = 0); at u from
//! the start of the relief toward the tip, e = C_a u/L_a (linear) or C_a (u/L_a)² (parabolic).

use serde::{Deserialize, Serialize};

use super::pair_stiffness::PairStiffness;
use crate::numerics::roots::{bracketed_roots, brent};

/// How the relief grows toward the tip.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ReliefShape {
    Linear,
    Parabolic,
}

impl ReliefShape {
    pub fn name(self) -> &'static str {
        match self {
            ReliefShape::Linear => "linear",
            ReliefShape::Parabolic => "parabolic",
        }
    }
}

/// The tip relief of one gear (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TipRelief {
    pub amount: f64,
    pub length: f64,
    pub shape: ReliefShape,
}

impl TipRelief {
    /// e at u from the start of the relief toward the tip (0 before it).
    pub fn at(&self, u: f64) -> f64 {
        if u <= 0.0 {
            return 0.0;
        }
        let t = (u / self.length).min(1.0);
        match self.shape {
            ReliefShape::Linear => self.amount * t,
            ReliefShape::Parabolic => self.amount * t * t,
        }
    }

    /// e as a polynomial in q, c₀ + c₁ q + c₂ q², where u = sign (q − start).
    fn polynomial(&self, start: f64, sign: f64) -> [f64; 3] {
        // u = sign q − sign start.
        let (a, b) = (sign / self.length, -sign * start / self.length);
        match self.shape {
            ReliefShape::Linear => [self.amount * b, self.amount * a, 0.0],
            ReliefShape::Parabolic => [self.amount * b * b, 2.0 * self.amount * a * b, self.amount * a * a],
        }
    }
}

/// The reliefs of both teeth of a pair: [pinion, wheel].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Reliefs(pub [Option<TipRelief>; 2]);

impl Reliefs {
    /// e(q) = e₁ + e₂ at position q from A on a path of length g_α.
    pub fn at(&self, path: f64, q: f64) -> f64 {
        let [p, w] = self.0;
        p.map_or(0.0, |r| r.at(q - (path - r.length))) + w.map_or(0.0, |r| r.at(r.length - q))
    }

    /// Where a relief starts (positions from A).
    pub fn starts(&self, path: f64) -> Vec<f64> {
        let [p, w] = self.0;
        p.map(|r| path - r.length).into_iter().chain(w.map(|r| r.length)).collect()
    }

    /// e(q) as c₀ + c₁ q + c₂ q² on a piece around q (no relief starts inside the piece).
    fn polynomial_near(&self, path: f64, q: f64) -> [f64; 3] {
        let [p, w] = self.0;
        let mut c = [0.0; 3];
        let mut add = |r: &TipRelief, start: f64, sign: f64| {
            if sign * (q - start) > 0.0 {
                let d = r.polynomial(start, sign);
                (0..3).for_each(|i| c[i] += d[i]);
            }
        };
        if let Some(r) = p {
            add(&r, path - r.length, 1.0);
        }
        if let Some(r) = w {
            add(&r, r.length, -1.0);
        }
        c
    }

    pub fn is_empty(&self) -> bool {
        self.0.iter().all(Option::is_none)
    }
}

/// The pairs' loads at one position of the cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct Shared {
    /// δ, the static transmission error along the line of action (m).
    pub deflection: f64,
    /// (position, load F_j in N) of every pair in contact, the reference pair among them.
    pub loads: Vec<(f64, f64)>,
}

impl Shared {
    /// The load of the pair at `s` (0 when it is not in contact).
    pub fn load_of(&self, s: f64) -> f64 {
        self.loads.iter().find(|(q, _)| (q - s).abs() < 1e-12).map_or(0.0, |(_, f)| *f)
    }
}

/// The most spur pairs in contact at once that [`LoadSharing::spur_loads`] takes (ε_α < 8).
pub(crate) const MAX_PAIRS: usize = 8;

/// A pair's stiffness with its reliefs: the load sharing at any torque.
#[derive(Debug, Clone)]
pub struct LoadSharing {
    pub stiffness: PairStiffness,
    pub reliefs: Reliefs,
}

impl LoadSharing {
    /// The sharing of the force `force` (N, along the line of action) when a pair is at `s`.
    pub fn at(&self, s: f64, force: f64) -> Shared {
        let k = &self.stiffness;
        let positions = k.pairs_with(s);
        if self.reliefs.is_empty() {
            let total: f64 = positions.iter().map(|q| k.pair_at(*q)).sum();
            let delta = force / total;
            return Shared {
                deflection: delta,
                loads: positions.iter().map(|q| (*q, k.pair_at(*q) * delta)).collect(),
            };
        }
        if !k.is_helical() {
            return self.spur_with_relief(&positions, force);
        }
        let total: f64 = positions.iter().map(|q| k.pair_at(*q)).sum();
        let e_max: f64 = self.reliefs.0.iter().flatten().map(|r| r.amount).sum();
        let lo = force / total;
        let load = |d: f64| {
            positions.iter().map(|q| self.line_load_and_slope(*q, d)).fold((0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1))
        };
        let delta = gap_for(load, force, lo, lo + e_max);
        Shared { deflection: delta, loads: positions.iter().map(|q| (*q, self.line_load(*q, delta))).collect() }
    }

    fn spur_with_relief(&self, positions: &[f64], force: f64) -> Shared {
        let mut loads = [0.0; MAX_PAIRS];
        let deflection = self.spur_loads(positions, force, &mut loads);
        Shared { deflection, loads: positions.iter().zip(loads).map(|(q, f)| (*q, f)).collect() }
    }

    /// The share F_j/F of the spur pair at `q` (from A) under `force` (N), with the pairs in
    /// contact beside it at q ± k p_b; allocation-free, as [`LoadSharing::spur_loads`].
    pub fn spur_share(&self, q: f64, force: f64) -> f64 {
        let k = &self.stiffness;
        let (pb, path) = (k.base_pitch, k.path);
        let first = q - (q / pb).floor() * pb;
        let (mut positions, mut n, mut at) = ([0.0; MAX_PAIRS], 0, None);
        for j in 0..MAX_PAIRS {
            let x = first + j as f64 * pb;
            if x >= path {
                break;
            }
            // The pair at q itself, exactly (first + j p_b may differ from q in the last bit).
            let x = if (x - q).abs() < 1e-9 * pb { q } else { x };
            if x == q {
                at = Some(n);
            }
            positions[n] = x;
            n += 1;
        }
        let Some(at) = at else { return 0.0 };
        let mut loads = [0.0; MAX_PAIRS];
        self.spur_loads(&positions[..n], force, &mut loads);
        loads[at] / force
    }

    /// The loads F_j (N) of the spur pairs at `positions` (from A: every pair in contact at one
    /// instant, at most `MAX_PAIRS`) under `force`, written into `loads`; returns δ. Σ F_j is
    /// piecewise linear in δ: the pairs taken in the order of their relief, δ = (F + Σ k e)/Σ k over
    /// the pairs loaded so far until it stays below the next pair's relief. Allocation-free: the
    /// efficiency's integrands call it at every quadrature node.
    pub fn spur_loads(&self, positions: &[f64], force: f64, loads: &mut [f64]) -> f64 {
        let k = &self.stiffness;
        let n = positions.len().min(MAX_PAIRS);
        let (mut kj, mut ej, mut order) = ([0.0; MAX_PAIRS], [0.0; MAX_PAIRS], [0usize; MAX_PAIRS]);
        for i in 0..n {
            kj[i] = k.pair_at(positions[i]);
            ej[i] = self.reliefs.at(k.path, positions[i]);
            order[i] = i;
        }
        order[..n].sort_by(|a, b| ej[*a].total_cmp(&ej[*b]));
        let (mut sum_k, mut sum_ke, mut delta) = (0.0, 0.0, 0.0);
        for (rank, &i) in order[..n].iter().enumerate() {
            sum_k += kj[i];
            sum_ke += kj[i] * ej[i];
            delta = (force + sum_ke) / sum_k;
            if order[..n].get(rank + 1).is_none_or(|next| delta <= ej[*next]) {
                break;
            }
        }
        for i in 0..n {
            loads[i] = kj[i] * (delta - ej[i]).max(0.0);
        }
        delta
    }

    /// The load (N) of the helical line whose mid-face is at s, at a gap δ.
    fn line_load(&self, s: f64, delta: f64) -> f64 {
        self.line_load_and_slope(s, delta).0
    }

    /// The load (N) of the helical line whose mid-face is at s at a gap δ, and its slope dF/dδ
    /// (N/m): the stiffness of the part of the line in contact.
    fn line_load_and_slope(&self, s: f64, delta: f64) -> (f64, f64) {
        let k = &self.stiffness;
        let (lo, hi) = ((s - 0.5 * k.lead).max(0.0), (s + 0.5 * k.lead).min(k.path));
        let (load, slope) = self.path_load(lo, hi, delta);
        (k.face_width / k.lead * load, k.face_width / k.lead * slope)
    }

    /// The transverse load per unit face width at q (from A) under a gap δ: k_w(q) max(0, δ − e(q))
    /// (N/m; zero off the path). Along a helical contact line it is also the normal load per unit
    /// length of the line (the 1/cos β_b of each cancels).
    pub fn line_density(&self, q: f64, delta: f64) -> f64 {
        let k = &self.stiffness;
        if !(0.0..=k.path).contains(&q) {
            return 0.0;
        }
        k.per_width(q) * (delta - self.reliefs.at(k.path, q)).max(0.0)
    }

    /// The gap δ̄ of the mean mesh: (b/p_b) ∫₀^g_α k_w max(0, δ̄ − e) dq = `force` (N). Without relief
    /// δ̄ = F/K̄. A helical pair's mean contact at a position (the mean |μ| along the path) carries
    /// [`LoadSharing::line_density`] at δ̄, as equal sharing's carries F_bn/L̄.
    pub fn mean_deflection(&self, force: f64) -> f64 {
        let k = &self.stiffness;
        let scale = k.face_width / k.base_pitch;
        let load = |d: f64| {
            let (f, slope) = self.path_load(0.0, k.path, d);
            (scale * f, scale * slope)
        };
        // Without relief the load is δ K̄: the root, and a lower bound of it with relief.
        let lo = force / (k.face_width / k.base_pitch * k.weighted_integral(0.0, k.path)[0]);
        if self.reliefs.is_empty() {
            return lo;
        }
        let e_max: f64 = self.reliefs.0.iter().flatten().map(|r| r.amount).sum();
        gap_for(load, force, lo, lo + e_max)
    }

    /// The instants τ ∈ (0, 1) of a spur pair's mesh cycle (τ = 0: a pair enters at A) where a
    /// pair's load bends under `force` (N): it crosses the start of a relief, or lifts off (touches
    /// down) where δ(τ) = e_j. The crossings are exact; the lift-offs are located by Brent's method
    /// on (δ − e_j)/e_max between 64 samples of the pair's time in contact, to 1e-13 of the cycle.
    /// The efficiency integrates between them, as between the cycle's other breaks.
    pub fn spur_kink_times(&self, force: f64) -> Vec<f64> {
        let k = &self.stiffness;
        let e_max: f64 = self.reliefs.0.iter().flatten().map(|r| r.amount).sum();
        if self.reliefs.is_empty() || k.is_helical() {
            return Vec::new();
        }
        let (pb, path) = (k.base_pitch, k.path);
        let mut out = Vec::new();
        for start in self.reliefs.starts(path) {
            out.extend((0..MAX_PAIRS).map(|j| start / pb - j as f64).filter(|t| *t > 0.0 && *t < 1.0));
        }
        let deflection = |tau: f64| {
            let mut q = [0.0; MAX_PAIRS];
            let n = (0..MAX_PAIRS).map(|j| (tau + j as f64) * pb).take_while(|x| *x < path).count();
            (0..n).for_each(|j| q[j] = (tau + j as f64) * pb);
            self.spur_loads(&q[..n], force, &mut [0.0; MAX_PAIRS])
        };
        for j in 0..MAX_PAIRS {
            let end = (path / pb - j as f64).min(1.0);
            if end <= 0.0 {
                break;
            }
            let nodes: Vec<f64> = (0..=64).map(|i| end * i as f64 / 64.0 * (1.0 - 1e-12)).collect();
            let gap = |tau: f64| (deflection(tau) - self.reliefs.at(path, (tau + j as f64) * pb)) / e_max;
            out.extend(bracketed_roots(gap, &nodes, 1e-13).into_iter().filter(|t| *t > 0.0 && *t < 1.0));
        }
        out.sort_by(f64::total_cmp);
        out
    }

    /// Where the line load k_w max(0, δ − e) has a kink under a gap δ (positions from A, inside the
    /// path): the starts of the reliefs and where a relief reaches δ (the load lifts off there).
    pub fn kinks(&self, delta: f64) -> Vec<f64> {
        let path = self.stiffness.path;
        let mut edges = vec![0.0, path];
        edges.extend(self.reliefs.starts(path).into_iter().filter(|q| *q > 0.0 && *q < path));
        edges.sort_by(f64::total_cmp);
        let mut out: Vec<f64> = edges[1..edges.len() - 1].to_vec();
        for w in edges.windows(2) {
            let [c0, c1, c2] = self.reliefs.polynomial_near(path, 0.5 * (w[0] + w[1]));
            out.extend(quadratic_roots(c2, c1, c0 - delta).into_iter().filter(|r| *r > w[0] && *r < w[1]));
        }
        out.sort_by(f64::total_cmp);
        out
    }

    /// ∫ k_w(q) max(0, δ − e(q)) dq over [lo, hi] ⊂ [0, g_α], in closed form (N/m · m).
    fn path_load(&self, lo: f64, hi: f64, delta: f64) -> (f64, f64) {
        let k = &self.stiffness;
        if hi <= lo {
            return (0.0, 0.0);
        }
        let mut breaks = vec![lo, hi];
        breaks.extend(self.reliefs.starts(k.path).into_iter().filter(|b| *b > lo && *b < hi));
        breaks.sort_by(f64::total_cmp);
        let (mut total, mut slope) = (0.0, 0.0);
        for w in breaks.windows(2) {
            // On the piece δ − e(q) = d₀ − c₁ q − c₂ q²; integrate it against k_w where positive.
            let [c0, c1, c2] = self.reliefs.polynomial_near(k.path, 0.5 * (w[0] + w[1]));
            let mut cuts = vec![w[0], w[1]];
            cuts.extend(quadratic_roots(c2, c1, c0 - delta).into_iter().filter(|r| *r > w[0] && *r < w[1]));
            cuts.sort_by(f64::total_cmp);
            for piece in cuts.windows(2) {
                let m = 0.5 * (piece[0] + piece[1]);
                if delta - (c0 + c1 * m + c2 * m * m) > 0.0 {
                    let [i0, i1, i2] = k.weighted_integral(piece[0], piece[1]);
                    total += (delta - c0) * i0 - c1 * i1 - c2 * i2;
                    slope += i0;
                }
            }
        }
        (total, slope)
    }
}

/// The gap δ at which `load(δ)` = (load N, its slope dN/dδ) carries `force`, between `lo` (the gap
/// without relief: a lower bound) and `hi`. The load is convex and increasing in δ (each part of a
/// line joins at its own relief and then carries k_w (δ − e)), so Newton's method from `lo`
/// overshoots once and then converges from above, quadratically (four to six steps instead of
/// Brent's dozen); kept within [lo, hi], and Brent's method if it has not converged in 50 steps.
fn gap_for(load: impl Fn(f64) -> (f64, f64), force: f64, lo: f64, hi: f64) -> f64 {
    let tol = 1e-15 * hi;
    let mut d = lo;
    for _ in 0..50 {
        let (f, slope) = load(d);
        if slope <= 0.0 {
            break;
        }
        let next = (d + (force - f) / slope).clamp(lo, hi);
        if (next - d).abs() <= tol {
            return next;
        }
        d = next;
    }
    brent(|d| load(d).0 - force, lo, hi, tol)
}

/// Real roots of a x² + b x + c (a linear or constant one when a or b vanish).
fn quadratic_roots(a: f64, b: f64, c: f64) -> Vec<f64> {
    if a == 0.0 {
        return if b == 0.0 { Vec::new() } else { vec![-c / b] };
    }
    let d = b * b - 4.0 * a * c;
    if d < 0.0 {
        return Vec::new();
    }
    // The stable pair: q = −(b + sign(b)√d)/2, roots q/a and c/q.
    let q = -0.5 * (b + b.signum() * d.sqrt());
    if q == 0.0 {
        return vec![0.0];
    }
    vec![q / a, c / q]
}
