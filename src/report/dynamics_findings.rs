//! Warnings and notes about the dynamics results: instability, tooth separation, dynamic efficiency
//! above one, a dynamic factor that only reflects a stiffness step, unstable ranges of the map.

use super::dynamics::DynamicsReport;
use super::finding::{Finding, Severity};
use crate::dynamics::floquet::Verdict;

/// Findings of the dynamics: instability, tooth separation, stiff ratios, Liouville.
pub(crate) fn dynamics_findings(r: &DynamicsReport) -> Vec<Finding> {
    let mut out = Vec::new();
    let warn = |m: String| Finding { severity: Severity::Warning, message: m };
    // (point label, formulation, K_v, f_n/f_mesh) where K_v is the stiffness step: one note for all.
    let mut step: Vec<(String, String, f64, f64)> = Vec::new();
    for p in &r.points {
        for f in &p.formulations {
            let name = f.formulation.name().to_string();
            if f.verdict == Verdict::Unstable {
                out.push(warn(format!(
                    "dynamics at {} ({name}): parametrically unstable, spectral radius {:.6}; no steady state exists in the linear model and none is reported",
                    p.label, f.spectral_radius.0
                )));
            }
            if !f.tooth_separation.is_empty() {
                let spans: Vec<String> =
                    f.tooth_separation.iter().map(|[a, b]| format!("τ = {:.4}–{:.4}", a.0, b.0)).collect();
                out.push(warn(format!(
                    "dynamics at {} ({name}): the dynamic mesh force turns negative (tooth separation) at {}; the linear model is not valid there",
                    p.label,
                    spans.join(", ")
                )));
            }
            if let (Some(eta), false) = (&f.max_dynamic_efficiency, f.tooth_separation.is_empty()) {
                if eta.0 > 1.0 {
                    out.push(warn(format!(
                        "dynamics at {} ({name}): the instantaneous efficiency from the tooth force reaches {:.6} > 1 where the teeth separate (F < 0 makes the friction power negative); the mean dynamic efficiency there is not physical",
                        p.label, eta.0
                    )));
                }
            }
            let step_kv = r.stiffness_step_ratio.filter(|_| p.frequency_ratio.0 > 10.0);
            if let (Some(ratio), Some(kv)) = (step_kv, &f.dynamic_factor) {
                if (kv.0 - ratio).abs() < 0.05 * ratio {
                    step.push((p.label.clone(), name.clone(), kv.0, p.frequency_ratio.0));
                }
            }
            let rel = ((f.monodromy_determinant.0 - f.liouville_determinant.0) / f.liouville_determinant.0).abs();
            if rel > 1e-8 {
                out.push(warn(format!(
                    "dynamics at {} ({name}): det Φ(T) = {:e} differs from Liouville's {:e} by {rel:.1e}",
                    p.label, f.monodromy_determinant.0, f.liouville_determinant.0
                )));
            }
        }
    }
    out.extend(stiffness_step_note(r, &step));
    out.extend(unstable_map_ranges(r));
    out
}

/// One note for every point whose K_v is the stiffness step k_double/k_single (quasi-static):
/// (point label, formulation, K_v, f_n/f_mesh) in `step`.
fn stiffness_step_note(r: &DynamicsReport, step: &[(String, String, f64, f64)]) -> Option<Finding> {
    let ratio = r.stiffness_step_ratio.filter(|_| !step.is_empty())?;
    let mut at: Vec<String> = Vec::new();
    for (label, name, kv, _) in step {
        let entry = format!("{name} {kv:.4}");
        match at.iter_mut().find(|a| a.starts_with(&format!("{label} ("))) {
            Some(a) => {
                a.pop();
                a.push_str(&format!(", {entry})"));
            }
            None => at.push(format!("{label} ({entry})")),
        }
    }
    let lowest = step.iter().map(|s| s.3).fold(f64::INFINITY, f64::min);
    Some(Finding {
        severity: Severity::Note,
        message: format!(
            "dynamics: K_v ≈ k_double/k_single = {ratio:.4} at {}: it comes from the stiffness step, not from dynamics: x is continuous where a pair enters, so F = k_double x jumps there (f_n/f_mesh ≥ {lowest:.1}, quasi-static). A stiffness table with ramps (`mesh_stiffness {{ table = [...] }}` or a CSV file) gives the dynamic factor of a real mesh",
            at.join("; ")
        ),
    })
}

/// A warning per formulation with unstable speed ranges in the stability map.
fn unstable_map_ranges(r: &DynamicsReport) -> Vec<Finding> {
    let mut out = Vec::new();
    let warn = |m: String| Finding { severity: Severity::Warning, message: m };
    if let Some(map) = &r.stability_map {
        for (i, ranges) in map.unstable_ranges.iter().enumerate() {
            if !ranges.is_empty() {
                let list: Vec<String> = ranges
                    .iter()
                    .map(|[a, b]| {
                        let u = &map.speed_unit;
                        format!("{:.0}–{:.0} {}", u.value(a), u.value(b), u.name)
                    })
                    .collect();
                out.push(warn(format!(
                    "stability map ({:?}): unstable (ρ > 1) at {}",
                    map.formulations[i],
                    list.join(", ")
                )));
            }
        }
    }
    out
}
