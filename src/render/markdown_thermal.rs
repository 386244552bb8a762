//! report.md's thermal section: the housing, the balance of each kept record (θ*, status in words,
//! what the housing gives off, the ratings) and the duty cycle's table.

use std::fmt::Write;

use super::markdown_losses::plots_of;
use crate::report::PlotKind;

use super::table::{fixed, header, row};
use crate::report::number::Q;
use crate::report::Report;

fn celsius(q: &Q) -> String {
    fixed(q.si() - 273.15, 1)
}

fn opt(q: Option<&Q>, f: impl Fn(&Q) -> String) -> String {
    q.map_or_else(|| "—".to_string(), f)
}

/// The section, empty without a housing.
pub fn thermal_section(r: &Report) -> String {
    let mut out = String::new();
    let Some(h) = &r.housing else { return out };
    let _ = writeln!(out, "\n## Thermal balance\n");
    let _ = writeln!(
        out,
        "One thermal node: the housing wall at the oil temperature θ gives off P_Q(θ) = h_c A Δθ + ε σ A (T⁴ − T_a⁴) + G_f Δθ + G_c max(0, θ − θ_set), h_c = √(h_n² + h_f²) with h_n = 1.31 |Δθ|^(1/3) and h_f = 3.26 v^0.89 W/(m² K) (the DOE-2 exterior convection model). The balance θ* is the lowest oil temperature above ambient where the losses P_V(θ) (mesh and budget, the oil read at θ) equal P_Q(θ). The thermal rating is the pinion torque at this speed whose balance is the oil's limit; the second at 95 °C, ISO/TR 14179-1's rating temperature.\n"
    );
    header(&mut out, &["housing", "value"]);
    let cooler = h.oil_cooler.as_ref().map_or_else(
        || "none".to_string(),
        |c| format!("{} W/K above {} °C", fixed(c.conductance.si(), 1), celsius(&c.above)),
    );
    for (name, value) in [
        ("surface area A", format!("{} m²", fixed(h.surface_area.si(), 3))),
        ("ambient θ_a", format!("{} °C", celsius(&h.ambient_temperature))),
        ("air speed v", format!("{} m/s", fixed(h.air_speed.si(), 2))),
        ("emissivity ε", fixed(h.emissivity.0, 2)),
        ("heat capacity C", opt(h.heat_capacity.as_ref(), |c| format!("{} kJ/K", fixed(c.si() / 1e3, 2)))),
        ("foundation G_f", format!("{} W/K", fixed(h.foundation_conductance.si(), 2))),
        ("oil cooler", cooler),
        ("oil limit", format!("{} °C", celsius(&h.max_oil_temperature))),
    ] {
        row(&mut out, &[name.to_string(), value]);
    }
    balance_table(&mut out, r);
    plots_of(&mut out, r, PlotKind::HeatBalance);
    if let Some(d) = &r.duty_cycle {
        duty_cycle_lines(&mut out, d);
        plots_of(&mut out, r, PlotKind::DutyCycleTemperature);
        plots_of(&mut out, r, PlotKind::DutyCycleEnergy);
    }
    out.push('\n');
    out
}

/// Per operating point, law and formulation: the balance θ*, what the housing gives off there and
/// the thermal ratings.
fn balance_table(out: &mut String, r: &Report) {
    if r.thermal.is_empty() {
        return;
    }
    let _ = writeln!(out);
    header(
        out,
        &[
            "operating point",
            "law",
            "formulation",
            "θ* °C",
            "status",
            "P_V at θ* W",
            "convection W",
            "radiation W",
            "foundation W",
            "cooler W",
            "h_c W/(m² K)",
            "rating N·m (kW)",
            "rating at 95 °C N·m (kW)",
        ],
    );
    let rating = |x: Option<&crate::report::thermal::Rating>| {
        x.map_or_else(|| "—".into(), |x| format!("{} ({})", fixed(x.torque.si(), 1), fixed(x.power.si() / 1e3, 2)))
    };
    for t in &r.thermal {
        row(
            out,
            &[
                super::headline::point_at(r, &t.pinion_torque, &t.pinion_speed),
                super::table::law_words(&t.label),
                t.formulation.name().to_string(),
                opt(t.oil_temperature.as_ref(), celsius),
                t.status.words().to_string(),
                fixed(t.power_loss.si(), 1),
                fixed(t.dissipation.convection.si(), 1),
                fixed(t.dissipation.radiation.si(), 1),
                fixed(t.dissipation.foundation.si(), 1),
                fixed(t.dissipation.cooler.si(), 1),
                fixed(t.heat_transfer_coefficient.si(), 2),
                rating(t.thermal_rating.as_ref()),
                rating(t.thermal_rating_95.as_ref()),
            ],
        );
    }
}

/// The duty cycle's steps, energies and efficiency, transient and at the fixed oil temperature.
fn duty_cycle_lines(out: &mut String, d: &crate::report::thermal::DutyCycleReport) {
    let _ = writeln!(out, "\n### Duty cycle \"{}\"\n", d.name);
    let _ = writeln!(
        out,
        "The losses of {} at each step; the transient C dθ/dt = P_V(θ) − P_Q(θ) from ambient, θ continuous across the steps (DOP853, error estimate {} K from two tolerances).\n",
        super::table::law_words(&d.label),
        d.error_estimate.as_ref().map_or("—".to_string(), |e| format!("{:.1e}", e.si()))
    );
    header(out, &["step", "duration, torque, speed", "θ at end °C", "energy lost kJ", "energy lost at fixed θ kJ"]);
    for (k, s) in d.steps.iter().enumerate() {
        row(
            out,
            &[
                (k + 1).to_string(),
                s.label.clone(),
                opt(s.oil_temperature_end.as_ref(), celsius),
                opt(s.energy_lost.as_ref(), |e| fixed(e.si() / 1e3, 2)),
                opt(s.energy_lost_fixed.as_ref(), |e| fixed(e.si() / 1e3, 2)),
            ],
        );
    }
    let pct =
        |x: Option<crate::report::number::Num>| x.map_or("—".to_string(), |x| format!("{} %", fixed(100.0 * x.0, 3)));
    let _ = writeln!(out);
    let _ = writeln!(out, "- Energy in: {} kJ.", fixed(d.energy_in.si() / 1e3, 2));
    if let (Some(lost), Some(given)) = (&d.energy_lost, &d.energy_dissipated) {
        let _ = writeln!(
            out,
            "- Transient: θ_max {} °C, energy lost {} kJ, given off {} kJ, cycle efficiency {}.",
            opt(d.oil_temperature_max.as_ref(), celsius),
            fixed(lost.si() / 1e3, 2),
            fixed(given.si() / 1e3, 2),
            pct(d.efficiency)
        );
    }
    if let Some(f) = &d.fixed_temperature {
        let _ = writeln!(
            out,
            "- At the fixed oil temperature {} °C: energy lost {} kJ, cycle efficiency {}.",
            celsius(&f.oil_temperature),
            fixed(f.energy_lost.si() / 1e3, 2),
            pct(f.efficiency)
        );
    }
}
