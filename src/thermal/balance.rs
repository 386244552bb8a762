//! The oil temperature a gearbox settles at, and the torque it can carry at a temperature limit.
//!
//! The balance θ* is the lowest root above ambient of P_V(θ) − P_Q(θ), the losses at oil
//! temperature θ less what the housing gives off ([`super::Housing::dissipation`]): the temperature a
//! gearbox started cold reaches. At ambient P_Q = 0 and P_V ≥ 0, so the difference starts at or above
//! zero. A box with no losses (standing still) stays at ambient.
//!
//! P_Q is cheap and strongly non-linear (θ^(4/3) convection, θ⁴ radiation); P_V is costly (a mesh
//! integral and the budget per temperature) and varies slowly. So the bracket is found from P_Q
//! alone: g₀ = P_Q⁻¹(P_V(θ_a)), the temperature at which the housing gives off the losses at
//! ambient ([`super::Housing::temperature_giving_off`]). If the surplus at g₀ is not positive the
//! losses did not rise from θ_a to g₀ and the root lies in [θ_a, g₀]. Within a bracket, P_V is
//! replaced by its secant through the two latest points and P_Q kept exact; the root of that model
//! is the next point (safeguarded by the bracket), to [`TEMPERATURE_TOLERANCE`]. When P_V falls
//! with θ (thinner oil: the usual case) the surplus falls strictly and this root is the only one. If instead the losses rose, the surplus is
//! scanned upward from g₀ in steps of [`SCAN_STEP`] up to [`SEARCH_LIMIT`] (200 °C) for its first sign
//! change; below g₀ the surplus cannot change sign when P_V rises (P_V(θ) ≥ P_V(θ_a) = P_Q(g₀) >
//! P_Q(θ) for θ < g₀). Two roots closer together than the scan step would be missed there. The
//! whole costs about eight P_V evaluations (the benchmark `thermal::balance_of_one_point`).
//!
//! The thermal rating at a speed (the idea of ISO/TR 14179-1) is the pinion torque T at which the
//! balance is the limit: P_V(θ_lim; T) = P_Q(θ_lim), a root in T (the losses grow with torque),
//! bracketed by doubling and located by Brent's method to 1e-10 relative. Zero when the no-load losses
//! alone exceed P_Q(θ_lim).
//!
//! ```
//! use gearloss::thermal::{balance, BalanceStatus, Housing};
//! // 300 W in, still air, 0.42 m²: the balance is where convection and radiation take 300 W.
//! let h = Housing::still_air(0.42, 298.15);
//! let b = balance(|_| 300.0, &h);
//! assert_eq!(b.status, BalanceStatus::Ok);
//! let t = b.temperature.unwrap();
//! assert!((h.dissipation(t).total - 300.0).abs() < 1e-8);
//! ```

use serde::{Deserialize, Serialize};

use super::housing::Housing;
use crate::numerics::roots::brent;

/// The highest oil temperature searched for a balance (K): 200 °C.
pub(crate) const SEARCH_LIMIT: f64 = 473.15;
/// The scan step that brackets the balance (K).
pub(crate) const SCAN_STEP: f64 = 5.0;
/// The balance is located to this (K).
pub(crate) const TEMPERATURE_TOLERANCE: f64 = 1e-10;

/// Where the balance lies against the oil's limit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BalanceStatus {
    /// θ* at or below the limit.
    Ok,
    /// θ* found, above the limit.
    AboveLimit,
    /// No balance up to 200 °C.
    NoEquilibrium,
}

impl BalanceStatus {
    /// The status as report.json and the record files write it.
    pub fn name(self) -> &'static str {
        match self {
            BalanceStatus::Ok => "ok",
            BalanceStatus::AboveLimit => "above_limit",
            BalanceStatus::NoEquilibrium => "no_equilibrium",
        }
    }

    /// The status in words, as report.md says it.
    pub fn words(self) -> &'static str {
        match self {
            BalanceStatus::Ok => "settles below the limit",
            BalanceStatus::AboveLimit => "settles above the limit",
            BalanceStatus::NoEquilibrium => "finds no balance up to 200 °C",
        }
    }
}

/// The balance of one operating point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Balance {
    /// θ* (K); `None` without a balance up to `SEARCH_LIMIT`.
    pub temperature: Option<f64>,
    pub status: BalanceStatus,
}

