//! loss_budget.svg (stacked bars of the budget at each operating point) and efficiency_map.svg
//! (filled contours with labelled iso-lines over torque × speed).

use plotters::prelude::*;

use super::maps::colour;
use super::panel::{plottable, PALETTE};
use crate::losses::parts::COLUMNS;
use crate::report::Report;

/// The parts of a budget bar, bottom to top: the mesh, then the budget's columns.
fn parts() -> Vec<&'static str> {
    std::iter::once("mesh (load-dependent)").chain(COLUMNS.iter().map(|c| c.bar)).collect()
}

/// loss_budget.svg: one bar per operating point and law (the first formulation of each law),
/// stacked by part; the legend stands beside the plot area.
pub fn loss_budget(r: &Report) -> Result<String, String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    let first = r.efficiency.first().map(|x| x.formulation);
    let bars: Vec<(String, Vec<f64>)> = r
        .efficiency
        .iter()
        .filter(|x| Some(x.formulation) == first)
        .filter_map(|x| {
            let b = x.budget.as_ref()?;
            let w = |q: Option<crate::report::number::Q>| q.map_or(0.0, |q| q.si());
            let label = format!(
                "{:.0} N·m, {:.0} {}: {}",
                x.pinion_torque.si(),
                r.speed_unit.value(&x.pinion_speed),
                r.speed_unit.name,
                crate::render::table::law_words(&x.label)
            );
            let powers = std::iter::once(x.power_loss.si()).chain(COLUMNS.iter().map(|c| w(b.part(c.column))));
            Some((label, powers.collect::<Vec<f64>>()))
        })
        .collect();
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
            .caption(
                format!("{}: loss budget ({} formulation)", r.title, first.map_or("", |f| f.name())),
                ("sans-serif", 16),
            )
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
            .y_desc("total power loss of the gearbox (W)")
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
        for (k, name) in parts().iter().enumerate() {
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

/// One contour panel: values[t][s] over speeds (x) and torques (y).
struct Field<'a> {
    title: String,
    speeds: &'a [f64],
    torques: &'a [f64],
    values: Vec<Vec<f64>>,
    unit: &'a str,
}

/// "Nice" iso-levels spanning [lo, hi]: about `n` of them on a 1-2-5 step.
fn levels(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if hi.partial_cmp(&lo) != Some(std::cmp::Ordering::Greater) {
        return vec![lo];
    }
    let raw = (hi - lo) / n as f64;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0].iter().map(|m| m * mag).find(|s| *s >= raw).unwrap_or(10.0 * mag);
    let first = (lo / step).ceil() * step;
    (0..).map(|i| first + i as f64 * step).take_while(|v| *v <= hi + 1e-12 * step).collect()
}

/// Marching squares: the segments of the iso-line `level` on the grid, in (speed, torque).
fn iso_segments(f: &Field, level: f64) -> Vec<[(f64, f64); 2]> {
    let mut out = Vec::new();
    let (xs, ys, v) = (f.speeds, f.torques, &f.values);
    for t in 0..ys.len() - 1 {
        for s in 0..xs.len() - 1 {
            let corners = [(s, t), (s + 1, t), (s + 1, t + 1), (s, t + 1)];
            let mut cuts = Vec::new();
            for k in 0..4 {
                let (a, b) = (corners[k], corners[(k + 1) % 4]);
                let (va, vb) = (v[a.1][a.0], v[b.1][b.0]);
                if !(va.is_finite() && vb.is_finite()) || (va - level) * (vb - level) > 0.0 || va == vb {
                    continue;
                }
                let w = (level - va) / (vb - va);
                cuts.push((xs[a.0] + w * (xs[b.0] - xs[a.0]), ys[a.1] + w * (ys[b.1] - ys[a.1])));
            }
            if cuts.len() >= 2 {
                out.push([cuts[0], cuts[1]]);
            }
            if cuts.len() == 4 {
                out.push([cuts[2], cuts[3]]);
            }
        }
    }
    out
}

/// Bilinear value at fractional grid position (s, t).
fn bilinear(v: &[Vec<f64>], s: f64, t: f64) -> f64 {
    let (s0, t0) = ((s.floor() as usize).min(v[0].len() - 2), (t.floor() as usize).min(v.len() - 2));
    let (fs, ft) = (s - s0 as f64, t - t0 as f64);
    let a = v[t0][s0] * (1.0 - fs) + v[t0][s0 + 1] * fs;
    let b = v[t0 + 1][s0] * (1.0 - fs) + v[t0 + 1][s0 + 1] * fs;
    a * (1.0 - ft) + b * ft
}

