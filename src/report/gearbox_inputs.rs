//! A drive's gearbox inputs for its report's Scene table: each stage's lubrication, every shaft's
//! bearing places and seals, the housing. The lowered gearbox keeps SI values only, so "as written" shows each
//! value in the unit it is usually written in (mm, kN, °C).

use super::input_row::{InputRow, SiValue};
use super::number::{Num, Q};
use crate::losses::{Bearing, Lubrication, Seal};
use crate::thermal::Housing;

/// A dimensional row: `key`, SI value and unit, and the value shown as `scale × SI` in `shown`.
fn q(rows: &mut Vec<InputRow>, key: String, si: f64, unit: &'static str, scale: f64, shown: &str) {
    let written = format!("{} {shown}", crate::numerics::rounding::sig(si * scale)).trim_end().to_string();
    rows.push(InputRow { key, written, si: SiValue::Dimensional(Q::new(si, unit)) });
}

fn plain(rows: &mut Vec<InputRow>, key: String, x: f64) {
    rows.push(InputRow { key, written: crate::numerics::rounding::sig(x), si: SiValue::Plain(Num(x)) });
}

/// Lengths per metre and their unit: mm, or inches for a scene sized in inches.
fn length_unit(inch: bool) -> (f64, &'static str) {
    if inch {
        (1.0 / 0.0254, "in")
    } else {
        (1e3, "mm")
    }
}

/// A lubrication's rows under `owner` (`gearbox`, a drive's stage name): `owner.lubrication (dip).*`.
pub(super) fn lubrication_inputs(rows: &mut Vec<InputRow>, owner: &str, l: &Lubrication, inch: bool) {
    let (per_m, mm) = length_unit(inch);
    match l {
        Lubrication::Dip { immersion, axis_height, housing_width } => {
            let k = |n: &str| format!("{owner}.lubrication (dip).{n}");
            q(rows, k("pinion_immersion"), immersion[0], "m", per_m, mm);
            q(rows, k("wheel_immersion"), immersion[1], "m", per_m, mm);
            q(rows, k("axis_height"), *axis_height, "m", per_m, mm);
            q(rows, k("housing_width"), *housing_width, "m", per_m, mm);
        }
        Lubrication::Injection { flow, jet_speed } => {
            let k = |n: &str| format!("{owner}.lubrication (injection).{n}");
            q(rows, k("flow"), *flow, "m^3/s", 6e4, "L/min");
            q(rows, k("jet_speed"), *jet_speed, "m/s", 1.0, "m/s");
        }
    }
}

/// A shaft's bearing places and seals: `shaft.bearing 1 (type, model).*`, `shaft.seal 1.*`.
pub(super) fn shaft_inputs(rows: &mut Vec<InputRow>, shaft: &str, (places, seals): (&[Bearing], &[Seal]), inch: bool) {
    let (per_m, mm) = length_unit(inch);
    for (i, b) in places.iter().enumerate() {
        let model = if b.skf.is_some() { "skf" } else { "palmgren" };
        let k = |n: &str| format!("{shaft}.bearing {} ({}, {model}).{n}", i + 1, b.kind.name());
        q(rows, k("mean_diameter"), b.mean_diameter, "m", per_m, mm);
        plain(rows, k("count"), b.count as f64);
        if let Some(p) = b.position {
            q(rows, k("at"), p, "m", per_m, mm);
        }
        if let Some(c0) = b.static_load_rating {
            q(rows, k("static_load_rating"), c0, "N", 1e-3, "kN");
        }
        for (name, v) in [("f0", b.f0), ("f1", b.f1), ("y", b.y)] {
            if let Some(v) = v {
                plain(rows, k(name), v);
            }
        }
        if let Some((c, [bore, outside])) = &b.skf {
            q(rows, k("bore"), *bore, "m", per_m, mm);
            q(rows, k("outside"), *outside, "m", per_m, mm);
            for (name, v) in [("r1", c.r1), ("r2", c.r2), ("s1", c.s1), ("s2", c.s2), ("mu_bl", c.mu_bl)] {
                plain(rows, k(name), v);
            }
            if let Some(m) = c.mu_ehl {
                plain(rows, k("mu_ehl"), m);
            }
        }
    }
    for (i, s) in seals.iter().enumerate() {
        let k = |n: &str| format!("{shaft}.seal {}.{n}", i + 1);
        q(rows, k("diameter"), s.diameter, "m", per_m, mm);
        plain(rows, k("count"), s.count as f64);
    }
}

/// The housing's rows (`gearbox.housing.*`).
pub(super) fn housing_inputs(rows: &mut Vec<InputRow>, h: &Housing) {
    let k = |n: &str| format!("gearbox.housing.{n}");
    let celsius = |rows: &mut Vec<InputRow>, key: String, kelvin: f64| {
        let written = format!("{} degC", crate::numerics::rounding::sig(kelvin - 273.15));
        rows.push(InputRow { key, written, si: SiValue::Dimensional(Q::new(kelvin, "K")) });
    };
    q(rows, k("area"), h.area, "m^2", 1.0, "m^2");
    celsius(rows, k("ambient"), h.ambient);
    q(rows, k("air_speed"), h.air_speed, "m/s", 1.0, "m/s");
    plain(rows, k("emissivity"), h.emissivity);
    if let Some(c) = h.heat_capacity {
        q(rows, k("heat_capacity"), c, "J/K", 1e-3, "kJ/K");
    }
    q(rows, k("foundation"), h.foundation_conductance, "W/K", 1.0, "W/K");
    if let Some(c) = &h.cooler {
        q(rows, k("cooler.conductance"), c.conductance, "W/K", 1.0, "W/K");
        celsius(rows, k("cooler.above"), c.above);
    }
    celsius(rows, k("max_oil_temperature"), h.max_oil_temperature);
}
