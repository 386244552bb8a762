//! report.md's drive-cycle section: the headline (energies at the wheel and the motor, the box's
//! losses in drive and recuperation with their error estimates, the cycle's efficiency both ways,
//! the peaks with their times, the sump), the plots, the losses by part and by phase, and the
//! vehicle as read.

use crate::render::markup::md;
use crate::render::table::{fixed, header, row, sig};
use crate::report::drive_cycle::{CycleTotals, DriveCycleReport};

pub(crate) fn cycle(out: &mut String, c: &DriveCycleReport, u: super::shown_units::Shown) {
    let (n, t) = (u.speed, u.torque);
    let w = &c.whole;
    md!(out, "## Drive cycle \"{}\": {}\n", c.name, c.vehicle);
    md!(
        out,
        "The trace `{}` ({} samples, {} s, piecewise linear; {} pieces after cutting where the wheel force changes sign, at the recuperation limit and at the phases), {} ({}), oil: {}. Each loss is integrated over each piece by Gauss–Legendre at 5 nodes, the piece cut further at the {} switches located inside the pieces where the losses change form (a shaft passing Palmgren's ν n = 2000; in coast, the power through a stage reversing); ± is its difference from 3 nodes, summed over the parts. Wheel energies are exact.\n",
        c.trace_file,
        c.samples,
        fixed(w.to_s - w.from_s, 0),
        c.pieces,
        c.law,
        c.formulation,
        c.oil,
        c.switches
    );
    header(out, &["over the cycle", "drive", "recuperation"]);
    let both = |out: &mut String, what: &str, a: String, b: String| row(out, &[what.to_string(), a, b]);
    both(out, "energy at the wheels (kWh)", fixed(w.wheel_drive_kwh, 4), fixed(w.wheel_recuperation_kwh, 4));
    both(out, "through the box's output: out, in (kWh)", fixed(w.box_drive_kwh, 4), fixed(w.box_recuperation_kwh, 4));
    both(out, "at the motor: out, in (kWh)", fixed(w.motor_out_kwh, 4), fixed(w.motor_in_kwh, 4));
    both(
        out,
        "gearbox loss (Wh)",
        format!("{} ± {}", fixed(w.loss_drive_wh, 3), sig(w.loss_drive_error_wh)),
        format!("{} ± {}", fixed(w.loss_recuperation_wh, 3), sig(w.loss_recuperation_error_wh)),
    );
    both(out, "loss / wheel energy (%)", fixed(w.loss_drive_percent, 3), fixed(w.loss_recuperation_percent, 3));
    both(
        out,
        "cycle efficiency of the box (%)",
        fixed(100.0 * w.efficiency_drive, 3),
        fixed(100.0 * w.efficiency_recuperation, 3),
    );
    md!(out);
    md!(
        out,
        "Distance {} km; the box loses {} Wh/km. Recuperation beyond the limit, to the friction brakes: {} kWh.\n",
        fixed(w.distance_km, 4),
        fixed(w.loss_wh_per_km, 3),
        fixed(w.brakes_kwh, 4)
    );
    md!(
        out,
        "Peaks (located on each piece: its ends and the vertex of the force's quadratic): wheel torque {} {} at {} s, in recuperation {} {} at {} s; motor speed {} {} at {} s (v = {} km/h).\n",
        fixed(t.of_si(c.peak_wheel_torque.value), 1),
        t.unit(),
        fixed(c.peak_wheel_torque.time_s, 2),
        fixed(t.of_si(c.peak_recuperation_torque.value), 1),
        t.unit(),
        fixed(c.peak_recuperation_torque.time_s, 2),
        fixed(n.of_rpm(c.peak_motor_speed_rpm.value), 0),
        n.unit(),
        fixed(c.peak_motor_speed_rpm.time_s, 2),
        fixed(c.peak_speed_kmh.value, 2)
    );
    if let Some(t) = &c.temperature {
        md!(
            out,
            "The sump: {} °C → {} °C, highest {} °C at {} s (on the piece's collocation polynomial); error estimate {} K. The books: C (θ_end − θ_start) = {} J, E_lost − E_given off = {} J.\n",
            fixed(t.start_c, 2),
            fixed(t.end_c, 2),
            fixed(t.max.value, 3),
            fixed(t.max.time_s, 2),
            sig(t.error_k),
            fixed(t.heat_stored_j, 1),
            fixed(t.lost_minus_dissipated_j, 1)
        );
    }
    if let Some(f) = &c.failure {
        md!(out, "**The transient stopped**: {f}.\n");
    }
    md!(
        out,
        "![speed, loss power, sump temperature and cumulative loss over the cycle]({})\n",
        super::cycle_plots::TRACE_FILE
    );
    if !c.map.torques.is_empty() {
        md!(out, "![the cycle's operating points over the box's efficiency map]({})\n", super::cycle_plots::MAP_FILE);
    }
    md!(out, "### Loss by part (Wh)\n");
    header(out, &["part", "drive", "recuperation", "±"]);
    for p in &c.parts {
        row(out, &[p.part.clone(), fixed(p.drive_wh, 3), fixed(p.recuperation_wh, 3), sig(p.error_wh)]);
    }
    md!(out);
    if !c.phases.is_empty() {
        md!(out, "### By phase\n");
        phases(out, c);
    }
    md!(out, "### The vehicle\n");
    header(out, &["as written", "value"]);
    for (k, v) in &c.vehicle_written {
        row(out, &[format!("`{k}`"), v.clone()]);
    }
    md!(out);
    header(out, &["derived", "value", "unit"]);
    for (k, v, u) in &c.vehicle_derived {
        row(out, &[k.clone(), sig(*v), u.clone()]);
    }
    md!(out);
    md!(out, "Every interval's values (forces, torques, speeds at its ends, each loss part, the motor's energy, θ) are in cycle_records.csv and report.json (`cycle.series`).\n");
}

fn phases(out: &mut String, c: &DriveCycleReport) {
    header(
        out,
        &[
            "phase",
            "s",
            "km",
            "wheel drive kWh",
            "wheel recup. kWh",
            "loss drive Wh",
            "loss recup. Wh",
            "η drive %",
            "η recup. %",
            "Wh/km",
            "θ end °C",
        ],
    );
    let line = |out: &mut String, t: &CycleTotals| {
        row(
            out,
            &[
                t.name.clone(),
                format!("{}–{}", fixed(t.from_s, 0), fixed(t.to_s, 0)),
                fixed(t.distance_km, 4),
                fixed(t.wheel_drive_kwh, 4),
                fixed(t.wheel_recuperation_kwh, 4),
                fixed(t.loss_drive_wh, 3),
                fixed(t.loss_recuperation_wh, 3),
                fixed(100.0 * t.efficiency_drive, 3),
                fixed(100.0 * t.efficiency_recuperation, 3),
                fixed(t.loss_wh_per_km, 3),
                t.end_temperature_c.map_or_else(|| "–".into(), |x| fixed(x, 2)),
            ],
        )
    };
    for t in &c.phases {
        line(out, t);
    }
    line(out, &c.whole);
    md!(out);
}
