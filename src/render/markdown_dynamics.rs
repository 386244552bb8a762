//! report.md: the dynamics section (no run times: those live in the timing files).

use super::markup::md;

use super::table::{fixed, header, row};
use crate::report::dynamics::{
    DynamicsPointReport, DynamicsReport, FormulationReport, Located, StabilityMapReport, StiffnessReport,
};
use crate::report::friction::MuValue;
use crate::report::units::Units;
use crate::report::Report;

fn sci(x: f64) -> String {
    if x.is_finite() {
        format!("{x:.3e}")
    } else {
        "—".into()
    }
}

pub(crate) fn dynamics(out: &mut String, r: &Report) {
    let Some(d) = &r.dynamics else { return };
    md!(out, "## Dynamics\n");
    md!(out, "{}\n", d.description);
    let u = r.units();
    model_table(out, d, u);
    for p in &d.points {
        point_section(out, d, p, u);
    }
    if let Some(map) = &d.stability_map {
        stability_map_section(out, map, u);
    }
    numerics(out, d);
}

/// The model's quantities: stiffness, mean stiffness, mass, damping, natural frequencies, law.
fn model_table(out: &mut String, d: &DynamicsReport, u: Units) {
    header(out, &["quantity", "value"]);
    let k_unit = u.stiffness();
    let k = match &d.stiffness {
        StiffnessReport::Pairs { single, double, triple } => format!(
            "single {} / double {} / triple {} ({})",
            k_unit.cell(single.si(), 2),
            k_unit.cell(double.si(), 2),
            k_unit.with(triple.si(), 2),
            d.stiffness_source.replace('_', " ")
        ),
        StiffnessReport::Table { table } => format!("table of {} values over one mesh cycle", table.len()),
        StiffnessReport::PerLength { per_length, cos2_base_helix_angle } => format!(
            "density k = {} along the contact lines; k(t) = k cos²β_b L(t), cos²β_b = {} ({})",
            u.stiffness_per_width().with(per_length.si(), 4),
            fixed(cos2_base_helix_angle.0, 6),
            d.stiffness_source.replace('_', " ")
        ),
        StiffnessReport::Computed { mean_mesh_stiffness } => format!(
            "from the teeth, mean {} over a mesh cycle ({}; the curve is in *Mesh stiffness from the teeth*)",
            k_unit.with(mean_mesh_stiffness.si(), 2),
            d.stiffness_source.replace('_', " ")
        ),
    };
    for (q, v) in [
        ("mesh stiffness", k),
        ("mean stiffness k̄", k_unit.with(d.mean_stiffness.si(), 3)),
        ("equivalent mass m_e", u.mass().with(d.equivalent_mass.si(), 5)),
        (
            "damping ratio ζ, damping c",
            format!("{}, {}", fixed(d.damping_ratio.0, 4), u.damping().with(d.damping.si(), 2)),
        ),
        ("natural frequency f_n", format!("{} Hz", fixed(d.natural_frequency.si(), 1))),
        ("friction law", d.friction.clone().unwrap_or_else(|| "none (base model only)".into())),
    ] {
        row(out, &[q.into(), v]);
    }
    if !d.natural_frequencies.is_empty() {
        let f: Vec<String> = d.natural_frequencies.iter().map(|f| fixed(f.si(), 1)).collect();
        row(out, &["natural frequencies of the mean system".into(), format!("{} Hz", f.join(", "))]);
        if let Some(r) = d.stiffness_ratio {
            row(out, &["highest / lowest natural frequency".into(), fixed(r.0, 2)]);
        }
    }
    md!(out);
    if let Some(iso) = &d.iso_6336 {
        md!(out, "{}\n", super::markdown_teeth::iso_readings(iso, u));
    }
}

