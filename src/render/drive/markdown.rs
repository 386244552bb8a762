//! report.md of a drive: the headline (every operating point's ends, loss parts and η), the
//! findings, the stages and shafts as given, the oil, then each operating point in full (stages,
//! shafts, bearing places with their loads, the mesh forces the statics read) and the model.

use crate::losses::parts::LossColumn;
use crate::render::markup::{counted, md};
use crate::render::table::{fixed, header, row};
use crate::report::drive::DriveReport;
use crate::report::thermal;
use crate::report::units::Units;
use crate::report::PlotKind;

use super::shown_units::Shown;

pub(crate) fn render_drive_markdown(r: &DriveReport) -> String {
    let u = Shown::of(r);
    let mut out = String::new();
    md!(out, "# {}\n", r.title);
    md!(
        out,
        "A drive of {} on {} shafts, overall ratio ω_in/ω_out = {} ({} → {}); operating points given as the {} torque and the {} speed. Laws: {}. README, \"Several stages\", states the model; every number below comes with the values it rests on.\n",
        counted(r.stages.len(), "stage", "stages"),
        r.shafts.len(),
        fixed(r.overall_ratio, 4),
        r.shafts.iter().find(|s| s.role == "input").map_or("", |s| &s.name),
        r.shafts.iter().find(|s| s.role == "output").map_or("", |s| &s.name),
        // A scene of one pair gives its torque at the pinion gear (the input's is that plus its
        // shaft's own losses).
        if r.one_pair && r.torque_at == crate::drive::ShaftEnd::Input { "pinion gear's" } else { r.torque_at.name() },
        r.speed_at.name(),
        if r.laws.is_empty() { "none (each mesh passes its power whole)".to_string() } else { r.laws.join(", ") }
    );
    // A scene of one pair: its mesh's own report first, where the reader of one pair looks for it.
    if let Some(dir) = r.stage_pairs.iter().find(|p| p.point.is_none()).and_then(|p| p.folder.as_ref()) {
        md!(
            out,
            "The scene is one pair, run as its one-stage drive: the pair's own report — its geometry, the contact along the line of action, each law's efficiency along the mesh cycle and every analysis of one pair the scene asks for, over the whole sweep — is [{dir}/report.md]({dir}/report.md). This report is the drive's: its power at both ends, its losses part by part{}.\n",
            if r.cycle.is_some() { ", its drive cycle" } else { "" }
        );
    }
    if r.points.is_empty() && r.cycle.is_some() {
        md!(out, "No operating points are given: the drive cycle below gives the box its load.\n");
    } else if r.points.is_empty() {
        md!(out, "The scene asks for no efficiency: the drive is walked only at the points its stages' meshes are analysed at, below.\n");
    } else {
        headline(&mut out, r);
    }
    let drawn = super::power_flow::chosen(r);
    if !drawn.is_empty() {
        let which: Vec<String> = drawn.iter().map(|p| format!("{} ({})", p.label, p.point.flow.name())).collect();
        md!(out, "![power from source to sink, every loss a step]({})\n", super::power_flow::FILE);
        md!(
            out,
            "The power flow of {}: each shaft's own losses and each stage's mesh loss a step down.\n",
            which.join(" and ")
        );
    }
    if let Some(rows) = super::loss_budget::drawn(r) {
        md!(out, "![the loss budget of each point, part by part]({})\n", super::loss_budget::FILE);
        md!(
            out,
            "The loss budget of the {} above under the {} formulation, one bar a point and law: the meshes, the gears' no-load losses, the bearings' and the seals'.\n",
            counted(rows.len(), "row", "rows"),
            rows[0].formulation
        );
    }
    if !r.findings.is_empty() {
        md!(out, "## Findings\n");
        for f in &r.findings {
            md!(out, "- **{:?}**: {}", f.severity, f.message);
        }
        md!(out);
    }
    inputs(&mut out, r);
    if !r.inputs.is_empty() {
        md!(out, "## Scene\n");
        md!(out, "Every input of the stages, the oil, the lubrication, the shafts' bearing places and seals and the housing, as written and in SI.\n");
        crate::render::markdown::inputs_table(&mut out, &r.inputs);
        md!(out);
    }
    stage_geometry(&mut out, r);
    thermal(&mut out, r);
    duty(&mut out, r);
    if let Some(c) = &r.cycle {
        super::cycle::cycle(&mut out, c, u);
    }
    if !r.points.is_empty() {
        md!(out, "## Operating points\n");
    }
    for p in &r.points {
        super::point_tables::point(&mut out, p, u);
    }
    super::stage_pairs::section(&mut out, r);
    super::loss_map::section(&mut out, r, u);
    model(&mut out, r);
    out
}

