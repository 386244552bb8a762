//! A drive's thermal balance (one sump, one thermal node, as for one pair): at each operating point,
//! law and formulation, the oil temperature θ* where the drive's whole loss P_V(θ) (every mesh,
//! gear, bearing and seal of the drive at the oil read at θ) equals what the housing gives off,
//! P_Q(θ) ([`crate::thermal::balance`]: the lowest root, bracketed by a scan and located by Brent).

use super::drive_setup::{DriveRow, DriveSetup};
use crate::drive::EndValue;
use crate::model::{Given, Scene, SceneDrive, ThermodynamicTemperature};
use crate::thermal::{Balance, Housing};

/// The balance of one operating point, law and formulation, with the drive's loss and the housing's
/// dissipation at θ*.
#[derive(Debug, Clone)]
pub struct DriveBalanceRow {
    pub torque_index: usize,
    pub speed_index: usize,
    pub law_index: usize,
    pub formulation: crate::efficiency::Formulation,
    pub balance: Balance,
    /// P_V(θ*) and P_Q(θ*) (W); None without a balance.
    pub loss: Option<f64>,
    pub dissipation: Option<f64>,
}

/// P_V(θ) of the drive at `row`'s point, law and formulation (W).
fn loss_at(scene: &Scene, drive: &SceneDrive, row: &DriveRow, theta: f64) -> f64 {
    let given = Given {
        value: ThermodynamicTemperature::new::<uom::si::thermodynamic_temperature::kelvin>(theta),
        written: format!("{theta} K"),
        span: Default::default(),
    };
    let at = scene.at_temperature(given);
    let setup = DriveSetup::new(&at, drive);
    let op = &scene.operating;
    let ends = drive.layout.operating;
    let torque = EndValue { at: ends.torque_at, value: op.pinion_torque.values[row.torque_index].value };
    let speed = EndValue { at: ends.speed_at, value: op.pinion_speed.values[row.speed_index].value };
    setup.point(row.law_index, row.formulation, torque, speed).power_lost()
}

/// The balance at every row of the operating points.
pub(crate) fn drive_balances(
    scene: &Scene,
    drive: &SceneDrive,
    housing: &Housing,
    rows: &[DriveRow],
) -> Vec<DriveBalanceRow> {
    use rayon::prelude::*;
    rows.par_iter()
        .map(|row| {
            let balance = crate::thermal::balance(|theta| loss_at(scene, drive, row, theta), housing);
            let loss = balance.temperature.map(|t| loss_at(scene, drive, row, t));
            DriveBalanceRow {
                torque_index: row.torque_index,
                speed_index: row.speed_index,
                law_index: row.law_index,
                formulation: row.formulation,
                balance,
                loss,
                dissipation: balance.temperature.map(|t| housing.dissipation(t).total),
            }
        })
        .collect()
}
