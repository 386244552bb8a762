//! What a panel draws on its chart: the shaded bands and marks along x, and each curve with its
//! gaps, clipping and markers.

use plotters::prelude::*;

use super::palette::PALETTE;

/// Series of fewer points than this get a marker at every point.
const MARKERS_BELOW: usize = 20;

/// A chart of one panel: f64 on both axes, drawn as SVG.
type Chart<'a, 'b> = ChartContext<
    'a,
    SVGBackend<'b>,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// The shaded x bands (a law's regimes) with their labels, and the vertical marks (A B P D E).
pub(super) fn draw_bands_and_marks(
    chart: &mut Chart,
    bands: &[(f64, f64, String)],
    marks: &[(String, f64)],
    y0: f64,
    y1: f64,
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    for (i, (a, b, label)) in bands.iter().enumerate() {
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
    for (name, u) in marks {
        chart.draw_series(LineSeries::new(vec![(*u, y0), (*u, y1)], BLACK.mix(0.35).stroke_width(1))).map_err(e)?;
        chart
            .draw_series(std::iter::once(Text::new(
                name.to_string(),
                (*u, y1),
                ("sans-serif", 14).into_font().color(&BLACK),
            )))
            .map_err(e)?;
    }
    Ok(())
}

/// One curve: split at non-finite values so that gaps stay gaps, values beyond the panel's clip
/// drawn at the clip and the first of them marked, markers at every point of a short curve (and,
/// for a curve of a shaded `group`, its group's marker at every tenth point of a long one).
pub(super) fn draw_curve(
    chart: &mut Chart,
    pts: &[(f64, f64)],
    color: RGBColor,
    group: Option<usize>,
    clip: &dyn Fn(f64) -> f64,
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
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
        match group {
            Some(g) => {
                let step = if few { 1 } else { (run.len() / 10).max(1) };
                let at: Vec<(f64, f64)> = run.iter().step_by(step).copied().collect();
                match g % 4 {
                    0 => chart.draw_series(at.iter().map(|p| Circle::new(*p, 3, color.filled()))),
                    1 => chart.draw_series(at.iter().map(|p| TriangleMarker::new(*p, 4, color.filled()))),
                    2 => chart.draw_series(
                        at.iter().map(|p| EmptyElement::at(*p) + Rectangle::new([(-3, -3), (3, 3)], color.filled())),
                    ),
                    _ => chart.draw_series(at.iter().map(|p| Cross::new(*p, 4, color.stroke_width(2)))),
                }
                .map_err(e)?;
            }
            None if few => {
                chart.draw_series(run.iter().map(|p| Circle::new(*p, 3, color.filled()))).map_err(e)?;
            }
            None => {}
        }
        chart.draw_series(LineSeries::new(run, color.stroke_width(2))).map_err(e)?;
    }
    if let Some(&(cx, cy)) = clipped.iter().min_by(|a, b| a.0.total_cmp(&b.0)) {
        let mark = if cy > 0.0 { "▲ clipped" } else { "▼ clipped" };
        chart
            .draw_series(std::iter::once(Text::new(mark, (cx, cy), ("sans-serif", 11).into_font().color(&color))))
            .map_err(e)?;
    }
    Ok(())
}
