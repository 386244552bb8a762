//! The periodic steady-state response over one mesh period, from the Floquet periodic state:
//! DTE, dynamic mesh force (total and per pair), friction force, dynamic factor, tooth separation,
//! the DTE spectrum in mesh orders and the efficiency from the dynamic mesh force.

use nalgebra::{Matrix4, Vector2};
use serde::Serialize;

use super::floquet::Floquet;
use super::propagator::{from_exponential, magnus, magnus_adaptive, segment_matrix};
use super::sdof::SdofSystem;
use crate::efficiency::contacts_at;

/// Samples per mesh period of the reported response.
pub const SAMPLES: usize = 256;
/// Mesh orders kept in the DTE spectrum.
pub const ORDERS: usize = 10;

#[derive(Debug, Clone, Serialize)]
pub struct PeriodicResponse {
    /// Sample times in mesh periods, [0, 1).
    pub tau: Vec<f64>,
    /// DTE x (m).
    pub dte: Vec<f64>,
    /// Dynamic mesh force, total (N).
    pub mesh_force: Vec<f64>,
    /// Dynamic mesh force of each pair slot k (the pair that entered k periods ago), NaN when out of contact.
    pub pair_force: Vec<Vec<f64>>,
    /// Total friction force Σ μ_j F_j (N).
    pub friction_force: Vec<f64>,
    /// Friction torques on pinion and wheel, −Σ μ_j F_j T1C_j and Σ μ_j F_j T2C_j (N·m).
    pub friction_torque: [Vec<f64>; 2],
    pub dte_peak_to_peak: f64,
    pub dte_mean: f64,
    /// max dynamic / max static mesh force (static: F0).
    pub dynamic_factor: f64,
    /// Intervals (τ from, τ to) where the mesh force is negative: tooth separation.
    pub separation: Vec<(f64, f64)>,
    /// (mesh order, amplitude of the DTE harmonic, m), orders 1..=ORDERS.
    pub spectrum: Vec<(usize, f64)>,
    /// Mean over the period of the instantaneous efficiency from the dynamic mesh force,
    /// 1 − Σ |μ_j| F_j v_s,j / (T_p ω_p).
    pub mean_dynamic_efficiency: Option<f64>,
}

/// The state at each sample time (τ in mesh periods, sorted, within [0, 1)), marching segment by
/// segment from X(0). For the exact propagator exp(M dt) is cached for the common sample step.
pub fn states(sys: &SdofSystem, x0: Vector2<f64>, taus: &[f64]) -> Vec<Vector2<f64>> {
    let mut out = Vec::with_capacity(taus.len());
    let mut x = x0;
    let mut t = 0.0;
    let mut k = 0;
    let exact = sys.exact_applies();
    for seg in &sys.segments {
        let m = exact.then(|| segment_matrix(sys, seg.start, seg.end));
        // Magnus: the substep density that converged over the whole segment, reused for each sample step.
        let density = if exact {
            0.0
        } else {
            magnus_adaptive(sys, seg.start, seg.end - seg.start).1 as f64 / (seg.end - seg.start)
        };
        let mut cache: Option<(f64, Matrix4<f64>)> = None;
        let mut step = |x: &Vector2<f64>, from: f64, dt: f64| -> Vector2<f64> {
            match &m {
                Some(m) => {
                    let e = match &cache {
                        Some((h, e)) if (*h - dt).abs() <= 1e-12 * dt => *e,
                        _ => {
                            let e = (m * dt).exp();
                            cache = Some((dt, e));
                            e
                        }
                    };
                    from_exponential(&e, from - seg.start).apply(x)
                }
                None => magnus(sys, from, dt, ((density * dt).ceil() as usize).max(2)).apply(x),
            }
        };
        while k < taus.len() && taus[k] * sys.period < seg.end {
            let target = taus[k] * sys.period;
            if target > t {
                x = step(&x, t, target - t);
                t = target;
            }
            out.push(x);
            k += 1;
        }
        if seg.end > t {
            x = step(&x, t, seg.end - t);
            t = seg.end;
        }
    }
    out
}