fn draw_field(
    area: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    f: &Field,
    speed_unit: &str,
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
    let mut chart = ChartBuilder::on(area)
        .caption(format!("{} ({})", f.title, f.unit), ("sans-serif", 14))
        .margin(14)
        .margin_right(78)
        .x_label_area_size(38)
        .y_label_area_size(62)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(e)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(format!("pinion speed ({speed_unit})"))
        .y_desc("pinion torque (N·m)")
        .x_labels(6)
        .y_labels(6)
        .x_label_formatter(&|x| crate::render::table::sig(*x))
        .y_label_formatter(&|y| crate::render::table::sig(*y))
        .draw()
        .map_err(e)?;
    // Filled bands: each grid cell split 4 × 4, coloured by the band of its bilinear centre value;
    // along each row of sub-cells, neighbours in the same band are drawn as one rectangle (the
    // picture is the same, the file a fraction of the size).
    const SUB: usize = 4;
    let (ns, nt) = (f.speeds.len(), f.torques.len());
    let band = |v: f64| lv.iter().filter(|l| v >= **l).count();
    let x_at = |k: usize| {
        let (s, i) = (k / SUB, k % SUB);
        if s + 1 >= ns {
            f.speeds[ns - 1]
        } else {
            f.speeds[s] + i as f64 / SUB as f64 * (f.speeds[s + 1] - f.speeds[s])
        }
    };
    let mut cells = Vec::new();
    for t in 0..nt - 1 {
        for j in 0..SUB {
            let (ft0, ft1) = (j as f64 / SUB as f64, (j + 1) as f64 / SUB as f64);
            let y = |fr: f64| f.torques[t] + fr * (f.torques[t + 1] - f.torques[t]);
            // (first sub-column, band) of the run being built.
            let mut run: Option<(usize, usize)> = None;
            for k in 0..=(ns - 1) * SUB {
                let here = (k < (ns - 1) * SUB)
                    .then(|| {
                        let (s, i) = (k / SUB, k % SUB);
                        bilinear(&f.values, s as f64 + (i as f64 + 0.5) / SUB as f64, t as f64 + 0.5 * (ft0 + ft1))
                    })
                    .filter(|v| v.is_finite())
                    .map(band);
                if run.map(|r| r.1) != here {
                    if let Some((k0, b)) = run {
                        let fill = colour(b as f64 / lv.len().max(1) as f64).filled();
                        cells.push(Rectangle::new([(x_at(k0), y(ft0)), (x_at(k), y(ft1))], fill));
                    }
                    run = here.map(|b| (k, b));
                }
            }
        }
    }
    chart.draw_series(cells).map_err(e)?;
    for l in &lv {
        let segs = iso_segments(f, *l);
        chart.draw_series(segs.iter().map(|s| PathElement::new(vec![s[0], s[1]], BLACK.stroke_width(1)))).map_err(e)?;
        if let Some(s) = segs.get(segs.len() / 2) {
            let label = crate::render::table::sig(*l);
            chart
                .draw_series(std::iter::once(Text::new(label, s[0], ("sans-serif", 11).into_font().color(&BLACK))))
                .map_err(e)?;
        }
    }
    colour_bar(area, &lv)
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

/// efficiency_map.svg: for each law (first formulation): total η, mesh η and total loss when the
/// scene describes its gearbox; else mesh η and mesh loss.
pub fn efficiency_map(r: &Report) -> Result<String, String> {
    let Some(m) = &r.efficiency_map else { return Err("the report has no efficiency map".into()) };
    // Speeds in the unit the scene wrote them in.
    let speeds = &m.speeds_written;
    let torques: Vec<f64> = m.pinion_torques.iter().map(|t| t.0).collect();
    let first = m.formulation;
    let fields: Vec<(String, Vec<Vec<f64>>, &str)> =
        m.fields.iter().map(|f| (f.title.clone(), f.values.clone(), f.unit.as_str())).collect();
    let per_row = if fields.len().is_multiple_of(3) { 3 } else { 2 };
    let rows = fields.len().div_ceil(per_row).max(1);
    let mut svg = String::new();
    {
        let root =
            SVGBackend::with_string(&mut svg, (420 * per_row as u32, 40 + 360 * rows as u32)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let root = root
            .titled(
                &format!("{}: efficiency map ({} formulation)", r.title, first.map_or("", |f| f.name())),
                ("sans-serif", 18),
            )
            .map_err(|e| e.to_string())?;
        let areas = root.split_evenly((rows, per_row));
        for (area, (title, values, unit)) in areas.iter().zip(fields) {
            let f = Field { title, speeds, torques: &torques, values, unit };
            draw_field(area, &f, &m.speed_unit)?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The iso-line of a plane v = x + y at level 1 on the unit square crosses at (1, 0) and (0, 1).
    #[test]
    fn marching_squares_on_a_plane() {
        let f = Field {
            title: String::new(),
            speeds: &[0.0, 1.0],
            torques: &[0.0, 1.0],
            values: vec![vec![0.0, 1.0], vec![1.0, 2.0]],
            unit: "",
        };
        let s = iso_segments(&f, 0.5);
        assert_eq!(s.len(), 1);
        let mut ends = s[0].to_vec();
        ends.sort_by(|a, b| a.0.total_cmp(&b.0));
        assert!((ends[0].0 - 0.0).abs() < 1e-12 && (ends[0].1 - 0.5).abs() < 1e-12);
        assert!((ends[1].0 - 0.5).abs() < 1e-12 && (ends[1].1 - 0.0).abs() < 1e-12);
        assert_eq!(levels(0.0, 1.0, 5), vec![0.0, 0.2, 0.4, 0.6000000000000001, 0.8, 1.0]);
    }
}
