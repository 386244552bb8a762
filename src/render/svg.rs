//! SVG plots drawn with plotters' SVG backend (no system fonts: text is laid out by plotters' own estimate).
//! Every plot reads the report only.

use plotters::coord::Shift;
use plotters::prelude::*;

use crate::report::Report;

const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
    RGBColor(140, 86, 75),
    RGBColor(127, 127, 127),
];

/// One panel of a figure.
#[derive(Default)]
pub struct Panel {
    pub y_label: String,
    pub x_label: String,
    pub x: Vec<f64>,
    /// (legend label, y); non-finite y values are left out.
    pub series: Vec<(String, Vec<f64>)>,
    /// Series on their own x values: (legend label, [(x, y)]), drawn after `series` in the same palette.
    pub xy: Vec<(String, Vec<(f64, f64)>)>,
    /// Single points drawn as markers with a legend: (label, [(x, y)]).
    pub points: Vec<(String, Vec<(f64, f64)>)>,
    /// Vertical marks with a letter (A B P D E).
    pub marks: Vec<(&'static str, f64)>,
    /// Shaded x-ranges with a label (regime bands).
    pub bands: Vec<(f64, f64, String)>,
    /// Values with |y| above this are drawn at the limit and marked with ▲/▼.
    pub clip: Option<f64>,
}

fn bounds(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let pad = if hi > lo { 0.06 * (hi - lo) } else { 0.5 * hi.abs().max(1e-3) };
    (lo - pad, hi + pad)
}

fn draw_panel(area: &DrawingArea<SVGBackend, Shift>, panel: &Panel) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    // Every series as (label, [(x, y)]): the shared-x ones first, then those on their own x.
    let mut all: Vec<(String, Vec<(f64, f64)>)> = panel
        .series
        .iter()
        .map(|(l, ys)| (l.clone(), panel.x.iter().copied().zip(ys.iter().copied()).collect()))
        .collect();
    all.extend(panel.xy.iter().cloned());
    let xs = all.iter().chain(&panel.points).flat_map(|(_, v)| v.iter().map(|p| p.0));
    let (x0, x1) =
        xs.filter(|x| x.is_finite()).fold((f64::INFINITY, f64::NEG_INFINITY), |a, x| (a.0.min(x), a.1.max(x)));
    if x1.partial_cmp(&x0) != Some(std::cmp::Ordering::Greater) {
        return Ok(());
    }
    let clip = |y: f64| panel.clip.map_or(y, |c| y.clamp(-c, c));
    let (y0, y1) = bounds(all.iter().chain(&panel.points).flat_map(|(_, s)| s.iter().map(|p| clip(p.1))));
    let mut chart = ChartBuilder::on(area)
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(72)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .x_labels(8)
        .y_labels(6)
        .light_line_style(WHITE.mix(0.0))
        .draw()
        .map_err(e)?;
    for (i, (a, b, label)) in panel.bands.iter().enumerate() {
        let shade = PALETTE[(i + 5) % PALETTE.len()].mix(0.10);
        chart.draw_series(std::iter::once(Rectangle::new([(*a, y0), (*b, y1)], shade.filled()))).map_err(e)?;
        chart
            .draw_series(std::iter::once(Text::new(
                label.clone(),
                (*a, y0 + 0.08 * (y1 - y0)),
                ("sans-serif", 12).into_font().color(&BLACK.mix(0.7)),
            )))
            .map_err(e)?;
    }
    for (name, u) in &panel.marks {
        chart.draw_series(LineSeries::new(vec![(*u, y0), (*u, y1)], BLACK.mix(0.35).stroke_width(1))).map_err(e)?;
        chart
            .draw_series(std::iter::once(Text::new(
                name.to_string(),
                (*u, y1),
                ("sans-serif", 14).into_font().color(&BLACK),
            )))
            .map_err(e)?;
    }
    for (i, (label, pts)) in all.iter().enumerate() {
        let color = PALETTE[i % PALETTE.len()];
        // Split at non-finite values so that gaps stay gaps.
        let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
        let mut clipped = Vec::new();
        for &(x, y) in pts {
            if y.is_finite() && x.is_finite() {
                let c = clip(y);
                if c != y {
                    clipped.push((x, c));
                }
                runs.last_mut().expect("one run").push((x, c));
            } else if !runs.last().expect("one run").is_empty() {
                runs.push(Vec::new());
            }
        }
        for (k, run) in runs.into_iter().filter(|r| !r.is_empty()).enumerate() {
            let s = chart.draw_series(LineSeries::new(run, color.stroke_width(2))).map_err(e)?;
            if k == 0 && !label.is_empty() {
                s.label(label.clone())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], color.stroke_width(2)));
            }
        }
        if let Some(&(cx, cy)) = clipped.iter().min_by(|a, b| a.0.total_cmp(&b.0)) {
            let mark = if cy > 0.0 { "▲ clipped" } else { "▼ clipped" };
            chart
                .draw_series(std::iter::once(Text::new(mark, (cx, cy), ("sans-serif", 11).into_font().color(&color))))
                .map_err(e)?;
        }
    }
    for (i, (label, pts)) in panel.points.iter().enumerate() {
        let color = PALETTE[(all.len() + i) % PALETTE.len()];
        let finite: Vec<(f64, f64)> = pts.iter().copied().filter(|p| p.0.is_finite() && p.1.is_finite()).collect();
        let s = chart.draw_series(finite.into_iter().map(|p| Cross::new(p, 6, color.stroke_width(2)))).map_err(e)?;
        if !label.is_empty() {
            s.label(label.clone()).legend(move |(x, y)| Cross::new((x + 8, y), 5, color.stroke_width(2)));
        }
    }
    if all.iter().chain(&panel.points).any(|(l, _)| !l.is_empty()) {
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.3))
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(e)?;
    }
    Ok(())
}

