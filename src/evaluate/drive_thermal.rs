//! A drive's thermal balance (one sump, one thermal node, as for one pair): at each operating point,
//! law and formulation, the oil temperature θ* where the drive's whole loss P_V(θ) (every mesh,
//! gear, bearing and seal of the drive at the oil read at θ) equals what the housing gives off,
//! P_Q(θ) ([`crate::thermal::balance`]: the lowest root, bracketed by a scan and located by Brent);
//! in drive, the thermal rating: the torque at the given end that puts θ* on the oil's limit.

use super::drive_setup::{DriveRow, DriveSetup};
use crate::model::{Scene, SceneDrive};
use crate::thermal::{Balance, Housing};

/// The balance of one operating point, law and formulation, with the drive's loss and the housing's
/// dissipation at θ* (at the search's limit, 200 °C, without a balance).
#[derive(Debug, Clone)]
pub struct DriveBalanceRow {
    pub torque_index: usize,
    pub speed_index: usize,
    pub law_index: usize,
    pub formulation: crate::efficiency::Formulation,
    pub balance: Balance,
    /// P_V(θ*) and P_Q(θ*) by path (W), and the wall's convective h_c (W/(m² K)) there.
    pub loss: f64,
    pub dissipation: crate::thermal::Dissipation,
    pub heat_transfer_coefficient: f64,
    /// In drive: the torque at the given end (N·m) the box carries continuously with the sump at
    /// the oil's limit ([`crate::thermal::rating_torque`] at this point's speed); None in coast, or
    /// when no torque reaches the limit.
    pub rating: Option<f64>,
    /// The same with the sump at ISO/TR 14179-1's 95 °C ([`crate::thermal::ratings`]); None also
    /// when the ambient is not below 95 °C.
    pub rating_95: Option<f64>,
}

/// P_V(θ) of the drive at `row`'s point, law and formulation (W).
fn loss_at(setup: &DriveSetup, scene: &Scene, row: &DriveRow, theta: f64) -> f64 {
    loss_at_torque(setup, scene, row, scene.operating.pinion_torque.values[row.torque_index].value, theta)
}

/// P_V(θ) of the drive at `row`'s speed, law and formulation with `torque` (N·m) at the given end.
fn loss_at_torque(setup: &DriveSetup, scene: &Scene, row: &DriveRow, torque: f64, theta: f64) -> f64 {
    let speed = scene.operating.pinion_speed.values[row.speed_index].value;
    loss_at_point(setup, (row.law_index, row.formulation), (torque, speed), theta)
}

/// P_V(θ) (W) of the drive of `base` (its meshes' geometry kept, the oil moved to θ) under (law,
/// formulation) with `torque` and `speed` at the ends its operating block names; 0 standing.
fn loss_at_point(
    base: &DriveSetup,
    (law, formulation): (usize, crate::efficiency::Formulation),
    (torque, speed): (f64, f64),
    theta: f64,
) -> f64 {
    if speed == 0.0 {
        return 0.0;
    }
    if base.is_one_pair() {
        // A scene of one pair: its walk's first pass settles at the given pinion torque, whose
        // losses are the point's but for rounding, without building the point.
        return super::thermal::one_pair_losses_at(base, (law, formulation), (torque, speed), theta).iter().sum();
    }
    base.walked_at((law, formulation), (torque, speed), theta).1.power_lost()
}

/// A drive's whole loss P_V(θ) as its thermal balance, ratings and duty cycle read it, for a library
/// user or a bench: the drive walked with its oil moved to θ (a scene of one pair's, its walk's first
/// pass), its meshes' geometry prepared once.
pub struct DriveLosses<'a> {
    setup: DriveSetup<'a>,
}

impl<'a> DriveLosses<'a> {
    /// The losses of `scene`'s drive `drive`.
    pub fn new(scene: &'a Scene, drive: &'a SceneDrive) -> DriveLosses<'a> {
        DriveLosses { setup: DriveSetup::new(scene, drive) }
    }

    /// P_V (W) under law `law` (index in the scene) and formulation `f` with `torque` (N·m) and
    /// `speed` (rad/s) at the ends the operating block names, the oil at `theta` (K); 0 standing.
    pub fn total(&self, law: usize, f: crate::efficiency::Formulation, torque_speed: (f64, f64), theta: f64) -> f64 {
        loss_at_point(&self.setup, (law, f), torque_speed, theta)
    }
}

/// At `oil_temperature = equilibrium`: `row` (evaluated by `base`, at ambient) found again at its
/// own balance θ* (the drive's whole loss at θ* equals what the housing gives off there), with the
/// law's validity read at θ*; a row without a balance stays at ambient, its status saying so.
pub(crate) fn row_at_balance(
    base: &DriveSetup,
    scene: &Scene,
    housing: &Housing,
    row: DriveRow,
) -> (DriveRow, Vec<super::laws::ValiditySummary>) {
    let balance = crate::thermal::balance(|theta| loss_at(base, scene, &row, theta), housing);
    let Some(theta) = balance.temperature else {
        let validity = base.validity(row.law_index, &row.point);
        return (DriveRow { balance: Some(balance), ..row }, validity);
    };
    let ends = (
        scene.operating.pinion_torque.values[row.torque_index].value,
        scene.operating.pinion_speed.values[row.speed_index].value,
    );
    let (setup, point) = base.walked_at((row.law_index, row.formulation), ends, theta);
    let validity = setup.validity(row.law_index, &point);
    (DriveRow { point, balance: Some(balance), ..row }, validity)
}

