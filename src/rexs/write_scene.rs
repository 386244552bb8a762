//! The `.gear` scene of an imported gear unit: every item with the REXS component it came from in
//! a comment, every choice the model did not make marked `chosen:`.

use std::fmt::Write;

use super::gear_unit::GearUnit;
use super::model::RexsModel;
use super::scene_text::{clean, n, shaft_name};
use super::shafts::ShaftData;
use super::stage_data::StageData;

pub(crate) fn write_scene(file_name: &str, model: &RexsModel, unit: &GearUnit) -> String {
    let stem = std::path::Path::new(file_name).file_stem().and_then(|s| s.to_str()).unwrap_or("REXS model");
    let mut s = String::new();
    let w = &mut s;
    let _ = writeln!(
        w,
        "# Imported by `gearloss import` from {} (REXS {}, {}).",
        clean(file_name),
        clean(&unit.version),
        clean(&unit.application)
    );
    let _ = writeln!(
        w,
        "# Each item names the REXS component it came from. What the model does not give was chosen here and"
    );
    let _ = writeln!(w, "# is marked `chosen:`; replace it with the unit's own data.");
    let _ = writeln!(w, "scene \"{}\" {{", clean(stem));
    let _ = writeln!(w, "    # chosen: the gears reference no material; steel.");
    let _ = writeln!(w, "    material steel {{ youngs_modulus = 210 GPa  poisson_ratio = 0.3 }}");
    if let Some(l) = &unit.lubricant {
        let base = if l.base_given { "" } else { "  # chosen: base oil (the model gives no ISO 6336 lubricant type)" };
        let _ = writeln!(w, "    # REXS lubricant {} \"{}\"", l.id, clean(&l.name));
        let _ = writeln!(
            w,
            "    lubricant \"{}\" {{ nu_40 = {} mm^2/s  nu_100 = {} mm^2/s  density_15 = {} kg/m^3  base = {} }}{base}",
            clean(&l.name),
            n(l.nu_40),
            n(l.nu_100),
            n(l.density_15),
            l.base
        );
    } else {
        let _ = writeln!(
            w,
            "    # chosen: the model gives no lubricant; an ISO VG 220 mineral gear oil (a common CLP grade)."
        );
        let _ = writeln!(w, "    lubricant = iso_vg(220, mineral)");
    }
    unit.planetary.write(w);
    for st in &unit.stages {
        stage(w, st);
    }
    let _ = writeln!(w, "    gearbox {{");
    for sh in &unit.shafts {
        shaft(w, sh);
    }
    let _ = writeln!(
        w,
        "        # chosen: REXS carries no housing surface or ambient; a housing for the duty cycle's losses."
    );
    let _ = writeln!(w, "        housing {{ surface_area = 1 m^2  ambient_temperature = 20 degC }}");
    let _ = writeln!(w, "    }}");
    cases(w, unit);
    let _ = writeln!(w, "    # chosen: the friction law (ISO/TR 14179-2's mean mesh friction, X_L from the base oil).");
    let _ = writeln!(w, "    friction {{ iso_14179_2() }}");
    let duty = if unit.cases.len() > 1 { "  duty_cycle" } else { "" };
    let _ = writeln!(w, "    analyses {{ efficiency(formulations = [external]){duty} }}");
    let _ = writeln!(w, "}}");
    let _ = model;
    s
}

fn stage(w: &mut String, st: &StageData) {
    let [p, g] = &st.gears;
    let _ = writeln!(w, "    # REXS cylindrical_stage {} \"{}\"; gears {} and {}", st.id, clean(&st.name), p.id, g.id);
    let _ = writeln!(w, "    stage \"stage_{}\" {{", st.id);
    let _ = writeln!(w, "        direction = {} deg", n(st.direction));
    let _ = writeln!(w, "        gears {{");
    let hand = if p.helix_angle == 0.0 {
        String::new()
    } else {
        format!("  hand = {}", if p.helix_angle > 0.0 { "right" } else { "left" })
    };
    let centre = st.center_distance.map_or_else(String::new, |a| format!("  center_distance = {} mm", n(a)));
    let _ = writeln!(
        w,
        "            module = {} mm  pressure_angle = {} deg  helix_angle = {} deg{hand}  face_width = {} mm{centre}",
        n(p.module),
        n(p.pressure_angle),
        n(p.helix_angle.abs()),
        n(st.face_width)
    );
    for (role, gear) in [("pinion", p), ("wheel", g)] {
        let tip = gear.tip_diameter.map_or_else(String::new, |d| format!("  tip_diameter = {} mm", n(d)));
        let _ = writeln!(
            w,
            "            {role} {{ teeth = {}  shaft = {}  at = {} mm  profile_shift = {}{tip}  material = steel  roughness_ra = 0.8 um }}  # REXS cylindrical_gear {}; chosen: roughness{}",
            gear.teeth,
            shaft_name(gear.shaft),
            n(gear.at),
            n(gear.profile_shift),
            gear.id,
            gear.profile_shift_note.as_ref().map_or_else(String::new, |note| format!("; chosen: {note}"))
        );
    }
    let _ = writeln!(w, "        }}");
    let _ =
        writeln!(w, "        # REXS gives no lubrication method for the gears: none is written, so the gears' no-load");
    let _ =
        writeln!(w, "        # (churning or jet) loss is left out; add `lubrication = dip(...)` or `injection(...)`.");
    let _ = writeln!(w, "    }}");
}

