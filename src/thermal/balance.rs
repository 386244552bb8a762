//! The oil temperature a gearbox settles at, and the torque it can carry at a temperature limit.
//!
//! The balance θ* is the lowest root above ambient of P_V(θ) − P_Q(θ), the losses at oil
//! temperature θ less what the housing gives off ([`super::Housing::dissipation`]): the temperature a
//! gearbox started cold reaches. At ambient P_Q = 0 and P_V ≥ 0, so the difference starts at or above
//! zero; it is scanned in steps of [`SCAN_STEP`] up to [`SEARCH_LIMIT`] (200 °C) for its first sign
//! change, which Brent's method then locates to [`TEMPERATURE_TOLERANCE`]. A box with no losses
//! (standing still) stays at ambient. (Two roots closer together than the scan step would be missed:
//! P_V falls and P_Q rises with θ, so the difference has one root in every scene we know.)
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
pub const SEARCH_LIMIT: f64 = 473.15;
/// The scan step that brackets the balance (K).
pub const SCAN_STEP: f64 = 5.0;
/// The balance is located to this (K).
pub const TEMPERATURE_TOLERANCE: f64 = 1e-10;

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
    /// θ* (K); `None` without a balance up to [`SEARCH_LIMIT`].
    pub temperature: Option<f64>,
    pub status: BalanceStatus,
}

/// The balance of losses `p_v(T)` (W at oil temperature T in K) against `housing`.
pub fn balance(p_v: impl Fn(f64) -> f64, housing: &Housing) -> Balance {
    let surplus = |t: f64| p_v(t) - housing.dissipation(t).total;
    let start = housing.ambient;
    let mut temperature = None;
    if surplus(start) <= 0.0 {
        temperature = Some(start);
    } else {
        let steps = ((SEARCH_LIMIT - start) / SCAN_STEP).ceil().max(1.0) as usize;
        let mut lo = start;
        for i in 1..=steps {
            let hi = (start + i as f64 * SCAN_STEP).min(SEARCH_LIMIT);
            if surplus(hi) <= 0.0 {
                temperature = Some(brent(surplus, lo, hi, TEMPERATURE_TOLERANCE));
                break;
            }
            lo = hi;
        }
    }
    let status = match temperature {
        None => BalanceStatus::NoEquilibrium,
        Some(t) if t > housing.max_oil_temperature => BalanceStatus::AboveLimit,
        Some(_) => BalanceStatus::Ok,
    };
    Balance { temperature, status }
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