fn headline(out: &mut String, r: &DriveReport) {
    let u = Shown::of(r);
    let w = u.units.power();
    let watts = |name: &str| format!("{name} ({})", w.unit);
    md!(out, "## Headline\n");
    let mut columns = vec![
        "point".to_string(),
        "law".to_string(),
        "formulation".to_string(),
        "flow".to_string(),
        format!("T_in ({})", u.torque.unit()),
        format!("n_in ({})", u.speed.unit()),
        watts("P_in"),
        format!("T_out ({})", u.torque.unit()),
        format!("n_out ({})", u.speed.unit()),
        watts("P_out"),
        watts("meshes"),
        watts("gears no-load"),
        watts("bearings"),
        watts("seals"),
        watts("total"),
        "η (%)".to_string(),
        "passes".to_string(),
    ];
    if r.one_pair {
        columns.push("η at the pinion (%)".to_string());
    }
    header(out, &columns);
    for p in &r.points {
        let d = &p.point;
        let l = &d.losses;
        row(
            out,
            &[
                p.label.clone(),
                p.law.clone(),
                p.formulation.clone(),
                d.flow.name().to_string(),
                fixed(u.torque.of_si(d.input_torque), 4),
                fixed(u.speed.of_rad_s(d.input_speed), 2),
                w.cell(d.input_power, 2),
                fixed(u.torque.of_si(d.output_torque), 4),
                fixed(u.speed.of_rad_s(d.output_speed), 2),
                w.cell(d.output_power, 2),
                w.cell(l.meshes, 3),
                w.cell(l.part(LossColumn::GearNoLoad), 3),
                w.cell(l.part(LossColumn::BearingsNoLoad) + l.part(LossColumn::BearingsLoad), 3),
                w.cell(l.part(LossColumn::Seals), 3),
                w.cell(l.total(), 3),
                if d.both_ends_deliver { "0 (both ends deliver)".into() } else { fixed(100.0 * d.efficiency, 4) },
                if d.settled() { d.iterations.to_string() } else { format!("{} (not settled)", d.iterations) },
            ]
            .into_iter()
            .chain(r.one_pair.then(|| p.pinion_efficiency().map_or_else(|| "—".into(), |e| fixed(100.0 * e, 4))))
            .collect::<Vec<String>>(),
        );
    }
    match &r.shown_rows {
        Some(shown) => md!(
            out,
            "\n{} of {} rows (operating points × laws × formulations): the first {} and every row of detail point{} {}; `drive_records.csv` holds every one.",
            r.points.len(),
            r.rows,
            shown.first,
            if shown.detail_points.len() == 1 { "" } else { "s" },
            shown.detail_points.iter().map(|p| p.to_string()).collect::<Vec<_>>().join(", ")
        ),
        None if r.rows > r.points.len() => md!(
            out,
            "\nThe first {} of {} rows (operating points × laws × formulations); `drive_records.csv` holds every one.",
            r.points.len(),
            r.rows
        ),
        None => {}
    }
    if let (Some((lo, lo_at)), Some((hi, hi_at)), true) = (&r.least_efficiency, &r.greatest_efficiency, r.rows > 1) {
        md!(
            out,
            "\nOver all {} rows: η from {} % at {lo_at} to {} % at {hi_at}{}.",
            r.rows,
            fixed(100.0 * lo, 4),
            fixed(100.0 * hi, 4),
            if r.both_ends_rows > 0 {
                format!("; {} rows where both ends deliver left out", r.both_ends_rows)
            } else {
                String::new()
            }
        );
    }
    md!(out, "\nη = P_sink/P_source: P_out/P_in in drive, P_in/P_out (power received by the motor over power the output delivers) in coast; T_in is the torque into the box at the input shaft's end, T_out the torque the output passes to the load (negative in coast). Total = P_in − P_out = meshes + gears' no-load + bearings + seals.\n");
    if r.one_pair {
        md!(out, "η at the pinion = 1 − total/(T_pinion ω_pinion): the same loss over the power at the pinion gear, the total efficiency a scene of one pair has always reported (η above takes the input's power, the pinion's plus its shaft's own losses).\n");
    }
}

