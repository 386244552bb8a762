//! drive_records.csv: one row per operating point, law and formulation of a drive, with every part
//! of its loss: the ends (torque, speed, power), the loss parts, η and the passes, each stage's
//! driving member, mesh efficiency and mesh loss, each bearing place's loads and losses, each
//! shaft's speed (signed), torques received and passed on, gears' no-load parts and seals. SI but speeds in rpm; numbers in Rust's shortest round-trip form.

use std::io::Write;

use super::drive_setup::DriveRow;
use crate::drive::PowerFlow;
use crate::model::SceneDrive;

/// The file's name in the report folder.
pub const FILE: &str = "drive_records.csv";

const RPM: f64 = 30.0 / std::f64::consts::PI;

/// The header: the fixed columns, then per stage and per bearing place and shaft.
pub(crate) fn header(out: &mut dyn Write, drive: &SceneDrive) -> std::io::Result<()> {
    let mut cols: Vec<String> = [
        "row",
        "torque_index",
        "speed_index",
        "law_index",
        "formulation",
        "flow",
        "input_torque_N_m",
        "input_speed_rpm",
        "input_power_W",
        "output_torque_N_m",
        "output_speed_rpm",
        "output_power_W",
        "meshes_W",
        "gear_no_load_W",
        "bearings_no_load_W",
        "bearings_load_W",
        "seals_W",
        "total_W",
        "efficiency",
        "both_ends_deliver",
        "passes",
    ]
    .iter()
    .map(|c| c.to_string())
    .collect();
    for s in &drive.layout.stages {
        for c in ["driving", "driving_torque_N_m", "mesh_efficiency", "mesh_loss_W", "no_load_W", "validity_outside"] {
            cols.push(format!("stage_{}_{c}", s.name));
        }
        if s.planetary.is_some() {
            cols.extend(PLANETARY.iter().map(|c| format!("stage_{}_{c}", s.name)));
        }
    }
    for s in &drive.layout.shafts {
        for i in 0..s.bearings.len() {
            for c in ["radial_N", "axial_N", "no_load_W", "load_W"] {
                cols.push(format!("bearing_{}_{}_{c}", s.name, i + 1));
            }
        }
        for c in ["speed_rpm", "received_torque_N_m", "passed_torque_N_m", "gear_no_load_W", "seals_W"] {
            cols.push(format!("shaft_{}_{c}", s.name));
        }
    }
    writeln!(out, "{}", cols.join(","))
}

/// A planetary stage's columns: its members, its meshes, its planets.
const PLANETARY: [&str; 15] = [
    "sun_speed_rpm",
    "sun_torque_N_m",
    "ring_speed_rpm",
    "ring_torque_N_m",
    "carrier_speed_rpm",
    "carrier_torque_N_m",
    "rolling_power_W",
    "basic_efficiency",
    "sun_planet_efficiency",
    "planet_ring_efficiency",
    "sun_planet_loss_W",
    "planet_ring_loss_W",
    "planet_bearing_load_N",
    "planet_bearings_W",
    "churning_W",
];

/// One row; `outside`: by stage, the law's contacts outside its validity (of
/// [`super::drive_setup::VALIDITY_SAMPLES`]).
pub(crate) fn row(
    out: &mut dyn Write,
    i: usize,
    flow: PowerFlow,
    r: &DriveRow,
    outside: &[usize],
) -> std::io::Result<()> {
    let d = &r.point;
    let l = &d.losses;
    let mut cells: Vec<String> = vec![
        (i + 1).to_string(),
        r.torque_index.to_string(),
        r.speed_index.to_string(),
        r.law_index.to_string(),
        r.formulation.name().to_string(),
        flow.name().to_string(),
    ];
    cells.extend(
        [
            d.input_torque,
            d.input_speed * RPM,
            d.input_power,
            d.output_torque,
            d.output_speed * RPM,
            d.output_power,
            l.meshes,
            l.gear_no_load,
            l.bearings_no_load,
            l.bearings_load,
            l.seals,
            l.total(),
            d.efficiency,
        ]
        .iter()
        .map(|x| x.to_string()),
    );
    cells.push(d.both_ends_deliver.to_string());
    cells.push(d.iterations.to_string());
    for (k, s) in d.stages.iter().enumerate() {
        cells.push(s.member_name(s.driving).to_string());
        cells.extend([s.driving_torque, s.mesh_efficiency, s.mesh_loss, s.no_load].iter().map(|x| x.to_string()));
        cells.push(outside.get(k).copied().unwrap_or(0).to_string());
        if let Some(p) = &s.planetary {
            let mut v = Vec::with_capacity(PLANETARY.len());
            for i in 0..3 {
                v.extend([p.speeds[i] * RPM, p.torques[i]]);
            }
            v.extend([p.rolling_power, p.basic_efficiency, p.mesh_efficiency[0], p.mesh_efficiency[1]]);
            v.extend([p.mesh_loss[0], p.mesh_loss[1], p.forces.bearing, p.planet_bearings[0] + p.planet_bearings[1]]);
            v.push(p.churning);
            cells.extend(v.iter().map(|x| x.to_string()));
        }
    }
    for s in &d.shafts {
        for b in s.bearings.iter().filter(|b| !b.on_planets) {
            cells.extend([b.radial_load, b.axial_load, b.no_load, b.load].iter().map(|x| x.to_string()));
        }
        cells.extend(
            [s.speed * RPM, s.received_torque, s.passed_torque, s.gear_no_load, s.seals].iter().map(|x| x.to_string()),
        );
    }
    writeln!(out, "{}", cells.join(","))
}
