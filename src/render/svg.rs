//! SVG plots drawn with plotters' SVG backend (no system fonts: text is laid out by plotters' own estimate).

use plotters::coord::Shift;
use plotters::prelude::*;

use crate::report::Report;

const PALETTE: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
];

/// One panel: curves over x (mm from T1) with the named points marked.
pub struct Panel<'a> {
    pub y_label: &'a str,
    pub series: Vec<(String, Vec<f64>)>,
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
    let pad = if hi > lo {
        0.06 * (hi - lo)
    } else {
        0.5 * hi.abs().max(1.0)
    };
    (lo - pad, hi + pad)
}

fn draw_panel(
    area: &DrawingArea<SVGBackend, Shift>,
    x: &[f64],
    marks: &[(&'static str, f64)],
    panel: &Panel,
    x_label: &str,
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    let (x0, x1) = (x[0], x[x.len() - 1]);
    let (y0, y1) = bounds(panel.series.iter().flat_map(|(_, s)| s.iter().copied()));
    let mut chart = ChartBuilder::on(area)
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(64)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(panel.y_label)
        .x_labels(8)
        .y_labels(6)
        .light_line_style(WHITE.mix(0.0))
        .draw()
        .map_err(e)?;
    for (name, u) in marks {
        chart
            .draw_series(LineSeries::new(
                vec![(*u, y0), (*u, y1)],
                BLACK.mix(0.35).stroke_width(1),
            ))
            .map_err(e)?;
        chart
            .draw_series(std::iter::once(Text::new(
                name.to_string(),
                (*u, y1),
                ("sans-serif", 14).into_font().color(&BLACK),
            )))
            .map_err(e)?;
    }
    for (i, (label, ys)) in panel.series.iter().enumerate() {
        let color = PALETTE[i % PALETTE.len()];
        let points: Vec<(f64, f64)> = x
            .iter()
            .zip(ys)
            .filter(|(_, y)| y.is_finite())
            .map(|(x, y)| (*x, *y))
            .collect();
        let s = chart
            .draw_series(LineSeries::new(points, color.stroke_width(2)))
            .map_err(e)?;
        if !label.is_empty() {
            s.label(label.clone()).legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 16, y)], color.stroke_width(2))
            });
        }
    }
    if panel.series.iter().any(|(l, _)| !l.is_empty()) {
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

/// Stacked panels sharing an x axis (mm from T1); returns the SVG text.
pub fn stacked_panels(
    title: &str,
    x_mm: &[f64],
    marks_mm: &[(&'static str, f64)],
    panels: &[Panel],
    x_label: &str,
) -> Result<String, String> {
    let mut svg = String::new();
    {
        let height = 40 + 260 * panels.len() as u32;
        let root = SVGBackend::with_string(&mut svg, (900, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let root = root
            .titled(title, ("sans-serif", 18))
            .map_err(|e| e.to_string())?;
        let areas = root.split_evenly((panels.len(), 1));
        for (area, panel) in areas.iter().zip(panels) {
            draw_panel(area, x_mm, marks_mm, panel, x_label)?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}

/// contact_state.svg: v_s (per speed), SR and p_H (per torque) along the line of action.
pub fn contact_state(r: &Report) -> Result<String, String> {
    let c = &r.curves;
    let x: Vec<f64> = c.u.iter().map(|u| u * 1e3).collect();
    let marks: Vec<(&'static str, f64)> = c.marks.iter().map(|(n, u)| (*n, u * 1e3)).collect();
    let panels = [
        Panel {
            y_label: "sliding velocity v_s (m/s)",
            series: c.sliding_velocity.clone(),
        },
        Panel {
            y_label: "slide-to-roll ratio SR",
            series: vec![(String::new(), c.slide_to_roll.clone())],
        },
        Panel {
            y_label: "Hertzian pressure p_H (MPa)",
            series: c
                .hertz_pressure
                .iter()
                .map(|(l, v)| (l.clone(), v.iter().map(|p| p * 1e-6).collect()))
                .collect(),
        },
    ];
    stacked_panels(
        &format!("{}: contact along the line of action", r.title),
        &x,
        &marks,
        &panels,
        "distance from T1 (mm)",
    )
}
