//! report.json's `stiffness` and `transmission_error`: the pair's stiffness from the teeth along
//! the path (positions s from A, for a helical pair of the mid-face section), the mesh stiffness
//! over one cycle, ISO 6336-1 Method B beside it, and per asked torque the static transmission error
//! over a cycle and one pair's load along its path. Series are `{values, unit}` in SI.

use serde::{Deserialize, Serialize};

use super::finding::{Finding, Severity};
use super::number::{Num, Q};
use crate::evaluate::teeth::TeethDetails;
use crate::geometry::teeth::iso_6336_method_b::{IsoStiffness, C_M};
use crate::geometry::teeth::transmission_error::series_positions;
use crate::mesh::MeshProblem;

/// A series of values in one SI unit.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Series {
    #[serde(with = "super::floats")]
    pub values: Vec<f64>,
    pub unit: String,
}

impl Series {
    fn new(values: impl IntoIterator<Item = f64>, unit: &str) -> Series {
        Series { values: values.into_iter().collect(), unit: unit.into() }
    }
}

/// A located value and where along the path.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Located {
    pub value: Q,
    pub position: Q,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct PairCurve {
    pub position: Series,
    pub stiffness: Series,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct IsoReport {
    /// c' and c_γα (N/m², 1 N/(mm·µm) = 1e9 N/m²).
    pub c_single: Q,
    pub c_gamma_alpha: Q,
    /// The readings: z_n of both gears, c′_th = 1/q′ (N/m²), C_B, E/E_st, and C_M, cos β, ε_α.
    pub virtual_teeth: [Num; 2],
    pub c_theoretical: Q,
    pub basic_rack_factor: Num,
    pub modulus_ratio: Num,
    pub c_m: Num,
    pub cos_helix: Num,
    pub contact_ratio: Num,
}

/// One gear's body as the method read it.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ToothBodyReport {
    pub gear: String,
    pub root_diameter: Q,
    /// The generating rack's dedendum h_fP = r − r_f + x m_n and tip radius ρ_fP that cut the fillet.
    pub rack_dedendum: Q,
    pub rack_tip_radius: Q,
    pub bore_diameter: Q,
    pub form_diameter: Q,
    /// Sainsot's h_f = r_f / r_int and θ_f (rad).
    pub foundation_ratio: Num,
    pub root_angle: Num,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tip_relief: Option<ReliefReport>,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ReliefReport {
    pub amount: Q,
    pub length: Q,
    pub shape: String,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct TeethStiffnessReport {
    pub model: String,
    pub bodies: Vec<ToothBodyReport>,
    /// One tooth pair over its engagement.
    pub pair: PairCurve,
    /// The mesh over one cycle.
    pub mesh: PairCurve,
    pub mean: Q,
    /// K̄ / b (N/m²).
    pub mean_per_width: Q,
    /// The largest single-pair stiffness per width, located.
    pub max_single_per_width: Located,
    pub iso_6336: IsoReport,
    /// Relative error estimate of k(s) (quadratures and series).
    pub relative_error: Num,
    /// Chebyshev degree of k_w(s) along the path.
    pub series_degree: usize,
    /// How a helical pair's contact lines are summed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub helical_lines: Option<String>,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct SteCurve {
    pub position: Series,
    pub ste: Series,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct LoadCurve {
    pub position: Series,
    pub load_share: Series,
    pub load: Series,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct TransmissionErrorReport {
    pub pinion_torque: Q,
    /// F_bn = T_p / r_b1 along the transverse line of action.
    pub normal_force: Q,
    pub mesh: SteCurve,
    pub pair: LoadCurve,
    pub peak_to_peak: Q,
    pub min: Located,
    pub max: Located,
    pub mean: Q,
    pub mean_error: Q,
}

impl From<&IsoStiffness> for IsoReport {
    fn from(iso: &IsoStiffness) -> Self {
        IsoReport {
            c_single: Q::new(iso.c_single * 1e9, "N/m^2"),
            c_gamma_alpha: Q::new(iso.c_gamma_alpha * 1e9, "N/m^2"),
            virtual_teeth: iso.virtual_teeth.map(Num),
            c_theoretical: Q::new(iso.c_theoretical * 1e9, "N/m^2"),
            basic_rack_factor: Num(iso.basic_rack_factor),
            modulus_ratio: Num(iso.modulus_ratio),
            c_m: Num(C_M),
            cos_helix: Num(iso.cos_helix),
            contact_ratio: Num(iso.contact_ratio),
        }
    }
}

fn located(value: f64, unit: &'static str, position: f64) -> Located {
    Located { value: Q::new(value, unit), position: Q::new(position, "m") }
}

/// The stiffness section.
pub(crate) fn stiffness_report(problem: &MeshProblem, t: &TeethDetails) -> TeethStiffnessReport {
    let k = &t.sharing.stiffness;
    let [lo, hi] = k.engagement();
    let pair_s = series_positions(lo, hi, &k.contact_ends());
    let s0 = k.position_at(0.0);
    let mesh_s = series_positions(s0, s0 + k.base_pitch, &k.contact_changes(s0));
    let gears = [&problem.gears.pinion, &problem.gears.wheel];
    let bodies = ["pinion", "wheel"]
        .iter()
        .enumerate()
        .map(|(i, name)| {
            let tooth = &k.teeth[i];
            let (h_f, theta_f) = tooth.foundation_parameters();
            ToothBodyReport {
                gear: name.to_string(),
                root_diameter: Q::new(2.0 * tooth.outline.input.root_radius, "m"),
                rack_dedendum: Q::new(tooth.outline.rack_dedendum, "m"),
                rack_tip_radius: Q::new(tooth.outline.tip_rounding, "m"),
                bore_diameter: Q::new(2.0 * tooth.bore_radius, "m"),
                form_diameter: Q::new(2.0 * tooth.outline.form_radius, "m"),
                foundation_ratio: Num(h_f),
                root_angle: Num(theta_f),
                tip_relief: gears[i].tip_relief.as_ref().map(|r| ReliefReport {
                    amount: Q::new(r.amount.value.value, "m"),
                    length: Q::new(r.length.value.value, "m"),
                    shape: r.shape.name().into(),
                }),
            }
        })
        .collect();
    TeethStiffnessReport {
        model: "potential_energy".into(),
        bodies,
        pair: PairCurve {
            position: Series::new(pair_s.iter().copied(), "m"),
            // At E the left limit (the pair is still in contact there).
            stiffness: Series::new(pair_s.iter().map(|s| k.pair_at(k.inside_end(*s))), "N/m"),
        },
        mesh: PairCurve {
            position: Series::new(mesh_s.iter().copied(), "m"),
            stiffness: Series::new(mesh_s.iter().map(|s| k.mesh_at(*s)), "N/m"),
        },
        mean: Q::new(k.mean(), "N/m"),
        mean_per_width: Q::new(k.mean() / k.face_width, "N/m^2"),
        max_single_per_width: located(t.max_single.0, "N/m^2", t.max_single.1),
        iso_6336: IsoReport::from(&t.iso),
        relative_error: Num(k.relative_error),
        series_degree: k.degree,
        helical_lines: k.is_helical().then(|| {
            "each contact line integrated exactly over its transverse sections (the slice method's limit: no slice count)".into()
        }),
    }
}

/// One report per asked torque.
pub(crate) fn transmission_error_reports(t: &TeethDetails) -> Vec<TransmissionErrorReport> {
    t.transmission_error
        .iter()
        .map(|te| TransmissionErrorReport {
            pinion_torque: Q::new(te.pinion_torque, "N*m"),
            normal_force: Q::new(te.force, "N"),
            mesh: SteCurve {
                position: Series::new(te.mesh.iter().map(|p| p.0), "m"),
                ste: Series::new(te.mesh.iter().map(|p| p.1), "m"),
            },
            pair: LoadCurve {
                position: Series::new(te.pair.iter().map(|p| p.0), "m"),
                load_share: Series::new(te.pair.iter().map(|p| p.1), "1"),
                load: Series::new(te.pair.iter().map(|p| p.2), "N"),
            },
            peak_to_peak: Q::new(te.peak_to_peak(), "m"),
            min: located(te.min.0, "m", te.min.1),
            max: located(te.max.0, "m", te.max.1),
            mean: Q::new(te.mean, "m"),
            mean_error: Q::new(te.mean_error, "m"),
        })
        .collect()
}

/// A relief above a tenth of the module; a body outside the range of Sainsot's fit; a dynamic
/// model that reads the unrelieved teeth.
pub(crate) fn teeth_findings(problem: &MeshProblem, s: &TeethStiffnessReport) -> Vec<Finding> {
    let mut out = Vec::new();
    let m_n = problem.gears.module.value.value;
    let micro = super::scene::units(problem).micro();
    for b in &s.bodies {
        if let Some(r) = &b.tip_relief {
            if r.amount.si() > 0.1 * m_n {
                out.push(Finding {
                    severity: Severity::Warning,
                    message: format!(
                        "the {} tip relief of {} is more than a tenth of the module ({}): no real relief reaches that",
                        b.gear,
                        micro.with(r.amount.si(), 1),
                        micro.with(0.1 * m_n, 1)
                    ),
                });
            }
        }
    }
    for b in &s.bodies {
        let (h_f, theta_f) = (b.foundation_ratio.0, b.root_angle.0);
        let coefficients = crate::geometry::teeth::compliance::sainsot_coefficients(h_f, theta_f);
        let outside: Vec<String> = ["L*", "M*", "P*", "Q*"]
            .iter()
            .zip(coefficients)
            .zip(crate::geometry::teeth::compliance::SAINSOT_RANGES)
            .filter(|((_, v), (lo, hi))| !(lo..=hi).contains(&v))
            .map(|((name, v), (lo, hi))| format!("{name} = {v:.4} (fitted {lo}–{hi})"))
            .collect();
        if !outside.is_empty() {
            out.push(Finding {
                severity: Severity::Warning,
                message: format!(
                    "the {} body lies outside the range of Sainsot's fillet-foundation fit: h_f = r_f/r_int = {:.4} and θ_f = {:.5} rad give {}; the foundation term is extrapolated (a bore closer to the root, h_f near 1, is the usual cause)",
                    b.gear,
                    h_f,
                    theta_f,
                    outside.join(", ")
                ),
            });
        }
    }
    let relieved = s.bodies.iter().any(|b| b.tip_relief.is_some());
    if relieved && problem.dynamics.as_ref().is_some_and(|d| d.stiffness.is_potential_energy()) {
        out.push(Finding {
            severity: Severity::Note,
            message: "the dynamic model reads the stiffness of the unmodified teeth: the tip relief changes the load sharing and the transmission error here, not the dynamics".into(),
        });
    }
    out
}
