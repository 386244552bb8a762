//! loss_map.svg: the total loss and η over the ends' torque × speed, drive above zero torque and
//! coast below, up to three laws and formulations: filled bands between iso-levels with the
//! iso-lines labelled and a colour bar per panel (the pair's efficiency map's panels), the bands
//! spread over the upper nine tenths of the values so that a few cells near zero torque (where η
//! falls to 0) do not take the whole scale, and each half's located best point ringed on the η
//! panel.

use plotters::prelude::*;

use crate::render::svg::{draw_field, fitted, Field};
use crate::report::drive::DriveReport;

use super::shown_units::Shown;

/// The map's file.
pub(crate) const FILE: &str = "loss_map.svg";

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
        let Shown { speed: n, torque: t } = Shown::of(r);
        for (k, m) in maps.iter().enumerate() {
            let x_label = format!("{} speed ({})", m.speed_at.name(), n.unit());
            let speeds: Vec<f64> = m.speeds_rpm.iter().map(|x| n.of_rpm(*x)).collect();
            let y_label = format!("{} torque ({}; < 0: coast)", m.torque_at.name(), t.unit());
            let torques: Vec<f64> = m.torques.iter().map(|x| t.of_si(*x)).collect();
            // η is 0 where no power goes through (zero torque, or both ends deliver): the limit
            // of P_out/P_in as the torque falls to zero with the no-load losses still there.
            let eta = m.efficiency.iter().map(|row| row.iter().map(|e| 100.0 * e.max(0.0)).collect()).collect();
            let loss = Field {
                title: format!("total loss — {} {}", m.law, m.formulation),
                speeds: &speeds,
                torques: &torques,
                values: m.loss.clone(),
                unit: "W",
            };
            let efficiency = Field {
                title: format!("η, ○ best located — {} {}", m.law, m.formulation),
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
