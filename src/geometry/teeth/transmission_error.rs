//! The static transmission error over one mesh cycle and the load of one pair along its path, at
//! one pinion torque: series for plots, and the figures located, not sampled — the extremes of δ by
//! the roots of its slope and the one-sided limits at every contact change and relief start, the
//! mean by adaptive Gauss–Kronrod with its error estimate.

use super::load_sharing::LoadSharing;
use crate::numerics::quadrature::integrate;
use crate::numerics::roots::extrema;

/// Points of every series, besides both one-sided values at each contact change.
pub const SERIES_POINTS: usize = 256;

/// One torque's transmission error.
#[derive(Debug, Clone, PartialEq)]
pub struct TransmissionError {
    pub pinion_torque: f64,
    /// F_bn = T_p / r_b1 (N).
    pub force: f64,
    /// (s, δ) over one cycle, s of the reference pair.
    pub mesh: Vec<(f64, f64)>,
    /// (s, F_j / F_bn, F_j) of one pair over its engagement.
    pub pair: Vec<(f64, f64, f64)>,
    /// (value, s) of the smallest and largest δ.
    pub min: (f64, f64),
    pub max: (f64, f64),
    pub mean: f64,
    /// Error estimate of the mean (m).
    pub mean_error: f64,
}

impl TransmissionError {
    pub fn peak_to_peak(&self) -> f64 {
        self.max.0 - self.min.0
    }
}

/// Evenly spaced positions over [a, b] with both sides of every break inside.
pub(crate) fn series_positions(a: f64, b: f64, breaks: &[f64]) -> Vec<f64> {
    let eps = 1e-9 * (b - a);
    let mut s: Vec<f64> = (0..SERIES_POINTS).map(|i| a + (b - a) * i as f64 / (SERIES_POINTS - 1) as f64).collect();
    for c in breaks.iter().filter(|c| **c > a && **c < b) {
        s.extend([c - eps, c + eps]);
    }
    s.sort_by(f64::total_cmp);
    s
}

impl LoadSharing {
    /// The breaks of δ over the cycle that starts at s0: contact changes and, mapped into the
    /// cycle, every relief start (and for a helical pair a line end crossing it).
    pub fn cycle_breaks(&self, s0: f64) -> Vec<f64> {
        let k = &self.stiffness;
        let p = k.base_pitch;
        let mut b = vec![s0, s0 + p];
        b.extend(k.contact_changes(s0));
        for start in self.reliefs.starts(k.path) {
            let offsets: &[f64] = if k.is_helical() { &[-0.5, 0.5] } else { &[0.0] };
            for o in offsets {
                let x = s0 + (start - o * k.lead - s0).rem_euclid(p);
                if x > s0 && x < s0 + p {
                    b.push(x);
                }
            }
        }
        b.sort_by(f64::total_cmp);
        b.dedup_by(|a, c| (*a - *c).abs() < 1e-14 * p);
        b
    }

    /// The breaks of one pair's load over its engagement: entry and exit of the others, relief starts.
    fn pair_breaks(&self) -> Vec<f64> {
        let k = &self.stiffness;
        let [lo, hi] = k.engagement();
        let mut b = vec![lo, hi];
        let cycle = self.cycle_breaks(lo);
        let mut j = 0.0;
        while lo + j * k.base_pitch < hi {
            b.extend(cycle.iter().map(|c| c + j * k.base_pitch).filter(|c| *c > lo && *c < hi));
            j += 1.0;
        }
        b.sort_by(f64::total_cmp);
        b.dedup_by(|a, c| (*a - *c).abs() < 1e-14 * k.base_pitch);
        b
    }

    /// The transmission error at a pinion torque (N·m) on a pinion of base radius `r_b1` (m).
    pub fn transmission_error(&self, pinion_torque: f64, r_b1: f64) -> TransmissionError {
        let k = &self.stiffness;
        let force = pinion_torque / r_b1;
        let s0 = k.position_at(0.0);
        let breaks = self.cycle_breaks(s0);
        let delta = |s: f64| self.at(s, force).deflection;
        let xtol = 1e-13 * k.base_pitch;
        // In units of the mean-stiffness deflection: the root finder also stops when |f| < xtol,
        // so f must be of order one.
        let scale = force / k.mean();
        let ((lo, at_lo), (hi, at_hi)) = extrema(|s| delta(s) / scale, &breaks, 16, xtol);
        let (min, max) = ((lo * scale, at_lo), (hi * scale, at_hi));
        let mean = integrate(delta, &breaks, 1e-10);
        let mesh = series_positions(s0, s0 + k.base_pitch, &breaks).into_iter().map(|s| (s, delta(s))).collect();
        let [lo, hi] = k.engagement();
        let pair = series_positions(lo, hi, &self.pair_breaks())
            .into_iter()
            .map(|s| {
                // At E the left limit: the pair carries its share up to the end of its path.
                let inside = k.inside_end(s);
                let f = self.at(inside, force).load_of(inside);
                (s, f / force, f)
            })
            .collect();
        TransmissionError {
            pinion_torque,
            force,
            mesh,
            pair,
            min,
            max,
            mean: mean.value / k.base_pitch,
            mean_error: mean.error / k.base_pitch,
        }
    }
}
