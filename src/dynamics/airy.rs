//! He & Singh's closed form for an undamped segment whose effective stiffness is linear in time
//! (their eqs 22–42, written with Airy functions instead of √z J_{±1/3}, so that everything stays
//! real for either sign of the slope; physics notes, "Dynamics").
//!
//! On a segment, ẍ + a(τ) x = g with a(τ) = α + β τ. The homogeneous equation ẍ = (p τ + q) x,
//! p = −β, q = −α, becomes Airy's y'' = ξ y under ξ = sgn(p) |p|^{1/3} (τ + q/p), so Ai(ξ(τ)) and
//! Bi(ξ(τ)) form a fundamental system and Φ(h) = W(h) W(0)⁻¹ with W = [[Ai, Bi], [ξ' Ai', ξ' Bi']].
//! Ai, Bi and their derivatives come from the `complex-bessel` crate (Amos' algorithms).
//!
//! The forcing of the internal formulation is the constant g = F0/m_e, so by Duhamel
//! q = W(h) ∫₀ʰ W(s)⁻¹ [0, g] ds = W(h) (π g / ξ') [−∫ Bi(ξ(s)) ds, ∫ Ai(ξ(s)) ds]
//! (the Wronskian of Ai and Bi is 1/π); the two integrals of Ai and Bi are taken by Gauss–Kronrod.
//! This is the undamped internal formulation with a constant-magnitude law (f affine in t); it
//! checks the Magnus route.

use complex_bessel::{airy, airyprime, biry, biryprime};
use nalgebra::{Complex, Matrix2};

use super::propagator::Propagation;
use super::sdof::{DynamicFormulation, SdofSystem};
use crate::numerics::quadrature::integrate;

/// a(τ) = α + β τ on [start, end], from A(t) sampled at the segment's quarter points.
fn linear_stiffness(sys: &SdofSystem, start: f64, end: f64) -> (f64, f64) {
    let seg = end - start;
    let (t1, t2) = (start + 0.25 * seg, start + 0.75 * seg);
    let a1 = -sys.matrices(t1).0[1][0];
    let a2 = -sys.matrices(t2).0[1][0];
    let beta = (a2 - a1) / (t2 - t1);
    (a1 - beta * (t1 - start), beta)
}

fn fundamental(p: f64, q: f64, tau: f64) -> Option<Matrix2<f64>> {
    let s = p.signum() * p.abs().cbrt();
    let xi = Complex::new(s * (tau + q / p), 0.0);
    let ai = airy(xi).ok()?.re;
    let bi = biry(xi).ok()?.re;
    let aip = airyprime(xi).ok()?.re;
    let bip = biryprime(xi).ok()?.re;
    Some(Matrix2::new(ai, bi, s * aip, s * bip))
}

/// True when the undamped system's a(t) is linear in t on every segment: the spur internal
/// formulation with a rectangular k (f affine for a constant-magnitude law), a helical pair's base
/// formulation (K_e = k cos²β_b L(t), piecewise linear) and the chord variant of the internal one
/// (He & Singh eqs 25–35).
pub fn linear_on_segments(sys: &SdofSystem) -> bool {
    sys.damping == 0.0
        && match sys.formulation {
            DynamicFormulation::Internal => sys.stiffness.is_piecewise_constant(),
            DynamicFormulation::Base => sys.stiffness.follows_contact_length(),
            DynamicFormulation::InternalChord => true,
            DynamicFormulation::External => false,
        }
}

/// The homogeneous propagator Φ over [start, start + h] by the Airy closed form, for an undamped
/// segment (c = 0). None when the closed form does not apply (damped, or a(τ) not linear: the base
/// and external formulations have constant a and are covered by the exact propagator).
pub fn airy_propagator(sys: &SdofSystem, start: f64, end: f64, h: f64) -> Option<Matrix2<f64>> {
    if !linear_on_segments(sys) {
        return None;
    }
    let (alpha, beta) = linear_stiffness(sys, start, end);
    let (p, q) = (-beta, -alpha);
    if beta.abs() * h <= 1e-12 * alpha.abs() {
        // Constant stiffness: cos/sin.
        let w = alpha.sqrt();
        let (s, c) = (w * h).sin_cos();
        return Some(Matrix2::new(c, s / w, -w * s, c));
    }
    let w0 = fundamental(p, q, 0.0)?;
    let wh = fundamental(p, q, h)?;
    Some(wh * w0.try_inverse()?)
}

/// The full propagation (Φ, q) over [start, start + h] by the Airy closed form and Duhamel's integral,
/// for the undamped internal formulation without transmission error; None where it does not apply.
pub fn airy_propagation(sys: &SdofSystem, start: f64, end: f64, h: f64) -> Option<Propagation<2>> {
    if !sys.transmission_error.is_empty() {
        return None;
    }
    let phi = airy_propagator(sys, start, end, h)?;
    let g = sys.static_force / sys.equivalent_mass;
    let (alpha, beta) = linear_stiffness(sys, start, end);
    let q = if beta.abs() * h <= 1e-12 * alpha.abs() {
        // Constant stiffness ω²: x_p = g/ω² (1 − cos ωh), v_p = g/ω sin ωh.
        let w = alpha.sqrt();
        let (sn, cs) = (w * h).sin_cos();
        nalgebra::Vector2::new(g / alpha * (1.0 - cs), g / w * sn)
    } else {
        let (p, qq) = (-beta, -alpha);
        let s = p.signum() * p.abs().cbrt();
        let xi = |t: f64| Complex::new(s * (t + qq / p), 0.0);
        let ai = integrate(|t| airy(xi(t)).map_or(f64::NAN, |v| v.re), &[0.0, h], 1e-13).value;
        let bi = integrate(|t| biry(xi(t)).map_or(f64::NAN, |v| v.re), &[0.0, h], 1e-13).value;
        let wh = fundamental(p, qq, h)?;
        wh * nalgebra::Vector2::new(-bi, ai) * (std::f64::consts::PI * g / s)
    };
    q.iter().all(|v| v.is_finite()).then_some(Propagation { phi, q })
}
