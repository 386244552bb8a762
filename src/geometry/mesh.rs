//! The mesh cycle of a spur pair: which pairs are in contact at a time of the cycle, where they are
//! on the line of action, and the times at which that changes.
//!
//! Time is measured in mesh periods, τ ∈ [0, 1), with τ = 0 when a pair enters contact at A. The
//! pairs in contact at τ are at u_k = T1A + p_b (τ + k), k = 0, 1, 2, …, while u_k < T1E (at most
//! [`MAX_CONTACTS`] for ε_α < 4). [`PairGeometry`] answers the questions of the cycle that do not
//! depend on the load; [`Mesh`] adds an operating point and gives the contact states.
//! Efficiency, friction and dynamics all read the cycle from here.

use super::contact::Sharing;
use super::contact::{ContactPoint, OperatingState};
use super::pair::PairGeometry;

/// The most pairs that can be in contact at once (ε_α < 4).
pub(crate) const MAX_CONTACTS: usize = 4;

impl PairGeometry {
    /// How many pairs are in contact at time τ of the mesh cycle.
    pub fn pairs_at(&self, tau: f64) -> usize {
        if self.is_helical() {
            return self.contact_lines(tau).len();
        }
        (0..MAX_CONTACTS)
            .filter(|k| {
                let u = self.points.a + self.base_pitch * (tau + *k as f64);
                u >= self.points.a && u < self.points.e
            })
            .count()
    }

    /// Times in [0, 1] where a pair reaches E or P, or one of `switch_points` (positions from T1),
    /// with 0 and 1 included and sorted: the switch times of one mesh cycle.
    pub fn cycle_break_times(&self, switch_points: &[f64]) -> Vec<f64> {
        if self.is_helical() {
            return self.helical_break_times(switch_points);
        }
        let p = self.points;
        let mut positions = vec![p.e, p.p];
        positions.extend_from_slice(switch_points);
        let mut times = vec![0.0, 1.0];
        for u in positions {
            for k in 0..MAX_CONTACTS {
                let tau = (u - p.a) / self.base_pitch - k as f64;
                if tau > 0.0 && tau < 1.0 {
                    times.push(tau);
                }
            }
        }
        times.sort_by(f64::total_cmp);
        times
    }

    /// Times in the cycle at which a pair passes the pitch point (where a law may be singular).
    pub fn pitch_times(&self) -> Vec<f64> {
        if self.is_helical() {
            return self.pitch_line_times();
        }
        (0..MAX_CONTACTS)
            .map(|k| (self.points.p - self.points.a) / self.base_pitch - k as f64)
            .filter(|t| *t > 0.0 && *t < 1.0)
            .collect()
    }

    /// The mesh period T = 2π/(ω1 z1) at a pinion speed ω1 (rad/s), in seconds.
    pub fn mesh_period(&self, pinion_speed: f64) -> f64 {
        2.0 * std::f64::consts::PI / (pinion_speed * self.teeth[0] as f64)
    }
}

/// A pair at one operating point: the contact states of the mesh cycle.
#[derive(Debug, Clone, Copy)]
pub struct Mesh<'a> {
    pub pair: &'a PairGeometry,
    pub state: OperatingState,
    /// E' (Pa).
    pub reduced_modulus: f64,
    pub sharing: Sharing<'a>,
}

/// Gauss–Legendre nodes per piece of a contact line in [`Mesh::contacts_at`] (each piece between
/// a line end and the pitch line; graded towards the pitch line). The mean efficiency doubles them
/// to estimate the error of the line integrals ([`crate::efficiency`]).
pub const LINE_NODES: usize = 8;

/// The contacts at one instant: for a spur pair the pairs in contact, kept on the stack because the
/// mean-efficiency integrands build them at every quadrature node; for a helical pair the
/// quadrature points along the contact lines, each carrying its share of the normal load
/// (w dl / F_bn, so that Σ over the points of share × g(u) is ∫ g w dl / F_bn).
#[derive(Debug, Clone)]
// The stack variant is the hot one (spur sweeps build it at every quadrature node): not boxed.
#[allow(clippy::large_enum_variant)]
pub enum Contacts {
    Pairs([ContactPoint; MAX_CONTACTS], usize),
    Lines(Vec<ContactPoint>),
}

impl std::ops::Deref for Contacts {
    type Target = [ContactPoint];
    fn deref(&self) -> &[ContactPoint] {
        match self {
            Contacts::Pairs(items, len) => &items[..*len],
            Contacts::Lines(v) => v,
        }
    }
}

