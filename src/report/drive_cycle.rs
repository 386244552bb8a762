//! A vehicle's drive cycle in the drive's report: the vehicle and trace as read, the cycle's
//! energies at the wheel, through the box and at the motor, the box's losses in drive and in
//! recuperation with their error estimates, by part and by phase, the peaks (located), the sump's
//! temperature, and the per-interval series (report.json; cycle_records.csv). Serde data.

use serde::{Deserialize, Serialize};

use super::drive_cycle_series::{series, CycleSeries};
use super::finding::{Finding, Severity};
use crate::evaluate::drive_cycle::{CycleEvaluation, CycleOil, PieceIntegrals, MOTOR, OUTPUT, PARTS, QUANTITIES};
use crate::model::{DriveCycleSpec, Scene, SceneDrive};
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

/// The box's η over the output torque × speed the cycle reaches, with the time the cycle spends
/// in each cell (s), for the plot.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct CycleMap {
    pub torques: Vec<f64>,
    pub speeds_rpm: Vec<f64>,
    /// None where both ends deliver.
    pub efficiency: Vec<Vec<Option<f64>>>,
    /// [torque cell][speed cell] seconds, cells centred on the grid's values.
    pub seconds: Vec<Vec<f64>>,
}

/// Where a stage's law is outside its validity range over the cycle (read at each piece's middle).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct CycleValidity {
    pub stage: String,
    pub pieces: usize,
    pub seconds: f64,
    /// The first such piece's start (s) and the law's reason.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_s: Option<f64>,
    pub reason: String,
}

/// The drive cycle's report.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct DriveCycleReport {
    pub name: String,
    pub vehicle: String,
    pub trace_file: String,
    pub law: String,
    pub formulation: String,
    /// The oil: "fixed at 80 °C" or "from 25 °C, the sump's transient".
    pub oil: String,
    /// The vehicle as written, then what is derived from it (what, value, unit).
    pub vehicle_written: Vec<(String, String)>,
    pub vehicle_derived: Vec<(String, f64, String)>,
    /// Samples, duration (s), distance (km), v_max (km/h), mean speed (km/h).
    pub samples: usize,
    pub pieces: usize,
    pub whole: CycleTotals,
    pub phases: Vec<CycleTotals>,
    pub parts: Vec<CyclePart>,
    /// Wheel torque (N·m) in drive and in recuperation, motor speed (rpm), v_max (km/h).
    pub peak_wheel_torque: Peak,
    pub peak_recuperation_torque: Peak,
    pub peak_motor_speed_rpm: Peak,
    pub peak_speed_kmh: Peak,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub temperature: Option<CycleTemperature>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub failure: Option<String>,
    /// By stage: (stage, pieces and seconds where its law is outside its validity range at the
    /// piece's middle, the first one's time (s) and reason).
    pub validity: Vec<CycleValidity>,
    pub map: CycleMap,
    pub series: CycleSeries,
    /// What the reader must know (also among the drive report's findings).
    pub findings: Vec<Finding>,
}