/// The balance of losses `p_v(T)` (W at oil temperature T in K) against `housing`.
pub fn balance(p_v: impl Fn(f64) -> f64, housing: &Housing) -> Balance {
    let temperature = lowest_root(p_v, housing);
    let status = match temperature {
        None => BalanceStatus::NoEquilibrium,
        Some(t) if t > housing.max_oil_temperature => BalanceStatus::AboveLimit,
        Some(_) => BalanceStatus::Ok,
    };
    Balance { temperature, status }
}

/// θ* as the module's documentation describes, `None` without a root up to [`SEARCH_LIMIT`].
fn lowest_root(p_v: impl Fn(f64) -> f64, housing: &Housing) -> Option<f64> {
    let q = |t: f64| housing.dissipation(t).total;
    let start = housing.ambient;
    let at_start = p_v(start);
    if at_start - q(start) <= 0.0 {
        return Some(start);
    }
    let g0 = housing.temperature_giving_off(at_start, SEARCH_LIMIT);
    let at_g0 = p_v(g0);
    if at_g0 - q(g0) <= 0.0 {
        return Some(locate(&p_v, housing, (start, at_start), (g0, at_g0)));
    }
    let steps = ((SEARCH_LIMIT - g0) / SCAN_STEP).ceil().max(1.0) as usize;
    let mut lo = (g0, at_g0);
    for i in 1..=steps {
        let t = (g0 + i as f64 * SCAN_STEP).min(SEARCH_LIMIT);
        let hi = (t, p_v(t));
        if hi.1 - q(t) <= 0.0 {
            return Some(locate(&p_v, housing, lo, hi));
        }
        lo = hi;
    }
    None
}

/// The root of P_V − P_Q between `lo` (surplus > 0) and `hi` (surplus ≤ 0), each given with its
/// P_V: P_V is replaced by the secant through the two latest points and P_Q kept exact, the model's
/// root (in P_Q alone, [`crate::numerics::roots::brent`]) is the next point; the bracket is kept,
/// and a model root outside it is replaced by the bracket's midpoint. Only P_V's curvature is
/// left to the secant, so it converges in a few P_V evaluations; it stops when the Newton step
/// |surplus / (dP_Q/dθ − secant slope)| from the latest point is below [`TEMPERATURE_TOLERANCE`],
/// or the bracket is.
fn locate(p_v: impl Fn(f64) -> f64, housing: &Housing, lo: (f64, f64), hi: (f64, f64)) -> f64 {
    let q = |t: f64| housing.dissipation(t).total;
    let (mut lo_t, mut hi_t) = (lo.0, hi.0);
    let (mut older, mut newer) = (lo, hi);
    for _ in 0..100 {
        let slope = (newer.1 - older.1) / (newer.0 - older.0);
        let model = |t: f64| q(t) - (newer.1 + slope * (t - newer.0));
        let next = if model(lo_t) < 0.0 && model(hi_t) > 0.0 {
            brent(model, lo_t, hi_t, 1e-3 * TEMPERATURE_TOLERANCE)
        } else {
            0.5 * (lo_t + hi_t)
        };
        let at = p_v(next);
        let surplus = at - q(next);
        if surplus > 0.0 {
            lo_t = next;
        } else {
            hi_t = next;
        }
        let dq = (q(next + 1e-3) - q(next - 1e-3)) / 2e-3;
        let newton_step = (surplus / (dq - slope)).abs();
        (older, newer) = (newer, (next, at));
        if surplus == 0.0 || newton_step < TEMPERATURE_TOLERANCE || hi_t - lo_t < TEMPERATURE_TOLERANCE {
            return next;
        }
    }
    brent(|t| p_v(t) - q(t), lo_t, hi_t, TEMPERATURE_TOLERANCE)
}

/// The pinion torque (N·m) at which the balance is `limit` (K), for losses `p_v(torque, T)` at one
/// speed; `guess` starts the bracket. `None` when no torque up to 2⁶⁰ × `guess` reaches it.
pub fn rating_torque(p_v: impl Fn(f64, f64) -> f64, housing: &Housing, limit: f64, guess: f64) -> Option<f64> {
    let q = housing.dissipation(limit).total;
    let surplus = |torque: f64| p_v(torque, limit) - q;
    if surplus(0.0) >= 0.0 {
        return Some(0.0);
    }
    let mut hi = guess.max(1e-3);
    for _ in 0..60 {
        if surplus(hi) > 0.0 {
            return Some(brent(surplus, 0.0, hi, 1e-10 * hi));
        }
        hi *= 2.0;
    }
    None
}

