//! Findings for results that are impossible or outside the formulas' assumptions: an efficiency
//! outside [0, 1], a power loss above the input power, a Hertz half-width comparable to the radius of
//! curvature (b_H > R/10, where the line-contact formulas no longer hold). Each comes with the number
//! and where it occurs, next to the result in the report.

use super::{Finding, Severity};
use crate::evaluate::Evaluation;

/// b_H / R above which the half-space (line-contact) assumption of Hertz's formulas fails.
pub const HALF_WIDTH_LIMIT: f64 = 0.1;

pub fn plausibility_findings(eval: &Evaluation) -> Vec<Finding> {
    let mut out = Vec::new();
    let warn = |m: String| Finding { severity: Severity::Warning, message: m };
    for (k, pe) in eval.points.iter().enumerate() {
        let label = &eval.cases[pe.case].label;
        if let Some((name, c)) =
            pe.table.iter().filter(|(_, c)| c.hertz_half_width > HALF_WIDTH_LIMIT * c.reduced_radius).max_by(|a, b| {
                (a.1.hertz_half_width / a.1.reduced_radius).total_cmp(&(b.1.hertz_half_width / b.1.reduced_radius))
            })
        {
            out.push(warn(format!(
                "operating point {} ({label}): Hertz half-width b_H = {:.4} mm exceeds R/10 = {:.4} mm at {} mm from T1{}: the line-contact formulas (pressure, film, every law that reads them) no longer hold",
                k + 1,
                c.hertz_half_width * 1e3,
                HALF_WIDTH_LIMIT * c.reduced_radius * 1e3,
                format_args!("{:.3}", c.u * 1e3),
                name.map_or(String::new(), |n| format!(" (point {n})"))
            )));
        }
        let input = pe.state.pinion_torque * pe.state.pinion_speed;
        for law in &pe.laws {
            for e in &law.efficiency {
                let f = super::formulation_name(e.formulation);
                let bad = |x: f64| !(0.0..=1.0).contains(&x);
                if bad(e.mean.value) || bad(e.min) || bad(e.max) {
                    out.push(warn(format!(
                        "operating point {} ({label}), {} ({f}): efficiency outside [0, 1] (η̄ = {:.6}, η from {:.6} to {:.6}): the law gives friction no gear mesh can have here",
                        k + 1,
                        law.id.name(),
                        e.mean.value,
                        e.min,
                        e.max
                    )));
                }
                if e.power_loss > input {
                    out.push(warn(format!(
                        "operating point {} ({label}), {} ({f}): power loss {:.3} W above the input power {:.3} W",
                        k + 1,
                        law.id.name(),
                        e.power_loss,
                        input
                    )));
                }
            }
        }
    }
    out
}