impl<'a> IntoIterator for &'a Contacts {
    type Item = &'a ContactPoint;
    type IntoIter = std::slice::Iter<'a, ContactPoint>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

/// How many pieces [`Mesh::line_contacts`] cuts a line spanning [lo, hi] along u into: two when it
/// crosses the pitch point, one otherwise (each piece holds `nodes` quadrature points).
pub(crate) fn line_pieces(lo: f64, hi: f64, pitch: f64) -> usize {
    if lo < pitch && pitch < hi {
        2
    } else {
        1
    }
}

/// Nodes and weights of the [`LINE_NODES`]-point and doubled Gauss–Legendre rules on [0, 1].
fn line_rule(nodes: usize) -> &'static (Vec<f64>, Vec<f64>) {
    use std::sync::OnceLock;
    static RULES: [OnceLock<(Vec<f64>, Vec<f64>)>; 3] = [OnceLock::new(), OnceLock::new(), OnceLock::new()];
    let slot = match nodes {
        n if n == LINE_NODES => 0,
        n if n == 2 * LINE_NODES => 1,
        _ => 2,
    };
    RULES[slot].get_or_init(|| crate::numerics::quadrature::gauss_legendre(nodes))
}

impl Mesh<'_> {
    /// The contact state at `u` (from T1). For a helical pair, under the mean load per unit line
    /// length F_bn / L̄ (the load at u varies with L(t)); `pairs_in_contact` is then 0.
    pub fn contact_at(&self, u: f64) -> ContactPoint {
        if self.pair.is_helical() {
            return self.mean_line_contact(u, u - self.pair.points.p);
        }
        self.pair.contact_at(u, &self.state, self.reduced_modulus, self.sharing)
    }

    fn mean_line_contact(&self, u: f64, s: f64) -> ContactPoint {
        let g = self.pair;
        let length = g.mean_contact_length();
        let (w, share) = match self.sharing {
            // The mean mesh's line load at u (LoadSharing::mean_deflection).
            Sharing::Stiffness(model) => {
                let force = self.transverse_force();
                let w = model.line_density(u - g.points.a, model.mean_deflection(force));
                let f_bn = g.normal_load(&self.state);
                (w, if f_bn > 0.0 { w * g.face_width / f_bn } else { 0.0 })
            }
            _ => (g.normal_load(&self.state) / length, g.face_width / length),
        };
        g.contact_with_load(u, s, &self.state, self.reduced_modulus, w, [share, share], 0)
    }

    fn transverse_force(&self) -> f64 {
        self.pair.sharing_force(&self.state)
    }

    /// The contact state at distance `s` from the pitch point, with `s` exact (for integrands near P).
    pub fn contact_at_offset(&self, s: f64) -> ContactPoint {
        let g = self.pair;
        let u = g.points.p + s;
        if g.is_helical() {
            return self.mean_line_contact(u, s);
        }
        g.contact_exact(u, s, &self.state, self.reduced_modulus, self.sharing, g.pairs_in_contact(u))
    }

    /// The contacts at time τ of the mesh cycle (τ in [0, 1)). Each carries its force share 1/n of
    /// the pairs found at τ, so that the shares always add up to one.
    pub fn contacts_at(&self, tau: f64) -> Contacts {
        self.contacts_near_pitch(tau, None)
    }

    /// As [`Mesh::contacts_at`], with `d` = τ − τ_P known exactly for the pair nearest the pitch
    /// point (when known): that pair's s = p_b d.
    pub fn contacts_near_pitch(&self, tau: f64, d: Option<f64>) -> Contacts {
        if self.pair.is_helical() {
            return self.line_contacts(tau, LINE_NODES);
        }
        let mut items = [ContactPoint::default(); MAX_CONTACTS];
        let n = self.fill_pair_contacts(tau, d, &mut items);
        Contacts::Pairs(items, n)
    }

    /// The pairs in contact of a spur pair at τ (as [`Mesh::contacts_near_pitch`]) written into
    /// `items`, their count returned: the mean-efficiency integrands reuse one buffer at every
    /// quadrature node instead of building and moving a [`Contacts`] (a third of a sweep's time went
    /// to zeroing and copying those arrays).
    pub fn fill_pair_contacts(&self, tau: f64, d: Option<f64>, items: &mut [ContactPoint; MAX_CONTACTS]) -> usize {
        let g = self.pair;
        let mut positions = [0.0; MAX_CONTACTS];
        let mut n = 0;
        for k in 0..MAX_CONTACTS {
            let u = g.points.a + g.base_pitch * (tau + k as f64);
            if u >= g.points.a && u < g.points.e {
                positions[n] = u;
                n += 1;
            }
        }
        let exact = d.map(|d| g.base_pitch * d);
        // By stiffness, the pairs' shares solved once for the instant.
        let mut shares = [0.0; MAX_CONTACTS];
        if let Sharing::Stiffness(model) = self.sharing {
            let force = self.transverse_force();
            let q = positions.map(|u| u - g.points.a);
            model.spur_loads(&q[..n], force, &mut shares);
            shares.iter_mut().for_each(|f| *f /= force);
        }
        for (j, (slot, u)) in items.iter_mut().zip(&positions[..n]).enumerate() {
            let s = u - g.points.p;
            let s = exact.filter(|e| (s - e).abs() < 1e-6 * g.base_pitch).unwrap_or(s);
            *slot = match self.sharing {
                Sharing::Stiffness(_) => {
                    let w = shares[j] * g.normal_load(&self.state) / g.face_width;
                    g.contact_with_load(*u, s, &self.state, self.reduced_modulus, w, [shares[j]; 2], n)
                }
                _ => g.contact_exact(*u, s, &self.state, self.reduced_modulus, self.sharing, n),
            };
        }
        n
    }

    /// The quadrature points along the contact lines of a helical pair at τ, `nodes` Gauss–Legendre
    /// points per piece. Each line is cut at the pitch line; on a piece that touches it the nodes
    /// are graded towards it (u = T1P + (u_end − T1P) v³), which keeps the rule exact for the
    /// piecewise-polynomial integrands of the Coulomb laws and makes the integrable singularities
    /// of laws that diverge at P harmless. Load per unit length w = F_bn / L(τ) (constant stiffness
    /// density, He & Singh assumption 2); each point's force share is w dl / F_bn = dl / L.
    pub fn line_contacts(&self, tau: f64, nodes: usize) -> Contacts {
        let g = self.pair;
        let lines = g.contact_lines(tau);
        let length: f64 = lines.iter().map(|l| l.length).sum();
        let w = g.normal_load(&self.state) / length;
        let load_share = g.face_width / length;
        let (x, wt) = line_rule(nodes);
        let pitch = g.points.p;
        let per_u = 1.0 / g.base_helix_angle.sin() / length;
        let mut out = Vec::with_capacity(lines.len() * 2 * nodes);
        // The equal line load at the force the shares are read at (w, or its value at 1 N at zero torque).
        let w_ref = self.transverse_force() / (g.base_helix_angle.cos() * length);
        // By stiffness: the gap δ of this instant, from any line's mid-face position (u at z = 0).
        let stiffness = match self.sharing {
            Sharing::Stiffness(model) => lines.iter().next().map(|l| {
                let mid = l.u[0] - l.z[0] * g.base_helix_angle.tan() - g.points.a;
                (model, model.at(mid, self.transverse_force()).deflection)
            }),
            _ => None,
        };
        for line in lines.iter() {
            let (lo, hi) = (line.u[0].min(line.u[1]), line.u[0].max(line.u[1]));
            let mut push = |s: f64, dl: f64| {
                // By stiffness the line load at s relative to the equal one, w_s/w.
                let r =
                    stiffness.map_or(1.0, |(model, delta)| model.line_density(pitch + s - g.points.a, delta) / w_ref);
                let c = g.contact_with_load(
                    pitch + s,
                    s,
                    &self.state,
                    self.reduced_modulus,
                    r * w,
                    [r * load_share, r * dl],
                    lines.len(),
                );
                out.push(c);
            };
            // Pieces cut at P (and, by stiffness, where the relief bends the line load), each graded
            // towards its end nearer P: s = s_near + (s_far − s_near) v³, ds = 3 |h| v² dv.
            let mut cuts = vec![lo, hi];
            if line_pieces(lo, hi, pitch) == 2 {
                cuts.push(pitch);
            }
            if let Some((model, delta)) = stiffness {
                cuts.extend(model.kinks(delta).into_iter().map(|q| q + g.points.a).filter(|u| *u > lo && *u < hi));
            }
            cuts.sort_by(f64::total_cmp);
            for piece in cuts.windows(2) {
                let (near, far) = if piece[0] >= pitch { (piece[0], piece[1]) } else { (piece[1], piece[0]) };
                let h = far - near;
                for (v, wv) in x.iter().zip(wt) {
                    push(near - pitch + h * v * v * v, 3.0 * h.abs() * v * v * wv * per_u);
                }
            }
        }
        Contacts::Lines(out)
    }
}
