//! Dynamics plots: the periodic response at one operating point, the stability map and the
//! work-precision diagram of the numerics study.

use super::panel::{figure, Panel};
use crate::report::Report;

/// Curves `(label, [(τ, SI value)])` in a shown unit.
fn shown(curves: &[(String, Vec<(f64, f64)>)], unit: crate::report::units::Shown) -> Vec<(String, Vec<(f64, f64)>)> {
    curves.iter().map(|(l, v)| (l.clone(), v.iter().map(|(t, x)| (*t, unit.value(*x))).collect())).collect()
}

/// dynamics_point_K.svg: DTE over the steady-state cycle, mesh force per pair, friction force, DTE spectrum.
pub fn dynamics_point(r: &Report, k: usize) -> Result<String, String> {
    let d = r.dynamics.as_ref().ok_or("no dynamics in the report")?;
    let c = &d.curves[k];
    let tau_panel = |y: &str, xy: Vec<(String, Vec<(f64, f64)>)>| Panel {
        y_label: y.into(),
        x_label: "time in mesh periods (0: a pair enters at A)".into(),
        xy,
        marks: c.marks.clone(),
        ..Default::default()
    };
    let orders: Vec<f64> = (1..=c.spectrum.first().map_or(0, |s| s.1.len())).map(|o| o as f64).collect();
    let u = r.units();
    let (micro, force) = (u.micro(), u.force());
    let second = if c.oloa.is_empty() {
        tau_panel(&force.titled("tooth force per pair"), shown(&c.pair_force, force))
    } else {
        tau_panel(&force.titled("OLOA bearing force K_y y"), shown(&c.oloa, force))
    };
    let panels = [
        tau_panel(&micro.titled("DTE x"), shown(&c.dte, micro)),
        second,
        tau_panel(&force.titled("applied friction force Σ μ w N"), shown(&c.friction_force, force)),
        Panel {
            y_label: micro.titled("DTE harmonic amplitude"),
            x_label: "mesh order".into(),
            x: orders,
            series: c.spectrum.iter().map(|(l, v)| (l.clone(), v.iter().map(|x| micro.value(*x)).collect())).collect(),
            ..Default::default()
        },
    ];
    figure(&format!("{}: dynamics at {}", r.title, c.label), &panels)
}

/// free_response_point_K.svg: the free (homogeneous) DTE from the scene's initial state (He & Singh
/// Figs 8–9), per formulation: its first three mesh periods in full, and over the whole window the
/// largest |DTE| of each period (from the plot samples; the located peaks are in report.md), which
/// shows growth or decay where forty periods of a fast oscillation would draw a solid band.
pub fn free_response(r: &Report, k: usize) -> Result<String, String> {
    let d = r.dynamics.as_ref().ok_or("no dynamics in the report")?;
    let c = &d.curves[k];
    const SHOWN: f64 = 3.0;
    let micro = r.units().micro();
    let first = c
        .free
        .iter()
        .map(|(l, v)| (l.clone(), v.iter().filter(|(t, _)| *t <= SHOWN).map(|(t, x)| (*t, micro.value(*x))).collect()))
        .collect();
    let envelope = c
        .free
        .iter()
        .map(|(l, v)| {
            let mut peaks: Vec<(f64, f64)> = Vec::new();
            for (t, x) in v {
                let period = t.floor().max(0.0);
                match peaks.last_mut() {
                    Some(p) if p.0 == period + 0.5 => p.1 = p.1.max(micro.value(x.abs())),
                    _ => peaks.push((period + 0.5, micro.value(x.abs()))),
                }
            }
            (l.clone(), peaks)
        })
        .collect();
    let panels = [
        Panel {
            y_label: micro.titled("free DTE"),
            x_label: format!("time in mesh periods (the first {SHOWN})"),
            xy: first,
            ..Default::default()
        },
        Panel {
            y_label: micro.titled("largest |DTE| in the period"),
            x_label: "mesh period (its middle)".into(),
            xy: envelope,
            ..Default::default()
        },
    ];
    figure(&format!("{}: free response at {}", r.title, c.label), &panels)
}

