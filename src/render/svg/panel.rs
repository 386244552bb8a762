//! A figure of panels: the curves, axes and legend every plot shares.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::curve::{draw_bands_and_marks, draw_curve};
pub(super) use super::palette::PALETTE;

/// Twenty categorical colours (the "tab20" set: each hue dark, then light), for panels of more than
/// eight labelled curves, so that no two curves share a colour up to twenty.
const WIDE_PALETTE: [RGBColor; 20] = [
    RGBColor(31, 119, 180),
    RGBColor(174, 199, 232),
    RGBColor(255, 127, 14),
    RGBColor(255, 187, 120),
    RGBColor(44, 160, 44),
    RGBColor(152, 223, 138),
    RGBColor(214, 39, 40),
    RGBColor(255, 152, 150),
    RGBColor(148, 103, 189),
    RGBColor(197, 176, 213),
    RGBColor(140, 86, 75),
    RGBColor(196, 156, 148),
    RGBColor(227, 119, 194),
    RGBColor(247, 182, 210),
    RGBColor(127, 127, 127),
    RGBColor(199, 199, 199),
    RGBColor(188, 189, 34),
    RGBColor(219, 219, 141),
    RGBColor(23, 190, 207),
    RGBColor(158, 218, 229),
];

/// The colour of curve `i` of `n` labelled ones.
fn categorical(i: usize, n: usize) -> RGBColor {
    if n > PALETTE.len() {
        WIDE_PALETTE[i % WIDE_PALETTE.len()]
    } else {
        PALETTE[i % PALETTE.len()]
    }
}

/// Curves a panel labels one by one; beyond this a panel with a [`Shading`] colours its curves by
/// a value on a colour scale (with a colour bar) and tells groups apart by their markers.
pub(super) const MAX_LABELLED: usize = 8;

/// How a panel with many curves draws them: curve i belongs to group `group[i]` (its marker and
/// legend entry) and is coloured by `value[i]` on the viridis scale, explained by a colour bar
/// labelled `value_label`.
#[derive(Default, Clone)]
pub struct Shading {
    pub group: Vec<usize>,
    pub value: Vec<f64>,
    pub group_labels: Vec<String>,
    pub value_label: String,
}

impl Shading {
    fn range(&self) -> (f64, f64) {
        let lo = self.value.iter().copied().filter(|v| v.is_finite()).fold(f64::INFINITY, f64::min);
        let hi = self.value.iter().copied().filter(|v| v.is_finite()).fold(f64::NEG_INFINITY, f64::max);
        (lo, hi)
    }

    /// The colour of curve i.
    fn colour(&self, i: usize) -> RGBColor {
        let (lo, hi) = self.range();
        let t = if hi > lo { (self.value.get(i).copied().unwrap_or(lo) - lo) / (hi - lo) } else { 0.5 };
        colour(t)
    }
}

/// The viridis scale at t in [0, 1].
pub(super) fn colour(t: f64) -> RGBColor {
    const STOPS: [(f64, f64, f64); 5] =
        [(68.0, 1.0, 84.0), (59.0, 82.0, 139.0), (33.0, 145.0, 140.0), (94.0, 201.0, 98.0), (253.0, 231.0, 37.0)];
    let t = if t.is_finite() { t.clamp(0.0, 1.0) } else { 0.0 } * (STOPS.len() - 1) as f64;
    let i = (t.floor() as usize).min(STOPS.len() - 2);
    let f = t - i as f64;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    let mix = |x: f64, y: f64| (x + f * (y - x)).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

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
    /// How to draw more than `MAX_LABELLED` curves of `series` (None: a palette and a legend entry each).
    pub shading: Option<Shading>,
}

impl Panel {
    /// The shading in force: given, and more curves than can be labelled one by one.
    fn shaded(&self) -> Option<&Shading> {
        self.shading.as_ref().filter(|_| self.series.len() > MAX_LABELLED)
    }
}

/// The widest a line of sans-serif text of `size` px may be, per character: an upper bound on the
/// average advance of the plots' fonts (DejaVu Sans ~0.55 em for mixed text), so that text measured
/// with it fits wherever the viewer's sans-serif is drawn.
pub(crate) const CHAR_WIDTH_EM: f64 = 0.6;

