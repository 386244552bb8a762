//! map_efficiency.svg: mean efficiency and friction power loss over the torque × speed map, one
//! pair of heat maps per law and formulation (up to [`MAX_MAPS`]), on the report's map grid.

use plotters::prelude::*;

pub(super) use super::panel::colour;
use super::panel::plottable;
use crate::report::friction::EfficiencyRecord;
use crate::report::Report;

/// Laws × formulations drawn as maps.
pub(super) const MAX_MAPS: usize = 3;

/// Cell edges around sorted centres: midpoints, the outer ones mirrored.
fn edges(c: &[f64]) -> Vec<f64> {
    let mut e = vec![c[0] - 0.5 * (c[1] - c[0])];
    e.extend(c.windows(2).map(|w| 0.5 * (w[0] + w[1])));
    e.push(c[c.len() - 1] + 0.5 * (c[c.len() - 1] - c[c.len() - 2]));
    e
}

/// One heat map: values over speed (x) × torque (y) cells.
pub(crate) struct Map<'a> {
    pub title: String,
    pub speeds: &'a [f64],
    pub torques: &'a [f64],
    /// values[t][s], NaN where missing.
    pub values: Vec<Vec<f64>>,
    /// The axes' descriptions.
    pub x_label: String,
    pub y_label: String,
    /// Circles over the map at (x, y), their area in proportion to the weight (none: a plain map).
    pub marks: Vec<(f64, f64, f64)>,
}

/// Heat maps two a row under `title`.
pub(crate) fn heat_maps(title: &str, maps: &[Map]) -> Result<String, String> {
    let mut svg = String::new();
    {
        let rows = maps.len().div_ceil(2).max(1);
        let root = SVGBackend::with_string(&mut svg, (1000, 40 + 320 * rows as u32)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let root = root.titled(title, ("sans-serif", 18)).map_err(|e| e.to_string())?;
        let areas = root.split_evenly((rows, 2));
        for (area, map) in areas.iter().zip(maps) {
            draw_map(area, map)?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}

fn draw_map(area: &DrawingArea<SVGBackend, plotters::coord::Shift>, m: &Map) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    let (xe, ye) = (edges(m.speeds), edges(m.torques));
    let (Some((x0, x1)), Some((y0, y1))) = (plottable(xe[0], xe[xe.len() - 1]), plottable(ye[0], ye[ye.len() - 1]))
    else {
        return Ok(());
    };
    let finite = m.values.iter().flatten().copied().filter(|v| v.is_finite());
    let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |a, v| (a.0.min(v), a.1.max(v)));
    let span = if hi > lo { hi - lo } else { 1.0 };
    let caption = if lo.is_finite() {
        format!("{}: {} (dark) to {} (yellow)", m.title, crate::render::table::sig(lo), crate::render::table::sig(hi))
    } else {
        format!("{}: no finite values", m.title)
    };
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 14))
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(72)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(e)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(m.x_label.as_str())
        .y_desc(m.y_label.as_str())
        .x_labels(8)
        .y_labels(6)
        .draw()
        .map_err(e)?;
    let cells = m
        .values
        .iter()
        .enumerate()
        .flat_map(|(t, row)| row.iter().enumerate().filter(|(_, v)| v.is_finite()).map(move |(s, v)| (t, s, *v)));
    chart
        .draw_series(cells.map(|(t, s, v)| {
            Rectangle::new([(xe[s], ye[t]), (xe[s + 1], ye[t + 1])], colour((v - lo) / span).filled())
        }))
        .map_err(e)?;
    let heaviest = m.marks.iter().map(|m| m.2).fold(0.0, f64::max);
    if heaviest > 0.0 {
        // The heaviest mark 9 px across; area in proportion to the weight.
        let radius = |w: f64| (9.0 * (w / heaviest).sqrt()).round().max(1.0) as i32;
        chart
            .draw_series(m.marks.iter().map(|&(x, y, w)| Circle::new((x, y), radius(w), RED.mix(0.8).stroke_width(1))))
            .map_err(e)?;
    }
    Ok(())
}

/// The map plot; the grid is the report's [`crate::report::Report::map_grid`].
pub fn efficiency_map(r: &Report) -> Result<String, String> {
    let Some((ti, si)) = &r.map_grid else { return Err("the report has no map grid".into()) };
    let on_grid = |rec: &&EfficiencyRecord| {
        ti.binary_search(&rec.torque_index).is_ok() && si.binary_search(&rec.speed_index).is_ok()
    };
    let mut combos: Vec<(String, crate::model::Formulation)> = Vec::new();
    for rec in &r.efficiency {
        if !combos.iter().any(|(l, f)| *l == rec.label && *f == rec.formulation) && combos.len() < MAX_MAPS {
            combos.push((rec.label.clone(), rec.formulation));
        }
    }
    let mut speeds = vec![f64::NAN; si.len()];
    let mut torques = vec![f64::NAN; ti.len()];
    for rec in r.efficiency.iter().filter(on_grid) {
        let (t, s) =
            (ti.binary_search(&rec.torque_index).unwrap_or(0), si.binary_search(&rec.speed_index).unwrap_or(0));
        speeds[s] = r.speed_unit.value(&rec.pinion_speed);
        torques[t] = rec.pinion_torque.si() / r.torque_unit.factor;
    }
    if speeds.iter().chain(&torques).any(|x| !x.is_finite()) || speeds.len() < 2 || torques.len() < 2 {
        return Err("the map grid is incomplete".into());
    }
    let mut maps = Vec::new();
    let power = r.units().power();
    for (label, f) in &combos {
        let mut eta = vec![vec![f64::NAN; si.len()]; ti.len()];
        let mut loss = eta.clone();
        for rec in r.efficiency.iter().filter(on_grid).filter(|x| x.label == *label && x.formulation == *f) {
            let (t, s) =
                (ti.binary_search(&rec.torque_index).unwrap_or(0), si.binary_search(&rec.speed_index).unwrap_or(0));
            eta[t][s] = 100.0 * rec.mean_efficiency.0;
            loss[t][s] = power.value(rec.power_loss.si());
        }
        let name = format!("{label} {}", f.name());
        let (x_label, y_label) =
            (format!("pinion speed ({})", r.speed_unit.name), format!("pinion torque ({})", r.torque_unit.shown()));
        maps.push(Map {
            title: format!("η̄ % — {name}"),
            speeds: &speeds,
            torques: &torques,
            values: eta,
            x_label: x_label.clone(),
            y_label: y_label.clone(),
            marks: Vec::new(),
        });
        maps.push(Map {
            title: format!("P_loss {} — {name}", power.unit),
            speeds: &speeds,
            torques: &torques,
            values: loss,
            x_label,
            y_label,
            marks: Vec::new(),
        });
    }
    heat_maps(&format!("{}: mean efficiency and power loss over the map", r.title), &maps)
}
