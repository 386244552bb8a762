//! power_flow.svg: the power along the drive from the source to the sink as a waterfall, every
//! loss (a shaft's bearings, seals and gears' no-load parts; a stage's mesh) a step down with its
//! watts, for the largest drive point and the largest coast point of the first law and
//! formulation. The axis starts near the sink's power, so that losses of a percent are seen.

use plotters::prelude::*;

use crate::drive::{DrivePoint, PowerFlow};
use crate::report::drive::{DrivePointReport, DriveReport};

pub(crate) const FILE: &str = "power_flow.svg";

/// One step of the waterfall: its label, the power before and after it (W).
struct Step {
    label: String,
    from: f64,
    to: f64,
}

/// The steps of a point, from the source to the sink.
fn steps(d: &DrivePoint) -> Vec<Step> {
    let mut order: Vec<usize> = (0..d.shafts.len()).collect();
    order.sort_by(|a, b| d.shafts[*b].received_power.total_cmp(&d.shafts[*a].received_power));
    let mut out = Vec::new();
    for (i, &j) in order.iter().enumerate() {
        let s = &d.shafts[j];
        out.push(Step { label: format!("shaft {}", s.name), from: s.received_power, to: s.passed_power });
        if let Some(&next) = order.get(i + 1) {
            // The stage with a gear on both shafts.
            let joins =
                s.gear_loads.iter().map(|l| l.stage).find(|k| d.shafts[next].gear_loads.iter().any(|l| l.stage == *k));
            let name = joins.and_then(|k| d.stages.get(k)).map_or("mesh".to_string(), |st| format!("mesh {}", st.name));
            out.push(Step { label: name, from: s.passed_power, to: d.shafts[next].received_power });
        }
    }
    out
}

/// The points drawn: of the first law and formulation, the drive point and the coast point of the
/// largest power (where one end alone delivers).
pub(crate) fn chosen(r: &DriveReport) -> Vec<&DrivePointReport> {
    let Some(first) = r.points.first() else { return Vec::new() };
    let of = |flow: PowerFlow| {
        r.points
            .iter()
            .filter(|p| p.law == first.law && p.formulation == first.formulation)
            .filter(|p| p.point.flow == flow && !p.point.both_ends_deliver && p.point.power_lost() > 0.0)
            .max_by(|a, b| a.point.input_power.abs().total_cmp(&b.point.input_power.abs()))
    };
    [of(PowerFlow::Drive), of(PowerFlow::Coast)].into_iter().flatten().collect()
}

/// The plot, when the report has a point that carries power.
pub(crate) fn power_flow(r: &DriveReport) -> Result<Option<String>, String> {
    let chosen = chosen(r);
    let Some(first) = chosen.first() else { return Ok(None) };
    let (law, formulation) = (&first.law, &first.formulation);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1000, 40 + 360 * chosen.len() as u32)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let root = root
            .titled(
                &format!("{}: power from source to sink, every loss a step ({law} {formulation})", r.title),
                ("sans-serif", 18),
            )
            .map_err(|e| e.to_string())?;
        for (area, p) in root.split_evenly((chosen.len(), 1)).iter().zip(&chosen) {
            draw(area, &format!("{} — {}", p.label, p.point.flow.name()), &steps(&p.point))?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(Some(svg))
}

fn draw(area: &DrawingArea<SVGBackend, plotters::coord::Shift>, title: &str, steps: &[Step]) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    let hi = steps.first().map_or(1.0, |s| s.from);
    let lo = steps.last().map_or(0.0, |s| s.to);
    let pad = 0.15 * (hi - lo).max(1e-9 * hi.abs().max(1.0));
    let (y0, y1) = (lo - pad, hi + pad);
    let n = steps.len();
    let mut chart = ChartBuilder::on(area)
        .caption(title, ("sans-serif", 14))
        .margin(12)
        .x_label_area_size(30)
        .y_label_area_size(80)
        .build_cartesian_2d(0.0..(n as f64 + 1.0), y0..y1)
        .map_err(e)?;
    chart.configure_mesh().disable_x_mesh().x_labels(0).y_desc("power (W)").draw().map_err(e)?;
    let blue = RGBColor(70, 110, 180);
    let red = RGBColor(200, 70, 60);
    chart.draw_series(std::iter::once(Rectangle::new([(0.1, y0), (0.9, hi)], blue.filled()))).map_err(e)?;
    chart
        .draw_series(std::iter::once(Text::new(
            format!("source {:.1} W", hi),
            (0.1, hi + 0.4 * pad),
            ("sans-serif", 12),
        )))
        .map_err(e)?;
    for (i, s) in steps.iter().enumerate() {
        let x = i as f64 + 1.0;
        chart
            .draw_series(std::iter::once(Rectangle::new([(x + 0.1, y0), (x + 0.9, s.to)], blue.mix(0.35).filled())))
            .map_err(e)?;
        chart
            .draw_series(std::iter::once(Rectangle::new([(x + 0.1, s.to), (x + 0.9, s.from)], red.filled())))
            .map_err(e)?;
        let words = format!("{}: −{:.2} W", s.label, s.from - s.to);
        let y = if i % 2 == 0 { s.from + 0.25 * pad } else { s.from + 0.6 * pad };
        chart
            .draw_series(std::iter::once(Text::new(words, (x + 0.05, y.min(y1 - 0.05 * pad)), ("sans-serif", 11))))
            .map_err(e)?;
    }
    chart
        .draw_series(std::iter::once(Text::new(
            format!("sink {:.1} W", lo),
            (n as f64 - 0.2, lo - 0.6 * pad),
            ("sans-serif", 12),
        )))
        .map_err(e)?;
    Ok(())
}