/// The font size (px) for a title of `text` across `width` px: `max` where it fits, smaller where it
/// would run past the canvas' edges (never below 9 px).
pub(crate) fn fitted(text: &str, width: u32, max: f64) -> f64 {
    let chars = text.chars().count().max(1) as f64;
    ((width as f64 - 24.0) / (CHAR_WIDTH_EM * chars)).clamp(9.0, max)
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
    draw_bands_and_marks(&mut chart, &panel.bands, &panel.marks, y0, y1)?;
    let shaded = panel.shaded();
    for (i, (_, pts)) in all.iter().enumerate() {
        let color = match shaded {
            Some(sh) if i < panel.series.len() => sh.colour(i),
            _ => categorical(i, all.len() + panel.points.len()),
        };
        // Shaded curves carry their group's marker.
        let group = shaded.filter(|_| i < panel.series.len()).map(|sh| sh.group.get(i).copied().unwrap_or(0));
        draw_curve(&mut chart, pts, color, group, &clip)?;
    }
    for (i, (_, pts)) in panel.points.iter().enumerate() {
        let color = categorical(all.len() + i, all.len() + panel.points.len());
        let finite: Vec<(f64, f64)> = pts.iter().copied().filter(|p| p.0.is_finite() && p.1.is_finite()).collect();
        chart.draw_series(finite.into_iter().map(|p| Cross::new(p, 6, color.stroke_width(2)))).map_err(e)?;
    }
    Ok(())
}

/// Stacked panels; returns the SVG text. Legends stand in a column right of the plot areas, so
/// that they never hide a curve, wide enough for their longest label (260 to 560 px).
pub fn figure(title: &str, panels: &[Panel]) -> Result<String, String> {
    let longest = panels.iter().flat_map(legend_entries).map(|(l, _, _)| l.chars().count()).max().unwrap_or(0);
    figure_with_legend(title, panels, (40 + 7 * longest as u32).clamp(260, 560))
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
    if let Some(sh) = panel.shaded() {
        let mut out: Vec<(String, RGBColor, bool)> =
            sh.group_labels.iter().map(|l| (legend_words(l), RGBColor(60, 60, 60), false)).collect();
        out.push((sh.value_label.clone(), RGBColor(60, 60, 60), false));
        return out;
    }
    let lines = panel.series.iter().map(|(l, _)| l).chain(panel.xy.iter().map(|(l, _)| l));
    let n = panel.series.len() + panel.xy.len();
    let total = n + panel.points.len();
    let mut out: Vec<(String, RGBColor, bool)> =
        lines.enumerate().map(|(i, l)| (legend_words(l), categorical(i, total), false)).collect();
    out.extend(panel.points.iter().enumerate().map(|(i, (l, _))| (legend_words(l), categorical(n + i, total), true)));
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
            } else if rest.is_empty() || rest.starts_with(' ') || rest.starts_with(',') {
                ("", rest)
            } else {
                continue;
            };
            return format!("{}{tail}", crate::render::table::law_words(&format!("{name}{args}")));
        }
    }
    label.to_string()
}

pub(super) fn draw_legend(area: &DrawingArea<SVGBackend, Shift>, panel: &Panel) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    let font = ("sans-serif", 12).into_font();
    if let Some(sh) = panel.shaded() {
        // One entry per group with its marker, then the colour bar of the value.
        let grey = RGBColor(60, 60, 60);
        for (k, label) in sh.group_labels.iter().enumerate() {
            let y = 24 + 18 * k as i32;
            area.draw(&PathElement::new(vec![(4, y), (24, y)], grey.stroke_width(2))).map_err(e)?;
            match k % 4 {
                0 => area.draw(&Circle::new((14, y), 3, grey.filled())),
                1 => area.draw(&TriangleMarker::new((14, y), 4, grey.filled())),
                2 => area.draw(&(EmptyElement::at((14, y)) + Rectangle::new([(-3, -3), (3, 3)], grey.filled()))),
                _ => area.draw(&Cross::new((14, y), 4, grey.stroke_width(2))),
            }
            .map_err(e)?;
            area.draw(&Text::new(legend_words(label), (30, y - 6), font.clone())).map_err(e)?;
        }
        let top = 24 + 18 * sh.group_labels.len() as i32 + 10;
        area.draw(&Text::new(sh.value_label.clone(), (4, top), font.clone())).map_err(e)?;
        let (lo, hi) = sh.range();
        const STEPS: i32 = 40;
        for k in 0..STEPS {
            let c = colour(k as f64 / (STEPS - 1) as f64);
            let x = 4 + 5 * k;
            area.draw(&Rectangle::new([(x, top + 18), (x + 5, top + 32)], c.filled())).map_err(e)?;
        }
        let number = |v: f64| crate::render::table::sig(v);
        area.draw(&Text::new(number(lo), (4, top + 36), font.clone())).map_err(e)?;
        let hi_text = number(hi);
        let right = 4 + 5 * STEPS - 7 * hi_text.chars().count() as i32;
        area.draw(&Text::new(hi_text, (right.max(60), top + 36), font.clone())).map_err(e)?;
        return Ok(());
    }
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
