//! A vehicle's drive cycle in the drive's report: the vehicle and trace as read, the cycle's
//! energies at the wheel, through the box and at the motor, the box's losses in drive and in
//! recuperation with their error estimates, by part and by phase, the peaks (located), the sump's
//! temperature, and the per-interval series (report.json; cycle_records.csv). Serde data.

use serde::{Deserialize, Serialize};

pub(crate) use super::drive_cycle_series::CycleMap;
use super::drive_cycle_series::{series, CycleSeries};
use super::drive_cycle_totals::{temperature, totals};
pub(crate) use super::drive_cycle_totals::{CyclePart, CycleTemperature, CycleTotals, Peak};
use super::finding::{Finding, Severity};
use crate::evaluate::cycle_bearings::CycleBearingLoads;
use crate::evaluate::drive_cycle::{CycleEvaluation, CycleOil, PARTS, QUANTITIES};
use crate::model::{DriveCycleSpec, Scene, SceneDrive};
use crate::vehicle::Mode;

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
    /// The law's notes on this stage (an input read at a bound of its range), by kind: the first
    /// piece's note, where that piece starts (s), the pieces and seconds they hold for.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub notes: Vec<CycleNote>,
}

/// A law's note over the cycle's pieces.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct CycleNote {
    pub note: String,
    pub first_s: f64,
    pub pieces: usize,
    pub seconds: f64,
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
    /// Switches of the losses' form located inside the pieces, where the integrals are cut
    /// further (a shaft passing Palmgren's ν n = 2000; in coast, the power through a stage
    /// reversing).
    #[serde(default)]
    pub switches: usize,
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

/// The cycle's report.
pub(crate) fn build_cycle_report(
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
    let ratio = crate::drive::walk::overall_ratio(&drive.layout) * car.final_ratio;
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
        switches: eval.switches,
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
                notes: v
                    .notes
                    .iter()
                    .map(|(note, first_s, pieces, seconds)| CycleNote {
                        note: note.clone(),
                        first_s: *first_s,
                        pieces: *pieces,
                        seconds: *seconds,
                    })
                    .collect(),
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
    report.findings.extend(overloaded_on_the_cycle(drive, &eval.bearings));
    report
}

/// The bearing places beyond their static rating at the cycle's torque extremes (the cycle's own
/// states, which its operating points and map need not reach; `evaluate/cycle_bearings.rs`).
fn overloaded_on_the_cycle(drive: &SceneDrive, c: &CycleBearingLoads) -> Vec<Finding> {
    let units = super::units::Units::of_system(super::drive_inputs::drive_unit_system(drive));
    let places = super::bearing_checks::drive_places(&drive.layout, units);
    let words = |i: usize| {
        let (t, torque) = c.peaks[i].unwrap_or_default();
        format!(
            "the cycle's {} ({} at {} s)",
            ["greatest output torque", "greatest recuperation torque"][i.min(1)],
            units.torque().with(torque, 1),
            crate::numerics::rounding::fixed(t, 2)
        )
    };
    super::bearing_checks::overloaded(places, &c.loads, &words)
        .into_iter()
        .map(|f| Finding { message: format!("drive cycle: {}", f.message), ..f })
        .collect()
}

/// The output torques and speeds (N·m, rad/s at the box's output) the scene defines besides the
/// cycle: its operating points and its map (given at the input: through the ratio, losses aside).
fn ranges(scene: &Scene, drive: &SceneDrive) -> Vec<Range> {
    use crate::drive::ShaftEnd;
    let ratio = crate::drive::walk::overall_ratio(&drive.layout).abs();
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
    let total = report.whole.to_s - report.whole.from_s;
    for v in &report.validity {
        for n in &v.notes {
            out.push(Finding {
                severity: Severity::Note,
                message: format!(
                    "drive cycle: stage `{}`: for {} s ({} % of the cycle's {} s, {} pieces) the law notes — {} (at the first such piece, {} s)",
                    v.stage,
                    crate::numerics::rounding::fixed(n.seconds, 1),
                    crate::numerics::rounding::fixed(100.0 * n.seconds / total.max(f64::MIN_POSITIVE), 1),
                    crate::numerics::rounding::fixed(total, 0),
                    n.pieces,
                    n.note,
                    crate::numerics::rounding::fixed(n.first_s, 2)
                ),
            });
        }
    }
    for CycleValidity { stage, pieces, seconds, first_s, reason, .. } in &report.validity {
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
