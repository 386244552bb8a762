//! A planetary stage of an imported gear unit as the scene writes it: a `stage` holding a
//! `planetary` block (sun, planet with its bearings, ring, carrier), each member naming the REXS
//! component it came from, the held member on `housing`.

use std::fmt::Write;

use super::planetary::PlanetaryData;
use super::planetary_hold::Member;
use super::scene_text::{clean, n, shaft_name};

pub(super) fn planetary_stage(w: &mut String, p: &PlanetaryData) {
    let ids = |v: &[u64]| v.iter().map(u64::to_string).collect::<Vec<_>>().join(", ");
    let _ = writeln!(
        w,
        "    # REXS planetary_stage {} \"{}\": sun {}, planets {}, ring {}, carrier {}; meshes (cylindrical_stage) {}",
        p.id,
        clean(&p.name),
        p.sun.id,
        ids(&p.planet_ids),
        p.ring.id,
        p.carrier_id,
        ids(&p.meshes)
    );
    let _ = writeln!(w, "    # The {} held by {}.", p.held.name(), clean(&p.held_by));
    let _ = writeln!(w, "    stage \"stage_{}\" {{", p.id);
    let _ = writeln!(w, "        direction = {} deg", n(p.direction));
    let _ = writeln!(w, "        planetary {{");
    let _ = writeln!(w, "            planets = {}", p.planet_ids.len());
    let centre = p.center_distance.map_or_else(String::new, |a| format!("  center_distance = {} mm", n(a)));
    let helix = if p.sun.helix_angle == 0.0 {
        String::new()
    } else {
        let hand = if p.sun.helix_angle > 0.0 { "right" } else { "left" };
        format!("  helix_angle = {} deg  hand = {hand}", n(p.sun.helix_angle.abs()))
    };
    let _ = writeln!(
        w,
        "            module = {} mm  pressure_angle = {} deg{helix}  face_width = {} mm{centre}",
        n(p.planet.module),
        n(p.planet.pressure_angle),
        n(p.face_width)
    );
    let place = |member: Member, shaft: u64, at: f64| {
        if p.held == member {
            "shaft = housing".to_string()
        } else {
            format!("shaft = {}  at = {} mm", shaft_name(shaft), n(at))
        }
    };
    let gear = |g: &super::stage_data::GearData| {
        let tip = g.tip_diameter.map_or_else(String::new, |d| format!("  tip_diameter = {} mm", n(d)));
        format!(
            "teeth = {}  profile_shift = {}{tip}  material = steel  roughness_ra = 0.8 um",
            g.teeth,
            n(g.profile_shift)
        )
    };
    let chosen = |g: &super::stage_data::GearData| {
        format!(
            "chosen: roughness{}",
            g.profile_shift_note.as_ref().map_or_else(String::new, |note| format!("; chosen: {note}"))
        )
    };
    let member = |label: &str, g: &super::stage_data::GearData, m: Member, kind: &str| {
        format!(
            "            {label} {{ {}  {} }}  # REXS {kind} {}; {}",
            gear(g),
            place(m, g.shaft, g.at),
            g.id,
            chosen(g)
        )
    };
    let _ = writeln!(w, "{}", member("sun    ", &p.sun, Member::Sun, "cylindrical_gear"));
    let _ = writeln!(
        w,
        "            planet  {{ {}  # REXS cylindrical_gear {}; {}",
        gear(&p.planet),
        p.planet.id,
        chosen(&p.planet)
    );
    if let Some(b) = p.planet_bearings.first() {
        let c0 = b.static_load_rating.map_or_else(String::new, |c| format!(", static_load_rating = {} kN", n(c)));
        let count = p.planet_bearings.len();
        let counted = if count > 1 { format!(", count = {count}") } else { String::new() };
        let _ = writeln!(
            w,
            "                      bearing(type = {}, bore = {} mm, outside = {} mm{c0}{counted})  # REXS {}; {}",
            b.kind,
            n(b.bore),
            n(b.outside),
            ids(&p.planet_bearings.iter().map(|b| b.id).collect::<Vec<_>>()),
            b.source_note()
        );
        if let Some(l) = p.planet_bearing_spacing {
            let _ = writeln!(w, "                      bearing_spacing = {} mm  # their places on the pin", n(l));
        }
    }
    let _ = writeln!(w, "            }}");
    let _ = writeln!(w, "{}", member("ring   ", &p.ring, Member::Ring, "ring_gear"));
    let carrier = match &p.carrier {
        Some((shaft, _, at)) => place(Member::Carrier, *shaft, *at),
        None => "shaft = housing".to_string(),
    };
    let _ = writeln!(
        w,
        "            carrier {{ {carrier} }}  # REXS planet_carrier {}; `at`: the planets' mid-plane on its shaft",
        p.carrier_id
    );
    let _ = writeln!(w, "        }}");
    let _ = writeln!(
        w,
        "        # REXS gives no lubrication method for the gears: none is written, so the stage's churning"
    );
    let _ = writeln!(w, "        # loss is left out; add `lubrication = dip(...)` or `injection(...)`.");
    let _ = writeln!(w, "    }}");
}
