//! What a checked scene will run, in words (`gearloss check`), and the blocks no analysis reads
//! (a `dynamics` block without a dynamics analysis is otherwise ignored without a word).

use crate::model::{Analyses, Scene};

/// One line per analysis the scene asks for, with its size.
pub fn would_run(scene: &Scene) -> Vec<String> {
    let a = &scene.analyses;
    let points = scene.operating.count();
    let laws = scene.friction.len();
    let pts = |n: usize| format!("{n} operating point{}", if n == 1 { "" } else { "s" });
    let mut out = Vec::new();
    if a.friction_along_loa {
        out.push(format!("friction along the line of action: {laws} law(s) at {}", pts(points)));
    }
    if let Some(f) = &a.efficiency {
        let names: Vec<&str> = f.iter().map(|x| x.name()).collect();
        out.push(format!(
            "efficiency: {laws} law(s) × {} × {} formulation(s) ({})",
            pts(points),
            f.len(),
            names.join(", ")
        ));
    }
    if let (Some(g), true) = (&scene.gearbox, a.efficiency.is_some() || a.efficiency_map.is_some()) {
        let places: usize = g.bearings.iter().map(Vec::len).sum();
        let seals: usize = g.seals.iter().map(Vec::len).sum();
        let lubrication =
            g.lubrication.as_ref().map_or("no lubrication method".to_string(), |l| format!("{} lubrication", l.name()));
        out.push(format!(
            "loss budget beside the mesh: {lubrication}, {places} bearing place(s), {seals} seal place(s)"
        ));
    }
    if let Some((t, s)) = &a.efficiency_map {
        out.push(format!("efficiency map: {} torques × {} speeds", t.values.len(), s.values.len()));
    }
    if a.film {
        out.push("film thickness and Λ along the line of action".to_string());
    }
    if let Some(d) = scene.dynamics.as_ref().filter(|_| a.dynamics) {
        let f: Vec<&str> = d.formulations.iter().map(|x| x.name()).collect();
        out.push(format!(
            "dynamics: {} model, {} formulation(s) ({}) at {}",
            d.model.id.name(),
            f.len(),
            f.join(", "),
            pts(points)
        ));
    }
    if let Some(s) = &a.stability_map {
        out.push(format!("stability map: {} pinion speeds", s.values.len()));
    }
    if a.numerics {
        out.push("numerics study: error against run time of every solver".to_string());
    }
    if a.thermal_balance.is_some() {
        out.push(format!("thermal balance: the oil temperature where losses equal heat given off, at {}", pts(points)));
    }
    if let (Some(_), Some(d)) = (a.duty_cycle, &scene.duty_cycle) {
        out.push(format!("duty cycle \"{}\": {} step(s), transient sump temperature", d.name, d.steps.len()));
    }
    if let Some(c) =
        scene.drive.as_ref().and_then(|d| d.cycle.as_ref()).filter(|_| scene.analyses.drive_cycle.is_some())
    {
        let tr = &c.cycle.trace;
        let transient = scene.housing.as_ref().is_some_and(|h| h.heat_capacity.is_some());
        out.push(format!(
            "drive cycle \"{}\" with \"{}\": {} samples over {} s, {}",
            c.name,
            c.vehicle_name,
            tr.time.len(),
            tr.duration(),
            if transient { "the sump's transient" } else { "at the fixed oil temperature" }
        ));
    }
    if let Some(t) = &a.transmission_error {
        out.push(format!(
            "mesh stiffness from the teeth and static transmission error at {} torque(s)",
            t.values.len()
        ));
    }
    if let Some(t) = &scene.operating.oil_temperatures {
        out.push(format!("all of it at {} oil temperatures, one report each", t.values.len()));
    }
    out
}

/// The blocks the scene gives that no analysis it asks for reads, each with what would use it.
pub fn unused_blocks(scene: &Scene) -> Vec<String> {
    let a = &scene.analyses;
    let cycle = scene.drive.as_ref().is_some_and(|d| d.cycle.is_some());
    let cycle_transient =
        cycle && a.drive_cycle.is_some() && scene.housing.as_ref().is_some_and(|h| h.heat_capacity.is_some());
    let thermal = a.thermal_balance.is_some()
        || a.duty_cycle.is_some()
        || scene.operating.equilibrium.is_some()
        || cycle_transient;
    let mut out = Vec::new();
    out.extend(unused_dynamics(a, scene.dynamics.is_some()));
    let budget = a.efficiency.is_some() || a.efficiency_map.is_some() || thermal;
    if scene.gearbox.as_ref().is_some_and(|g| !g.is_empty()) && !budget {
        out.push("the `gearbox` block's lubrication, bearings and seals are not used: no analysis asks for the loss budget (add `efficiency` to `analyses`)".to_string());
    }
    if scene.housing.is_some() && !thermal {
        out.push("the `housing` block is not used: no analysis asks for the thermal balance (add `thermal_balance` or `duty_cycle` to `analyses`, write `oil_temperature = equilibrium`, or give the housing a `heat_capacity` and run a `drive_cycle`)".to_string());
    }
    if cycle && a.drive_cycle.is_none() {
        out.push("the `vehicle` and `drive_cycle` blocks are not used: add `drive_cycle` to `analyses`".to_string());
    }
    if scene.duty_cycle.is_some() && a.duty_cycle.is_none() {
        out.push("the `duty_cycle` block is not used: add `duty_cycle` to `analyses`".to_string());
    }
    out.extend(unused_laws(a, !scene.friction.is_empty(), thermal));
    out
}

/// The blocks of one mesh's problem that no analysis it asks for reads: its `dynamics` block (when
/// `dynamics` is given) and its friction laws (when `laws` are), as [`unused_blocks`] says them.
pub(crate) fn unused_mesh_blocks(a: &Analyses, dynamics: bool, laws: bool) -> Vec<String> {
    let thermal = a.thermal_balance.is_some() || a.duty_cycle.is_some();
    unused_dynamics(a, dynamics).into_iter().chain(unused_laws(a, laws, thermal)).collect()
}

fn unused_dynamics(a: &Analyses, given: bool) -> Option<String> {
    (given && !(a.dynamics || a.stability_map.is_some() || a.numerics)).then(|| "the `dynamics` block is not used: no analysis asks for dynamics (add `dynamics`, `stability_map(...)` or `numerics` to `analyses`)".to_string())
}

/// `thermal`: the scene asks for a thermal balance (each of its analyses reads the laws).
fn unused_laws(a: &Analyses, given: bool, thermal: bool) -> Option<String> {
    let laws = a.efficiency.is_some()
        || a.efficiency_map.is_some()
        || a.friction_along_loa
        || a.drive_cycle.is_some()
        || thermal;
    (given && !laws).then(|| "the friction laws are not used: no analysis asks for friction (add `efficiency` or `friction_along_loa` to `analyses`)".to_string())
}
