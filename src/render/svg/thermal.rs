//! heat_balance.svg (P_V and P_Q against the oil temperature, the balance and the limit marked),
//! duty_cycle_temperature.svg (the sump over the cycle, steps shaded, the limit drawn) and
//! duty_cycle_energy.svg (energy lost per step, transient and fixed temperature side by side).
//! Temperatures are drawn in °C (°F for a scene written in inches; report.json holds K).

use plotters::prelude::*;

use super::panel::{plottable, PALETTE};
use crate::report::thermal::{DutyCycleReport, HeatBalanceReport};
use crate::report::units::Units;

fn err<E: std::error::Error + Send + Sync>(e: DrawingAreaErrorKind<E>) -> String {
    e.to_string()
}

/// heat_balance.svg of the balance `h` in a drive's report titled `title`, in units `u`.
pub(crate) fn heat_balance_figure(title: &str, h: &HeatBalanceReport, u: Units) -> Result<String, String> {
    // Drawn up to 30 K beyond the limit or the balance, whichever is higher (the curve in report.json
    // runs to 200 °C).
    let (deg, w) = (u.temperature(), u.power());
    let limit = deg.value(h.max_oil_temperature.si());
    let right = limit.max(h.oil_temperature.as_ref().map_or(limit, |b| deg.value(b.si()))) + 30.0 * deg.per_kelvin();
    let keep = h.temperature.iter().take_while(|x| deg.value(**x) <= right).count().max(2);
    let t: Vec<f64> = h.temperature[..keep].iter().map(|x| deg.value(*x)).collect();
    let in_unit = |v: &[f64]| v[..keep].iter().map(|x| w.value(*x)).collect::<Vec<f64>>();
    let (p_v, p_q) = (&in_unit(&h.power_loss)[..], &in_unit(&h.dissipation)[..]);
    let top = p_v.iter().chain(p_q).copied().filter(|x| x.is_finite()).fold(0.0, f64::max);
    let Some((y0, y1)) = plottable(0.0, 1.05 * top.max(1e-9)) else { return Err("no finite power to draw".into()) };
    let (x0, x1) = (t[0], *t.last().unwrap_or(&200.0));
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 560)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(format!("{title}: heat balance at {}", h.label), ("sans-serif", 15))
            .margin(14)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(err)?;
        chart.configure_mesh().x_desc(deg.titled("oil temperature θ")).y_desc(w.titled("power")).draw().map_err(err)?;
        let line = |v: &[f64]| t.iter().copied().zip(v.iter().copied()).filter(|p| p.1.is_finite()).collect::<Vec<_>>();
        chart
            .draw_series(LineSeries::new(line(p_v), PALETTE[0].stroke_width(2)))
            .map_err(err)?
            .label("losses P_V(θ)")
            .legend(|(x, y)| PathElement::new([(x, y), (x + 18, y)], PALETTE[0].stroke_width(2)));
        chart
            .draw_series(LineSeries::new(line(p_q), PALETTE[1].stroke_width(2)))
            .map_err(err)?
            .label("given off P_Q(θ)")
            .legend(|(x, y)| PathElement::new([(x, y), (x + 18, y)], PALETTE[1].stroke_width(2)));
        if limit < x1 {
            chart
                .draw_series(std::iter::once(PathElement::new(
                    [(limit, y0), (limit, y1)],
                    BLACK.mix(0.6).stroke_width(2),
                )))
                .map_err(err)?
                .label(format!("oil limit {limit:.0} {}", deg.unit))
                .legend(|(x, y)| PathElement::new([(x, y), (x + 18, y)], BLACK.mix(0.6).stroke_width(2)));
        }
        if let Some(b) = &h.oil_temperature {
            let theta = deg.value(b.si());
            let q = interpolate(&t, p_q, theta);
            chart
                .draw_series(std::iter::once(Circle::new((theta, q), 6, BLACK.filled())))
                .map_err(err)?
                .label(format!("balance θ* = {theta:.1} {}", deg.unit))
                .legend(|(x, y)| Circle::new((x + 9, y), 4, BLACK.filled()));
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperLeft)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .draw()
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    Ok(svg)
}

/// Linear interpolation in a sorted table (for placing a located point on a drawn curve).
fn interpolate(x: &[f64], y: &[f64], at: f64) -> f64 {
    let i = x.partition_point(|v| *v < at).clamp(1, x.len() - 1);
    let w = (at - x[i - 1]) / (x[i] - x[i - 1]);
    y[i - 1] + w * (y[i] - y[i - 1])
}