/// The ISO/TR 14179-1 rating temperature (K): 95 °C.
const RATING_TEMPERATURE: f64 = 368.15;

/// The torques (N·m, at the end the losses are given against) at which θ* is the oil's limit and
/// 95 °C, at one speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ratings {
    pub at_limit: Option<f64>,
    pub at_95: Option<f64>,
}

/// The two thermal ratings of a gearbox whose losses at one speed are `p_v(torque, θ)`: the torque
/// that puts θ* on the housing's `max_oil_temperature`, and ISO/TR 14179-1's at 95 °C (None when
/// the ambient is not below 95 °C). Each is [`rating_torque`] from the bracket's start `guess`.
pub fn ratings(p_v: impl Fn(f64, f64) -> f64 + Copy, housing: &Housing, guess: f64) -> Ratings {
    Ratings {
        at_limit: rating_torque(p_v, housing, housing.max_oil_temperature, guess),
        at_95: (RATING_TEMPERATURE > housing.ambient)
            .then(|| rating_torque(p_v, housing, RATING_TEMPERATURE, guess))
            .flatten(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Losses linear in torque, falling with temperature: the rating torque puts the balance on the
    /// limit (to 1e-8 K), and the balance is ok just below it and above the limit just above it.
    #[test]
    fn rating_torque_puts_the_balance_on_the_limit() {
        let h = Housing::still_air(0.42, 298.15);
        let p_v = |torque: f64, t: f64| 80.0 + 1.5 * torque * (1.0 - 1e-3 * (t - 298.15));
        let limit = 368.15;
        let rating = rating_torque(p_v, &h, limit, 100.0).unwrap();
        let at = balance(|t| p_v(rating, t), &h);
        assert!((at.temperature.unwrap() - limit).abs() < 1e-8, "{at:?}");
        assert_eq!(balance(|t| p_v(0.99 * rating, t), &h).status, BalanceStatus::Ok);
        let hot = Housing { max_oil_temperature: limit, ..h.clone() };
        assert_eq!(balance(|t| p_v(1.01 * rating, t), &hot).status, BalanceStatus::AboveLimit);
    }

    /// Losses rising with temperature (the scan branch) and losses falling steeply (the bracket
    /// branch): θ* is a root to 1e-6 W of surplus, the surplus is positive 1e-6 K below it, and the
    /// falling case (900 W falling 2.7-fold every 40 K) costs at most 10 P_V evaluations (9 when
    /// written).
    #[test]
    fn rising_and_falling_losses() {
        let h = Housing::still_air(0.42, 298.15);
        let calls = std::cell::Cell::new(0);
        let rising = |t: f64| 150.0 + 2.5 * (t - 298.15);
        let falling = |t: f64| {
            calls.set(calls.get() + 1);
            900.0 * (-(t - 298.15) / 40.0).exp() + 60.0
        };
        for p_v in [&rising as &dyn Fn(f64) -> f64, &falling] {
            let t = balance(p_v, &h).temperature.unwrap();
            let surplus = |t: f64| p_v(t) - h.dissipation(t).total;
            assert!(surplus(t).abs() < 1e-6 && surplus(t - 1e-6) > 0.0, "{t}");
        }
        calls.set(0);
        balance(falling, &h);
        assert!(calls.get() <= 10, "{} evaluations", calls.get());
    }

    /// No-load losses above what the housing gives off at the limit: a rating of zero; losses above
    /// what it gives off at 200 °C: no balance.
    #[test]
    fn limits_of_the_search() {
        let h = Housing::still_air(0.1, 298.15);
        let q_limit = h.dissipation(393.15).total;
        assert_eq!(rating_torque(|_, _| 1.01 * q_limit, &h, 393.15, 10.0), Some(0.0));
        let q_top = h.dissipation(SEARCH_LIMIT).total;
        let b = balance(|_| 1.01 * q_top, &h);
        assert_eq!((b.temperature, b.status), (None, BalanceStatus::NoEquilibrium));
        assert_eq!(balance(|_| 0.0, &h).temperature, Some(298.15));
    }
}