fn inputs(out: &mut String, r: &DriveReport) {
    let units = Units::of_system(r.unit_system);
    let len = units.length();
    // The inputs keep millimetres; an inch report shows inches and the normal diametral pitch.
    let mm = |x: f64, decimals: usize| len.cell(x * 1e-3, decimals);
    let inch = !units.is_si();
    md!(out, "## Stages\n");
    header(
        out,
        &[
            "stage",
            "pinion on → wheel on",
            &len.titled("at"),
            "z",
            "u",
            if inch { "P_nd (1/in)" } else { "m_n (mm)" },
            "β (°)",
            "hand (pinion)",
            "φ (°)",
            &len.titled("a"),
            &len.titled("b"),
            "α_wt (°)",
            "ε_α",
            "ε_β",
            "lubrication",
        ],
    );
    for s in &r.stages {
        // A kind's own words (kind_pieces.rs), else a pair's.
        let (joins, teeth, ratio) = super::kind_pieces::stage_words(s).unwrap_or_else(|| {
            (format!("{} → {}", s.shafts[0], s.shafts[1]), format!("{}/{}", s.teeth[0], s.teeth[1]), fixed(s.ratio, 4))
        });
        row(
            out,
            &[
                s.name.clone(),
                joins,
                format!("{} / {}", mm(s.at_mm[0], 2), mm(s.at_mm[1], 2)),
                teeth,
                ratio,
                if inch { fixed(25.4 / s.normal_module_mm, 4) } else { fixed(s.normal_module_mm, 4) },
                fixed(s.helix_angle_deg, 2),
                if s.pinion_hand.is_empty() { "spur".into() } else { s.pinion_hand.clone() },
                fixed(s.direction_deg, 2),
                mm(s.centre_distance_mm, 3),
                mm(s.face_width_mm, 2),
                fixed(s.working_pressure_angle_deg, 3),
                fixed(s.contact_ratio, 3),
                fixed(s.overlap_ratio, 3),
                s.lubrication.clone(),
            ],
        );
    }
    super::kind_pieces::notes(out, &r.stages);
    for s in r.stages.iter().filter(|s| s.load_sharing.is_some()) {
        md!(out, "\nStage `{}`'s load sharing: {}.", s.name, s.load_sharing.as_deref().unwrap_or_default());
    }
    super::kind_pieces::inputs(out, &r.stages, Units::of_system(r.unit_system));
    super::point_tables::shafts(out, &r.shafts, Units::of_system(r.unit_system));
    super::shaft_bending::inputs(out, r);
    let Some(l) = &r.lubricant else {
        // (A drive without a lubricant: every analysis it asks for reads none.)
        return;
    };
    md!(out, "\n## Oil (one sump)\n");
    let units = Units::of_system(r.unit_system);
    // The oil temperature in words where the lubricant's table does not say it as it is (at
    // `equilibrium`: the balance of point 1).
    let said = |what: &String| what == "oil temperature" && l.temperature.is_some();
    let oil: Vec<_> = r.oil.iter().filter(|(what, _, _)| !said(what)).collect();
    if !oil.is_empty() {
        header(out, &["value", "", "unit"]);
        for (what, v, unit) in oil {
            let (v, unit) = input_shown(*v, unit, units);
            row(out, &[what.clone(), v, unit]);
        }
        md!(out);
    }
    // The lubricant as a pair's report gives it: what every mesh, film and loss reads.
    crate::render::markdown_losses::lubricant_table(out, l, units);
    md!(out);
}

/// An input row's value (4 decimals) and unit as the report shows it: as the report holds it in SI,
/// or converted to the inch–pound unit of its kind (a unit of no other kind stays as it is).
fn input_shown(value: f64, unit: &str, units: Units) -> (String, String) {
    let kind = match unit {
        _ if units.is_si() => None,
        "degC" => {
            let t = units.temperature();
            return (fixed(t.from_celsius(value), 4), t.unit.into());
        }
        "mPa*s" => Some((units.dynamic_viscosity(), 1e-3)),
        "mm^2/s" => Some((units.kinematic_viscosity(), 1e-6)),
        "kg/m^3" => Some((units.density(), 1.0)),
        "m^2" => Some((units.area(), 1.0)),
        "m/s" => Some((units.velocity(), 1.0)),
        "W/K" => Some((units.conductance(), 1.0)),
        _ => None,
    };
    match kind {
        Some((shown, to_si)) => (fixed(shown.value(value * to_si), 4), shown.unit.into()),
        None => (fixed(value, 4), unit.into()),
    }
}