/// Totals of the pieces in [from, to].
fn totals(name: &str, (from, to): (f64, f64), pieces: &[Piece], eval: &CycleEvaluation, thermal: bool) -> CycleTotals {
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

/// The cycle's report.
pub fn build_cycle_report(
    scene: &Scene,
    drive: &SceneDrive,
    spec: &DriveCycleSpec,
    eval: &CycleEvaluation,
) -> DriveCycleReport {
    let car = &spec.cycle.vehicle;
    let trace = &spec.cycle.trace;
    let pieces = &eval.pieces;
    let thermal = !eval.thermal.is_empty();
    let span = (trace.time[0], trace.time[trace.time.len() - 1]);
    let whole = totals("whole cycle", span, pieces, eval, thermal);
    let phases = spec.cycle.phases.iter().map(|p| totals(&p.name, (p.from, p.to), pieces, eval, thermal)).collect();
    let ratio = overall_ratio(drive) * car.final_ratio;
    let (f0, f1, f2) = car.road_coefficients(0.0);
    let vehicle_derived = vec![
        ("effective mass m_eff".to_string(), car.effective_mass(), "kg".to_string()),
        ("road load f0 (level)".into(), f0, "N".into()),
        ("road load f1".into(), f1, "N*s/m".into()),
        ("road load f2".into(), f2, "N*s^2/m^2".into()),
        ("motor speed / wheel speed".into(), ratio, "1".into()),
    ];
    let mut parts = Vec::new();
    for (k, name) in QUANTITIES.iter().enumerate().take(PARTS) {
        let (mut d, mut c, mut e) = (0.0, 0.0, 0.0);
        for (p, r) in pieces.iter().zip(&eval.integrals) {
            match p.mode {
                Mode::Drive => d += r.value[k],
                Mode::Coast | Mode::CoastCapped => c += r.value[k],
                Mode::Standing => {}
            }
            e += r.error[k];
        }
        parts.push(CyclePart {
            part: name.replace('_', " "),
            drive_wh: d / 3600.0,
            recuperation_wh: c / 3600.0,
            error_wh: e / 3600.0,
        });
    }
    let (mut top, mut bottom) = (Peak { value: 0.0, time_s: span.0 }, Peak { value: 0.0, time_s: span.0 });
    for p in pieces.iter().filter(|p| p.mode != Mode::Standing) {
        let ((hi, t_hi), (lo, t_lo)) = p.force_extremes();
        if hi * car.wheel_radius > top.value {
            top = Peak { value: hi * car.wheel_radius, time_s: t_hi };
        }
        if lo * car.wheel_radius < bottom.value {
            bottom = Peak { value: lo * car.wheel_radius, time_s: t_lo };
        }
    }
    let fastest = (0..trace.speed.len()).fold(0, |m, k| if trace.speed[k] > trace.speed[m] { k } else { m });
    let peak_speed = Peak { value: trace.speed[fastest] * 3.6, time_s: trace.time[fastest] };
    let motor_rpm = trace.speed[fastest] / car.wheel_radius * ratio.abs() * 30.0 / std::f64::consts::PI;
    let mut report = DriveCycleReport {
        name: spec.name.clone(),
        vehicle: spec.vehicle_name.clone(),
        trace_file: spec.trace_file.clone(),
        law: scene.friction[eval.law_index].label(),
        formulation: eval.formulation.name().to_string(),
        oil: match eval.oil {
            CycleOil::Fixed(t) => format!("fixed at {} °C", crate::numerics::rounding::fixed(t - 273.15, 1)),
            CycleOil::Transient { start, c } => format!(
                "the sump's transient from {} °C, heat capacity {} kJ/K",
                crate::numerics::rounding::fixed(start - 273.15, 1),
                crate::numerics::rounding::fixed(c / 1e3, 2)
            ),
        },
        vehicle_written: spec.written.clone(),
        vehicle_derived,
        samples: trace.time.len(),
        pieces: pieces.len(),
        whole,
        phases,
        parts,
        peak_wheel_torque: top,
        peak_recuperation_torque: bottom,
        peak_motor_speed_rpm: Peak { value: motor_rpm, time_s: peak_speed.time_s },
        peak_speed_kmh: peak_speed,
        temperature: temperature(eval),
        failure: eval.failure.clone(),
        validity: eval
            .validity
            .iter()
            .zip(&drive.layout.stages)
            .map(|(v, s)| CycleValidity {
                stage: s.name.clone(),
                pieces: v.pieces,
                seconds: v.seconds,
                first_s: v.first.map(|f| f.0),
                reason: v.first.map_or_else(String::new, |f| f.1.to_string()),
            })
            .collect(),
        map: super::drive_cycle_series::cycle_map(spec, eval),
        series: series(spec, eval, ratio),
        findings: Vec::new(),
    };
    let at_box = BoxPeaks {
        torque: top.value / car.final_ratio,
        recuperation: bottom.value / car.final_ratio,
        speed: trace.speed[fastest] / car.wheel_radius * car.final_ratio,
    };
    report.findings = cycle_findings(&report, &ranges(scene, drive), at_box);
    report
}

/// The output torques and speeds (N·m, rad/s at the box's output) the scene defines besides the
/// cycle: its operating points and its map (given at the input: through the ratio, losses aside).
fn ranges(scene: &Scene, drive: &SceneDrive) -> Vec<Range> {
    use crate::drive::ShaftEnd;
    let ratio = overall_ratio(drive).abs();
    let torque = |t: f64, at: ShaftEnd| if at == ShaftEnd::Input { t * ratio } else { t };
    let speed = |w: f64, at: ShaftEnd| if at == ShaftEnd::Input { w.abs() / ratio } else { w };
    let span = |v: &[f64]| v.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(*x), b.max(*x)));
    let mut out = Vec::new();
    let ends = drive.layout.operating;
    let op = &scene.operating;
    if !op.pinion_torque.values.is_empty() {
        let t: Vec<f64> = op.pinion_torque.values.iter().map(|x| torque(x.value, ends.torque_at)).collect();
        let w: Vec<f64> = op.pinion_speed.values.iter().map(|x| speed(x.value, ends.speed_at)).collect();
        out.push((span(&t), span(&w)));
    }
    if let (Some((t, w)), Some(e)) = (&scene.analyses.efficiency_map, scene.analyses.map_ends) {
        let t: Vec<f64> = t.values.iter().map(|x| torque(x.value, e.torque_at)).collect();
        let w: Vec<f64> = w.values.iter().map(|x| speed(x.value, e.speed_at)).collect();
        out.push((span(&t), span(&w)));
    }
    out
}

