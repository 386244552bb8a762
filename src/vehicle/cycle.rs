//! A drive cycle: a vehicle over a speed trace, cut into pieces on which everything the gearbox
//! sees is smooth (README, "Vehicles and drive cycles").
//!
//! On interval k of the trace (t_k to t_k+1) the speed is linear, v = v_k + a τ, and the wheel
//! force F(τ) a quadratic ([`Vehicle::force_on`]; the grade of an interval is its end sample's, as
//! NREL FASTSim reads it). An interval standing still at both ends is one standing piece (no
//! force, no loss). Any other interval is cut where F changes sign (drive ↔ coast), where the
//! wheel torque crosses the recuperation limit, and at the phase boundaries: roots of quadratics,
//! located in closed form. The wheel's energies on a piece, ∫ F v dt, are exact (a cubic in τ).

use super::road_load::Vehicle;
use super::trace::Trace;

/// A named stretch of the cycle (s from the trace's first sample).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Phase {
    pub name: String,
    pub from: f64,
    pub to: f64,
}

/// What the gearbox does on a piece.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// v = 0 on the whole interval: nothing turns.
    Standing,
    /// F > 0: the motor drives the wheels.
    Drive,
    /// F < 0: the wheels drive the motor (recuperation).
    Coast,
    /// F r below −(the recuperation limit): the box carries the limit, the brakes the rest.
    CoastCapped,
}

/// A piece of an interval, on which the force, torque and speed are smooth.
#[derive(Debug, Clone, PartialEq)]
pub struct Piece {
    /// The trace's interval (t_k to t_k+1) the piece lies in.
    pub interval: usize,
    /// From and to (s, on the trace's clock).
    pub from: f64,
    pub to: f64,
    pub mode: Mode,
    /// The interval's start time (s) and speed (m/s), its acceleration (m/s²), F's coefficients in
    /// τ = t − start.
    start: f64,
    v0: f64,
    a: f64,
    force: [f64; 3],
    /// −(limit)/r_dyn (N): the lowest force the box carries; −∞ without a limit.
    floor: f64,
}

impl Piece {
    /// v (m/s) at `t`.
    pub fn speed(&self, t: f64) -> f64 {
        self.v0 + self.a * (t - self.start)
    }

    /// The same piece of the interval between `from` and `to` (s): a part of it, cut where
    /// something the gearbox does changes form inside.
    pub(crate) fn between(&self, from: f64, to: f64) -> Piece {
        Piece { from, to, ..self.clone() }
    }

    /// The time of F's vertex (s), when it lies inside the piece.
    pub(crate) fn force_vertex(&self) -> Option<f64> {
        let vertex = self.start - self.force[1] / (2.0 * self.force[2]);
        (self.force[2] != 0.0 && vertex > self.from && vertex < self.to).then_some(vertex)
    }

    /// F (N) at `t` (the force inside the piece: at its ends, the one-sided limit).
    pub fn force(&self, t: f64) -> f64 {
        let tau = t - self.start;
        self.force[0] + tau * (self.force[1] + tau * self.force[2])
    }

    /// The force the gearbox carries (N at the wheel): F, or the recuperation limit's floor.
    pub fn carried_force(&self, t: f64) -> f64 {
        if self.mode == Mode::CoastCapped {
            self.floor
        } else {
            self.force(t)
        }
    }

    /// ∫ F v dt over the piece (J): exact.
    pub fn wheel_energy(&self) -> f64 {
        let [c0, c1, c2] = self.force;
        cubic_integral([c0 * self.v0, c0 * self.a + c1 * self.v0, c1 * self.a + c2 * self.v0, c2 * self.a], self.taus())
    }

    /// ∫ F_carried v dt (J): the energy through the gearbox's output, exact.
    pub fn box_energy(&self) -> f64 {
        match self.mode {
            Mode::CoastCapped => self.floor * self.distance(),
            _ => self.wheel_energy(),
        }
    }

    /// ∫ v dt over the piece (m).
    pub fn distance(&self) -> f64 {
        cubic_integral([self.v0, self.a, 0.0, 0.0], self.taus())
    }

    fn taus(&self) -> (f64, f64) {
        (self.from - self.start, self.to - self.start)
    }

