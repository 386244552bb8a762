//! The plane of action of a helical pair and its contact lines (He & Singh §2, eqs 11–12, Fig. 2).
//!
//! The plane of action is spanned by u, the transverse line of action measured from T1, and z, the
//! face width, z ∈ [−b/2, b/2]. Contact lines are straight, inclined by the base helix angle β_b to
//! the axial direction (dl = du / sin β_b = dz / cos β_b), one transverse base pitch p_bt apart, and
//! move along u at r_b1 ω1. Line k has its z = +b/2 end at x_k(τ) = T1A + (τ + k) p_bt (eq 11),
//! so u(z) = x_k − (b/2 − z) tan β_b; its loaded part is its intersection with the path of contact
//! [T1A, T1E] × [−b/2, b/2]. Time τ is in mesh periods, τ = 0 when the leading end of a line enters
//! at A. A line's two ends lie b tan β_b apart along u (the *lead* of the line, ε_β p_bt).
//!
//! The breaks of one mesh cycle are the times at which a line end passes a corner of the path
//! (x_k ∈ {T1A, T1E, T1A + b tan β_b, T1E + b tan β_b}) or, with friction, the pitch line
//! (x_k ∈ {T1P, T1P + b tan β_b}): they are found for any geometry (He & Singh's 8 zones and 6
//! regions are the NASA-ART pair's case). For β = 0 a line is one spur contact (u = x_k over the
//! whole face width) and everything reduces to the spur mesh cycle.

use super::pair::PairGeometry;

/// The most contact lines at once.
pub(crate) const MAX_LINES: usize = 8;

/// The loaded part of one contact line at an instant.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct ContactLine {
    /// k: the line entered k mesh periods before the one entering at τ = 0.
    pub index: usize,
    /// z at its two ends, smaller first (m).
    pub z: [f64; 2],
    /// u at those ends (m from T1); equal for a spur pair.
    pub u: [f64; 2],
    /// Length of the loaded part (m).
    pub length: f64,
}

/// The lines in contact at an instant, on the stack.
#[derive(Debug, Clone, Copy)]
pub struct LinesAt {
    items: [ContactLine; MAX_LINES],
    len: usize,
}

impl std::ops::Deref for LinesAt {
    type Target = [ContactLine];
    fn deref(&self) -> &[ContactLine] {
        &self.items[..self.len]
    }
}

impl PairGeometry {
    /// b tan β_b: how far apart along u the two ends of a contact line lie (0 for spur).
    pub fn line_lead(&self) -> f64 {
        if self.is_helical() {
            self.face_width * self.base_helix_angle.tan()
        } else {
            0.0
        }
    }

    /// x_k(τ) = T1A + (τ + k) p_bt, the u of line k's z = +b/2 end (He & Singh eq 11).
    pub fn line_end(&self, k: usize, tau: f64) -> f64 {
        self.points.a + self.base_pitch * (tau + k as f64)
    }

    /// The loaded contact lines at time τ ∈ [0, 1) (He & Singh eq 12, for any geometry).
    pub fn contact_lines(&self, tau: f64) -> LinesAt {
        let p = self.points;
        let half = 0.5 * self.face_width;
        let mut out = LinesAt { items: [ContactLine::default(); MAX_LINES], len: 0 };
        let lead = self.line_lead();
        for k in 0..MAX_LINES {
            let x = self.line_end(k, tau);
            if lead == 0.0 {
                if x >= p.a && x < p.e {
                    out.items[out.len] = ContactLine { index: k, z: [-half, half], u: [x, x], length: self.face_width };
                    out.len += 1;
                }
                continue;
            }
            let tan = self.base_helix_angle.tan();
            // u(z) = x − (b/2 − z) tan β_b: u = T1A at z_A, u = T1E at z_E.
            let z_lo = (half - (x - p.a) / tan).max(-half);
            let z_hi = (half - (x - p.e) / tan).min(half);
            if z_hi > z_lo {
                let u = |z: f64| x - (half - z) * tan;
                let length = (z_hi - z_lo) / self.base_helix_angle.cos();
                out.items[out.len] = ContactLine { index: k, z: [z_lo, z_hi], u: [u(z_lo), u(z_hi)], length };
                out.len += 1;
            }
        }
        out
    }