fn thermal(out: &mut String, r: &DriveReport) {
    let Some(h) = &r.heat.housing else { return };
    let units = Units::of_system(r.unit_system);
    md!(out, "## Thermal balance (one sump)\n");
    md!(out, "The oil temperature θ* where the whole drive's loss P_V(θ) (every mesh, gear, bearing and seal, the oil read at θ) equals what the housing gives off, P_Q(θ): the lowest root above ambient, bracketed in 5 K steps and located by Brent's method to 1e-10 K. In drive, the thermal rating is the torque at the given end that puts θ* on the oil's limit at the point's speed; the second at 95 °C, ISO/TR 14179-1's rating temperature.\n");
    crate::render::markdown_thermal::housing_table(out, h, units);
    // Every record names its point (a drive's ends).
    crate::render::markdown_thermal::balance_table(out, &r.heat.thermal, units, &|_| String::new());
    md!(out);
    if r.heat.heat_balance.is_some() {
        image(out, PlotKind::HeatBalance, thermal::HEAT_BALANCE_TITLE);
    }
}

/// Each stage mesh's geometry, in the pair's tables.
fn stage_geometry(out: &mut String, r: &DriveReport) {
    if r.stage_geometry.is_empty() {
        return;
    }
    md!(out, "## Stage geometry\n");
    md!(out, "Each stage's mesh as a pair's report gives its own: the pair with its pinion in the pinion's place, H_V as the walk integrates it.\n");
    for s in &r.stage_geometry {
        let mesh = s.mesh.as_ref().map_or_else(String::new, |m| format!(", {m} mesh"));
        md!(out, "### Stage `{}`{mesh}\n", s.stage);
        let names = [s.gears[0].as_str(), s.gears[1].as_str()];
        let units = Units::of_system(r.unit_system);
        crate::render::markdown_geometry::geometry_tables(out, &s.geometry, units, names);
        if let Some(h) = &s.geometry.helical {
            crate::render::markdown_helical::plane_of_action(out, "#### Plane of action", h, &s.plot, units);
        }
        md!(out);
    }
}

fn image(out: &mut String, kind: PlotKind, title: &str) {
    md!(out, "![{title}]({})\n", kind.file());
}

/// The duty cycle as a pair's report gives it, and its plots.
fn duty(out: &mut String, r: &DriveReport) {
    let Some(d) = &r.heat.duty_cycle else { return };
    crate::render::markdown_thermal::duty_cycle_lines(out, "## Duty cycle", d, Units::of_system(r.unit_system));
    md!(out);
    if d.samples.is_some() {
        image(out, PlotKind::DutyCycleTemperature, thermal::DUTY_TEMPERATURE_TITLE);
    }
    image(out, PlotKind::DutyCycleEnergy, thermal::DUTY_ENERGY_TITLE);
}

fn model(out: &mut String, r: &DriveReport) {
    md!(out, "## How these numbers are found\n");
    md!(out, "- **Kinematics**: the input turns counter-clockwise about +z (a given output speed is a magnitude); an external mesh reverses the sense, ω_wheel = −ω_pinion z_pinion/z_wheel.");
    md!(out, "- **Power walk**: from the source (input in drive, output in coast) each shaft passes on what it receives less its own bearings, seals and the no-load parts of the stages whose pinion it carries; each stage passes on η_mesh times its driving gear's power, η_mesh = 1 − P_mesh/(T ω) of the law at the driving gear's torque, the driving gear in the pinion's role (the pair with roles swapped where the wheel drives). Given the sink's torque, the walk runs back from it.");
    md!(out, "- **Mesh forces**: F_t = T/r_w, F_r = F_t tan α_wt, F_a = T tan β/r of the driving gear, at the contact point on the line of centres; the axial force on a right-hand driving gear turning counter-clockwise points along +z, and flips with the hand, the sense and on the driven gear.");
    md!(out, "- **Statics**: each shaft a rigid beam on its two bearing places; five equations give the places' reactions (the axial force all at the locating place); a place's radial load per bearing is |(R_x, R_y)|/count.");
    if r.shafts.iter().any(|s| s.beam.is_some()) {
        md!(out, "- **Elastic shafts**: a shaft with sections is a beam (Euler–Bernoulli, or Timoshenko with Cowper's shear coefficient) bent in both transverse planes by its gears' forces and the couples of their axial forces, on rigid or sprung places; on two places its reactions are the rigid beam's statics, on more the beam's (the outer two from equilibrium); the bending moment comes from the loads and reactions, the largest σ_b = |M|/W at one-sided limits at every node; the mesh misalignment is b × the gears' relative tilt on the line of action (reported, not fed back).");
    }
    md!(out, "- **Fixed point**: the walk is repeated with the bearing loads of the previous pass until no driving torque moves by more than 1e-12 relative (the passes are reported).");
    for reading in &r.loss_readings {
        md!(out, "- **Loss parts**: {reading}.");
    }
}