fn shaft(w: &mut String, sh: &ShaftData) {
    let role = if sh.input {
        "input  "
    } else if sh.output {
        "output  "
    } else {
        ""
    };
    let _ = writeln!(w, "        # REXS shaft {} \"{}\"", sh.id, clean(&sh.name));
    let _ = writeln!(
        w,
        "        shaft {} {{ {role}position = [{}, {}] mm",
        shaft_name(sh.id),
        n(sh.origin[1]),
        n(sh.origin[2])
    );
    for x in &sh.sections {
        let bore = if x.bore > 0.0 { format!(", bore = {} mm", n(x.bore)) } else { String::new() };
        let _ = writeln!(
            w,
            "            section(from = {} mm, to = {} mm, diameter = {} mm{bore})  # REXS shaft_section {}",
            n(x.from),
            n(x.to),
            n(x.outer_diameter),
            x.id
        );
    }
    for b in &sh.bearings {
        let c0 = b.static_load_rating.map_or_else(String::new, |c| format!(", static_load_rating = {} kN", n(c)));
        let locating = if b.locating { ", locating" } else { "" };
        let _ = writeln!(
            w,
            "            bearing(type = {}, bore = {} mm, outside = {} mm{c0}, at = {} mm{locating})  # REXS {} `{}`, axial: {}; {}",
            b.kind,
            n(b.bore),
            n(b.outside),
            n(b.at),
            b.id,
            clean(&b.designation),
            clean(&b.axial),
            b.source_note()
        );
    }
    let _ = writeln!(w, "        }}");
}

fn cases(w: &mut String, unit: &GearUnit) {
    let mut torques: Vec<f64> = Vec::new();
    let mut speeds: Vec<f64> = Vec::new();
    for c in &unit.cases {
        if !torques.contains(&c.torque) {
            torques.push(c.torque);
        }
        if !speeds.contains(&c.speed) {
            speeds.push(c.speed);
        }
    }
    let list = |v: &[f64]| v.iter().map(|x| n(*x)).collect::<Vec<_>>().join(", ");
    let mut temps: Vec<f64> = unit.cases.iter().filter_map(|c| c.oil_temperature).collect();
    temps.dedup();
    // A comment never shares the operating line: it would swallow the block's closing brace.
    let oil = match temps.as_slice() {
        [] => "oil_temperature = 70 degC".to_string(),
        [t] => format!("oil_temperature = {} degC", n(*t)),
        many => format!("oil_temperature = [{}] degC", list(many)),
    };
    let _ = writeln!(
        w,
        "    # The load spectrum's {} case(s) at the input: every torque × every speed (the cases themselves",
        unit.cases.len()
    );
    let _ = writeln!(w, "    # are the duty cycle's steps).");
    if temps.is_empty() {
        let _ = writeln!(w, "    # chosen: the oil at 70 °C, the model gives no lubricant temperature.");
    }
    let _ = writeln!(
        w,
        "    operating {{ input_torque = [{}] N*m  input_speed = [{}] rpm  {oil} }}",
        list(&torques),
        list(&speeds)
    );
    if unit.cases.len() > 1 {
        let (hours, note) = match unit.operating_time {
            Some(h) => (h, format!("the unit's operating time, {} h", n(h))),
            None => (1.0, "chosen: 1 h, the model gives no operating time".to_string()),
        };
        // Cases without a share divide what the others leave equally (all of it when none has one).
        let missing = unit.cases.iter().filter(|c| c.fraction.is_none()).count().max(1) as f64;
        let given: f64 = unit.cases.iter().filter_map(|c| c.fraction).sum();
        let left_over = (1.0 - given).max(0.0) / missing;
        let _ = writeln!(w, "    # One step per load case in file order, its duration its share of {note}.");
        let _ = writeln!(w, "    duty_cycle \"load spectrum\" {{");
        for c in &unit.cases {
            let share = c.fraction.unwrap_or(left_over);
            let _ = writeln!(
                w,
                "        step(duration = {} h, input_torque = {} N*m, input_speed = {} rpm)  # REXS load case {}",
                n(share * hours),
                n(c.torque),
                n(c.speed.abs()),
                c.id
            );
        }
        let _ = writeln!(w, "    }}");
    }
}