    /// Total length of the contact lines L(τ) (m).
    pub fn contact_length(&self, tau: f64) -> f64 {
        self.contact_lines(tau).iter().map(|l| l.length).sum()
    }

    /// dL/dτ (m per mesh period): each line end moving inside the face (not on a face edge)
    /// lengthens or shortens its line at p_bt / sin β_b per period. 0 for a spur pair.
    pub fn contact_length_rate(&self, tau: f64) -> f64 {
        if !self.is_helical() {
            return 0.0;
        }
        let half = 0.5 * self.face_width;
        let tol = 1e-12 * self.face_width;
        let rate = self.base_pitch / self.base_helix_angle.sin();
        let mut out = 0.0;
        for l in self.contact_lines(tau).iter() {
            // The end at smaller z is on u = T1A (moving away: the line grows) unless on the edge;
            // the end at larger z is on u = T1E (the line shrinks) unless on the edge.
            if l.z[0] > -half + tol {
                out += rate;
            }
            if l.z[1] < half - tol {
                out -= rate;
            }
        }
        out
    }

    /// The mean of L(τ) over a mesh cycle, L̄ = ε_α b / cos β_b (m): each line sweeps the path of
    /// contact (area AE · b) in one pass, at p_bt per period.
    pub fn mean_contact_length(&self) -> f64 {
        self.contact_ratio * self.face_width / self.base_helix_angle.cos()
    }

    /// Length of the contact lines on the approach (u < T1P) and recess (u > T1P) sides at τ (m).
    pub fn contact_length_by_side(&self, tau: f64) -> [f64; 2] {
        let pitch = self.points.p;
        let mut out = [0.0; 2];
        for l in self.contact_lines(tau).iter() {
            if l.u[0] == l.u[1] {
                out[usize::from(l.u[0] >= pitch)] += l.length;
                continue;
            }
            let (lo, hi) = (l.u[0].min(l.u[1]), l.u[0].max(l.u[1]));
            let approach = ((pitch.min(hi) - lo).max(0.0)) / (hi - lo);
            out[0] += approach * l.length;
            out[1] += (1.0 - approach) * l.length;
        }
        out
    }

    /// Positions of the contact-line ends at which the cycle changes form: the corners of the path
    /// (T1A and T1E at either end of the face) and the given positions (the pitch point, law
    /// switches) at either end. For a spur pair (lead 0) just the given positions and T1E.
    fn line_end_positions(&self, positions: &[f64]) -> Vec<f64> {
        let lead = self.line_lead();
        let mut out = vec![self.points.e];
        out.extend_from_slice(positions);
        if lead > 0.0 {
            let base = out.clone();
            out.push(self.points.a + lead);
            out.extend(base.iter().map(|x| x + lead));
        }
        out
    }

    /// The times in (0, 1) at which the z = +b/2 end of some line reaches one of `positions`, sorted
    /// and without duplicates.
    fn times_at(&self, positions: impl IntoIterator<Item = f64>) -> Vec<f64> {
        let mut times = Vec::new();
        for u in positions {
            for k in 0..MAX_LINES {
                let tau = (u - self.points.a) / self.base_pitch - k as f64;
                if tau > 1e-14 && tau < 1.0 - 1e-14 {
                    times.push(tau);
                }
            }
        }
        times.sort_by(f64::total_cmp);
        times.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
        times
    }

    /// Times in (0, 1) at which an end of a line passes the pitch line (x_k = T1P or T1P + b tan β_b):
    /// where the mean-efficiency integrand of a law singular at P has a singular derivative.
    pub fn pitch_line_times(&self) -> Vec<f64> {
        self.times_at([self.points.p, self.points.p + self.line_lead()])
    }

    /// The break times of one mesh cycle for a helical pair: 0, 1, and every time a line end passes
    /// a corner of the path or one of `switch_points` (the pitch point is always included), sorted
    /// and without duplicates.
    pub fn helical_break_times(&self, switch_points: &[f64]) -> Vec<f64> {
        let mut positions = vec![self.points.p];
        positions.extend_from_slice(switch_points);
        let mut times = vec![0.0];
        times.extend(self.times_at(self.line_end_positions(&positions)));
        times.push(1.0);
        times
    }
}
