//! Stage 4, report: the serde data every renderer reads. Nothing here formats text for a reader.

pub mod dynamics;
pub mod friction;
pub mod number;
pub mod plausibility;

use serde::Serialize;

use crate::evaluate::{Evaluation, PointEvaluation};
use crate::geometry::{ContactPoint, SpurGeometry, TipSource};
use crate::model::{Given, LoadSharing, ModuleSource, Scene};
use crate::scene::units::SiQuantity;
use number::{m, mps, pa, rad, Num, Q};

/// The report of one scene.
#[derive(Debug, Clone, Serialize)]
pub struct Report {
    pub title: String,
    /// Folder name: the title in lower case, words joined by `_`.
    pub slug: String,
    pub inputs: Vec<InputRow>,
    pub geometry: GeometryReport,
    pub operating_points: Vec<OperatingPointReport>,
    /// One record per (operating point, law, formulation); empty unless the scene asks for `efficiency`.
    pub efficiency: Vec<friction::EfficiencyRecord>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dynamics: Option<dynamics::DynamicsReport>,
    pub findings: Vec<Finding>,
    pub plots: Vec<PlotRef>,
    /// Sampled curves for the plots (not in report.json: they repeat the tables at finer spacing).
    #[serde(skip)]
    pub curves: Curves,
    /// The unit the scene wrote the pinion speed in, for tables and plot axes.
    #[serde(skip)]
    pub speed_unit: number::DisplayUnit,
}

/// One input of the scene, as written and in SI (a plain number when dimensionless).
#[derive(Debug, Clone, Serialize)]
pub struct InputRow {
    pub key: String,
    pub written: String,
    pub si: SiValue,
}

/// A dimensional value with its unit, or a plain number.
#[derive(Debug, Clone, Copy, Serialize)]
#[serde(untagged)]
pub enum SiValue {
    Plain(Num),
    Dimensional(Q),
}

