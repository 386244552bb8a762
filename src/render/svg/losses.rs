//! A drive's loss_budget.svg bars (stacked, a bar a kept row and law) and every map panel
//! (filled contours with labelled iso-lines over torque × speed).

use plotters::prelude::*;

use super::contours::{bilinear, iso_lines, levels, Field};
use super::maps::colour;
use super::panel::{plottable, PALETTE};
use crate::losses::parts::COLUMNS;
use crate::report::units::Shown;

/// The parts of a budget bar, bottom to top: the mesh or meshes (`meshes`, their name), then the
/// budget's columns.
fn parts(meshes: &'static str) -> Vec<&'static str> {
    std::iter::once(meshes).chain(COLUMNS.iter().map(|c| c.bar)).collect()
}

/// A budget figure: one bar per labelled entry (`bars`: the label and the parts' powers in `power`'s
/// unit, bottom to top: the mesh or meshes, named `meshes`, then the budget's columns), stacked by
/// part, the legend and the bars' labels beside the plot area. A pair's and a drive's loss_budget.svg.
pub(crate) fn budget_bars(
    caption: &str,
    meshes: &'static str,
    power: Shown,
    bars: &[(String, Vec<f64>)],
) -> Result<String, String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    let top = bars.iter().map(|(_, p)| p.iter().sum::<f64>()).fold(0.0, f64::max);
    let Some((y0, y1)) = plottable(0.0, 1.08 * top.max(1e-9)) else { return Err("no finite loss to draw".into()) };
    let mut svg = String::new();
    {
        let height = 420 + 18 * bars.len() as u32;
        let root = SVGBackend::with_string(&mut svg, (1180, height)).into_drawing_area();
        root.fill(&WHITE).map_err(e)?;
        let (plot, legend) = root.split_horizontally(720);
        let n = bars.len().max(1) as f64;
        let mut chart = ChartBuilder::on(&plot)
            .caption(caption, ("sans-serif", 16))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(-0.5..n - 0.5, y0..y1)
            .map_err(e)?;
        chart
            .configure_mesh()
            .disable_x_mesh()
            .x_labels(bars.len().max(1))
            .x_label_formatter(&|x| format!("{}", x.round() as i64 + 1))
            .x_desc("bar (operating point and law, listed at right)")
            .y_desc(power.titled("total power loss of the gearbox"))
            .draw()
            .map_err(e)?;
        for (i, (_, parts)) in bars.iter().enumerate() {
            let mut base = 0.0;
            for (k, p) in parts.iter().enumerate() {
                let x = i as f64;
                chart
                    .draw_series(std::iter::once(Rectangle::new(
                        [(x - 0.35, base), (x + 0.35, base + p)],
                        PALETTE[k].filled(),
                    )))
                    .map_err(e)?;
                base += p;
            }
        }
        let style = ("sans-serif", 13).into_font();
        for (k, name) in parts(meshes).iter().enumerate() {
            let y = 40 + 20 * k as i32;
            legend.draw(&Rectangle::new([(10, y), (24, y + 12)], PALETTE[k].filled())).map_err(e)?;
            legend.draw(&Text::new(name.to_string(), (30, y), style.clone())).map_err(e)?;
        }
        for (i, (label, _)) in bars.iter().enumerate() {
            let y = 160 + 18 * i as i32;
            legend
                .draw(&Text::new(format!("{}. {label}", i + 1), (10, y), ("sans-serif", 11).into_font()))
                .map_err(e)?;
        }
        root.present().map_err(e)?;
    }
    Ok(svg)
}

/// What a map panel marks: located points (x, y) ringed, and weights (x, y, w) as circles.
pub(crate) type Marks<'a> = (&'a [(f64, f64)], &'a [(f64, f64, f64)]);

