//! One operating point of a drive in report.md: its stages (driving member, torques, forces, η_mesh,
//! losses), its shafts (speed, torque and power received and passed on, own losses), its bearing
//! places (loads per bearing, P_0, P_1) and the mesh forces each shaft's statics read; and the
//! shafts as the scene gives them (their places, locating place and seals).

use crate::render::markup::md;
use crate::render::table::{fixed, header, row};
use crate::report::drive::DrivePointReport;

use super::shown_units::Shown;

pub(crate) fn point(out: &mut String, p: &DrivePointReport, u: Shown) {
    let (n, t) = (u.speed, u.torque);
    let d = &p.point;
    md!(out, "### {} — {} {}\n", p.label, p.law, p.formulation);
    md!(
        out,
        "{}: {} W in at the input, {} W out at the output, {} W lost, η = {}; {}.\n",
        d.flow.name(),
        fixed(d.input_power, 3),
        fixed(d.output_power, 3),
        fixed(d.power_lost(), 3),
        if d.both_ends_deliver {
            "0 (both ends deliver)".into()
        } else {
            format!("{} %", fixed(100.0 * d.efficiency, 4))
        },
        if d.settled() {
            format!("the bearing losses settled in {} passes", d.iterations)
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
            "F_t (N)",
            "F_r (N)",
            "F_a (N)",
            "η_mesh (%)",
            "mesh loss (W)",
            "no-load (W)",
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
                fixed(s.tangential_force, 2),
                fixed(s.radial_force, 2),
                fixed(s.axial_force, 2),
                fixed(100.0 * s.mesh_efficiency, 4),
                fixed(s.mesh_loss, 3),
                fixed(s.no_load, 3),
                validity,
            ],
        );
    }
    md!(out);
    super::planetary::point(out, d, u);
    header(
        out,
        &[
            "shaft",
            &format!("n ({}, + ccw)", n.unit()),
            &format!("T received ({})", t.unit()),
            &format!("T passed ({})", t.unit()),
            "P received (W)",
            "P passed (W)",
            "bearings (W)",
            "seals (W)",
            "gears no-load (W)",
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
                fixed(s.received_power, 3),
                fixed(s.passed_power, 3),
                fixed(0.0 + bearings, 3),
                fixed(s.seals, 3),
                fixed(s.gear_no_load, 3),
            ],
        );
    }
    md!(out);
    header(
        out,
        &[
            "shaft",
            "place at (mm)",
            "type × count",
            "locating",
            "F_r per bearing (N)",
            "F_a per bearing (N)",
            "P_0 (W)",
            "P_1 (W)",
        ],
    );
    for s in &d.shafts {
        for b in &s.bearings {
            row(
                out,
                &[
                    s.name.clone(),
                    b.position.map_or_else(|| "—".into(), |x| fixed(x * 1e3, 2)),
                    format!("{} × {}", b.kind, b.count),
                    if b.locating { "yes".into() } else { String::new() },
                    fixed(b.radial_load, 2),
                    fixed(b.axial_load, 2),
                    fixed(b.no_load, 3),
                    fixed(b.load, 3),
                ],
            );
        }
    }
    md!(out);
    super::shaft_bending::point(out, d);
    header(out, &["shaft", "gear", "point x, y, z (mm)", "force F_x, F_y, F_z (N)"]);
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
                    l.point.iter().map(|x| fixed(x * 1e3, 3)).collect::<Vec<_>>().join(", "),
                    l.force.iter().map(|x| fixed(*x, 2)).collect::<Vec<_>>().join(", "),
                ],
            );
        }
    }
    md!(out);
}

/// The shafts as the scene gives them: role, bearing places (type × count at mm, or "(no `at`)"
/// for a one-pair scene's shaft written without positions), the locating place, the seals.
pub(super) fn shafts(out: &mut String, shafts: &[crate::report::drive_inputs::ShaftInputs]) {
    md!(out, "\n## Shafts\n");
    header(out, &["shaft", "role", "bearing places (type × count at mm)", "locating", "seals (mm × count)"]);
    for s in shafts {
        let at = |at: f64| if s.without_at { " (no `at`)".to_string() } else { format!(" at {}", fixed(at, 2)) };
        let places: Vec<String> = s.bearings.iter().map(|(k, n, x, _)| format!("{k} × {n}{}", at(*x))).collect();
        let locating = s.bearings.iter().find(|b| b.3).map_or("—".into(), |b| {
            if s.without_at {
                "the first".into()
            } else {
                format!("at {}", fixed(b.2, 2))
            }
        });
        let seals: Vec<String> = s.seals.iter().map(|(d, n)| format!("{} × {n}", fixed(*d, 1))).collect();
        row(out, &[s.name.clone(), s.role.clone(), places.join("; "), locating, seals.join("; ")]);
    }
}