/// One operating point: every formulation's Floquet numbers and response, then its located lines,
/// bearings, free response and plots.
fn point_section(out: &mut String, d: &DynamicsReport, p: &DynamicsPointReport, u: Units) {
    let (micro, force, torque) = (u.micro(), u.force(), u.torque());
    md!(
        out,
        "### Dynamics at {}\n\nf_mesh = {} Hz, f_n/f_mesh = {}\n",
        p.label,
        fixed(p.mesh_frequency.si(), 2),
        fixed(p.frequency_ratio.0, 3)
    );
    let cols = [
        "formulation".to_string(),
        "propagator".into(),
        "ρ".into(),
        "multipliers".into(),
        "verdict".into(),
        "det Φ(T)".into(),
        "Liouville".into(),
        micro.heading("DTE p-p"),
        "K_v".into(),
        "η_dyn %".into(),
        format!("max applied friction {} / T_p {} / T_w {}", force.unit, torque.unit, torque.unit),
        "separation".into(),
    ];
    header(out, &cols);
    for f in &p.formulations {
        let mults: Vec<String> = f
            .floquet_multipliers
            .iter()
            .map(|[re, im]| {
                let sign = if fixed(im.0, 6).starts_with('-') { '-' } else { '+' };
                format!("{}{sign}{}i", fixed(re.0, 6), fixed(im.0.abs(), 6))
            })
            .collect();
        row(
            out,
            &[
                f.formulation.name().to_string(),
                format!("{:?}", f.method).to_lowercase(),
                fixed(f.spectral_radius.0, 6),
                mults.join(", "),
                format!("{:?}", f.verdict).to_lowercase(),
                sci(f.monodromy_determinant.0),
                sci(f.liouville_determinant.0),
                f.dte_peak_to_peak.map_or("—".into(), |q| micro.q(&q, 4)),
                f.dynamic_factor.map_or("—".into(), |k| fixed(k.0, 4)),
                f.mean_dynamic_efficiency.map_or("—".into(), |e| fixed(100.0 * e.0, 4)),
                match (&f.peak_applied_friction_force, f.peak_friction_torque.as_slice()) {
                    (Some(ff), [tp, tw]) => {
                        format!("{} / {} / {}", force.q(&ff.value, 1), torque.q(&tp.value, 3), torque.q(&tw.value, 3))
                    }
                    _ if f.formulation != crate::dynamics::DynamicFormulation::Base && d.friction_diverges_at_pitch => {
                        "diverges at P".into()
                    }
                    _ => "—".into(),
                },
                if f.tooth_separation.is_empty() { "none".into() } else { "**yes**".into() },
            ],
        );
    }
    md!(out);
    located_lines(out, &p.formulations, u);
    bearing_lines(out, &p.formulations, u);
    free_lines(out, &p.formulations, u);
    if let Some(c) = d.curves.iter().find(|c| c.label == p.label) {
        if !c.dte.is_empty() {
            md!(out, "![DTE, mesh and friction forces, DTE spectrum]({})\n", c.file);
        }
        if !c.free.is_empty() {
            md!(out, "![free response from the initial state]({})\n", c.free_file);
        }
    }
}

/// The stability map's table: per formulation the largest ρ and K_v over the map's speeds and the
/// located unstable ranges.
fn stability_map_section(out: &mut String, map: &StabilityMapReport, u: Units) {
    md!(
        out,
        "### Stability map\n\nPinion torque {}, {} speeds.\n",
        u.torque().with(map.pinion_torque.si(), 2),
        map.points.len()
    );
    let unit = &map.speed_unit;
    let at_unit = format!("at {}", unit.name);
    header(out, &["formulation", "max ρ", &at_unit, "max K_v (stable)", "unstable ranges"]);
    for (i, f) in map.formulations.iter().enumerate() {
        let (mut rho, mut at, mut kv) = (0.0f64, 0.0, 0.0f64);
        for p in &map.points {
            if p.spectral_radius[i].0 > rho {
                rho = p.spectral_radius[i].0;
                at = unit.value(&p.pinion_speed);
            }
            if let MuValue::Value(v) = p.dynamic_factor[i] {
                kv = kv.max(v.0);
            }
        }
        let ranges: Vec<String> =
            map.unstable_ranges[i].iter().map(|[a, b]| format!("{:.0}–{:.0}", unit.value(a), unit.value(b))).collect();
        row(
            out,
            &[
                f.name().to_string(),
                fixed(rho, 6),
                fixed(at, 0),
                fixed(kv, 4),
                if ranges.is_empty() { "none".into() } else { format!("{} {}", ranges.join(", "), unit.name) },
            ],
        );
    }
    md!(out, "\n![stability map](stability_map.svg)\n");
}

/// The located extrema (value at τ in mesh periods), means with their error estimates, separation.
/// 6-DOF: the bearing forces and displacements of both gears, per formulation.
fn bearing_lines(out: &mut String, formulations: &[FormulationReport], u: Units) {
    if formulations.iter().all(|f| f.gears.is_empty()) {
        return;
    }
    let (force, micro) = (u.force(), u.micro());
    let cols = [
        "formulation".to_string(),
        "gear".into(),
        force.heading("LOA bearing force p-p"),
        force.heading("LOA mean"),
        force.heading("OLOA bearing force p-p"),
        force.heading("OLOA mean"),
        force.heading("OLOA orders 1 / 2"),
        micro.heading("y p-p"),
        micro.heading("x p-p"),
    ];
    header(out, &cols);
    for f in formulations {
        for g in &f.gears {
            let order =
                |k: usize| g.bearing_force_oloa_spectrum.get(k).map_or("—".into(), |l| force.q(&l.amplitude, 3));
            row(
                out,
                &[
                    f.formulation.name().into(),
                    g.gear.clone(),
                    force.q(&g.bearing_force_loa_peak_to_peak, 2),
                    force.q(&g.bearing_force_loa_mean, 2),
                    force.q(&g.bearing_force_oloa_peak_to_peak, 3),
                    force.q(&g.bearing_force_oloa_mean, 3),
                    format!("{} / {}", order(0), order(1)),
                    micro.q(&g.oloa_displacement_peak_to_peak, 5),
                    micro.q(&g.loa_displacement_peak_to_peak, 5),
                ],
            );
        }
    }
    md!(out);
}