/// ω_in/ω_out of the chain (signed).
fn overall_ratio(drive: &SceneDrive) -> f64 {
    let layout = &drive.layout;
    let speeds = crate::drive::walk::shaft_speeds(
        layout,
        crate::drive::EndValue { at: crate::drive::ShaftEnd::Input, value: 1.0 },
    );
    1.0 / speeds[layout.output]
}

/// The sump's path: start, end, the located maximum, the error estimate and the books.
fn temperature(eval: &CycleEvaluation) -> Option<CycleTemperature> {
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

/// An operating range: (least, greatest) output torque (N·m) and speed (rad/s).
type Range = ((f64, f64), (f64, f64));

/// The cycle's peaks at the box's output: torque in drive and in recuperation (N·m), speed (rad/s).
#[derive(Clone, Copy)]
struct BoxPeaks {
    torque: f64,
    recuperation: f64,
    speed: f64,
}

/// What the reader must know about the cycle: a transient that stopped, energy to the brakes, a
/// law outside its validity range, peaks beyond every operating range the scene defines.
fn cycle_findings(report: &DriveCycleReport, ranges: &[Range], peaks: BoxPeaks) -> Vec<Finding> {
    let mut out = Vec::new();
    for CycleValidity { stage, pieces, seconds, first_s, reason } in &report.validity {
        if let (true, Some(t)) = (*pieces > 0, first_s) {
            out.push(Finding {
                severity: Severity::Warning,
                message: format!(
                    "drive cycle: stage `{stage}`: the law is outside its validity range on {pieces} pieces ({} s of the cycle), first at {} s ({reason})",
                    crate::numerics::rounding::fixed(*seconds, 1),
                    crate::numerics::rounding::fixed(*t, 2)
                ),
            });
        }
    }
    if !ranges.is_empty() {
        let BoxPeaks { torque: top_torque, recuperation: low_torque, speed: top_speed } = peaks;
        let words = |what: &str, value: String, t: f64| {
            format!("drive cycle: its peak {what} ({value} at {} s) lies outside every operating range the scene defines (its operating points and map)", crate::numerics::rounding::fixed(t, 2))
        };
        if ranges.iter().all(|(t, _)| top_torque > t.1) {
            out.push(Finding {
                severity: Severity::Warning,
                message: words(
                    "output torque",
                    format!("{} N·m", crate::numerics::rounding::fixed(top_torque, 1)),
                    report.peak_wheel_torque.time_s,
                ),
            });
        }
        if ranges.iter().all(|(t, _)| low_torque < t.0) {
            out.push(Finding {
                severity: Severity::Warning,
                message: words(
                    "recuperation torque",
                    format!("{} N·m", crate::numerics::rounding::fixed(low_torque, 1)),
                    report.peak_recuperation_torque.time_s,
                ),
            });
        }
        if ranges.iter().all(|(_, w)| top_speed > w.1 * (1.0 + 1e-12)) {
            out.push(Finding {
                severity: Severity::Warning,
                message: words(
                    "motor speed",
                    format!("{} rpm", crate::numerics::rounding::fixed(report.peak_motor_speed_rpm.value, 0)),
                    report.peak_motor_speed_rpm.time_s,
                ),
            });
        }
    }
    if let Some(f) = &report.failure {
        out.push(Finding { severity: Severity::Warning, message: format!("drive cycle: {f}") });
    }
    if report.whole.brakes_kwh > 0.0 {
        out.push(Finding {
            severity: Severity::Note,
            message: format!(
                "drive cycle: the recuperation limit sends {} kWh to the friction brakes",
                crate::numerics::rounding::fixed(report.whole.brakes_kwh, 4)
            ),
        });
    }
    out
}
