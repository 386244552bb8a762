//! The drive cycle's per-interval series (one row per interval of the trace, the pieces of an
//! interval summed) and the time the cycle spends over the box's map: what report.json carries
//! and cycle_records.csv writes.

use serde::{Deserialize, Serialize};

use crate::evaluate::drive_cycle::{box_load, CycleEvaluation, ANGLE, MOTOR, N, PARTS};
use crate::model::DriveCycleSpec;
use crate::numerics::rounding::round_sig;
use crate::vehicle::Mode;

/// Columns of the series: one value per interval each (ten significant digits). Forces, torques
/// and speeds at an interval's start and end are the one-sided limits inside it; energies are the
/// interval's (J); the sump's temperature at its end only with the transient.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct CycleSeries {
    pub columns: Vec<String>,
    pub values: Vec<Vec<f64>>,
}

impl CycleSeries {
    /// The column `name`, if the series has it.
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let k = self.columns.iter().position(|c| c == name)?;
        Some(self.values.iter().map(|r| r[k]).collect())
    }

    /// cycle_records.csv: the columns, then a row per interval.
    pub fn to_csv(&self) -> String {
        let mut out = self.columns.join(",");
        out.push('\n');
        for r in &self.values {
            let cells: Vec<String> = r.iter().map(|x| x.to_string()).collect();
            out.push_str(&cells.join(","));
            out.push('\n');
        }
        out
    }
}

/// The records file of a cycle.
pub(crate) const FILE: &str = "cycle_records.csv";

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

/// The series' columns, in order.
pub(crate) const COLUMNS: [&str; 24] = [
    "t_start_s",
    "t_end_s",
    "v_start_km_h",
    "v_end_km_h",
    "force_start_N",
    "force_end_N",
    "wheel_torque_start_N_m",
    "wheel_torque_end_N_m",
    "wheel_speed_start_rpm",
    "wheel_speed_end_rpm",
    "motor_speed_start_rpm",
    "motor_speed_end_rpm",
    "motor_mean_torque_N_m",
    "loss_J",
    "loss_error_J",
    "meshes_J",
    "gear_no_load_J",
    "bearings_no_load_J",
    "bearings_load_J",
    "seals_J",
    "motor_J",
    "wheel_J",
    "brakes_J",
    "oil_temperature_end_C",
];

const RPM: f64 = 30.0 / std::f64::consts::PI;

/// One row per interval of the trace.
pub(crate) fn series(spec: &DriveCycleSpec, eval: &CycleEvaluation, motor_per_wheel: f64) -> CycleSeries {
    let car = &spec.cycle.vehicle;
    let tr = &spec.cycle.trace;
    let intervals = tr.time.len() - 1;
    let mut sums = vec![[0.0; N]; intervals];
    let mut errors = vec![0.0; intervals];
    let mut wheel = vec![0.0; intervals];
    let mut brakes = vec![0.0; intervals];
    let mut first = vec![None; intervals];
    let mut last = vec![0; intervals];
    for (k, (p, r)) in eval.pieces.iter().zip(&eval.integrals).enumerate() {
        let i = p.interval;
        for (sum, v) in sums[i].iter_mut().zip(&r.value) {
            *sum += v;
        }
        errors[i] += r.error[..PARTS].iter().sum::<f64>();
        wheel[i] += p.wheel_energy();
        brakes[i] += p.box_energy() - p.wheel_energy();
        first[i].get_or_insert(k);
        last[i] = k;
    }
    let rows = (0..intervals)
        .map(|i| {
            let (a, b) = (&eval.pieces[first[i].expect("every interval has a piece")], &eval.pieces[last[i]]);
            let force = |p: &crate::vehicle::Piece, t: f64| if p.mode == Mode::Standing { 0.0 } else { p.force(t) };
            let (f0, f1) = (force(a, a.from), force(b, b.to));
            let wheel_rpm = |v: f64| v / car.wheel_radius * RPM;

            let mut row = vec![
                tr.time[i],
                tr.time[i + 1],
                tr.speed[i] * 3.6,
                tr.speed[i + 1] * 3.6,
                f0,
                f1,
                f0 * car.wheel_radius,
                f1 * car.wheel_radius,
                wheel_rpm(tr.speed[i]),
                wheel_rpm(tr.speed[i + 1]),
                wheel_rpm(tr.speed[i]) * motor_per_wheel.abs(),
                wheel_rpm(tr.speed[i + 1]) * motor_per_wheel.abs(),
                if sums[i][ANGLE] > 0.0 { sums[i][MOTOR] / sums[i][ANGLE] } else { 0.0 },
                sums[i][..PARTS].iter().sum(),
                errors[i],
            ];
            row.extend(&sums[i][..PARTS]);
            row.extend([sums[i][MOTOR], wheel[i], brakes[i]]);
            if let Some(t) = eval.thermal.get(last[i]) {
                row.push(t.end - 273.15);
            }
            row.into_iter().map(round_sig).collect()
        })
        .collect();
    let shown = if eval.thermal.is_empty() { COLUMNS.len() - 1 } else { COLUMNS.len() };
    CycleSeries { columns: COLUMNS[..shown].iter().map(|c| c.to_string()).collect(), values: rows }
}

/// The map with the seconds the cycle spends in each of its cells (the Gauss nodes of every
/// moving piece, weighted by their share of its time).
pub(crate) fn cycle_map(spec: &DriveCycleSpec, eval: &CycleEvaluation) -> CycleMap {
    let (torques, speeds, eta) = eval.map.clone();
    let efficiency = eta.iter().map(|r| r.iter().map(|e| e.is_finite().then(|| round_sig(*e))).collect()).collect();
    let mut seconds = vec![vec![0.0; speeds.len()]; torques.len()];
    let nearest = |grid: &[f64], x: f64| {
        (0..grid.len()).min_by(|&a, &b| (grid[a] - x).abs().total_cmp(&(grid[b] - x).abs())).unwrap_or(0)
    };
    if !torques.is_empty() {
        let (x, w) = crate::numerics::quadrature::gauss_legendre(crate::evaluate::drive_cycle::HIGH_ORDER);
        for p in eval.pieces.iter().filter(|p| p.mode != Mode::Standing) {
            let h = p.to - p.from;
            for (x, w) in x.iter().zip(&w) {
                let (torque, speed) = box_load(spec, p, p.from + x * h);
                seconds[nearest(&torques, torque)][nearest(&speeds, speed)] += w * h;
            }
        }
    }
    let seconds = seconds.into_iter().map(|r| r.into_iter().map(round_sig).collect()).collect();
    let round = |v: Vec<f64>| v.into_iter().map(round_sig).collect();
    CycleMap {
        torques: round(torques),
        speeds_rpm: round(speeds.iter().map(|w| w * RPM).collect()),
        efficiency,
        seconds,
    }
}