/// One map panel of `f`: filled bands between iso-levels on a 1-2-5 step over the upper nine
/// tenths of its values, the iso-lines labelled, a colour bar at the right, the axes described by
/// `axes` (x, y), each of `best` (located points) marked by a ring, and `weights` (x, y, weight)
/// drawn as red circles of area in proportion to the weight (a drive cycle's time at each cell).
pub(crate) fn draw_field(
    area: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    f: &Field,
    axes: (&str, &str),
    (best, weights): Marks<'_>,
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    let finite: Vec<f64> = f.values.iter().flatten().copied().filter(|v| v.is_finite()).collect();
    let lo = finite.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = finite.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    // Iso-levels over the upper nine tenths of the values: a few extreme cells (an efficiency map's
    // lightest loads) would otherwise take every band.
    let mut sorted = finite.clone();
    sorted.sort_by(f64::total_cmp);
    let p10 = sorted.get(sorted.len() / 10).copied().unwrap_or(lo);
    let lv = levels(p10, hi, 8);
    let (Some((x0, x1)), Some((y0, y1))) = (
        plottable(f.speeds[0], *f.speeds.last().unwrap_or(&1.0)),
        plottable(f.torques[0], *f.torques.last().unwrap_or(&1.0)),
    ) else {
        return Ok(());
    };
    let caption = format!("{} ({})", f.title, f.unit);
    let (width, _) = area.dim_in_pixel();
    let mut chart = ChartBuilder::on(area)
        .caption(&caption, ("sans-serif", super::panel::fitted(&caption, width, 14.0)))
        .margin(14)
        .margin_right(78)
        .x_label_area_size(38)
        .y_label_area_size(62)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(e)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(axes.0)
        .y_desc(axes.1)
        .x_labels(6)
        .y_labels(6)
        .x_label_formatter(&|x| crate::render::table::sig(*x))
        .y_label_formatter(&|y| crate::render::table::sig(*y))
        .draw()
        .map_err(e)?;
    // Filled bands: each grid cell split SUB × SUB, coloured by the band of its bilinear centre
    // value; along each row of sub-cells, neighbours in the same band are drawn as one rectangle
    // (the picture is the same, the file a fraction of the size). A sub-cell is kept at 3 pixels or
    // more (SUB from 4 down to 1 as the grid gets finer): finer than that the picture cannot show.
    let (ns, nt) = (f.speeds.len(), f.torques.len());
    let (w, h) = area.dim_in_pixel();
    let cell_px = ((w as f64 - 170.0) / (ns - 1).max(1) as f64).min((h as f64 - 90.0) / (nt - 1).max(1) as f64);
    let sub = (cell_px / 3.0).floor().clamp(1.0, 4.0) as usize;
    let cells = band_rectangles(f, &lv, sub)
        .into_iter()
        .map(|(corners, b)| Rectangle::new(corners, colour(b as f64 / lv.len().max(1) as f64).filled()));
    chart.draw_series(cells).map_err(e)?;
    for l in &lv {
        let lines = iso_lines(f, *l);
        chart.draw_series(lines.iter().map(|p| PathElement::new(p.clone(), BLACK.stroke_width(1)))).map_err(e)?;
        if let Some(p) = lines.iter().max_by_key(|p| p.len()) {
            let label = crate::render::table::sig(*l);
            chart
                .draw_series(std::iter::once(Text::new(
                    label,
                    p[p.len() / 2],
                    ("sans-serif", 11).into_font().color(&BLACK),
                )))
                .map_err(e)?;
        }
    }
    // The located best point (report.md gives its value), marked where its panel shows it.
    let heaviest = weights.iter().map(|m| m.2).fold(0.0, f64::max);
    if heaviest > 0.0 {
        // The heaviest 9 px across; area in proportion to the weight.
        let radius = |w: f64| (9.0 * (w / heaviest).sqrt()).round().max(1.0) as i32;
        let marks = weights.iter().map(|&(x, y, w)| Circle::new((x, y), radius(w), RED.mix(0.85).stroke_width(1)));
        chart.draw_series(marks).map_err(e)?;
    }
    for p in best {
        chart.draw_series(std::iter::once(Circle::new(*p, 5, WHITE.filled()))).map_err(e)?;
        chart.draw_series(std::iter::once(Circle::new(*p, 5, BLACK.stroke_width(2)))).map_err(e)?;
    }
    colour_bar(area, &lv)
}