/// The free responses: peak, growth and the Floquet-mode spectrum lines.
fn free_lines(out: &mut String, formulations: &[FormulationReport], u: Units) {
    let (micro, vel) = (u.micro(), u.velocity());
    for f in formulations {
        let Some(fr) = &f.free_response else { continue };
        md!(
            out,
            "Free response, {}: x0 = {}, v0 = {} over {} mesh periods; peak |x| {} at t = {} T; largest |x| in the first period {}, in the last {}. Lines (Floquet modes, f = arg λ/(2πT) + k f_mesh):\n",
            f.formulation.name(),
            micro.with(fr.x0.si(), 5),
            vel.with(fr.v0.si(), 5),
            fr.periods,
            micro.with(fr.peak.value.si(), 5),
            fixed(fr.peak.tau.0, 4),
            micro.with(fr.first_period_peak.si(), 5),
            micro.with(fr.last_period_peak.si(), 5)
        );
        let cols = [
            "f / f_mesh".to_string(),
            micro.heading("amplitude"),
            micro.heading("error est."),
            "growth per period |λ|".into(),
        ];
        header(out, &cols);
        for l in &fr.lines {
            row(
                out,
                &[
                    fixed(l.order.0, 4),
                    micro.q(&l.amplitude, 6),
                    format!("{:.1e}", micro.value(l.amplitude_error.si())),
                    fixed(l.growth_per_period.0, 6),
                ],
            );
        }
        md!(out);
    }
}

fn located_lines(out: &mut String, formulations: &[FormulationReport], u: Units) {
    let at = |l: &Located, shown: crate::report::units::Shown, digits: usize| {
        format!("{} at τ = {}", shown.with(l.value.si(), digits), fixed(l.tau.0, 6))
    };
    let (micro, force) = (u.micro(), u.force());
    for f in formulations {
        let (Some(lo), Some(hi), Some(fmax), Some(fmin)) =
            (&f.dte_min, &f.dte_max, &f.tooth_force_max, &f.tooth_force_min)
        else {
            continue;
        };
        let mut parts = vec![
            format!("DTE min {}, max {}", at(lo, micro, 4), at(hi, micro, 4)),
            format!("tooth force F min {}, max {}", at(fmin, force, 1), at(fmax, force, 1)),
        ];
        if let (Some(m), Some(e)) = (&f.dte_mean, &f.dte_mean_error) {
            parts.push(format!("mean DTE {} (± {:.1e})", micro.with(m.si(), 4), micro.value(e.si())));
        }
        if let (Some(m), Some(e)) = (&f.mean_dynamic_efficiency, &f.mean_dynamic_efficiency_error) {
            parts.push(format!("mean η_dyn {} % (± {:.1e})", fixed(100.0 * m.0, 4), 100.0 * e.0));
        }
        if let Some(ff) = &f.peak_applied_friction_force {
            parts.push(format!("max applied friction force {}", at(ff, force, 1)));
        }
        if let Some(mf) = &f.peak_mu_times_tooth_force {
            parts.push(format!("max μ × tooth force {} (not applied by this equation)", at(mf, force, 1)));
        }
        if !f.tooth_separation.is_empty() {
            let spans: Vec<String> =
                f.tooth_separation.iter().map(|[a, b]| format!("τ = {}–{}", fixed(a.0, 6), fixed(b.0, 6))).collect();
            parts.push(format!("teeth separate at {}", spans.join(", ")));
        }
        md!(out, "- {}: {}", f.formulation.name(), parts.join("; "));
    }
    md!(out);
}

fn numerics(out: &mut String, d: &DynamicsReport) {
    let Some(n) = &d.numerics else { return };
    md!(
        out,
        "### Numerical error of the integrators\n\n{:?} formulation at the first operating point, {} mesh periods from the static deflection, every integration restarted at every switch time. Error: max |x − x_ref| over the last period / peak-to-peak DTE, against the {:?} reference; final-state error in the scaled state norm. Run times are machine-dependent and kept in `timing_numerics.json` and `timing_work_precision.svg`.\n",
        n.formulation, n.periods, n.reference
    );
    header(out, &["method", "rtol", "error", "final-state error", "steps", "rejected", "RHS evaluations", "note"]);
    for r in &n.runs {
        row(
            out,
            &[
                r.method.clone(),
                format!("{:.0e}", r.rtol.0),
                r.error.map_or("—".into(), |e| sci(e.0)),
                r.final_state_error.map_or("—".into(), |e| sci(e.0)),
                r.steps.to_string(),
                r.rejected.to_string(),
                r.evaluations.to_string(),
                r.failure.clone().unwrap_or_default(),
            ],
        );
    }
    md!(out, "\n![work-precision](timing_work_precision.svg)\n");
}
