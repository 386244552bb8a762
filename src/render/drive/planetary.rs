//! A drive's planetary stages in report.md: what each is (members, planets, ratios, both meshes,
//! the assembly and neighbour conditions), and at each operating point its members' speeds and
//! torques, the rolling power, both meshes, η₀ and η, the planets' forces and bearings.

use crate::drive::planetary::inputs::PlanetaryInputs;
use crate::drive::DrivePoint;
use crate::drive::KindInputs;
use crate::render::markup::md;
use crate::render::table::{fixed, header, row};
use crate::report::drive_inputs::StageInputs;
use crate::report::units::Units;

use super::shown_units::Shown;

/// A planetary stage's own inputs; None for a stage of another kind.
fn own_inputs(s: &StageInputs) -> Option<&PlanetaryInputs> {
    match s.kind.as_deref() {
        Some(KindInputs::Planetary(p)) => Some(p),
        None => None,
    }
}

/// A planetary stage's words in the stages' table: its two turning members' shafts, the teeth
/// sun/planet/ring, i₀; None for a stage of another kind.
pub(crate) fn stage_words(s: &StageInputs) -> Option<(String, String, String)> {
    let p = own_inputs(s)?;
    Some((
        p.members
            .iter()
            .filter(|(_, shaft)| shaft != "housing")
            .map(|(m, shaft)| format!("{} on {shaft}", m.name()))
            .collect::<Vec<_>>()
            .join(" → "),
        format!("{}/{}/{}", p.teeth[0], p.teeth[1], p.teeth[2]),
        format!("i₀ {}", fixed(p.stationary_ratio, 4)),
    ))
}

/// The planetary stages' inputs, after the stages' table.
pub(crate) fn inputs(out: &mut String, stages: &[StageInputs], units: Units) {
    let (len, mass) = (units.length(), units.mass());
    let mm = |x: f64| len.cell(x * 1e-3, 3);
    let planetary: Vec<_> = stages.iter().filter_map(|s| own_inputs(s).map(|p| (s, p))).collect();
    if planetary.is_empty() {
        return;
    }
    md!(out, "\n### Planetary stages\n");
    md!(out, "A row of the table above gives a planetary stage's sun–planet mesh; here its members, planets and the planet–ring mesh (internal). Willis: n_sun − i₀ n_ring − (1 − i₀) n_carrier = 0, i₀ = −z_ring/z_sun; only the rolling power P_w = T_sun (ω_sun − ω_carrier) passes the meshes, which lose the share 1 − η₀ of it, η₀ = η_sp η_pr.\n");
    header(
        out,
        &[
            "stage",
            "sun / ring / carrier on",
            "z sun/planet/ring",
            "planets",
            "K_γ",
            "i₀",
            "ratio",
            "(z_s + z_r)/n",
            &len.titled("neighbour gap"),
            "α_w ring mesh (°)",
            "ε_α ring mesh",
            &len.titled("d_a ring"),
            &mass.titled("planet mass"),
            "planet bearing",
        ],
    );
    for (s, p) in planetary {
        let on: Vec<String> = p.members.iter().map(|(_, shaft)| shaft.clone()).collect();
        row(
            out,
            &[
                s.name.clone(),
                on.join(" / "),
                format!("{}/{}/{}", p.teeth[0], p.teeth[1], p.teeth[2]),
                p.planets.to_string(),
                fixed(p.load_sharing_factor, 3),
                fixed(p.stationary_ratio, 4),
                fixed(p.ratio, 4),
                fixed(p.assembly, 4),
                p.neighbour_gap_mm.map_or("— (one planet)".into(), mm),
                fixed(p.ring_pressure_angle_deg, 3),
                fixed(p.ring_contact_ratio, 3),
                mm(p.ring_tip_diameter_mm),
                mass.cell(p.planet_mass_kg, 4),
                if p.planet_bearing.is_empty() { "none".into() } else { p.planet_bearing.clone() },
            ],
        );
    }
}

/// Each planetary stage at one operating point.
pub(crate) fn point(out: &mut String, d: &DrivePoint, u: Shown) {
    let (n, t) = (u.speed, u.torque);
    let (force, w) = (u.units.force(), u.units.power());
    for s in &d.stages {
        let Some(p) = s.planetary() else { continue };
        md!(
            out,
            "Planetary stage {}: the {} drives, the {} is driven, the {} is held; P_w = T_sun (ω_sun − ω_carrier) = {}, the {} drives the meshes; η₀ = η_sp η_pr = {} %, η = {} %.\n",
            s.name,
            p.driving_member.name(),
            p.driven_member.name(),
            p.held.name(),
            w.with(p.rolling_power, 3),
            if p.sun_drives_meshes { "sun" } else { "ring" },
            fixed(100.0 * p.basic_efficiency, 5),
            fixed(100.0 * p.efficiency, 5)
        );
        header(
            out,
            &[
                "member",
                &format!("n ({}, + ccw)", n.unit()),
                &format!("T ({}, on the member)", t.unit()),
                &w.titled("P in"),
            ],
        );
        for m in crate::drive::kinematics::planetary::PlanetaryMember::ALL {
            let i = m.index();
            row(
                out,
                &[
                    m.name().into(),
                    fixed(n.of_rad_s(p.speeds[i]), 3),
                    fixed(t.of_si(p.torques[i]), 4),
                    w.cell(p.torques[i] * p.speeds[i], 3),
                ],
            );
        }
        md!(out);
        header(
            out,
            &[
                "mesh",
                &format!("pinion T per planet ({})", t.unit()),
                &format!("n in the carrier's frame ({})", n.unit()),
                "η (%)",
                &w.titled("loss, all planets"),
            ],
        );
        for (i, name) in ["sun–planet", "planet–ring"].iter().enumerate() {
            row(
                out,
                &[
                    (*name).into(),
                    fixed(t.of_si(p.mesh_torque[i]), 4),
                    fixed(n.of_rad_s(p.mesh_speed[i]), 3),
                    fixed(100.0 * p.mesh_efficiency[i], 5),
                    w.cell(p.mesh_loss[i], 3),
                ],
            );
        }
        md!(out);
        let f = &p.forces;
        md!(
            out,
            "Each planet (the most loaded where K_γ > 1): {} {} relative to the carrier; F_t {} (sun mesh) and {} (ring mesh), F_r {} and {}, centrifugal m ω_c² a_w {}; its bearing carries |B| = {}; the planets' bearings lose {} (no-load) + {} (load); churning {}.\n",
            fixed(n.of_rad_s(p.planet_speed), 3),
            n.unit(),
            force.with(f.tangential[0], 2),
            force.with(f.tangential[1], 2),
            force.with(f.radial[0], 2),
            force.with(f.radial[1], 2),
            force.with(f.centrifugal, 3),
            force.with(f.bearing, 2),
            w.with(p.planet_bearings[0], 3),
            w.with(p.planet_bearings[1], 3),
            w.with(p.churning, 3)
        );
        if f.axial != 0.0 {
            md!(
                out,
                "Helical: each mesh's axial force F_a = {} (on the sun n F_a = {}, on the ring as much the other way; on the planet the two cancel into the tilting moment M = F_a (r_w,sp + r_w,pr) = {}, which its bearings take and pass to the carrier: {}).\n",
                force.with(f.axial, 2),
                force.with(f64::from(p.planets) * f.axial, 2),
                u.units.torque().with(f.tilting, 4),
                p.tilting_support
            );
        }
    }
}
