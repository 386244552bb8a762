//! The mesh cycle of a spur pair: which pairs are in contact at a time of the cycle, where they are
//! on the line of action, and the times at which that changes.
//!
//! Time is measured in mesh periods, τ ∈ [0, 1), with τ = 0 when a pair enters contact at A. The
//! pairs in contact at τ are at u_k = T1A + p_b (τ + k), k = 0, 1, 2, …, while u_k < T1E (at most
//! [`MAX_CONTACTS`] for ε_α < 4). [`PairGeometry`] answers the questions of the cycle that do not
//! depend on the load; [`Mesh`] adds an operating point and gives the contact states.
//! Efficiency, friction and dynamics all read the cycle from here.

use super::contact::Sharing;
use super::{ContactPoint, OperatingState, PairGeometry};

/// The most pairs that can be in contact at once (ε_α < 4).
pub const MAX_CONTACTS: usize = 4;

impl PairGeometry {
    /// How many pairs are in contact at time τ of the mesh cycle.
    pub fn pairs_at(&self, tau: f64) -> usize {
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
    pub sharing: Sharing,
}

/// The pairs in contact at one instant, kept on the stack because the mean-efficiency integrands
/// build them at every quadrature node.
#[derive(Debug, Clone, Copy)]
pub struct Contacts {
    items: [ContactPoint; MAX_CONTACTS],
    len: usize,
}

impl std::ops::Deref for Contacts {
    type Target = [ContactPoint];
    fn deref(&self) -> &[ContactPoint] {
        &self.items[..self.len]
    }
}

impl<'a> IntoIterator for &'a Contacts {
    type Item = &'a ContactPoint;
    type IntoIter = std::slice::Iter<'a, ContactPoint>;
    fn into_iter(self) -> Self::IntoIter {
        self.items[..self.len].iter()
    }
}

impl Mesh<'_> {
    /// The contact state at `u` (from T1).
    pub fn contact_at(&self, u: f64) -> ContactPoint {
        self.pair.contact_at(u, &self.state, self.reduced_modulus, self.sharing)
    }

    /// The contact state at distance `s` from the pitch point, with `s` exact (for integrands near P).
    pub fn contact_at_offset(&self, s: f64) -> ContactPoint {
        let g = self.pair;
        let u = g.points.p + s;
        g.contact_exact(u, s, &self.state, self.reduced_modulus, self.sharing, g.pairs_in_contact(u))
    }

    /// The contacts at time τ of the mesh cycle (τ in [0, 1)). Each carries its force share 1/n of
    /// the pairs found at τ, so that the shares always add up to one.
    pub fn contacts_at(&self, tau: f64) -> Contacts {
        self.contacts_near_pitch(tau, f64::NAN)
    }

    /// As [`Mesh::contacts_at`], with `d` = τ − τ_P known exactly for the pair nearest the pitch
    /// point (NaN when not known): that pair's s = p_b d.
    pub fn contacts_near_pitch(&self, tau: f64, d: f64) -> Contacts {
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
        let exact = g.base_pitch * d;
        let mut out = Contacts { items: [ContactPoint::default(); MAX_CONTACTS], len: n };
        for (slot, u) in out.items.iter_mut().zip(&positions[..n]) {
            let s = u - g.points.p;
            let s = if exact.is_finite() && (s - exact).abs() < 1e-6 * g.base_pitch { exact } else { s };
            *slot = g.contact_exact(*u, s, &self.state, self.reduced_modulus, self.sharing, n);
        }
        out
    }
}
