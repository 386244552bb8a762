//! The thermal section's tables of a drive's report.md: the housing, the balance of each kept row
//! (θ*, status in words, what the housing gives off, the ratings) and the duty cycle's table.

use super::markup::md;

use super::table::{fixed, header, row};
use crate::report::number::Q;
use crate::report::thermal::{HousingReport, ThermalRecord};
use crate::report::units::Units;

fn opt(q: Option<&Q>, f: impl Fn(&Q) -> String) -> String {
    q.map_or_else(|| "—".to_string(), f)
}

/// The housing's inputs (defaults filled in), in units `u`.
pub(crate) fn housing_table(out: &mut String, h: &HousingReport, u: Units) {
    header(out, &["housing", "value"]);
    let (deg, g) = (u.temperature(), u.conductance());
    let cooler = h.oil_cooler.as_ref().map_or_else(
        || "none".to_string(),
        |c| format!("{} above {}", g.with(c.conductance.si(), 1), deg.with(c.above.si(), 1)),
    );
    for (name, value) in [
        ("surface area A", u.area().with(h.surface_area.si(), 3)),
        ("ambient θ_a", deg.with(h.ambient_temperature.si(), 1)),
        ("air speed v", u.velocity().with(h.air_speed.si(), 2)),
        ("emissivity ε", fixed(h.emissivity.0, 2)),
        ("heat capacity C", opt(h.heat_capacity.as_ref(), |c| u.heat_capacity().with(c.si(), 2))),
        ("foundation G_f", g.with(h.foundation_conductance.si(), 2)),
        ("oil cooler", cooler),
        ("oil limit", deg.with(h.max_oil_temperature.si(), 1)),
    ] {
        row(out, &[name.to_string(), value]);
    }
}

/// Per operating point, law and formulation: the balance θ*, what the housing gives off there and
/// the thermal ratings; each row in its record's words, else `point`'s.
pub(crate) fn balance_table(
    out: &mut String,
    records: &[ThermalRecord],
    u: Units,
    point: &dyn Fn(&ThermalRecord) -> String,
) {
    if records.is_empty() {
        return;
    }
    md!(out);
    let (deg, w, torque, kw) = (u.temperature(), u.power(), u.torque(), u.kilowatt());
    let rating_heading = |what: &str| format!("{what} {} ({})", torque.unit, kw.unit);
    let cols = [
        "operating point".to_string(),
        "law".into(),
        "formulation".into(),
        deg.heading("θ*"),
        "status".into(),
        w.heading("P_V at θ*"),
        w.heading("convection"),
        w.heading("radiation"),
        w.heading("foundation"),
        w.heading("cooler"),
        u.heat_transfer().heading("h_c"),
        rating_heading("rating"),
        rating_heading(&format!("rating at {}", deg.with(368.15, 0))),
    ];
    header(out, &cols);
    let rating = |x: Option<&crate::report::thermal::Rating>| {
        x.map_or_else(|| "—".into(), |x| format!("{} ({})", torque.q(&x.torque, 1), kw.q(&x.power, 2)))
    };
    for t in records {
        row(
            out,
            &[
                t.point.clone().unwrap_or_else(|| point(t)),
                super::table::law_words(&t.label),
                t.formulation.name().to_string(),
                opt(t.oil_temperature.as_ref(), |q| deg.q(q, 1)),
                crate::report::units::balance_words(t.status, u),
                w.q(&t.power_loss, 1),
                w.q(&t.dissipation.convection, 1),
                w.q(&t.dissipation.radiation, 1),
                w.q(&t.dissipation.foundation, 1),
                w.q(&t.dissipation.cooler, 1),
                u.heat_transfer().q(&t.heat_transfer_coefficient, 2),
                rating(t.thermal_rating.as_ref()),
                rating(t.thermal_rating_95.as_ref()),
            ],
        );
    }
}

/// The duty cycle's steps, energies and efficiency, transient and at the fixed oil temperature,
/// under `heading` (`## Duty cycle`).
pub(crate) fn duty_cycle_lines(out: &mut String, heading: &str, d: &crate::report::thermal::DutyCycleReport, u: Units) {
    let (deg, kj, w) = (u.temperature(), u.energy(), u.power());
    let celsius = |q: &Q| deg.q(q, 1);
    md!(out, "\n{heading} \"{}\"\n", d.name);
    let law = super::table::law_words(&d.label);
    match &d.error_estimate {
        Some(e) => md!(
            out,
            "The losses of {law} at each step; the transient C dθ/dt = P_V(θ) − P_Q(θ) from ambient, θ continuous across the steps (DOP853, error estimate {:.1e} K from two tolerances).\n",
            e.si()
        ),
        None => md!(
            out,
            "The losses of {law} at each step; no transient of the sump (it needs the housing's `heat_capacity`).\n"
        ),
    }
    let cols = [
        "step".to_string(),
        "duration, torque, speed".into(),
        deg.heading("θ at end"),
        kj.heading("energy lost"),
        kj.heading("given off"),
        w.heading("P_V at fixed θ"),
        kj.heading("energy lost at fixed θ"),
    ];
    header(out, &cols);
    for (k, s) in d.steps.iter().enumerate() {
        row(
            out,
            &[
                (k + 1).to_string(),
                s.label.clone(),
                opt(s.oil_temperature_end.as_ref(), celsius),
                opt(s.energy_lost.as_ref(), |e| kj.q(e, 2)),
                opt(s.energy_dissipated.as_ref(), |e| kj.q(e, 2)),
                opt(s.power_loss_fixed.as_ref(), |p| w.q(p, 2)),
                opt(s.energy_lost_fixed.as_ref(), |e| kj.q(e, 2)),
            ],
        );
    }
    // The cycle's efficiency needs the energy in (a drive given at its output has none).
    let pct =
        |x: Option<crate::report::number::Num>| x.map_or("—".to_string(), |x| format!("{} %", fixed(100.0 * x.0, 3)));
    let efficiency = |x| match d.energy_in {
        Some(_) => format!(", cycle efficiency {}", pct(x)),
        None => String::new(),
    };
    md!(out);
    if let Some(e) = &d.energy_in {
        md!(out, "- Energy in: {}.", kj.with(e.si(), 2));
    }
    if let (Some(lost), Some(given)) = (&d.energy_lost, &d.energy_dissipated) {
        md!(
            out,
            "- Transient: θ_max {}, energy lost {}, given off {}{}.",
            opt(d.oil_temperature_max.as_ref(), |q| deg.with(q.si(), 1)),
            kj.with(lost.si(), 2),
            kj.with(given.si(), 2),
            efficiency(d.efficiency)
        );
    }
    if let Some(f) = &d.fixed_temperature {
        md!(
            out,
            "- At the fixed oil temperature {}: energy lost {}{}.",
            deg.with(f.oil_temperature.si(), 1),
            kj.with(f.energy_lost.si(), 2),
            efficiency(f.efficiency)
        );
    }
}
