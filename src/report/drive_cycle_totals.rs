//! A drive cycle's totals (the whole cycle, or a phase: energies at the wheels, through the box and
//! at the motor, the losses with their error estimates, the cycle's efficiency both ways), its
//! located peaks and the sump's path with its books. Serde data of the cycle's report.

use serde::{Deserialize, Serialize};

use crate::evaluate::drive_cycle::{CycleEvaluation, CycleOil, PieceIntegrals, MOTOR, OUTPUT, PARTS};
use crate::vehicle::{Mode, Piece};

/// A stretch of the cycle (the whole, or a phase) in totals. Energies at the wheel in kWh, the
/// box's losses in Wh, each loss with its error estimate.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct CycleTotals {
    pub name: String,
    pub from_s: f64,
    pub to_s: f64,
    pub distance_km: f64,
    /// ∫ max(0, F v) dt and −∫ min(0, F v) dt at the wheels (kWh, exact).
    pub wheel_drive_kwh: f64,
    pub wheel_recuperation_kwh: f64,
    /// The part of the recuperation the brakes take beyond the limit (kWh).
    pub brakes_kwh: f64,
    /// Through the box's output: out of it while driving, into it while recuperating (kWh).
    pub box_drive_kwh: f64,
    pub box_recuperation_kwh: f64,
    /// The motor's energy out while driving and in while recuperating (kWh).
    pub motor_out_kwh: f64,
    pub motor_in_kwh: f64,
    pub loss_drive_wh: f64,
    pub loss_drive_error_wh: f64,
    pub loss_recuperation_wh: f64,
    pub loss_recuperation_error_wh: f64,
    /// Losses as % of the wheel energy of the same direction.
    pub loss_drive_percent: f64,
    pub loss_recuperation_percent: f64,
    /// Energy out of the box / energy into it, in drive and in recuperation (0 when none).
    pub efficiency_drive: f64,
    pub efficiency_recuperation: f64,
    pub loss_wh_per_km: f64,
    /// The sump at the stretch's end (°C), with the transient.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub end_temperature_c: Option<f64>,
}

/// A loss part over the cycle (Wh): in drive, in recuperation, the error estimate of both.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct CyclePart {
    pub part: String,
    pub drive_wh: f64,
    pub recuperation_wh: f64,
    pub error_wh: f64,
}

/// A located extreme: value and when (s).
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
pub struct Peak {
    pub value: f64,
    pub time_s: f64,
}

/// The sump over the cycle.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct CycleTemperature {
    pub start_c: f64,
    pub end_c: f64,
    pub max: Peak,
    /// θ's largest difference between the two collocation orders at a piece's end (K).
    pub error_k: f64,
    /// C (θ_end − θ_start) and E_lost − E_dissipated (J): the books.
    pub heat_stored_j: f64,
    pub lost_minus_dissipated_j: f64,
    pub heat_capacity_j_per_k: f64,
}

/// Totals of the pieces in [from, to].
pub(crate) fn totals(
    name: &str,
    (from, to): (f64, f64),
    pieces: &[Piece],
    eval: &CycleEvaluation,
    thermal: bool,
) -> CycleTotals {
    let mut t = CycleTotals { name: name.into(), from_s: from, to_s: to, ..Default::default() };
    let (mut out_drive, mut out_rec, mut last) = (0.0, 0.0, None);
    for (k, (p, r)) in pieces.iter().zip(&eval.integrals).enumerate() {
        if p.from < from || p.to > to {
            continue;
        }
        last = Some(k);
        t.distance_km += p.distance() / 1e3;
        let lost: f64 = r.value[..PARTS].iter().sum();
        let error: f64 = r.error[..PARTS].iter().sum();
        match p.mode {
            Mode::Drive => {
                t.wheel_drive_kwh += p.wheel_energy() / 3.6e6;
                t.motor_out_kwh += r.value[MOTOR] / 3.6e6;
                out_drive += r.value[OUTPUT];
                t.loss_drive_wh += lost / 3600.0;
                t.loss_drive_error_wh += error / 3600.0;
            }
            Mode::Coast | Mode::CoastCapped => {
                t.wheel_recuperation_kwh -= p.wheel_energy() / 3.6e6;
                t.brakes_kwh += (p.box_energy() - p.wheel_energy()) / 3.6e6;
                t.motor_in_kwh -= r.value[MOTOR] / 3.6e6;
                out_rec -= r.value[OUTPUT];
                t.loss_recuperation_wh += lost / 3600.0;
                t.loss_recuperation_error_wh += error / 3600.0;
            }
            Mode::Standing => {}
        }
    }
    (t.box_drive_kwh, t.box_recuperation_kwh) = (out_drive / 3.6e6, out_rec / 3.6e6);
    let ratio = |a: f64, b: f64| if b > 0.0 { a / b } else { 0.0 };
    t.loss_drive_percent = ratio(100.0 * t.loss_drive_wh, 1e3 * t.wheel_drive_kwh);
    t.loss_recuperation_percent = ratio(100.0 * t.loss_recuperation_wh, 1e3 * t.wheel_recuperation_kwh);
    t.efficiency_drive = ratio(out_drive, 3.6e6 * t.motor_out_kwh);
    t.efficiency_recuperation = ratio(3.6e6 * t.motor_in_kwh, out_rec);
    t.loss_wh_per_km = ratio(t.loss_drive_wh + t.loss_recuperation_wh, t.distance_km);
    if thermal {
        t.end_temperature_c = last.and_then(|k| eval.thermal.get(k)).map(|th| th.end - 273.15);
    }
    t
}

/// The sump's path: start, end, the located maximum, the error estimate and the books.
pub(crate) fn temperature(eval: &CycleEvaluation) -> Option<CycleTemperature> {
    let CycleOil::Transient { start, c } = eval.oil else { return None };
    let last = eval.thermal.last()?;
    let mut max = Peak { value: start, time_s: eval.pieces.first().map_or(0.0, |p| p.from) };
    for th in &eval.thermal {
        if th.highest.0 > max.value {
            max = Peak { value: th.highest.0, time_s: th.highest.1 };
        }
    }
    let lost: f64 = eval.integrals.iter().map(|r: &PieceIntegrals| r.value[..PARTS].iter().sum::<f64>()).sum();
    let dissipated: f64 = eval.thermal.iter().map(|t| t.dissipated).sum();
    Some(CycleTemperature {
        start_c: start - 273.15,
        end_c: last.end - 273.15,
        max: Peak { value: max.value - 273.15, time_s: max.time_s },
        error_k: eval.thermal.iter().map(|t| t.error).fold(0.0, f64::max),
        heat_stored_j: c * (last.end - start),
        lost_minus_dissipated_j: lost - dissipated,
        heat_capacity_j_per_k: c,
    })
}
