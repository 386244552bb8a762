//! plane_of_action.svg for a helical pair: the path of contact in the plane of action (u along the
//! transverse line of action, z across the face) coloured by μ(u) of the first law at the first
//! reported operating point (under the mean load per unit length), the pitch line, the contact lines
//! at a few instants, and the total contact length L(t) with its approach and recess parts over one
//! mesh cycle.

use plotters::prelude::*;

use super::panel::{draw_legend, draw_panel, plottable, Panel, PALETTE};
use crate::report::helical::HelicalReport;
use crate::report::Report;

fn plane(
    area: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    legend: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    h: &HelicalReport,
    mu: Option<(&str, &[f64], &[f64])>,
    len: crate::report::units::Shown,
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    let [a, p, end, half] = h.path.map(|x| len.value(x));
    let (Some((x0, x1)), Some((y0, y1))) = (plottable(a, end), plottable(-half, half)) else { return Ok(()) };
    let pad = 0.04 * (x1 - x0);
    let caption = match mu {
        Some((label, _, values)) => {
            let finite = values.iter().copied().filter(|v| v.is_finite());
            let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |acc, v| (acc.0.min(v), acc.1.max(v)));
            format!(
                "plane of action, μ of {label}: {} (dark) to {} (yellow); contact lines at τ = 0, ¼, ½, ¾",
                crate::render::table::sig(lo),
                crate::render::table::sig(hi)
            )
        }
        None => "plane of action: contact lines at τ = 0, ¼, ½, ¾".into(),
    };
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 13))
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(72)
        .build_cartesian_2d(x0 - pad..x1 + pad, y0 - 0.1 * half..y1 + 0.1 * half)
        .map_err(e)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(len.titled("u from T1"))
        .y_desc(len.titled("z across the face"))
        .draw()
        .map_err(e)?;
    if let Some((_, u, values)) = mu {
        let finite = values.iter().copied().filter(|v| v.is_finite());
        let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |acc, v| (acc.0.min(v), acc.1.max(v)));
        let span = if hi > lo { hi - lo } else { 1.0 };
        let cells = u.windows(2).zip(values.windows(2)).filter(|(_, v)| v[0].is_finite() && v[1].is_finite());
        chart
            .draw_series(cells.map(|(x, v)| {
                let c = super::maps::colour((0.5 * (v[0] + v[1]) - lo) / span);
                Rectangle::new([(len.value(x[0]), -half), (len.value(x[1]), half)], c.filled())
            }))
            .map_err(e)?;
    }
    let outline = vec![(a, -half), (end, -half), (end, half), (a, half), (a, -half)];
    chart.draw_series(LineSeries::new(outline, BLACK.stroke_width(1))).map_err(e)?;
    chart.draw_series(LineSeries::new(vec![(p, -half), (p, half)], BLACK.mix(0.5).stroke_width(1))).map_err(e)?;
    for (name, x) in [("A", a), ("P", p), ("E", end)] {
        chart
            .draw_series(std::iter::once(Text::new(name, (x, half * 1.05), ("sans-serif", 13).into_font())))
            .map_err(e)?;
    }
    for (i, (_, lines)) in h.lines_at.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()];
        for l in lines {
            let pts = vec![(len.value(l[0].0), len.value(l[0].1)), (len.value(l[1].0), len.value(l[1].1))];
            chart.draw_series(LineSeries::new(pts, colour.stroke_width(3))).map_err(e)?;
        }
    }
    // The legend stands beside the plane, never over a contact line.
    for (i, (tau, _)) in h.lines_at.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()];
        let y = 40 + 18 * i as i32;
        legend.draw(&PathElement::new(vec![(4, y), (24, y)], colour.stroke_width(3))).map_err(e)?;
        legend.draw(&Text::new(format!("τ = {tau}"), (30, y - 6), ("sans-serif", 12).into_font())).map_err(e)?;
    }
    Ok(())
}

/// The figure of a pair's report; Err when the report has no helical geometry.
pub fn plane_of_action(r: &Report) -> Result<String, String> {
    let Some(h) = &r.geometry.helical else { return Err("the pair is not helical".into()) };
    let mu = r
        .curves
        .points
        .first()
        .and_then(|p| p.mu.first())
        .map(|(l, v)| (l.as_str(), r.curves.u.as_slice(), v.as_slice()));
    figure(&format!("{}: contact lines and their length", r.title), h, mu, r.units().length())
}

/// The figure of a helical mesh `h` titled `title`: the plane of action (coloured by `mu`, the
/// law's label, u and μ(u), where given) above L(t); a pair's plot and each helical stage mesh's
/// of a drive.
pub(crate) fn figure(
    title: &str,
    h: &HelicalReport,
    mu: Option<(&str, &[f64], &[f64])>,
    len: crate::report::units::Shown,
) -> Result<String, String> {
    let [tau, total, approach, recess] = &h.length_curve;
    let mm = |v: &Vec<f64>| v.iter().map(|x| len.value(*x)).collect::<Vec<_>>();
    let panel = Panel {
        y_label: len.titled("contact length"),
        x_label: "τ (mesh periods)".into(),
        x: tau.clone(),
        series: vec![
            ("L(t) total".into(), mm(total)),
            ("approach side".into(), mm(approach)),
            ("recess side".into(), mm(recess)),
        ],
        ..Default::default()
    };
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1040, 620)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let root =
            root.titled(title, ("sans-serif", super::panel::fitted(title, 1040, 18.0))).map_err(|e| e.to_string())?;
        let (top, bottom) = root.split_vertically(340);
        let (top, top_legend) = top.split_horizontally(880);
        plane(&top, &top_legend, h, mu, len)?;
        let (bottom, bottom_legend) = bottom.split_horizontally(880);
        draw_panel(&bottom, &panel)?;
        draw_legend(&bottom_legend, &panel)?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}
