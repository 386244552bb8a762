//! power_flow.svg: the power along the drive from the source to the sink as a waterfall, every
//! loss (a shaft's bearings, seals and gears' no-load parts; a stage's mesh) a step down with its
//! watts, for the largest drive point and the largest coast point of the first law and
//! formulation. The axis starts near the sink's power, so that losses of a percent are seen: the
//! cut is marked on the axis (two slashes) and said in the panel's caption.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::drive::{DrivePoint, PowerFlow};
use crate::render::svg::fitted;
use crate::report::drive::{DrivePointReport, DriveReport};
use crate::report::units::{Shown, Units};

pub(crate) const FILE: &str = "power_flow.svg";

/// The plot's width (px).
const WIDTH: u32 = 1000;

/// One step of the waterfall: its label, the power before and after it (in the report's power
/// unit, W or hp).
struct Step {
    label: String,
    from: f64,
    to: f64,
}

/// The steps of a point, from the source to the sink.
fn steps(d: &DrivePoint, w: Shown) -> Vec<Step> {
    let mut order: Vec<usize> = (0..d.shafts.len()).collect();
    order.sort_by(|a, b| d.shafts[*b].received_power.total_cmp(&d.shafts[*a].received_power));
    let mut out = Vec::new();
    for (i, &j) in order.iter().enumerate() {
        let s = &d.shafts[j];
        out.push(Step {
            label: format!("shaft {}", s.name),
            from: w.value(s.received_power),
            to: w.value(s.passed_power),
        });
        if let Some(&next) = order.get(i + 1) {
            // The stage with a gear on both shafts.
            let joins =
                s.gear_loads.iter().map(|l| l.stage).find(|k| d.shafts[next].gear_loads.iter().any(|l| l.stage == *k));
            let name = joins.and_then(|k| d.stages.get(k)).map_or("mesh".to_string(), |st| format!("mesh {}", st.name));
            out.push(Step { label: name, from: w.value(s.passed_power), to: w.value(d.shafts[next].received_power) });
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
    let w = Units::of_system(r.unit_system).power();
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (WIDTH, 40 + 380 * chosen.len() as u32)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let title = format!("{}: power from source to sink, every loss a step", r.title);
        let root = root.titled(&title, ("sans-serif", fitted(&title, WIDTH, 18.0))).map_err(|e| e.to_string())?;
        for (area, p) in root.split_evenly((chosen.len(), 1)).iter().zip(&chosen) {
            let caption = format!("{} — {} ({law} {formulation})", p.label, p.point.flow.name());
            draw(area, &caption, &steps(&p.point, w), w)?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(Some(svg))
}

fn draw(
    area: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    title: &str,
    steps: &[Step],
    w: Shown,
) -> Result<(), String> {
    // The labels' decimals: W's, and three more in hp.
    let (d1, d2, unit) = (w.decimals(1), w.decimals(2), w.unit);
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    let hi = steps.first().map_or(1.0, |s| s.from);
    let lo = steps.last().map_or(0.0, |s| s.to);
    let pad = 0.15 * (hi - lo).max(1e-9 * hi.abs().max(1.0));
    let (y0, y1) = (lo - pad, hi + 1.6 * pad);
    // Bars: the source, one a step, the sink.
    let n = steps.len() + 2;
    let caption = format!("{title}; the axis starts at {y0:.d1$} {unit}");
    let mut chart = ChartBuilder::on(area)
        .caption(&caption, ("sans-serif", fitted(&caption, WIDTH, 14.0)))
        .margin(12)
        .margin_right(20)
        .x_label_area_size(12)
        .y_label_area_size(80)
        .build_cartesian_2d(0.0..n as f64, y0..y1)
        .map_err(e)?;
    chart
        .configure_mesh()
        .disable_x_mesh()
        .max_light_lines(0)
        .x_labels(0)
        .y_labels(6)
        .y_desc(format!("power ({unit})"))
        .y_label_formatter(&|y| format!("{y:.0$}", w.decimals(0)))
        .draw()
        .map_err(e)?;
    let blue = RGBColor(70, 110, 180);
    let red = RGBColor(200, 70, 60);
    // Each bar's words centred above it, in at most three short lines, so that neighbours never meet.
    let above = |x: f64, top: f64, lines: &[String]| {
        let style = ("sans-serif", 11).into_font().color(&BLACK).pos(Pos::new(HPos::Center, VPos::Bottom));
        lines
            .iter()
            .rev()
            .enumerate()
            .map(|(k, l)| Text::new(l.clone(), (x + 0.5, top + (0.05 + 0.3 * k as f64) * pad), style.clone()))
            .collect::<Vec<_>>()
    };
    chart.draw_series(std::iter::once(Rectangle::new([(0.1, y0), (0.9, hi)], blue.filled()))).map_err(e)?;
    chart.draw_series(above(0.0, hi, &["source".into(), format!("{hi:.d1$} {unit}")])).map_err(e)?;
    for (i, s) in steps.iter().enumerate() {
        let x = i as f64 + 1.0;
        chart
            .draw_series(std::iter::once(Rectangle::new([(x + 0.1, y0), (x + 0.9, s.to)], blue.mix(0.35).filled())))
            .map_err(e)?;
        chart
            .draw_series(std::iter::once(Rectangle::new([(x + 0.1, s.to), (x + 0.9, s.from)], red.filled())))
            .map_err(e)?;
        chart
            .draw_series(above(x, s.from, &[s.label.clone(), format!("−{:.d2$} {unit}", s.from - s.to)]))
            .map_err(e)?;
    }
    let x = n as f64 - 1.0;
    chart.draw_series(std::iter::once(Rectangle::new([(x + 0.1, y0), (x + 0.9, lo)], blue.filled()))).map_err(e)?;
    chart.draw_series(above(x, lo, &["sink".into(), format!("{lo:.d1$} {unit}")])).map_err(e)?;
    // The cut axis: two short slashes across the y axis just above its foot.
    let (columns, rows) = chart.plotting_area().get_pixel_range();
    let (ox, oy) = area.get_base_pixel();
    let (ax, ay) = (columns.start - ox, rows.end - oy - 14);
    for dy in [0, 6] {
        let slash = PathElement::new(vec![(ax - 6, ay - dy + 3), (ax + 6, ay - dy - 3)], BLACK.stroke_width(1));
        area.draw(&slash).map_err(e)?;
    }
    Ok(())
}