/// The filled bands of a field: each grid cell split `sub` × `sub`, each sub-cell in the band of
/// its bilinear centre value; along each row of sub-cells, neighbours in the same band make one
/// rectangle, and a run the next row repeats exactly grows downward instead of starting its own.
/// Returns (corners in speed × torque, band) in drawing order.
fn band_rectangles(f: &Field, lv: &[f64], sub: usize) -> Vec<([(f64, f64); 2], usize)> {
    let (ns, nt) = (f.speeds.len(), f.torques.len());
    let band = |v: f64| lv.iter().filter(|l| v >= **l).count();
    let x_at = |k: usize| {
        let (s, i) = (k / sub, k % sub);
        if s + 1 >= ns {
            f.speeds[ns - 1]
        } else {
            f.speeds[s] + i as f64 / sub as f64 * (f.speeds[s + 1] - f.speeds[s])
        }
    };
    // Runs (first sub-column, end sub-column, band) of each row of sub-cells, open downward.
    let mut open: Vec<((usize, usize, usize), f64, f64)> = Vec::new();
    let mut cells = Vec::new();
    let flush = |run: &((usize, usize, usize), f64, f64), cells: &mut Vec<_>| {
        let ((k0, k1, b), y0, y1) = *run;
        cells.push(([(x_at(k0), y0), (x_at(k1), y1)], b));
    };
    for t in 0..nt - 1 {
        for j in 0..sub {
            let (ft0, ft1) = (j as f64 / sub as f64, (j + 1) as f64 / sub as f64);
            let y = |fr: f64| f.torques[t] + fr * (f.torques[t + 1] - f.torques[t]);
            let mut runs = Vec::new();
            // (first sub-column, band) of the run being built.
            let mut run: Option<(usize, usize)> = None;
            for k in 0..=(ns - 1) * sub {
                let here = (k < (ns - 1) * sub)
                    .then(|| {
                        let (s, i) = (k / sub, k % sub);
                        bilinear(&f.values, s as f64 + (i as f64 + 0.5) / sub as f64, t as f64 + 0.5 * (ft0 + ft1))
                    })
                    .filter(|v| v.is_finite())
                    .map(band);
                if run.map(|r| r.1) != here {
                    if let Some((k0, b)) = run {
                        runs.push((k0, k, b));
                    }
                    run = here.map(|b| (k, b));
                }
            }
            let mut next = Vec::with_capacity(runs.len());
            for r in runs {
                match open.iter().position(|(o, _, _)| *o == r) {
                    Some(i) => next.push((r, open.swap_remove(i).1, y(ft1))),
                    None => next.push((r, y(ft0), y(ft1))),
                }
            }
            open.iter().for_each(|o| flush(o, &mut cells));
            open = next;
        }
    }
    open.iter().for_each(|o| flush(o, &mut cells));
    cells
}

/// The bands' colour bar at the right of a map panel: one box per band, bottom (lowest) to top,
/// with the iso-level between two boxes written beside it.
fn colour_bar(area: &DrawingArea<SVGBackend, plotters::coord::Shift>, lv: &[f64]) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    let (w, h) = area.dim_in_pixel();
    let bands = lv.len() + 1;
    let (top, bottom) = (40_i32, h as i32 - 60);
    let step = (bottom - top) as f64 / bands as f64;
    let x = w as i32 - 66;
    for b in 0..bands {
        let y1 = bottom - (b as f64 * step).round() as i32;
        let y0 = bottom - ((b + 1) as f64 * step).round() as i32;
        let fill = colour(b as f64 / lv.len().max(1) as f64).filled();
        area.draw(&Rectangle::new([(x, y0), (x + 14, y1)], fill)).map_err(e)?;
        area.draw(&Rectangle::new([(x, y0), (x + 14, y1)], BLACK.stroke_width(1))).map_err(e)?;
    }
    for (i, l) in lv.iter().enumerate() {
        let y = bottom - ((i + 1) as f64 * step).round() as i32;
        let label = crate::render::table::sig(*l);
        area.draw(&Text::new(label, (x + 18, y - 6), ("sans-serif", 11).into_font())).map_err(e)?;
    }
    Ok(())
}
