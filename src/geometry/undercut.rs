//! How far a rack-cut gear below its undercut limit is undercut: the radius up to which the
//! generating rack's flank end cuts away its involute.
//!
//! A rack generating a gear of transverse pitch radius r (transverse pressure angle α) rolls its
//! pitch line on the pitch circle; the rack's straight flank ends h = (h_a0 − x) m_n below that
//! line (h_a0 = 1: the end of the straight flank of ISO 53's rack, its tip rounding left out, the
//! reading of the undercut limit x_min = 1 − z sin²α_t/(2 cos β) beside it). Where h / sin α
//! exceeds r sin α (x < x_min) that end passes the interference point T and its path relative to
//! the gear (a prolate involute, the trochoid) cuts into the involute from the base circle up
//! (Niemann & Winter, *Maschinenelemente* II, §21.3; Litvin & Fuentes, *Gear Geometry and Applied
//! Theory*, §10.7). In the gear's frame, with the gear turned by φ and the rack moved by −r φ:
//!
//! - the involute at radius ρ: the contact point Q = P + s n on the line of action (P the pitch
//!   point, n = (cos α, −sin α)), s = r sin α − √(ρ² − r_b²), at φ = −s/(r cos α); its polar angle
//!   θ_i(ρ) = arg Q − φ;
//! - the flank end at radius ρ: C = (x_C, r − h) with x_C = √(ρ² − (r − h)²), at
//!   φ = −(h tan α + x_C)/r; its polar angle θ_t(ρ) = arg C − φ.
//!
//! The involute is cut where θ_t < θ_i; the undercut reaches the radius r_u where θ_t = θ_i (one
//! root between r_b and r, found by bisection to the last bit). DIN 3960's condition for an
//! undercut that does no harm: the mate's tip meets the flank above r_u.

/// The radius (m) up to which the involute of a gear of transverse pitch radius `r` and
/// transverse pressure angle `alpha`, cut by a rack whose straight flank ends `h` below the pitch
/// line, is undercut; None when it is not (h / sin α ≤ r sin α).
///
/// ```
/// use gearloss::geometry::undercut_radius;
/// let alpha = 20f64.to_radians();
/// // 10 teeth of module 1 mm without profile shift: undercut a little above the base circle.
/// let ru = undercut_radius(5e-3, alpha, 1e-3).unwrap();
/// assert!(ru > 5e-3 * alpha.cos() && ru < 5e-3);
/// // 17 teeth with x = 0.1: no undercut.
/// assert!(undercut_radius(8.5e-3, alpha, 0.9e-3).is_none());
/// ```
pub fn undercut_radius(r: f64, alpha: f64, h: f64) -> Option<f64> {
    let rb = r * alpha.cos();
    if h / alpha.sin() <= r * alpha.sin() {
        return None;
    }
    let (sin, cos) = alpha.sin_cos();
    let involute_angle = |rho: f64| {
        let s = r * sin - (rho * rho - rb * rb).max(0.0).sqrt();
        let phi = -s / (r * cos);
        (r - s * sin).atan2(s * cos) - phi
    };
    let trochoid_angle = |rho: f64| {
        let xc = (rho * rho - (r - h) * (r - h)).max(0.0).sqrt();
        let phi = -(h * alpha.tan() + xc) / r;
        (r - h).atan2(xc) - phi
    };
    let cut = |rho: f64| trochoid_angle(rho) < involute_angle(rho);
    let (mut lo, mut hi) = (rb, r);
    if cut(hi) {
        return Some(r);
    }
    while hi - lo > f64::EPSILON * hi {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if cut(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(hi)
}