    /// The largest and the smallest F on the piece (N) with their times: ends and the vertex.
    pub fn force_extremes(&self) -> ((f64, f64), (f64, f64)) {
        let mut candidates = vec![self.from, self.to];
        if self.force[2] != 0.0 {
            let vertex = self.start - self.force[1] / (2.0 * self.force[2]);
            if vertex > self.from && vertex < self.to {
                candidates.push(vertex);
            }
        }
        let at = |t: f64| (self.force(t), t);
        let max =
            candidates.iter().map(|&t| at(t)).fold((f64::NEG_INFINITY, 0.0), |m, x| if x.0 > m.0 { x } else { m });
        let min = candidates.iter().map(|&t| at(t)).fold((f64::INFINITY, 0.0), |m, x| if x.0 < m.0 { x } else { m });
        (max, min)
    }
}

/// ∫ (d₀ + d₁ τ + d₂ τ² + d₃ τ³) dτ from τ₀ to τ₁.
fn cubic_integral(d: [f64; 4], (t0, t1): (f64, f64)) -> f64 {
    let p = |t: f64| t * (d[0] + t * (d[1] / 2.0 + t * (d[2] / 3.0 + t * d[3] / 4.0)));
    p(t1) - p(t0)
}

/// The roots of c₀ + c₁ τ + c₂ τ² strictly inside (lo, hi), in closed form (the cancellation-free
/// pair of roots of a quadratic).
fn roots_inside(c: [f64; 3], lo: f64, hi: f64) -> Vec<f64> {
    let [c0, c1, c2] = c;
    let scale = c0.abs().max(c1.abs() * hi).max(c2.abs() * hi * hi);
    let mut roots = Vec::new();
    if c2.abs() * hi * hi <= 1e-14 * scale {
        if c1 != 0.0 {
            roots.push(-c0 / c1);
        }
    } else {
        let disc = c1 * c1 - 4.0 * c2 * c0;
        if disc >= 0.0 {
            let q = -0.5 * (c1 + c1.signum() * disc.sqrt());
            if q != 0.0 {
                roots.push(q / c2);
                roots.push(c0 / q);
            } else {
                roots.push(0.0);
            }
        }
    }
    let margin = 1e-12 * (hi - lo);
    roots.retain(|&r| r > lo + margin && r < hi - margin);
    roots.sort_by(f64::total_cmp);
    roots
}

/// A vehicle over a trace, cut into its pieces.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Cycle {
    pub vehicle: Vehicle,
    pub trace: Trace,
    pub phases: Vec<Phase>,
}

impl Cycle {
    /// Every piece of the cycle, in time order.
    pub fn pieces(&self) -> Vec<Piece> {
        let tr = &self.trace;
        let floor = self.vehicle.recuperation_limit.map_or(f64::NEG_INFINITY, |l| -l / self.vehicle.wheel_radius);
        let mut out = Vec::new();
        for k in 0..tr.time.len() - 1 {
            let (start, end) = (tr.time[k], tr.time[k + 1]);
            let (v0, v1) = (tr.speed[k], tr.speed[k + 1]);
            let a = (v1 - v0) / (end - start);
            let h = end - start;
            let force = self.vehicle.force_on(v0, a, tr.grade[k + 1]);
            let piece =
                |from: f64, to: f64, mode: Mode| Piece { interval: k, from, to, mode, start, v0, a, force, floor };
            if v0 == 0.0 && v1 == 0.0 {
                out.push(Piece { force: [0.0; 3], ..piece(start, end, Mode::Standing) });
                continue;
            }
            let mut cuts = roots_inside(force, 0.0, h);
            if floor.is_finite() {
                cuts.extend(roots_inside([force[0] - floor, force[1], force[2]], 0.0, h));
            }
            let margin = 1e-12 * h;
            cuts.extend(
                self.phases
                    .iter()
                    .flat_map(|p| [p.from, p.to])
                    .map(|t| t - start)
                    .filter(|&t| t > margin && t < h - margin),
            );
            cuts.sort_by(f64::total_cmp);
            cuts.dedup_by(|a, b| (*a - *b).abs() <= margin);
            let mut edges = vec![0.0];
            edges.extend(cuts);
            edges.push(h);
            for w in edges.windows(2) {
                let (from, to) = (start + w[0], if w[1] == h { end } else { start + w[1] });
                let mid = piece(from, to, Mode::Drive).force(0.5 * (from + to));
                let mode = match mid {
                    f if f > 0.0 => Mode::Drive,
                    f if f < floor => Mode::CoastCapped,
                    _ => Mode::Coast,
                };
                out.push(piece(from, to, mode));
            }
        }
        out
    }
}
