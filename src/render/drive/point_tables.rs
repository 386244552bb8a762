//! One operating point of a drive in report.md: its stages (driving member, torques, forces, η_mesh,
//! losses), its shafts (speed, torque and power received and passed on, own losses), its bearing
//! places (loads per bearing, P_0, P_1) and the mesh forces each shaft's statics read; and the
//! shafts as the scene gives them (their places, locating place and seals).

use crate::render::markup::md;
use crate::render::table::{fixed, header, row};
use crate::report::drive::DrivePointReport;
use crate::report::units::Units;

use super::shown_units::Shown;

pub(crate) fn point(out: &mut String, p: &DrivePointReport, u: Shown) {
    let (n, t) = (u.speed, u.torque);
    let (f, w, len) = (u.units.force(), u.units.power(), u.units.length());
    let d = &p.point;
    md!(out, "### {} — {} {}\n", p.label, p.law, p.formulation);
    if let Some(b) = &p.balance {
        let status = &b.status;
        match b.temperature {
            Some(theta) => {
                let mut oil = Vec::new();
                if let Some(nu) = b.kinematic_viscosity {
                    oil.push(format!("ν = {} mm²/s", fixed(nu * 1e6, 4)));
                }
                if let Some(eta) = b.dynamic_viscosity {
                    oil.push(format!("η = {} mPa·s", fixed(eta * 1e3, 4)));
                }
                let oil = if oil.is_empty() { String::new() } else { format!(" ({})", oil.join(", ")) };
                md!(
                    out,
                    "At its own balance (`oil_temperature = equilibrium`): θ* = {} °C{oil}, the sump {status}; every number below is read there.\n",
                    fixed(theta - 273.15, 3)
                )
            }
            None => md!(
                out,
                "At `oil_temperature = equilibrium` the sump {status}: the point is read at the scene's oil.\n"
            ),
        }
    }
    md!(
        out,
        "{}: {} in at the input, {} out at the output, {} lost, η = {}; {}.\n",
        d.flow.name(),
        w.with(d.input_power, 3),
        w.with(d.output_power, 3),
        w.with(d.power_lost(), 3),
        if d.both_ends_deliver {
            "0 (both ends deliver)".into()
        } else {
            format!("{} %", fixed(100.0 * d.efficiency, 4))
        },
        if d.settled() {
            match d.iterations {
                1 => "the bearing losses settled in one pass".to_string(),
                n => format!("the bearing losses settled in {n} passes"),
            }
        } else {
            format!("**not settled**: {}", d.unsettled_words())
        }
    );
    header(
        out,
        &[
            "stage",
            "driving",
            &format!("T driving ({})", t.unit()),
            &format!("T driven ({})", t.unit()),
            &format!("n driving ({})", n.unit()),
            &f.titled("F_t"),
            &f.titled("F_r"),
            &f.titled("F_a"),
            "η_mesh (%)",
            &w.titled("mesh loss"),
            &w.titled("no-load"),
            "law outside validity",
        ],
    );
    for (k, s) in d.stages.iter().enumerate() {
        let validity = p.validity.get(k).map_or_else(String::new, |(o, n, _)| format!("{o} of {n}"));
        row(
            out,
            &[
                s.name.clone(),
                s.member_name(s.driving).to_string(),
                fixed(t.of_si(s.driving_torque), 4),
                fixed(t.of_si(s.driven_torque), 4),
                fixed(n.of_rad_s(s.driving_speed), 2),
                f.cell(s.tangential_force, 2),
                f.cell(s.radial_force, 2),
                f.cell(s.axial_force, 2),
                fixed(100.0 * s.mesh_efficiency, 4),
                w.cell(s.mesh_loss, 3),
                w.cell(s.no_load, 3),
                validity,
            ],
        );
    }
    md!(out);
    super::kind_pieces::point(out, d, u);
    header(
        out,
        &[
            "shaft",
            &format!("n ({}, + ccw)", n.unit()),
            &format!("T received ({})", t.unit()),
            &format!("T passed ({})", t.unit()),
            &w.titled("P received"),
            &w.titled("P passed"),
            &w.titled("bearings"),
            &w.titled("seals"),
            &w.titled("gears no-load"),
        ],
    );
    for s in &d.shafts {
        let bearings: f64 = s.bearings.iter().map(|b| b.no_load + b.load).sum();
        row(
            out,
            &[
                s.name.clone(),
                fixed(n.of_rad_s(s.speed), 2),
                fixed(t.of_si(s.received_torque), 4),
                fixed(t.of_si(s.passed_torque), 4),
                w.cell(s.received_power, 3),
                w.cell(s.passed_power, 3),
                w.cell(0.0 + bearings, 3),
                w.cell(s.seals, 3),
                w.cell(s.gear_no_load, 3),
            ],
        );
    }
    md!(out);
    header(
        out,
        &[
            "shaft",
            &len.titled("place at"),
            "type × count",
            "locating",
            &f.titled("F_r per bearing"),
            &f.titled("F_a per bearing"),
            &w.titled("P_0"),
            &w.titled("P_1"),
        ],
    );
    for s in &d.shafts {
        for b in &s.bearings {
            row(
                out,
                &[
                    s.name.clone(),
                    b.position.map_or_else(|| "—".into(), |x| len.cell(x, 2)),
                    format!("{} × {}", b.kind, b.count),
                    if b.locating { "yes".into() } else { String::new() },
                    f.cell(b.radial_load, 2),
                    f.cell(b.axial_load, 2),
                    w.cell(b.no_load, 3),
                    w.cell(b.load, 3),
                ],
            );
        }
    }
    md!(out);
    super::shaft_bending::point(out, d, u.units);
    header(out, &["shaft", "gear", &len.titled("point x, y, z"), &f.titled("force F_x, F_y, F_z")]);
    for s in &d.shafts {
        for l in &s.gear_loads {
            row(
                out,
                &[
                    s.name.clone(),
                    format!(
                        "{} of stage {}",
                        d.stages.get(l.stage).map_or(l.member.name(), |x| x.member_name(l.member)),
                        d.stages.get(l.stage).map_or(String::new(), |x| x.name.clone())
                    ),
                    l.point.iter().map(|x| len.cell(*x, 3)).collect::<Vec<_>>().join(", "),
                    l.force.iter().map(|x| f.cell(*x, 2)).collect::<Vec<_>>().join(", "),
                ],
            );
        }
    }
    md!(out);
}