/// Stacked panels; returns the SVG text.
pub fn figure(title: &str, panels: &[Panel]) -> Result<String, String> {
    let mut svg = String::new();
    {
        let height = 40 + 260 * panels.len() as u32;
        let root = SVGBackend::with_string(&mut svg, (900, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let root = root.titled(title, ("sans-serif", 18)).map_err(|e| e.to_string())?;
        let areas = root.split_evenly((panels.len(), 1));
        for (area, panel) in areas.iter().zip(panels) {
            draw_panel(area, panel)?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}

fn mm(v: &[f64]) -> Vec<f64> {
    v.iter().map(|u| u * 1e3).collect()
}

fn marks_mm(r: &Report) -> Vec<(&'static str, f64)> {
    r.curves.marks.iter().map(|(n, u)| (*n, u * 1e3)).collect()
}

/// contact_state.svg: v_s (per speed), SR and p_H (per torque) along the line of action.
pub fn contact_state(r: &Report) -> Result<String, String> {
    let c = &r.curves;
    let along = |y: &str, series: Vec<(String, Vec<f64>)>| Panel {
        y_label: y.into(),
        x_label: "distance from T1 (mm)".into(),
        x: mm(&c.u),
        series,
        marks: marks_mm(r),
        ..Default::default()
    };
    let panels = [
        along("sliding velocity v_s (m/s)", c.sliding_velocity.clone()),
        along("slide-to-roll ratio SR", vec![(String::new(), c.slide_to_roll.clone())]),
        along(
            "Hertzian pressure p_H (MPa)",
            c.hertz_pressure.iter().map(|(l, v)| (l.clone(), v.iter().map(|p| p * 1e-6).collect())).collect(),
        ),
    ];
    figure(&format!("{}: contact along the line of action", r.title), &panels)
}

/// A symmetric clip level for signed μ curves: 1.3 × the largest |μ| away from the pitch point.
fn mu_clip(x_mm: &[f64], series: &[(String, Vec<f64>)], p_mm: f64, half_width_mm: f64) -> f64 {
    let mut max: f64 = 0.0;
    for (_, ys) in series {
        for (x, y) in x_mm.iter().zip(ys) {
            if (x - p_mm).abs() > half_width_mm && y.is_finite() {
                max = max.max(y.abs());
            }
        }
    }
    if max > 0.0 {
        1.3 * max
    } else {
        1.0
    }
}

/// point_K_friction.svg: μ and local power loss along the line of action, η over one mesh cycle.
pub fn point_friction(r: &Report, k: usize) -> Result<String, String> {
    let c = &r.curves;
    let pc = &c.points[k];
    let x = mm(&c.u);
    let p_mm = r.geometry.points_from_t1.P.si() * 1e3;
    let span = (x[x.len() - 1] - x[0]) * 0.06;
    let panels = [
        Panel {
            y_label: "coefficient of friction μ (signed)".into(),
            x_label: "distance from T1 (mm)".into(),
            clip: Some(mu_clip(&x, &pc.mu, p_mm, span)),
            x: x.clone(),
            series: pc.mu.clone(),
            marks: marks_mm(r),
            bands: pc.regime_bands.iter().map(|(a, b, l)| (a * 1e3, b * 1e3, l.clone())).collect(),
            ..Default::default()
        },
        Panel {
            y_label: "local friction power loss (W)".into(),
            x_label: "distance from T1 (mm)".into(),
            clip: Some(mu_clip(&x, &pc.power_loss, p_mm, span)),
            x,
            series: pc.power_loss.clone(),
            marks: marks_mm(r),
            ..Default::default()
        },
        Panel {
            y_label: "instantaneous efficiency η (%)".into(),
            x_label: "time in mesh periods (0: a pair enters at A)".into(),
            x: c.tau.clone(),
            series: pc.efficiency.iter().map(|(l, v)| (l.clone(), v.iter().map(|e| 100.0 * e).collect())).collect(),
            ..Default::default()
        },
    ];
    figure(&format!("{}: friction at {}", r.title, pc.label), &panels)
}

/// Mean η and power loss against the swept variable, at each value of the other one.
/// `by_speed`: x is the pinion speed (in the unit the scene wrote), one curve per (law, formulation, torque); else x is torque.
pub fn sweep(r: &Report, by_speed: bool) -> Result<String, String> {
    let key = |q: f64| format!("{q:.9e}");
    let x_of = |rec: &crate::report::friction::EfficiencyRecord| {
        if by_speed {
            r.speed_unit.value(&rec.pinion_speed)
        } else {
            rec.pinion_torque.si()
        }
    };
    let other = |rec: &crate::report::friction::EfficiencyRecord| {
        if by_speed {
            format!("{:.1} N·m", rec.pinion_torque.si())
        } else {
            format!("{:.0} {}", r.speed_unit.value(&rec.pinion_speed), r.speed_unit.name)
        }
    };
    let mut xs: Vec<f64> = r.efficiency.iter().map(x_of).collect();
    xs.sort_by(f64::total_cmp);
    xs.dedup_by(|a, b| key(*a) == key(*b));
    let mut labels: Vec<String> = Vec::new();
    for rec in &r.efficiency {
        let l = format!("{} {} @ {}", rec.label, crate::report::formulation_name(rec.formulation), other(rec));
        if !labels.contains(&l) {
            labels.push(l);
        }
    }
    let mut eta: Vec<(String, Vec<f64>)> = labels.iter().map(|l| (l.clone(), vec![f64::NAN; xs.len()])).collect();
    let mut loss = eta.clone();
    for rec in &r.efficiency {
        let l = format!("{} {} @ {}", rec.label, crate::report::formulation_name(rec.formulation), other(rec));
        let i = labels.iter().position(|x| *x == l).expect("label collected above");
        let j = xs.iter().position(|x| key(*x) == key(x_of(rec))).expect("x collected above");
        eta[i].1[j] = 100.0 * rec.mean_efficiency.0;
        loss[i].1[j] = rec.power_loss.si();
    }
    let x_label =
        if by_speed { format!("pinion speed ({})", r.speed_unit.name) } else { "pinion torque (N·m)".to_string() };
    let panels = [
        Panel {
            y_label: "mean efficiency η̄ (%)".into(),
            x_label: x_label.clone(),
            x: xs.clone(),
            series: eta,
            ..Default::default()
        },
        Panel { y_label: "friction power loss (W)".into(), x_label, x: xs, series: loss, ..Default::default() },
    ];
    let what = if by_speed { "speed" } else { "torque" };
    figure(&format!("{}: mean efficiency and power loss against {what}", r.title), &panels)
}

/// composite_mu_vs_speed.svg: mean |μ| of the composite law against speed, per torque (He–Cho–Singh Fig. 2b).
pub fn composite_mu_vs_speed(r: &Report) -> Result<String, String> {
    let mut xs: Vec<f64> = Vec::new();
    let mut series: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    for op in &r.operating_points {
        let speed = r.speed_unit.value(&op.pinion_speed);
        for law in op.friction.iter().filter(|l| l.law == crate::friction::catalog::LawId::Composite) {
            let label = format!("{} @ {:.1} N·m", law.label, op.pinion_torque.si());
            match series.iter_mut().find(|(l, _)| *l == label) {
                Some((_, v)) => v.push((speed, law.mean_abs_mu.0)),
                None => series.push((label, vec![(speed, law.mean_abs_mu.0)])),
            }
            xs.push(speed);
        }
    }
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    let series = series
        .into_iter()
        .map(|(l, pts)| {
            let ys = xs.iter().map(|x| pts.iter().find(|(px, _)| px == x).map_or(f64::NAN, |p| p.1)).collect();
            (l, ys)
        })
        .collect();
    let panel = Panel {
        y_label: "mean |μ| over A–E".into(),
        x_label: format!("pinion speed ({})", r.speed_unit.name),
        x: xs,
        series,
        ..Default::default()
    };
    figure(&format!("{}: composite law, mean |μ| against speed", r.title), &[panel])
}

/// sweep_mu.svg: mean η and power loss against μ for swept laws, at up to three operating points.
pub fn sweep_mu(r: &Report) -> Result<String, String> {
    let laws = crate::report::friction::mu_swept_laws(&r.efficiency);
    let ops: Vec<usize> = match r.operating_points.len() {
        0 => Vec::new(),
        1 => vec![0],
        2 => vec![0, 1],
        n => vec![0, n / 2, n - 1],
    };
    let same = |a: &crate::report::number::Q, b: &crate::report::number::Q| a.si().to_bits() == b.si().to_bits();
    let mut xs: Vec<f64> = Vec::new();
    // (legend, [(μ, η̄ %, P_loss W)])
    type Curve = (String, Vec<(f64, f64, f64)>);
    let mut curves: Vec<Curve> = Vec::new();
    for rec in r.efficiency.iter().filter(|x| laws.contains(&x.law)) {
        let Some(k) = ops.iter().position(|&k| {
            same(&r.operating_points[k].pinion_torque, &rec.pinion_torque)
                && same(&r.operating_points[k].pinion_speed, &rec.pinion_speed)
        }) else {
            continue;
        };
        let Some(mu) = rec.parameters.get("mu") else { continue };
        let label = format!(
            "{} {} @ {}",
            rec.law,
            crate::report::formulation_name(rec.formulation),
            r.operating_points[ops[k]].label
        );
        xs.push(mu);
        let point = (mu, 100.0 * rec.mean_efficiency.0, rec.power_loss.si());
        match curves.iter_mut().find(|(l, _)| *l == label) {
            Some((_, v)) => v.push(point),
            None => curves.push((label, vec![point])),
        }
    }
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    let pick = |j: usize| -> Vec<(String, Vec<f64>)> {
        curves
            .iter()
            .map(|(l, pts)| {
                let ys = xs
                    .iter()
                    .map(|x| pts.iter().find(|p| p.0 == *x).map_or(f64::NAN, |p| if j == 1 { p.1 } else { p.2 }))
                    .collect();
                (l.clone(), ys)
            })
            .collect()
    };
    let panels = [
        Panel {
            y_label: "mean efficiency η̄ (%)".into(),
            x_label: "coefficient of friction μ".into(),
            x: xs.clone(),
            series: pick(1),
            ..Default::default()
        },
        Panel {
            y_label: "friction power loss (W)".into(),
            x_label: "coefficient of friction μ".into(),
            x: xs.clone(),
            series: pick(2),
            ..Default::default()
        },
    ];
    figure(&format!("{}: mean efficiency and power loss against μ", r.title), &panels)
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
    let panels = [
        tau_panel(
            "DTE x (µm)",
            c.dte.iter().map(|(l, v)| (l.clone(), v.iter().map(|(t, x)| (*t, x * 1e6)).collect())).collect(),
        ),
        tau_panel("tooth force per pair (N)", c.pair_force.clone()),
        tau_panel("applied friction force Σ μ w N (N)", c.friction_force.clone()),
        Panel {
            y_label: "DTE harmonic amplitude (µm)".into(),
            x_label: "mesh order".into(),
            x: orders,
            series: c.spectrum.iter().map(|(l, v)| (l.clone(), v.iter().map(|x| x * 1e6).collect())).collect(),
            ..Default::default()
        },
    ];
    figure(&format!("{}: dynamics at {}", r.title, c.label), &panels)
}

/// stability_map.svg: spectral radius and dynamic factor against speed, per formulation.
pub fn stability_map(r: &Report) -> Result<String, String> {
    use crate::report::friction::MuValue;
    let map = r.dynamics.as_ref().and_then(|d| d.stability_map.as_ref()).ok_or("no stability map")?;
    let x: Vec<f64> = map.points.iter().map(|p| map.speed_unit.value(&p.pinion_speed)).collect();
    let x_label = format!("pinion speed ({})", map.speed_unit.name);
    let names: Vec<String> = map.formulations.iter().map(|f| format!("{f:?}").to_lowercase()).collect();
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
pub fn work_precision(r: &Report) -> Result<String, String> {
    let t = r.dynamics.as_ref().and_then(|d| d.timings.as_ref()).ok_or("no numerics")?;
    let mut methods: Vec<String> = t.runs.iter().map(|x| x.0.clone()).collect();
    methods.dedup();
    let ok = |e: f64| e.is_finite() && e > 0.0;
    let floor = t.runs.iter().filter(|x| ok(x.2)).map(|x| x.2).fold(f64::INFINITY, f64::min);
    let worst = t.runs.iter().filter(|x| ok(x.2)).map(|x| x.2).fold(0.0f64, f64::max);
    let xy = methods
        .iter()
        .map(|m| {
            let pts = t
                .runs
                .iter()
                .filter(|r| r.0 == *m && ok(r.2) && r.3 > 0.0)
                .map(|r| (r.2.log10(), r.3.log10()))
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