/// stability_map.svg: spectral radius and dynamic factor against speed, per formulation.
pub fn stability_map(r: &Report) -> Result<String, String> {
    use crate::report::friction::MuValue;
    let map = r.dynamics.as_ref().and_then(|d| d.stability_map.as_ref()).ok_or("no stability map")?;
    let x: Vec<f64> = map.points.iter().map(|p| map.speed_unit.value(&p.pinion_speed)).collect();
    let x_label = format!("pinion speed ({})", map.speed_unit.name);
    let names: Vec<String> = map.formulations.iter().map(|f| f.name().to_string()).collect();
    let mut rho: Vec<(String, Vec<f64>)> = names
        .iter()
        .enumerate()
        .map(|(i, n)| (n.clone(), map.points.iter().map(|p| p.spectral_radius[i].0).collect()))
        .collect();
    rho.push(("ρ = 1".into(), vec![1.0; x.len()]));
    let kv = names
        .iter()
        .enumerate()
        .map(|(i, n)| {
            let ys = map
                .points
                .iter()
                .map(|p| match p.dynamic_factor[i] {
                    MuValue::Value(v) => v.0,
                    MuValue::Text(_) => f64::NAN,
                })
                .collect();
            (n.clone(), ys)
        })
        .collect();
    let panels = [
        Panel {
            y_label: "spectral radius ρ".into(),
            x_label: x_label.clone(),
            x: x.clone(),
            series: rho,
            ..Default::default()
        },
        Panel { y_label: "dynamic factor (stable speeds)".into(), x_label, x, series: kv, ..Default::default() },
    ];
    figure(&format!("{}: stability map at {:.1} N·m", r.title, map.pinion_torque.si()), &panels)
}

/// timing_work_precision.svg: log10 run time against log10 error, one full curve per method through
/// every tolerance it ran (in ladder order), the exact/Magnus reference as a point at the error floor,
/// failed runs marked at the worst error seen (machine-dependent: never snapshotted).
pub fn work_precision(r: &Report, t: &crate::report::numerics::Timings) -> Result<String, String> {
    let mut methods: Vec<String> = t.runs.iter().map(|x| x.0.clone()).collect();
    methods.dedup();
    let ok = |e: Option<f64>| e.is_some_and(|e| e.is_finite() && e > 0.0);
    let errors = || t.runs.iter().filter(|x| ok(x.2)).filter_map(|x| x.2);
    let floor = errors().fold(f64::INFINITY, f64::min);
    let worst = errors().fold(0.0f64, f64::max);
    let xy = methods
        .iter()
        .map(|m| {
            let pts = t
                .runs
                .iter()
                .filter(|r| r.0 == *m && r.3 > 0.0)
                .filter_map(|r| r.2.filter(|e| ok(Some(*e))).map(|e| (e.log10(), r.3.log10())))
                .collect();
            (m.clone(), pts)
        })
        .collect();
    let mut points = Vec::new();
    if t.reference_seconds > 0.0 && floor.is_finite() {
        points.push((
            "exact/Magnus reference (error ≈ 0)".to_string(),
            vec![(floor.log10() - 1.0, t.reference_seconds.log10())],
        ));
    }
    let failed: Vec<(f64, f64)> = t
        .runs
        .iter()
        .filter(|r| !ok(r.2) && r.3 > 0.0 && r.3.is_finite())
        .map(|r| (worst.max(1e-16).log10() + 0.5, r.3.log10()))
        .collect();
    if !failed.is_empty() {
        points.push(("failed run (placed right of the worst error)".to_string(), failed));
    }
    let panel = Panel {
        y_label: "log10 run time (s)".into(),
        x_label: "log10 error (max |x − x_ref| / peak-to-peak DTE)".into(),
        xy,
        points,
        ..Default::default()
    };
    figure(&format!("{}: work-precision (this machine)", r.title), &[panel])
}