/// The shafts as the scene gives them: role, bearing places (type × count at a position, or "(no
/// `at`)" for a one-pair scene's shaft written without positions), the locating place, the seals
/// (the inputs keep millimetres; shown in the report's length unit).
pub(super) fn shafts(out: &mut String, shafts: &[crate::report::drive_inputs::ShaftInputs], units: Units) {
    let len = units.length();
    let mm = |x: f64, decimals: usize| len.cell(x * 1e-3, decimals);
    md!(out, "\n## Shafts\n");
    header(
        out,
        &[
            "shaft",
            "role",
            &format!("bearing places (type × count at {})", len.unit),
            "locating",
            &format!("seals ({} × count)", len.unit),
        ],
    );
    for s in shafts {
        let at = |at: f64| if s.without_at { " (no `at`)".to_string() } else { format!(" at {}", mm(at, 2)) };
        let places: Vec<String> = s.bearings.iter().map(|(k, n, x, _)| format!("{k} × {n}{}", at(*x))).collect();
        let locating = s.bearings.iter().find(|b| b.3).map_or("—".into(), |b| {
            if s.without_at {
                "the first".into()
            } else {
                format!("at {}", mm(b.2, 2))
            }
        });
        let seals: Vec<String> = s.seals.iter().map(|(d, n)| format!("{} × {n}", mm(*d, 1))).collect();
        row(out, &[s.name.clone(), s.role.clone(), places.join("; "), locating, seals.join("; ")]);
    }
}
