//! loss_map.svg: the total loss and η over the ends' torque × speed, drive above zero torque and
//! coast below, up to three laws and formulations.

use crate::render::svg::maps::{heat_maps, Map};
use crate::report::drive::DriveReport;

/// The map's file.
pub(crate) const FILE: &str = "loss_map.svg";

/// Total loss and η over torque × speed, up to three laws and formulations.
pub(crate) fn loss_map(r: &DriveReport) -> Result<String, String> {
    let mut maps = Vec::new();
    for m in r.maps.iter().take(3) {
        let x_label = format!("{} speed (rpm)", m.speed_at.name());
        let y_label = format!("{} torque (N*m; < 0: coast)", m.torque_at.name());
        // η = 0 where no power goes through (zero torque, or both ends deliver): left blank.
        let eta = m
            .efficiency
            .iter()
            .map(|row| row.iter().map(|e| if *e > 0.0 { 100.0 * e } else { f64::NAN }).collect())
            .collect();
        maps.push(Map {
            title: format!("total loss W — {} {}", m.law, m.formulation),
            speeds: &m.speeds_rpm,
            torques: &m.torques,
            values: m.loss.clone(),
            x_label: x_label.clone(),
            y_label: y_label.clone(),
            marks: Vec::new(),
        });
        maps.push(Map {
            title: format!("η % (blank: no power through) — {} {}", m.law, m.formulation),
            speeds: &m.speeds_rpm,
            torques: &m.torques,
            values: eta,
            x_label,
            y_label,
            marks: Vec::new(),
        });
    }
    heat_maps(&format!("{}: total loss and efficiency, drive (T > 0) and coast (T < 0)", r.title), &maps)
}
