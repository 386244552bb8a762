//! A figure of panels: the curves, axes and legend every plot shares.

use plotters::coord::Shift;
use plotters::prelude::*;

pub(super) const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
    RGBColor(140, 86, 75),
    RGBColor(127, 127, 127),
];

/// Series of fewer points than this get a marker at every point.
const MARKERS_BELOW: usize = 20;

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
    pub marks: Vec<(String, f64)>,
    /// Shaded x-ranges with a label (regime bands).
    pub bands: Vec<(f64, f64, String)>,
    /// Values with |y| above this are drawn at the limit and marked with ▲/▼.
    pub clip: Option<f64>,
}

/// A range plotters can draw ticks for: finite, increasing, with a finite width not lost in the
/// rounding of its ends. A degenerate range is widened around its value; None if none can be drawn
/// (values near the largest f64), so that a plot can never hang or fail on extreme numbers.
pub(crate) fn plottable(lo: f64, hi: f64) -> Option<(f64, f64)> {
    if !(lo.is_finite() && hi.is_finite()) || hi < lo {
        return None;
    }
    let scale = lo.abs().max(hi.abs());
    if scale > 1e300 {
        return None;
    }
    if hi - lo <= 1e-9 * scale || hi == lo {
        let half = (1e-3 * scale).max(1e-12);
        return Some((lo - half, hi + half));
    }
    Some((lo, hi))
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

pub(super) fn draw_panel(area: &DrawingArea<SVGBackend, Shift>, panel: &Panel) -> Result<(), String> {
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
    let Some((x0, x1)) = plottable(x0, x1) else { return Ok(()) };
    // A hair wider than the data (1e-9 of the span): an end of the data at a round value keeps its
    // tick, whatever the last bit of that value.
    let hair = 1e-9 * (x1 - x0);
    let (x0, x1) = (x0 - hair, x1 + hair);
    let clip = |y: f64| panel.clip.map_or(y, |c| y.clamp(-c, c));
    let (y0, y1) = bounds(all.iter().chain(&panel.points).flat_map(|(_, s)| s.iter().map(|p| clip(p.1))));
    let Some((y0, y1)) = plottable(y0, y1) else { return Ok(()) };
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
    for (i, (_, pts)) in all.iter().enumerate() {
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
        // A sweep of few points gets a marker at each point (the line alone hides where they are).
        let few = pts.iter().filter(|p| p.0.is_finite() && p.1.is_finite()).count() < MARKERS_BELOW;
        for run in runs.into_iter().filter(|r| !r.is_empty()) {
            if few {
                chart.draw_series(run.iter().map(|p| Circle::new(*p, 3, color.filled()))).map_err(e)?;
            }
            chart.draw_series(LineSeries::new(run, color.stroke_width(2))).map_err(e)?;
        }
        if let Some(&(cx, cy)) = clipped.iter().min_by(|a, b| a.0.total_cmp(&b.0)) {
            let mark = if cy > 0.0 { "▲ clipped" } else { "▼ clipped" };
            chart
                .draw_series(std::iter::once(Text::new(mark, (cx, cy), ("sans-serif", 11).into_font().color(&color))))
                .map_err(e)?;
        }
    }
    for (i, (_, pts)) in panel.points.iter().enumerate() {
        let color = PALETTE[(all.len() + i) % PALETTE.len()];
        let finite: Vec<(f64, f64)> = pts.iter().copied().filter(|p| p.0.is_finite() && p.1.is_finite()).collect();
        chart.draw_series(finite.into_iter().map(|p| Cross::new(p, 6, color.stroke_width(2)))).map_err(e)?;
    }
    Ok(())
}

/// Stacked panels; returns the SVG text. Legends stand in a column right of the plot areas, so
/// that they never hide a curve.
pub fn figure(title: &str, panels: &[Panel]) -> Result<String, String> {
    figure_with_legend(title, panels, 260)
}

/// [`figure`] with a legend column `legend_width` pixels wide, for long legend labels.
pub fn figure_with_legend(title: &str, panels: &[Panel], legend_width: u32) -> Result<String, String> {
    let mut svg = String::new();
    {
        let labelled = panels.iter().any(|p| legend_entries(p).iter().any(|(l, _, _)| !l.is_empty()));
        let height = 40 + 260 * panels.len() as u32;
        let width = if labelled { 880 + legend_width } else { 900 };
        let root = SVGBackend::with_string(&mut svg, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let root = root.titled(title, ("sans-serif", 18)).map_err(|e| e.to_string())?;
        let areas = root.split_evenly((panels.len(), 1));
        for (area, panel) in areas.iter().zip(panels) {
            if labelled {
                let (plot, legend) = area.split_horizontally(880);
                draw_panel(&plot, panel)?;
                draw_legend(&legend, panel)?;
            } else {
                draw_panel(area, panel)?;
            }
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}

/// (label in words, colour, drawn as a cross) of every labelled series of a panel, in drawing order.
fn legend_entries(panel: &Panel) -> Vec<(String, RGBColor, bool)> {
    let lines = panel.series.iter().map(|(l, _)| l).chain(panel.xy.iter().map(|(l, _)| l));
    let n = panel.series.len() + panel.xy.len();
    let mut out: Vec<(String, RGBColor, bool)> =
        lines.enumerate().map(|(i, l)| (legend_words(l), PALETTE[i % PALETTE.len()], false)).collect();
    out.extend(
        panel.points.iter().enumerate().map(|(i, (l, _))| (legend_words(l), PALETTE[(n + i) % PALETTE.len()], true)),
    );
    out
}

/// A law's label in words wherever it starts a legend label (`coulomb(mu = 0.04) external` →
/// "Coulomb μ = 0.04 external"); other labels as they are.
pub(crate) fn legend_words(label: &str) -> String {
    for law in crate::friction::catalog::LAWS {
        let name = law.id.name();
        if let Some(rest) = label.strip_prefix(name) {
            let (args, tail) = if rest.starts_with('(') {
                match rest.find(')') {
                    Some(i) => (&rest[..=i], &rest[i + 1..]),
                    None => (rest, ""),
                }
            } else if rest.is_empty() || rest.starts_with(' ') {
                ("", rest)
            } else {
                continue;
            };
            return format!("{}{tail}", crate::render::table::law_words(&format!("{name}{args}")));
        }
    }
    label.to_string()
}

fn draw_legend(area: &DrawingArea<SVGBackend, Shift>, panel: &Panel) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    let font = ("sans-serif", 12).into_font();
    for (k, (label, color, cross)) in legend_entries(panel).into_iter().filter(|(l, _, _)| !l.is_empty()).enumerate() {
        let y = 24 + 18 * k as i32;
        if cross {
            area.draw(&Cross::new((14, y), 5, color.stroke_width(2))).map_err(e)?;
        } else {
            area.draw(&PathElement::new(vec![(4, y), (24, y)], color.stroke_width(2))).map_err(e)?;
        }
        area.draw(&Text::new(label, (30, y - 6), font.clone())).map_err(e)?;
    }
    Ok(())
}