impl PeriodicResponse {
    /// The response from a Floquet analysis; None when there is no periodic state (unstable).
    pub fn compute(sys: &SdofSystem, floquet: &Floquet) -> Option<PeriodicResponse> {
        let x0 = floquet.periodic_state?;
        let taus: Vec<f64> = (0..SAMPLES).map(|i| i as f64 / SAMPLES as f64).collect();
        let xs = states(sys, x0, &taus);
        let mut r = PeriodicResponse {
            tau: taus.clone(),
            dte: xs.iter().map(|x| x[0]).collect(),
            mesh_force: Vec::with_capacity(SAMPLES),
            pair_force: vec![vec![f64::NAN; SAMPLES]; 3],
            friction_force: Vec::with_capacity(SAMPLES),
            friction_torque: [Vec::with_capacity(SAMPLES), Vec::with_capacity(SAMPLES)],
            dte_peak_to_peak: 0.0,
            dte_mean: 0.0,
            dynamic_factor: 0.0,
            separation: Vec::new(),
            spectrum: Vec::new(),
            mean_dynamic_efficiency: None,
        };
        let g = sys.ctx.geometry;
        let input_power = sys.ctx.state.pinion_torque * sys.ctx.state.pinion_speed;
        let mut eta_sum = 0.0;
        for (i, (tau, x)) in taus.iter().zip(&xs).enumerate() {
            let t = tau * sys.period;
            let f = sys.mesh_force(t, &[x[0], x[1]]);
            r.mesh_force.push(f);
            let contacts = contacts_at(&sys.ctx, *tau);
            let mut friction = 0.0;
            let mut torque = [0.0, 0.0];
            let mut loss = 0.0;
            for c in &contacts {
                let slot = (((c.u - g.points.a) / g.base_pitch) - tau).round() as usize;
                if slot < 3 {
                    r.pair_force[slot][i] = c.load_share * f;
                }
                let mu = sys.law.map_or(0.0, |l| l.mu(c));
                friction += mu * c.load_share * f;
                torque[0] -= mu * c.load_share * f * c.u;
                torque[1] += mu * c.load_share * f * (g.line_of_action_length - c.u);
                loss += mu.abs() * c.load_share * f * c.sliding_velocity;
            }
            r.friction_force.push(friction);
            r.friction_torque[0].push(torque[0]);
            r.friction_torque[1].push(torque[1]);
            eta_sum += 1.0 - loss / input_power;
        }
        if sys.law.is_some() {
            r.mean_dynamic_efficiency = Some(eta_sum / SAMPLES as f64);
        }
        let (lo, hi) = r.dte.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(*v), b.max(*v)));
        r.dte_peak_to_peak = hi - lo;
        r.dte_mean = r.dte.iter().sum::<f64>() / SAMPLES as f64;
        r.dynamic_factor = r.mesh_force.iter().fold(f64::NEG_INFINITY, |a, b| a.max(*b)) / sys.static_force;
        let mut open: Option<f64> = None;
        for (i, f) in r.mesh_force.iter().enumerate() {
            match (open, *f < 0.0) {
                (None, true) => open = Some(taus[i]),
                (Some(s), false) => {
                    r.separation.push((s, taus[i]));
                    open = None;
                }
                _ => {}
            }
        }
        if let Some(s) = open {
            r.separation.push((s, 1.0));
        }
        r.spectrum = (1..=ORDERS)
            .map(|h| {
                let (mut re, mut im) = (0.0, 0.0);
                for (i, x) in r.dte.iter().enumerate() {
                    let arg = 2.0 * std::f64::consts::PI * (h * i) as f64 / SAMPLES as f64;
                    re += x * arg.cos();
                    im -= x * arg.sin();
                }
                (h, 2.0 * re.hypot(im) / SAMPLES as f64)
            })
            .collect();
        Some(r)
    }
}
