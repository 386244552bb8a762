//! mesh_stiffness.svg (K(s) over two mesh cycles with the PEM mean and ISO 6336-1's c_γα b drawn,
//! one pair's k(s) beside), transmission_error.svg (STE over one cycle, one curve per torque) and
//! load_share.svg (one pair's share of F_bn along its path, one curve per torque). Positions from A
//! in mm, stiffness in N/µm, STE in µm (in, lbf/µin and µin for a scene written in inches).

use plotters::prelude::*;

use super::panel::{plottable, PALETTE};
use crate::report::teeth::Series;
use crate::report::units::Units;
use crate::report::Report;

fn err<E: std::error::Error + Send + Sync>(e: DrawingAreaErrorKind<E>) -> String {
    e.to_string()
}

/// A labelled curve, a style index, and whether it is dashed (a reference line).
struct Curve {
    label: String,
    points: Vec<(f64, f64)>,
    colour: usize,
}

fn lines(title: &str, x_desc: &str, y_desc: &str, curves: &[Curve], y_from_zero: bool) -> Result<String, String> {
    let all = || curves.iter().flat_map(|c| c.points.iter()).filter(|p| p.0.is_finite() && p.1.is_finite());
    let (x0, x1) = all().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.0), b.max(p.0)));
    let (y0, y1) = all().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.1), b.max(p.1)));
    let Some((x0, x1)) = plottable(x0, x1) else { return Err("nothing to draw".into()) };
    let y0 = if y_from_zero { 0.0 } else { y0 };
    let pad = 0.08 * (y1 - y0).max(1e-12);
    let Some((y0, y1)) = plottable(if y_from_zero { 0.0 } else { y0 - pad }, y1 + 2.5 * pad) else {
        return Err("nothing to draw".into());
    };
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 520)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 15))
            .margin(14)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(err)?;
        chart.configure_mesh().x_desc(x_desc).y_desc(y_desc).draw().map_err(err)?;
        for c in curves {
            let style = PALETTE[c.colour % PALETTE.len()].stroke_width(2);
            chart
                .draw_series(LineSeries::new(c.points.iter().copied(), style))
                .map_err(err)?
                .label(c.label.clone())
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 18, y)], style));
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK.mix(0.4))
            .draw()
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    Ok(svg)
}

/// The plotted points of a series `y` over positions `x`, each converted for the plot.
fn points(x: &Series, y: &Series, fx: impl Fn(f64) -> f64, fy: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    x.values.iter().zip(&y.values).map(|(x, y)| (fx(*x), fy(*y))).collect()
}

/// `position s from A (mm)`.
fn position_label(u: Units) -> String {
    format!("position s from A ({})", u.length().unit)
}

/// mesh_stiffness.svg.
pub fn mesh_stiffness(r: &Report) -> Result<String, String> {
    let s = r.stiffness.as_ref().ok_or("the report has no stiffness")?;
    let u = r.units();
    let (len, k_unit) = (u.length(), u.stiffness());
    let pitch = s.mesh.position.values.last().copied().unwrap_or(0.0) - s.mesh.position.values[0];
    let mesh: Vec<(f64, f64)> = [0.0, pitch]
        .iter()
        .flat_map(|o| points(&s.mesh.position, &s.mesh.stiffness, |x| len.value(x + o), |k| k_unit.value(k)))
        .collect();
    let (a, b) = (mesh[0].0, mesh[mesh.len() - 1].0);
    let width = s.mean.si() / s.mean_per_width.si();
    let iso = k_unit.value(s.iso_6336.c_gamma_alpha.si() * width);
    let mean = k_unit.value(s.mean.si());
    let curves = [
        Curve { label: "mesh K(s), potential-energy method".into(), points: mesh, colour: 0 },
        Curve {
            label: "one pair k(s)".into(),
            points: points(&s.pair.position, &s.pair.stiffness, |x| len.value(x), |k| k_unit.value(k)),
            colour: 1,
        },
        Curve { label: format!("mean K̄ = {mean:.1} {}", k_unit.unit), points: vec![(a, mean), (b, mean)], colour: 2 },
        Curve {
            label: format!("ISO 6336-1 c_γα b = {iso:.1} {}", k_unit.unit),
            points: vec![(a, iso), (b, iso)],
            colour: 3,
        },
    ];
    lines(
        &format!("{}: mesh stiffness from the teeth", r.title),
        &position_label(u),
        &k_unit.titled("stiffness"),
        &curves,
        true,
    )
}

/// transmission_error.svg.
pub fn transmission_error(r: &Report) -> Result<String, String> {
    let u = r.units();
    let (len, micro, torque) = (u.length(), u.micro(), u.torque());
    let curves: Vec<Curve> = r
        .transmission_error
        .iter()
        .enumerate()
        .map(|(i, t)| Curve {
            label: format!(
                "{:.0} {} (p-p {})",
                torque.value(t.pinion_torque.si()),
                torque.unit,
                micro.with(t.peak_to_peak.si(), 3)
            ),
            points: points(&t.mesh.position, &t.mesh.ste, |x| len.value(x), |d| micro.value(d)),
            colour: i,
        })
        .collect();
    lines(
        &format!("{}: static transmission error", r.title),
        &position_label(u),
        &micro.titled("STE along the line of action"),
        &curves,
        true,
    )
}

/// load_share.svg.
pub fn load_share(r: &Report) -> Result<String, String> {
    let u = r.units();
    let (len, torque) = (u.length(), u.torque());
    let curves: Vec<Curve> = r
        .transmission_error
        .iter()
        .enumerate()
        .map(|(i, t)| Curve {
            label: format!("{:.0} {}", torque.value(t.pinion_torque.si()), torque.unit),
            points: points(&t.pair.position, &t.pair.load_share, |x| len.value(x), |w| w),
            colour: i,
        })
        .collect();
    lines(&format!("{}: load share of one pair", r.title), &position_label(u), "share of F_bn", &curves, true)
}