/// duty_cycle_temperature.svg of the duty cycle `d` in a report titled `title`, in units `u`.
pub(crate) fn duty_temperature_figure(title: &str, d: &DutyCycleReport, u: Units) -> Result<String, String> {
    let s = d.samples.as_ref().ok_or("the duty cycle has no transient")?;
    let minutes: Vec<f64> = s.time.iter().map(|t| t / 60.0).collect();
    let deg = u.temperature();
    let theta: Vec<f64> = s.oil_temperature.iter().map(|t| deg.value(*t)).collect();
    let limit = deg.value(d.max_oil_temperature.si());
    let lo = theta.iter().copied().fold(deg.value(d.ambient_temperature.si()), f64::min);
    let hi = theta.iter().copied().fold(limit, f64::max);
    let Some((y0, y1)) = plottable(lo - 2.0 * deg.per_kelvin(), hi + 5.0 * deg.per_kelvin()) else {
        return Err("no finite temperature to draw".into());
    };
    let end = d.steps.iter().map(|s| s.duration.si()).sum::<f64>() / 60.0;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 520)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(format!("{title}: sump temperature over \"{}\"", d.name), ("sans-serif", 15))
            .margin(14)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(0.0..end.max(1e-9), y0..y1)
            .map_err(err)?;
        chart.configure_mesh().x_desc("time (min)").y_desc(deg.titled("oil temperature θ")).draw().map_err(err)?;
        let mut start = 0.0;
        for (k, step) in d.steps.iter().enumerate() {
            let stop = start + step.duration.si() / 60.0;
            if k % 2 == 1 {
                chart
                    .draw_series(std::iter::once(Rectangle::new([(start, y0), (stop, y1)], BLACK.mix(0.06).filled())))
                    .map_err(err)?;
            }
            start = stop;
        }
        chart
            .draw_series(LineSeries::new(
                minutes.iter().copied().zip(theta.iter().copied()),
                PALETTE[0].stroke_width(2),
            ))
            .map_err(err)?
            .label("θ(t) (steps shaded alternately)")
            .legend(|(x, y)| PathElement::new([(x, y), (x + 18, y)], PALETTE[0].stroke_width(2)));
        chart
            .draw_series(std::iter::once(PathElement::new(
                [(0.0, limit), (end, limit)],
                BLACK.mix(0.6).stroke_width(2),
            )))
            .map_err(err)?
            .label(format!("oil limit {limit:.0} {}", deg.unit))
            .legend(|(x, y)| PathElement::new([(x, y), (x + 18, y)], BLACK.mix(0.6).stroke_width(2)));
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .draw()
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    Ok(svg)
}

/// duty_cycle_energy.svg of the duty cycle `d` in a report titled `title`, in units `u`.
pub(crate) fn duty_energy_figure(title: &str, d: &DutyCycleReport, u: Units) -> Result<String, String> {
    let energy = u.energy();
    let kj = |q: &Option<crate::report::number::Q>| q.as_ref().map(|q| energy.value(q.si()));
    let bars: Vec<(Option<f64>, Option<f64>)> =
        d.steps.iter().map(|s| (kj(&s.energy_lost), kj(&s.energy_lost_fixed))).collect();
    let top = bars.iter().flat_map(|(a, b)| [*a, *b]).flatten().fold(0.0, f64::max);
    let Some((y0, y1)) = plottable(0.0, 1.1 * top.max(1e-9)) else { return Err("no finite energy to draw".into()) };
    let n = bars.len() as f64;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 480)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(format!("{title}: energy lost per step of \"{}\"", d.name), ("sans-serif", 15))
            .margin(14)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(0.5..n + 0.5, y0..y1)
            .map_err(err)?;
        chart
            .configure_mesh()
            .disable_x_mesh()
            .x_labels(bars.len().min(30))
            .x_label_formatter(&|x| format!("{}", x.round() as i64))
            .x_desc("step")
            .y_desc(energy.titled("energy lost"))
            .draw()
            .map_err(err)?;
        let series = [(0, -0.2, "transient from ambient"), (1, 0.2, "at the fixed oil temperature")];
        for (which, offset, name) in series {
            let rects: Vec<Rectangle<(f64, f64)>> = bars
                .iter()
                .enumerate()
                .filter_map(|(k, b)| {
                    let v = if which == 0 { b.0 } else { b.1 }?;
                    let x = (k + 1) as f64 + offset;
                    Some(Rectangle::new([(x - 0.18, 0.0), (x + 0.18, v)], PALETTE[which].filled()))
                })
                .collect();
            if rects.is_empty() {
                continue;
            }
            chart
                .draw_series(rects)
                .map_err(err)?
                .label(name)
                .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 12, y + 5)], PALETTE[which].filled()));
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .draw()
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    Ok(svg)
}
