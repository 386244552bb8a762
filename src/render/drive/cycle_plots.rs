//! The drive cycle's plots: cycle.svg (the speed trace, the box's mean loss power on each
//! interval, the sump temperature, the cumulative loss energy in drive and in recuperation) and
//! cycle_map.svg (the box's η over output torque × speed with the time the cycle spends at each
//! cell as circles). They read the report's series only.

use plotters::prelude::*;

use crate::render::svg::{draw_field, figure, fitted, Field, Panel};
use crate::report::drive_cycle::DriveCycleReport;

pub(crate) const TRACE_FILE: &str = "cycle.svg";
pub(crate) const MAP_FILE: &str = "cycle_map.svg";
/// cycle_map.svg's width (px).
const WIDTH: u32 = 1000;

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
    // The mean loss power of each interval, drawn as a step: in drive and in recuperation apart
    // (an interval by the sign of its wheel energy), each curve broken where the other runs.
    let (mut power_drive, mut power_recup) = (Vec::new(), Vec::new());
    for k in 0..t0.len() {
        let p = loss[k] / (t1[k] - t0[k]);
        let (on, off) =
            if wheel[k] >= 0.0 { (&mut power_drive, &mut power_recup) } else { (&mut power_recup, &mut power_drive) };
        on.push((t0[k], p));
        on.push((t1[k], p));
        if off.last().is_some_and(|l: &(f64, f64)| l.1.is_finite()) {
            off.push((t0[k], f64::NAN));
        }
    }
    // The scene's phases, shaded and named on every panel.
    let phases: Vec<(f64, f64, String)> = c.phases.iter().map(|p| (p.from_s, p.to_s, p.name.clone())).collect();
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
            bands: phases.clone(),
            ..Default::default()
        },
        Panel {
            y_label: "gearbox loss power (W)".into(),
            x_label: x_label.clone(),
            xy: vec![
                ("mean over each interval, in drive".into(), power_drive),
                ("mean over each interval, in recuperation".into(), power_recup),
            ],
            bands: phases.clone(),
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
            bands: phases.clone(),
            ..Default::default()
        });
    }
    panels.push(Panel {
        y_label: "cumulative gearbox loss (Wh)".into(),
        x_label,
        xy: vec![("in drive".into(), drive), ("in recuperation".into(), recup)],
        bands: phases,
        ..Default::default()
    });
    figure(&format!("{title}: \"{}\" with {}", c.name, c.vehicle), &panels)
}

/// cycle_map.svg: η over output torque × speed as the loss map draws it (bands between iso-levels
/// over the upper nine tenths of the values, the iso-lines labelled, a colour bar), every cell
/// shown (η falls to 0 at zero torque, where no power passes: the lowest band), and the time the
/// cycle spends at each cell as red circles.
pub(crate) fn map(title: &str, c: &DriveCycleReport, u: super::shown_units::Shown) -> Result<String, String> {
    let m = &c.map;
    let speeds: Vec<f64> = m.speeds_rpm.iter().map(|x| u.speed.of_rpm(*x)).collect();
    let torques: Vec<f64> = m.torques.iter().map(|x| u.torque.of_si(*x)).collect();
    let eta: Vec<Vec<f64>> = m
        .efficiency
        .iter()
        .map(|row| row.iter().map(|e| e.map_or(f64::NAN, |e| 100.0 * e.max(0.0))).collect())
        .collect();
    let mut marks = Vec::new();
    for (t, row) in m.seconds.iter().enumerate() {
        for (s, secs) in row.iter().enumerate() {
            if *secs > 0.0 {
                marks.push((speeds[s], torques[t], *secs));
            }
        }
    }
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (WIDTH, 600)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let heading = format!("{title}: \"{}\" over the box's efficiency", c.name);
        let root = root.titled(&heading, ("sans-serif", fitted(&heading, WIDTH, 18.0))).map_err(|e| e.to_string())?;
        if m.speeds_rpm.len() >= 2 && m.torques.len() >= 2 {
            let field = Field {
                title: "η, ○ time spent at each cell".into(),
                speeds: &speeds,
                torques: &torques,
                values: eta,
                unit: "%",
            };
            let x_label = format!("output speed ({})", u.speed.unit());
            let y_label = format!("output torque ({}; < 0: recuperation)", u.torque.unit());
            let axes = (x_label.as_str(), y_label.as_str());
            draw_field(&root, &field, axes, (&[], &marks))?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}
