//! The drive cycle's plots: cycle.svg (the speed trace, the box's mean loss power on each
//! interval, the sump temperature, the cumulative loss energy in drive and in recuperation) and
//! cycle_map.svg (the box's η over output torque × speed with the time the cycle spends at each
//! cell as circles). They read the report's series only.

use crate::render::svg::maps::{heat_maps, Map};
use crate::render::svg::{figure, Panel};
use crate::report::drive_cycle::DriveCycleReport;

pub(crate) const TRACE_FILE: &str = "cycle.svg";
pub(crate) const MAP_FILE: &str = "cycle_map.svg";
/// η below this is left blank on the map, so that the colours resolve where the cycle drives.
const SHOWN_FROM: f64 = 0.9;

/// The column `name` of the series (NaN without it).
fn column(c: &DriveCycleReport, name: &str) -> std::vec::IntoIter<f64> {
    c.series.column(name).unwrap_or_else(|| vec![f64::NAN; c.series.values.len()]).into_iter()
}

pub(crate) fn trace(title: &str, c: &DriveCycleReport) -> Result<String, String> {
    let t0: Vec<f64> = column(c, "t_start_s").collect();
    let t1: Vec<f64> = column(c, "t_end_s").collect();
    let v0: Vec<f64> = column(c, "v_start_km_h").collect();
    let v1: Vec<f64> = column(c, "v_end_km_h").collect();
    let loss: Vec<f64> = column(c, "loss_J").collect();
    let wheel: Vec<f64> = column(c, "wheel_J").collect();
    let theta: Vec<f64> = column(c, "oil_temperature_end_C").collect();
    let mut speed = vec![(t0[0], v0[0])];
    speed.extend(t1.iter().copied().zip(v1.iter().copied()));
    // The mean loss power of each interval, drawn as a step.
    let mut power = Vec::new();
    for k in 0..t0.len() {
        let p = loss[k] / (t1[k] - t0[k]);
        power.push((t0[k], p));
        power.push((t1[k], p));
    }
    let (mut drive, mut recup) = (vec![(t0[0], 0.0)], vec![(t0[0], 0.0)]);
    let (mut sd, mut sr) = (0.0, 0.0);
    for k in 0..t0.len() {
        // An interval counts as drive or recuperation by the sign of its wheel energy (the
        // report's tables split its pieces exactly).
        if wheel[k] >= 0.0 {
            sd += loss[k] / 3600.0
        } else {
            sr += loss[k] / 3600.0
        }
        drive.push((t1[k], sd));
        recup.push((t1[k], sr));
    }
    let x_label = "time (s)".to_string();
    let mut panels = vec![
        Panel {
            y_label: "vehicle speed (km/h)".into(),
            x_label: x_label.clone(),
            xy: vec![("v(t)".into(), speed)],
            ..Default::default()
        },
        Panel {
            y_label: "gearbox loss power (W)".into(),
            x_label: x_label.clone(),
            xy: vec![("mean over each interval".into(), power)],
            ..Default::default()
        },
    ];
    if theta.iter().any(|x| x.is_finite()) {
        let mut path = vec![(t0[0], c.temperature.as_ref().map_or(f64::NAN, |t| t.start_c))];
        path.extend(t1.iter().copied().zip(theta.iter().copied()));
        panels.push(Panel {
            y_label: "sump temperature (°C)".into(),
            x_label: x_label.clone(),
            xy: vec![("θ at each interval's end".into(), path)],
            ..Default::default()
        });
    }
    panels.push(Panel {
        y_label: "cumulative gearbox loss (Wh)".into(),
        x_label,
        xy: vec![("in drive".into(), drive), ("in recuperation".into(), recup)],
        ..Default::default()
    });
    figure(&format!("{title}: \"{}\" with {}", c.name, c.vehicle), &panels)
}

pub(crate) fn map(title: &str, c: &DriveCycleReport) -> Result<String, String> {
    let m = &c.map;
    let eta: Vec<Vec<f64>> = m
        .efficiency
        .iter()
        .map(|row| {
            row.iter()
                .map(|e| match e {
                    Some(e) if *e >= SHOWN_FROM => 100.0 * e,
                    _ => f64::NAN,
                })
                .collect()
        })
        .collect();
    let mut marks = Vec::new();
    for (t, row) in m.seconds.iter().enumerate() {
        for (s, secs) in row.iter().enumerate() {
            if *secs > 0.0 {
                marks.push((m.speeds_rpm[s], m.torques[t], *secs));
            }
        }
    }
    let maps = [Map {
        title: "η % (blank: below 90 %; circles: time spent there)".into(),
        speeds: &m.speeds_rpm,
        torques: &m.torques,
        values: eta,
        x_label: "output speed (rpm)".into(),
        y_label: "output torque (N*m; < 0: recuperation)".into(),
        marks,
    }];
    heat_maps(&format!("{title}: \"{}\" over the box's efficiency", c.name), &maps)
}