impl SiValue {
    pub fn si(&self) -> f64 {
        match self {
            SiValue::Plain(n) => n.0,
            SiValue::Dimensional(q) => q.si(),
        }
    }
    pub fn unit(&self) -> &'static str {
        match self {
            SiValue::Plain(_) => "",
            SiValue::Dimensional(q) => q.unit,
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Severity {
    Note,
    Warning,
}

/// Something the reader must know: a source used, a limit reached, a value flagged.
#[derive(Debug, Clone, Serialize)]
pub struct Finding {
    pub severity: Severity,
    pub message: String,
}

#[derive(Debug, Clone, Serialize)]
pub struct PlotRef {
    pub file: String,
    pub title: String,
}

#[derive(Debug, Clone, Serialize)]
pub struct GearReport {
    pub teeth: u32,
    pub profile_shift: Num,
    pub pitch_diameter: Q,
    pub base_diameter: Q,
    pub tip_diameter: Q,
    pub tip_diameter_source: TipSource,
    pub working_pitch_diameter: Q,
    pub addendum_contact_ratio: Num,
    pub tip_thickness: Q,
    pub undercut_limit: Num,
}

/// Positions along the line of action, from T1.
#[derive(Debug, Clone, Serialize)]
#[allow(non_snake_case)]
pub struct PointsReport {
    pub A: Q,
    /// B = E − p_b and D = A + p_b, the limits of single contact: only for ε_α < 2.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub B: Option<Q>,
    pub P: Q,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub D: Option<Q>,
    pub E: Q,
    /// For ε_α ≥ 2: every point where the number of pairs changes (A + k p_b, E − k p_b), in order.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub pair_changes: Vec<NamedPoint>,
}

/// A named point of the line of action.
#[derive(Debug, Clone, Serialize)]
pub struct NamedPoint {
    pub name: &'static str,
    pub distance_from_t1: Q,
}

#[derive(Debug, Clone, Serialize)]
pub struct GeometryReport {
    pub module: Q,
    pub pressure_angle: Q,
    pub gear_ratio: Num,
    pub center_distance: Q,
    pub center_distance_source: &'static str,
    pub zero_backlash_center_distance: Q,
    pub operating_pressure_angle: Q,
    pub zero_backlash_pressure_angle: Q,
    pub face_width: Q,
    pub base_pitch: Q,
    pub line_of_action_length: Q,
    pub points_from_t1: PointsReport,
    pub contact_ratio: Num,
    /// Ohlendorf's gear loss factor H_V.
    pub ohlendorf_loss_factor: Num,
    pub reduced_modulus: Q,
    pub load_sharing: LoadSharing,
    pub pinion: GearReport,
    pub wheel: GearReport,
}

#[derive(Debug, Clone, Serialize)]
pub struct OperatingPointReport {
    pub pinion_torque: Q,
    pub pinion_speed: Q,
    /// The operating point as the user wrote its units, e.g. `239.3 N*m, 100 rpm`.
    pub label: String,
    pub wheel_speed: Q,
    pub normal_load: Q,
    pub mesh_period: Q,
    pub pitch_line_velocity: Q,
    pub contact: Vec<ContactRow>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub film: Option<Vec<friction::FilmRow>>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub friction: Vec<friction::LawReport>,
    /// The plot of μ, η and local power loss at this point, when drawn.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plot: Option<String>,
}

/// The contact state at one point of the line of action.
#[derive(Debug, Clone, Serialize)]
pub struct ContactRow {
    pub point: Option<&'static str>,
    pub distance_from_t1: Q,
    pub s: Q,
    pub radius_of_curvature_pinion: Q,
    pub radius_of_curvature_wheel: Q,
    pub reduced_radius: Q,
    pub velocity_pinion: Q,
    pub velocity_wheel: Q,
    pub sliding_velocity: Q,
    pub sum_velocity: Q,
    pub entrainment_velocity: Q,
    pub slide_to_roll: Num,
    pub pairs_in_contact: usize,
    pub load_share: Num,
    pub load_per_width: Q,
    pub hertz_pressure: Q,
    pub hertz_half_width: Q,
}

/// Curves along the line of action, for plots: x in m from T1.
#[derive(Debug, Clone, Default)]
pub struct Curves {
    pub u: Vec<f64>,
    /// (label, v_s in m/s) for each plotted speed.
    pub sliding_velocity: Vec<(String, Vec<f64>)>,
    pub slide_to_roll: Vec<f64>,
    /// (label, p_H in Pa) for each plotted torque.
    pub hertz_pressure: Vec<(String, Vec<f64>)>,
    /// A B P D E from T1 (m).
    pub marks: Vec<(&'static str, f64)>,
    /// Per plotted operating point: μ, local power loss along the line of action, η over a cycle.
    pub points: Vec<PointCurves>,
    /// η(τ) sample times (mesh periods).
    pub tau: Vec<f64>,
}

/// Curves of one operating point.
#[derive(Debug, Clone, Default)]
pub struct PointCurves {
    pub file: String,
    pub label: String,
    /// (law label, signed μ)
    pub mu: Vec<(String, Vec<f64>)>,
    /// Composite regime bands along the line of action: (from, to, regime) in m.
    pub regime_bands: Vec<(f64, f64, String)>,
    /// (law label, W)
    pub power_loss: Vec<(String, Vec<f64>)>,
    /// (law label · formulation, η)
    pub efficiency: Vec<(String, Vec<f64>)>,
}

pub use crate::evaluate::{pick, MAX_CURVES};

/// The folder name of a scene: lower case, ASCII letters and digits, words joined by `_`.
pub fn slug(title: &str) -> String {
    let mut out = String::new();
    for c in title.chars() {
        if c.is_ascii_alphanumeric() {
            out.push(c.to_ascii_lowercase());
        } else if !out.ends_with('_') && !out.is_empty() {
            out.push('_');
        }
    }
    let out = out.trim_end_matches('_').to_string();
    if out.is_empty() {
        "scene".into()
    } else {
        out
    }
}

fn input<T: SiQuantity>(rows: &mut Vec<InputRow>, key: &str, g: &Given<T>, unit: &'static str) {
    rows.push(InputRow {
        key: key.into(),
        written: g.written.clone(),
        si: SiValue::Dimensional(Q::new(g.value.si(), unit)),
    });
}

fn inputs(scene: &Scene) -> Vec<InputRow> {
    let mut rows = Vec::new();
    let g = &scene.gears;
    if let ModuleSource::DiametralPitch(p) = &g.module_source {
        input(&mut rows, "gears.diametral_pitch", p, "1/m");
    }
    input(&mut rows, "gears.module", &g.module, "m");
    input(&mut rows, "gears.pressure_angle", &g.pressure_angle, "rad");
    if let Some(a) = &g.center_distance {
        input(&mut rows, "gears.center_distance", a, "m");
    }
    input(&mut rows, "gears.face_width", &g.face_width, "m");
    for (name, gear) in [("pinion", &g.pinion), ("wheel", &g.wheel)] {
        rows.push(InputRow {
            key: format!("{name}.teeth"),
            written: gear.teeth.written.clone(),
            si: SiValue::Plain(Num(gear.teeth.value as f64)),
        });
        rows.push(InputRow {
            key: format!("{name}.profile_shift"),
            written: gear.profile_shift.written.clone(),
            si: SiValue::Plain(Num(gear.profile_shift.value)),
        });
        if let Some(d) = &gear.tip_diameter {
            input(&mut rows, &format!("{name}.tip_diameter"), d, "m");
        }
        if let Some(j) = &gear.inertia {
            input(&mut rows, &format!("{name}.inertia"), j, "kg*m^2");
        }
        for (key, r) in [
            ("roughness_ra", &gear.roughness_ra),
            ("roughness_rq", &gear.roughness_rq),
            ("roughness_rz", &gear.roughness_rz),
        ] {
            if let Some(r) = r {
                input(&mut rows, &format!("{name}.{key}"), r, "m");
            }
        }
        input(
            &mut rows,
            &format!("{name}.material ({}).youngs_modulus", gear.material.name),
            &gear.material.youngs_modulus,
            "Pa",
        );
        rows.push(InputRow {
            key: format!("{name}.material ({}).poisson_ratio", gear.material.name),
            written: gear.material.poisson_ratio.written.clone(),
            si: SiValue::Plain(Num(gear.material.poisson_ratio.value)),
        });
    }
    if let Some(l) = &scene.lubricant {
        input(&mut rows, "lubricant.dynamic_viscosity", &l.dynamic_viscosity, "Pa*s");
        if let Some(d) = &l.density {
            input(&mut rows, "lubricant.density", d, "kg/m^3");
        }
        if let Some(n) = &l.kinematic_viscosity {
            input(&mut rows, "lubricant.kinematic_viscosity", n, "m^2/s");
        }
        if let Some(a) = &l.pressure_viscosity {
            input(&mut rows, "lubricant.pressure_viscosity", a, "1/Pa");
        }
        if let Some(t) = &l.temperature {
            input(&mut rows, "lubricant.temperature", t, "K");
        }
    }
    rows
}

fn gear_report(g: &SpurGeometry, i: usize) -> GearReport {
    GearReport {
        teeth: g.teeth[i],
        profile_shift: Num(g.profile_shift[i]),
        pitch_diameter: m(2.0 * g.pitch_radius[i]),
        base_diameter: m(2.0 * g.base_radius[i]),
        tip_diameter: m(2.0 * g.tip_radius[i]),
        tip_diameter_source: g.tip_source[i],
        working_pitch_diameter: m(2.0 * g.working_pitch_radius[i]),
        addendum_contact_ratio: Num(g.addendum_contact_ratio[i]),
        tip_thickness: m(g.tip_thickness[i]),
        undercut_limit: Num(g.undercut_limit[i]),
    }
}

fn geometry_report(eval: &Evaluation) -> GeometryReport {
    let g = &eval.geometry;
    let p = &g.points;
    GeometryReport {
        module: m(g.module),
        pressure_angle: rad(g.pressure_angle),
        gear_ratio: Num(g.gear_ratio),
        center_distance: m(g.center_distance),
        center_distance_source: if g.center_distance_given { "given" } else { "zero_backlash" },
        zero_backlash_center_distance: m(g.zero_backlash_center_distance),
        operating_pressure_angle: rad(g.operating_pressure_angle),
        zero_backlash_pressure_angle: rad(g.zero_backlash_pressure_angle),
        face_width: m(g.face_width),
        base_pitch: m(g.base_pitch),
        line_of_action_length: m(g.line_of_action_length),
        points_from_t1: {
            let single = g.contact_ratio < 2.0;
            PointsReport {
                A: m(p.a),
                B: single.then(|| m(p.b)),
                P: m(p.p),
                D: single.then(|| m(p.d)),
                E: m(p.e),
                pair_changes: if single {
                    Vec::new()
                } else {
                    g.pair_change_points()
                        .into_iter()
                        .map(|(name, u)| NamedPoint { name, distance_from_t1: m(u) })
                        .collect()
                },
            }
        },
        contact_ratio: Num(g.contact_ratio),
        ohlendorf_loss_factor: Num(eval.ohlendorf_loss_factor),
        reduced_modulus: pa(eval.reduced_modulus),
        load_sharing: eval.sharing,
        pinion: gear_report(g, 0),
        wheel: gear_report(g, 1),
    }
}

fn contact_row(point: Option<&'static str>, c: &ContactPoint) -> ContactRow {
    ContactRow {
        point,
        distance_from_t1: m(c.u),
        s: m(c.s),
        radius_of_curvature_pinion: m(c.radius_of_curvature[0]),
        radius_of_curvature_wheel: m(c.radius_of_curvature[1]),
        reduced_radius: m(c.reduced_radius),
        velocity_pinion: mps(c.rolling_velocity[0]),
        velocity_wheel: mps(c.rolling_velocity[1]),
        sliding_velocity: mps(c.sliding_velocity),
        sum_velocity: mps(c.sum_velocity),
        entrainment_velocity: mps(c.entrainment_velocity),
        slide_to_roll: Num(c.slide_to_roll),
        pairs_in_contact: c.pairs_in_contact,
        load_share: Num(c.load_share),
        load_per_width: Q::new(c.load_per_width, "N/m"),
        hertz_pressure: pa(c.hertz_pressure),
        hertz_half_width: m(c.hertz_half_width),
    }
}

fn operating_point_report(scene: &Scene, eval: &Evaluation, pe: &PointEvaluation) -> OperatingPointReport {
    let g = &eval.geometry;
    let label = eval.cases[pe.case].label.clone();
    OperatingPointReport {
        pinion_torque: Q::new(pe.state.pinion_torque, "N*m"),
        pinion_speed: Q::new(pe.state.pinion_speed, "rad/s"),
        label,
        wheel_speed: Q::new(g.wheel_speed(&pe.state), "rad/s"),
        normal_load: Q::new(g.normal_load(&pe.state), "N"),
        mesh_period: Q::new(pe.mesh_period, "s"),
        pitch_line_velocity: mps(pe.state.pinion_speed * g.working_pitch_radius[0]),
        contact: pe.table.iter().map(|(n, c)| contact_row(*n, c)).collect(),
        film: friction::film_rows(pe),
        friction: scene.friction.iter().zip(&pe.laws).map(|(spec, law)| friction::law_report(spec, pe, law)).collect(),
        plot: None,
    }
}

pub fn formulation_name(f: crate::model::Formulation) -> &'static str {
    match f {
        crate::model::Formulation::External => "external",
        crate::model::Formulation::Internal => "internal",
    }
}

fn curves(scene: &Scene, eval: &Evaluation) -> Curves {
    let c = &eval.contact_curves;
    Curves {
        u: c.u.clone(),
        sliding_velocity: c.sliding_velocity.clone(),
        slide_to_roll: c.slide_to_roll.clone(),
        hertz_pressure: c.hertz_pressure.clone(),
        marks: eval.geometry.named_points(),
        points: point_curves(scene, eval),
        tau: crate::evaluate::cycle_times(),
    }
}

fn point_curves(scene: &Scene, eval: &Evaluation) -> Vec<PointCurves> {
    let mut out = Vec::new();
    for (k, pe) in eval.points.iter().enumerate() {
        if !pe.has_curves || pe.laws.is_empty() {
            continue;
        }
        let mut pc = PointCurves {
            file: format!("point_{}_friction.svg", k + 1),
            label: eval.cases[pe.case].label.clone(),
            ..Default::default()
        };
        for (spec, law) in scene.friction.iter().zip(&pe.laws) {
            let Some(c) = &law.curves else { continue };
            let label = friction::law_label(spec);
            pc.mu.push((label.clone(), c.mu.clone()));
            pc.power_loss.push((label.clone(), c.power_loss.clone()));
            for (f, eta) in &c.efficiency {
                pc.efficiency.push((format!("{label} {}", formulation_name(*f)), eta.clone()));
            }
            pc.regime_bands.extend(law.regime_bands.iter().map(|(a, b, r)| (*a, *b, format!("{r:?}"))));
        }
        out.push(pc);
    }
    out
}

fn findings(scene: &Scene, eval: &Evaluation) -> Vec<Finding> {
    let g = &eval.geometry;
    let mut out = Vec::new();
    let note = |m: String| Finding { severity: Severity::Note, message: m };
    let warn = |m: String| Finding { severity: Severity::Warning, message: m };
    for (i, name) in [(0, "pinion"), (1, "wheel")] {
        out.push(note(match g.tip_source[i] {
            TipSource::Given => format!("{name} tip diameter as given: {:.4} mm", 2e3 * g.tip_radius[i]),
            TipSource::AddendumRule => format!(
                "{name} tip diameter from the addendum rule d_a = m (z + 2 + 2x): {:.4} mm",
                2e3 * g.tip_radius[i]
            ),
        }));
        if g.tip_thickness[i] < 0.2 * g.module {
            out.push(warn(format!(
                "{name} tip thickness s_a = {:.4} mm is below 0.2 m = {:.4} mm: risk of a brittle tip",
                g.tip_thickness[i] * 1e3,
                0.2e3 * g.module
            )));
        }
        let start = g.involute_start_from_t1(i);
        let (contact_start, beyond) =
            if i == 0 { (g.points.a, g.points.a < start) } else { (g.points.e, g.points.e > start) };
        if beyond {
            out.push(warn(format!(
                "contact at {:.4} mm from T1 lies below the {name}'s generated involute, which starts at {:.4} mm (root interference with a rack-cut flank)",
                contact_start * 1e3,
                start * 1e3
            )));
        }
    }
    if g.center_distance_given {
        out.push(note(format!(
            "operating pressure angle from the given centre distance {:.4} mm; the zero-backlash centre distance is {:.4} mm (α_w = {:.4}°)",
            g.center_distance * 1e3,
            g.zero_backlash_center_distance * 1e3,
            g.zero_backlash_pressure_angle.to_degrees()
        )));
    } else {
        out.push(note(format!(
            "centre distance from the involute function (zero backlash): {:.4} mm",
            g.center_distance * 1e3
        )));
    }
    out.push(note(match scene.gears.load_sharing {
        LoadSharing::Equal => "load sharing: equal (1/n of the normal load on each of n pairs in contact)".into(),
        LoadSharing::None => "load sharing: none (every contact carries the whole normal load)".into(),
    }));
    out
}

/// Builds the report of an evaluated scene.
pub fn build_report(scene: &Scene, eval: &Evaluation) -> Report {
    let mut findings = findings(scene, eval);
    findings.extend(friction::law_findings(scene, eval));
    findings.extend(plausibility::plausibility_findings(eval));
    let mut report = Report {
        title: scene.title.clone(),
        slug: slug(&scene.title),
        inputs: inputs(scene),
        geometry: geometry_report(eval),
        operating_points: eval.points.iter().map(|p| operating_point_report(scene, eval, p)).collect(),
        efficiency: friction::efficiency_records(scene, eval),
        dynamics: eval.dynamics.as_ref().map(|d| dynamics::dynamics_report(scene, eval, d)),
        findings,
        plots: vec![PlotRef {
            file: "contact_state.svg".into(),
            title: "Sliding velocity, slide-to-roll ratio and Hertzian pressure along the line of action".into(),
        }],
        curves: curves(scene, eval),
        speed_unit: number::DisplayUnit::of(&scene.operating.pinion_speed),
    };
    if let Some(d) = &report.dynamics {
        report.findings.extend(dynamics::dynamics_findings(d));
        if d.stability_map.is_some() {
            report.plots.push(PlotRef {
                file: "stability_map.svg".into(),
                title: "Floquet spectral radius and dynamic factor against pinion speed".into(),
            });
        }
        if d.numerics.is_some() {
            report.plots.push(PlotRef {
                file: "timing_work_precision.svg".into(),
                title: "Work-precision: error against run time (machine-dependent)".into(),
            });
        }
    }
    for pc in &report.curves.points {
        if let Some(op) = report.operating_points.iter_mut().find(|o| o.label == pc.label) {
            op.plot = Some(pc.file.clone());
        }
    }
    let sweeps = &scene.operating;
    if !report.efficiency.is_empty() {
        if sweeps.pinion_speed.values.len() > 1 {
            report.plots.push(PlotRef {
                file: "sweep_speed.svg".into(),
                title: "Mean efficiency and power loss against pinion speed".into(),
            });
        }
        if !friction::mu_swept_laws(&report.efficiency).is_empty() {
            report.plots.push(PlotRef {
                file: "sweep_mu.svg".into(),
                title: "Mean efficiency and power loss against the coefficient of friction".into(),
            });
        }
        if sweeps.pinion_torque.values.len() > 1 {
            report.plots.push(PlotRef {
                file: "sweep_torque.svg".into(),
                title: "Mean efficiency and power loss against pinion torque".into(),
            });
        }
    }
    if sweeps.pinion_speed.values.len() > 1
        && scene.friction.iter().any(|l| l.law == crate::friction::catalog::LawId::Composite)
        && !eval.points[0].laws.is_empty()
    {
        report.plots.push(PlotRef {
            file: "composite_mu_vs_speed.svg".into(),
            title: "Composite law: mean |μ| against pinion speed (He–Cho–Singh Fig. 2b)".into(),
        });
    }
    for path in non_finite_paths(&report) {
        report.findings.push(Finding { severity: Severity::Warning, message: format!("not a finite number: {path}") });
    }
    report
}

/// Paths of every value in the report that is not a finite number (serialised as `null`).
pub fn non_finite_paths(report: &Report) -> Vec<String> {
    fn walk(v: &serde_json::Value, path: String, out: &mut Vec<String>) {
        match v {
            serde_json::Value::Object(map) => {
                for (k, x) in map {
                    // `point` is an optional label, not a number.
                    if k == "point" {
                        continue;
                    }
                    walk(x, format!("{path}.{k}"), out);
                }
            }
            serde_json::Value::Array(items) => {
                for (i, x) in items.iter().enumerate() {
                    walk(x, format!("{path}[{i}]"), out);
                }
            }
            serde_json::Value::Null => out.push(path),
            _ => {}
        }
    }
    let mut out = Vec::new();
    if let Ok(v) = serde_json::to_value(report) {
        walk(&v, String::new(), &mut out);
    }
    out
}
