//! What a drive's thermal balance reads beside its own walk (`super::drive_thermal`;
//! [`crate::thermal`] holds the housing and the solvers): a one-pair drive's losses at an oil
//! temperature from its walk's first pass, the speeds' ratings located once a speed, a duty cycle
//! and the heat-balance curve over any P_V(θ).
//!
//! A one-pair drive's P_V(θ) is its walk with the oil read at θ (ν by ASTM D341, ρ by thermal
//! expansion, η = ρν, α from the base oil where the scene does not give it;
//! `DriveSetup::at_oil_temperature`) at the pinion's torque, at the pinion gear, and speed, its one
//! pass added up (`DriveSetup::one_pair_losses`): the mesh loss of one law and formulation as a
//! budget charges it plus every loss beside the mesh.

use super::drive_setup::DriveSetup;
use crate::efficiency::Formulation;
use crate::model::Scene;
use crate::thermal::{self, Balance, DutyCycle, Housing, Ratings};

/// A torque and a speed at the ends `drive`'s operating block names (a one-pair drive's: the
/// pinion's).
fn end_values(drive: &DriveSetup, (torque, speed): (f64, f64)) -> (crate::drive::EndValue, crate::drive::EndValue) {
    let ends = drive.operating_ends();
    let at = |at, value| crate::drive::EndValue { at, value };
    (at(ends.torque_at, torque), at(ends.speed_at, speed))
}

/// A one-pair drive's [mesh loss, every loss beside it] (W) under (law, formulation) at `torque`
/// and `speed` (the pinion's) with its oil at `theta` (K): its walk's first pass
/// (`DriveSetup::one_pair_losses`), without building the point: a scene of one pair's P_V(θ) at
/// each of its drive rows (`drive_thermal`).
pub(crate) fn one_pair_losses_at(
    drive: &DriveSetup,
    (law, f): (usize, Formulation),
    torque_speed: (f64, f64),
    theta: f64,
) -> [f64; 2] {
    let (torque, speed) = end_values(drive, torque_speed);
    drive.at_oil_temperature(theta).one_pair_losses(law, f, torque, speed)
}

/// Each speed's ratings of a sweep, computed by the first point that asks (a 200 × 200 sweep
/// locates 200 speeds' ratings, not 40 000 points'): they depend on the speed alone, not on the
/// point's torque. Keyed by law, formulation and speed index; every speed's bracket starts at the
/// sweep's largest torque, so that a speed's ratings are one number whichever point asks first;
/// each located on the drive's own P_V(torque, θ).
pub(crate) struct RatingTable {
    slots: Vec<std::sync::OnceLock<Ratings>>,
    speeds: usize,
    /// The bracket's start for every speed: the sweep's largest torque (at least 1 N·m).
    guess: f64,
}

impl RatingTable {
    /// The table of `scene`'s sweep: its laws, both formulations and its speeds.
    pub(crate) fn new(scene: &Scene) -> RatingTable {
        let speeds = scene.operating.pinion_speed.values.len();
        let guess = scene.operating.pinion_torque.values.iter().map(|v| v.value).fold(1.0, f64::max);
        let slots = (0..scene.friction.len() * 2 * speeds).map(|_| std::sync::OnceLock::new()).collect();
        RatingTable { slots, speeds, guess }
    }

    /// The ratings of law `law` (index in the scene), formulation `f` at speed index `speed_index`,
    /// located on `p_v(torque, θ)` (W) the first time they are asked for
    /// ([`crate::thermal::ratings`]).
    pub(crate) fn get(
        &self,
        (law, f, speed_index): (usize, Formulation, usize),
        housing: &Housing,
        p_v: impl Fn(f64, f64) -> f64 + Copy,
    ) -> Ratings {
        *self.slots[(law * 2 + f.index()) * self.speeds + speed_index]
            .get_or_init(|| thermal::ratings(p_v, housing, self.guess))
    }
}

/// A duty cycle evaluated at the scene's fixed oil temperature and, with a heat capacity, as a
/// transient from ambient.
#[derive(Debug, Clone, PartialEq)]
pub struct DutyCycleResult {
    /// The law (index in the scene's list) and formulation the losses are read with.
    pub law_index: usize,
    pub formulation: Formulation,
    /// P_V of each step at the fixed temperature (W), when the scene has one.
    pub fixed: Option<Vec<f64>>,
    pub transient: Option<Result<thermal::Transient, String>>,
}

/// A duty cycle on `p_v(step, θ)` (W) under the scene's first law and formulation `f`: each step's
/// P_V at the fixed oil temperature, when there is one, and with a heat capacity the sump's
/// transient from ambient ([`crate::thermal::transient`]); a drive's (`drive_thermal::drive_duty`).
pub(crate) fn duty_cycle_of(
    p_v: impl Fn(usize, f64) -> f64 + Copy,
    housing: &Housing,
    cycle: &DutyCycle,
    (fixed, f): (Option<f64>, Formulation),
) -> DutyCycleResult {
    let durations: Vec<f64> = cycle.steps.iter().map(|s| s.duration).collect();
    DutyCycleResult {
        law_index: 0,
        formulation: f,
        fixed: fixed.map(|t| (0..cycle.steps.len()).map(|k| p_v(k, t)).collect()),
        transient: housing.heat_capacity.map(|c| thermal::transient(p_v, housing, c, &durations)),
    }
}

/// Temperatures of the heat-balance curve.
pub(crate) const CURVE_POINTS: usize = 120;

/// P_V(θ) and P_Q(θ) of one operating point, law and formulation from ambient to 200 °C, for the
/// heat-balance plot (the balance itself is located, not read from these).
#[derive(Debug, Clone, PartialEq)]
pub struct HeatBalanceCurve {
    pub case: usize,
    pub law_index: usize,
    pub formulation: Formulation,
    pub temperatures: Vec<f64>,
    pub losses: Vec<f64>,
    pub dissipation: Vec<f64>,
    pub balance: Balance,
}

/// The curve of `p_v` (W at θ in K) against what `housing` gives off, from ambient to the balance
/// search's limit, at (operating point, law index, formulation): a drive's first row.
pub(crate) fn heat_balance_curve(
    p_v: impl Fn(f64) -> f64,
    housing: &Housing,
    (case, law_index, formulation): (usize, usize, Formulation),
) -> HeatBalanceCurve {
    let top = thermal::balance::SEARCH_LIMIT;
    let temperatures: Vec<f64> = (0..CURVE_POINTS)
        .map(|i| housing.ambient + (top - housing.ambient) * i as f64 / (CURVE_POINTS - 1) as f64)
        .collect();
    HeatBalanceCurve {
        case,
        law_index,
        formulation,
        losses: temperatures.iter().map(|t| p_v(*t)).collect(),
        dissipation: temperatures.iter().map(|t| housing.dissipation(*t).total).collect(),
        temperatures,
        balance: thermal::balance(p_v, housing),
    }
}
