//! loss_map.svg: the total loss and η over the ends' torque × speed, drive above zero torque and
//! coast below, up to three laws and formulations: filled bands between iso-levels with the
//! iso-lines labelled and a colour bar per panel (the pair's efficiency map's panels), the bands
//! spread over the upper nine tenths of the values so that a few cells near zero torque (where η
//! falls to 0) do not take the whole scale, and each half's located best point ringed on the η
//! panel; and report.md's section on the maps ([`section`]).

use plotters::prelude::*;

use crate::render::markup::md;
use crate::render::svg::{draw_field, fitted, Field};
use crate::render::table::{fixed, header, row};
use crate::report::drive::DriveReport;

use super::shown_units::Shown;

/// The map's file.
pub(crate) const FILE: &str = "loss_map.svg";
/// Its cells as data, as a pair's efficiency_map.csv.
pub(crate) const CSV_FILE: &str = "loss_map.csv";

/// The plot's width (px): a loss panel and an η panel side by side.
const WIDTH: u32 = 1000;

/// Total loss and η over torque × speed, up to three laws and formulations.
pub(crate) fn loss_map(r: &DriveReport) -> Result<String, String> {
    let maps: Vec<_> = r.maps.iter().take(3).collect();
    let mut svg = String::new();
    {
        let rows = maps.len().max(1) as u32;
        let root = SVGBackend::with_string(&mut svg, (WIDTH, 40 + 380 * rows)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let title = format!("{}: total loss and efficiency, drive (T > 0) and coast (T < 0)", r.title);
        let root = root.titled(&title, ("sans-serif", fitted(&title, WIDTH, 18.0))).map_err(|e| e.to_string())?;
        let areas = root.split_evenly((rows as usize, 2));
        let Shown { speed: n, torque: t, units } = Shown::of(r);
        let w = units.power();
        for (k, m) in maps.iter().enumerate() {
            let x_label = format!("{} speed ({})", m.speed_at.name(), n.unit());
            let speeds: Vec<f64> = m.speeds_rpm.iter().map(|x| n.of_rpm(*x)).collect();
            let y_label = format!("{} torque ({}; < 0: coast)", m.torque_at.name(), t.unit());
            let torques: Vec<f64> = m.torques.iter().map(|x| t.of_si(*x)).collect();
            // η is 0 where no power goes through (zero torque, or both ends deliver): the limit
            // of P_out/P_in as the torque falls to zero with the no-load losses still there.
            // A scene of one pair's map draws its own η total, whose best point is located.
            let shown = if m.pinion_efficiency.is_empty() { &m.efficiency } else { &m.pinion_efficiency };
            let eta = shown.iter().map(|row| row.iter().map(|e| 100.0 * e.max(0.0)).collect()).collect();
            let eta_name = if m.pinion_efficiency.is_empty() { "η" } else { "η at the pinion" };
            let loss = Field {
                title: format!("total loss — {} {}", m.law, m.formulation),
                speeds: &speeds,
                torques: &torques,
                values: m.loss.iter().map(|row| row.iter().map(|x| w.value(*x)).collect()).collect(),
                unit: w.unit,
            };
            let efficiency = Field {
                title: format!("{eta_name}, ○ best located — {} {}", m.law, m.formulation),
                speeds: &speeds,
                torques: &torques,
                values: eta,
                unit: "%",
            };
            let best: Vec<(f64, f64)> = m.best.iter().map(|b| (n.of_rpm(b.speed_rpm), t.of_si(b.torque))).collect();
            if m.speeds_rpm.len() < 2 || m.torques.len() < 2 {
                continue;
            }
            draw_field(&areas[2 * k], &loss, (&x_label, &y_label), (&[], &[]))?;
            draw_field(&areas[2 * k + 1], &efficiency, (&x_label, &y_label), (&best, &[]))?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}

/// report.md's section on the maps: per law and formulation the grid's extent, least η and most loss,
/// and the best point of each half, located.
pub(crate) fn section(out: &mut String, r: &DriveReport, u: Shown) {
    let w = u.units.power();
    if !r.maps.is_empty() {
        md!(out, "## Loss map\n");
        md!(out, "![total loss and efficiency over torque and speed]({})\n", super::loss_map::FILE);
        md!(out, "Every cell of every law and formulation is in [{CSV_FILE}]({CSV_FILE}) (SI: N·m, rad/s, W).\n");
        header(
            out,
            &[
                "law",
                "formulation",
                &format!("torques ({})", u.torque.unit()),
                &format!("speeds ({})", u.speed.unit()),
                "least η of the grid points (drive)",
                &w.titled("most loss of the grid points"),
                "most passes",
            ],
        );
        for m in &r.maps {
            let drive_eta = m
                .efficiency
                .iter()
                .zip(&m.torques)
                .filter(|(_, t)| **t > 0.0)
                .flat_map(|(row, _)| row.iter().copied())
                .fold(f64::INFINITY, f64::min);
            let most = m.loss.iter().flatten().copied().fold(f64::NEG_INFINITY, f64::max);
            row(
                out,
                &[
                    m.law.clone(),
                    m.formulation.clone(),
                    format!(
                        "{} … {} ({})",
                        fixed(u.torque.of_si(m.torques[0]), 1),
                        fixed(u.torque.of_si(m.torques[m.torques.len() - 1]), 1),
                        m.torques.len()
                    ),
                    format!(
                        "{} … {} ({})",
                        fixed(u.speed.of_rpm(m.speeds_rpm[0]), 1),
                        fixed(u.speed.of_rpm(m.speeds_rpm[m.speeds_rpm.len() - 1]), 1),
                        m.speeds_rpm.len()
                    ),
                    format!("{} %", fixed(100.0 * drive_eta, 3)),
                    w.cell(most, 2),
                    m.most_passes.to_string(),
                ],
            );
        }
        md!(out, "\nThe grid's cells are the drive solved at the grid points; the least η and most loss above are of those points, not located between them (the map is a picture; the headline's numbers are computed at their points).\n");
        if r.maps.iter().any(|m| !m.best.is_empty()) {
            md!(out, "\nThe best point of each half of the map, located: from the half's best grid point, coordinate ascent by golden sections over the box of its neighbours (torques of the half's sign only), each step the drive solved afresh, until a sweep moves the point by less than 1e-7 of the box.\n");
            header(
                out,
                &[
                    "law",
                    "formulation",
                    "half",
                    &format!("torque ({})", u.torque.unit()),
                    &format!("speed ({})", u.speed.unit()),
                    if r.one_pair { "η at the pinion" } else { "η" },
                    &format!("grid's best ({}, {}, η)", u.torque.unit(), u.speed.unit()),
                    "drives solved",
                ],
            );
            for m in &r.maps {
                for b in &m.best {
                    row(
                        out,
                        &[
                            m.law.clone(),
                            m.formulation.clone(),
                            b.flow.clone(),
                            fixed(u.torque.of_si(b.torque), 3),
                            fixed(u.speed.of_rpm(b.speed_rpm), 3),
                            format!("{} %", fixed(100.0 * b.efficiency, 4)),
                            format!(
                                "{}, {}, {} %",
                                fixed(u.torque.of_si(b.grid_torque), 1),
                                fixed(u.speed.of_rpm(b.grid_speed_rpm), 1),
                                fixed(100.0 * b.grid_efficiency, 4)
                            ),
                            b.evaluations.to_string(),
                        ],
                    );
                }
            }
            md!(out, "");
        }
    }
}

/// loss_map.csv: one row per grid point, law and formulation, as a pair's efficiency_map.csv
/// writes its cells (SI, numbers to 10 significant digits): the torque and speed at the ends the
/// map is given at (named by them: `output_torque_N_m`), the law and formulation, the whole loss
/// P_source − P_sink and η (0 where both ends deliver).
pub(crate) fn csv(r: &DriveReport) -> String {
    use std::fmt::Write;
    let end = |e: crate::drive::ShaftEnd| match e {
        crate::drive::ShaftEnd::Input => "input",
        crate::drive::ShaftEnd::Output => "output",
    };
    let num = |x: f64| format!("{:e}", crate::numerics::rounding::round_sig(x));
    let mut out = String::new();
    for (k, m) in r.maps.iter().enumerate() {
        if k == 0 {
            // A scene of one pair's map is given at its pinion, and gives its own η beside the drive's.
            let (t, s) = if r.one_pair { ("pinion", "pinion") } else { (end(m.torque_at), end(m.speed_at)) };
            let parts: String = m.parts.iter().map(|p| format!("{}_W,", p.key)).collect();
            let pinion = if m.pinion_efficiency.is_empty() { "" } else { ",pinion_efficiency" };
            let _ = writeln!(
                out,
                "{t}_torque_N_m,{s}_speed_rad_s,law,formulation,{parts}total_loss_W,total_efficiency{pinion}"
            );
        }
        for (i, torque) in m.torques.iter().enumerate() {
            for (j, rpm) in m.speeds_rpm.iter().enumerate() {
                let parts: String = m.parts.iter().map(|p| format!("{},", num(p.values[i][j]))).collect();
                let pinion = m.pinion_efficiency.get(i).map_or_else(String::new, |row| format!(",{}", num(row[j])));
                let _ = writeln!(
                    out,
                    "{},{},\"{}\",{},{parts}{},{}{pinion}",
                    num(*torque),
                    num(rpm * std::f64::consts::PI / 30.0),
                    m.law.replace('"', "\"\""),
                    m.formulation,
                    num(m.loss[i][j]),
                    num(m.efficiency[i][j])
                );
            }
        }
    }
    out
}