/// At `oil_temperature = equilibrium`: the scene with its oil at the balance of its first row (first
/// operating point, law and formulation), where the map, the duty cycle, the thermal balance's rows
/// and the stages' analyses of one pair are read (each row of the sweep at its own); the scene
/// itself otherwise, or when that row finds no balance.
pub(crate) fn at_first_balance<'s>(scene: &'s Scene, drive: &SceneDrive) -> std::borrow::Cow<'s, Scene> {
    use std::borrow::Cow;
    let (Some(span), Some(housing)) = (scene.operating.equilibrium, scene.housing.as_ref()) else {
        return Cow::Borrowed(scene);
    };
    let setup = DriveSetup::new(scene, drive);
    let torques: Vec<f64> = scene.operating.pinion_torque.values.iter().map(|t| t.value).collect();
    let speeds: Vec<f64> = scene.operating.pinion_speed.values.iter().map(|w| w.value).collect();
    let Some(first) = setup.grid_rows(&torques, &speeds, drive.layout.operating, 0..1).pop() else {
        return Cow::Borrowed(scene);
    };
    let Some(t) = crate::thermal::balance(|theta| loss_at(&setup, scene, &first, theta), housing).temperature else {
        return Cow::Borrowed(scene);
    };
    Cow::Owned(scene.at_balance_of_point_1(t, span))
}

/// A drive's duty cycle under its first law and formulation: each step's P_V at the scene's oil
/// temperature and, with a heat capacity, the sump's transient from ambient
/// ([`crate::thermal::transient`], C dθ/dt = P_V(θ) − P_Q(θ), standing steps without losses).
pub fn drive_duty(
    scene: &Scene,
    drive: &SceneDrive,
    housing: &Housing,
    cycle: &crate::thermal::DutyCycle,
) -> super::thermal::DutyCycleResult {
    let f = scene.analyses.first_formulation();
    let base = DriveSetup::new(scene, drive);
    let p_v = |k: usize, theta: f64| {
        let s = &cycle.steps[k];
        loss_at_point(&base, (0, f), (s.pinion_torque, s.pinion_speed), theta)
    };
    let fixed = scene.operating.oil_temperature.as_ref().map(|t| t.value.value);
    super::thermal::duty_cycle_of(p_v, housing, cycle, (fixed, f))
}

/// P_V(θ) of the drive at `row`'s point, law and formulation against what `housing` gives off,
/// from ambient to the balance search's limit ([`super::thermal::heat_balance_curve`]).
pub(crate) fn heat_balance_curve(
    scene: &Scene,
    drive: &SceneDrive,
    housing: &Housing,
    row: &DriveRow,
) -> super::thermal::HeatBalanceCurve {
    let base = DriveSetup::new(scene, drive);
    let point = row.torque_index * scene.operating.pinion_speed.values.len() + row.speed_index;
    let p_v = |theta: f64| loss_at(&base, scene, row, theta);
    super::thermal::heat_balance_curve(p_v, housing, (point, row.law_index, row.formulation))
}

/// The balance of the report's kept rows.
pub(crate) fn drive_balances(
    scene: &Scene,
    drive: &SceneDrive,
    housing: &Housing,
    rows: &[DriveRow],
) -> Vec<DriveBalanceRow> {
    use rayon::prelude::*;
    let base = DriveSetup::new(scene, drive);
    let table = super::thermal::RatingTable::new(scene);
    rows.par_iter().map(|row| row_balance(&base, scene, (housing, &table), row)).collect()
}

/// The balance of `row`, what the housing gives off at θ* and, in drive, its speed's ratings from
/// `table` (a speed's ratings do not depend on the row's torque: located once per law, formulation
/// and speed, from the sweep's largest torque): the same numbers whether the row is streamed into
/// the record files (`super::drive`) or kept for the report ([`drive_balances`]).
pub(crate) fn row_balance(
    base: &DriveSetup,
    scene: &Scene,
    (housing, table): (&Housing, &super::thermal::RatingTable),
    row: &DriveRow,
) -> DriveBalanceRow {
    let balance = crate::thermal::balance(|theta| loss_at(base, scene, row, theta), housing);
    let t = balance.temperature.unwrap_or(crate::thermal::balance::SEARCH_LIMIT);
    let ratings = (row.point.flow == crate::drive::PowerFlow::Drive).then(|| {
        let p_v = |torque: f64, theta: f64| loss_at_torque(base, scene, row, torque, theta);
        table.get((row.law_index, row.formulation, row.speed_index), housing, p_v)
    });
    DriveBalanceRow {
        torque_index: row.torque_index,
        speed_index: row.speed_index,
        law_index: row.law_index,
        formulation: row.formulation,
        balance,
        loss: loss_at(base, scene, row, t),
        dissipation: housing.dissipation(t),
        heat_transfer_coefficient: housing.heat_transfer_coefficient(t),
        rating: ratings.and_then(|r| r.at_limit),
        rating_95: ratings.and_then(|r| r.at_95),
    }
}
