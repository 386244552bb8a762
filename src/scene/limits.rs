//! Plausible ranges of the scene's quantities, in one table: a value outside its range is an error
//! with the value, the range and the key's position, before any work is done. The ranges are wide
//! (from watch gears to mill drives) and exist so that a typo in a unit or an exponent gives a clear
//! message instead of a run that overflows, loops in a plot or reports a mesh period of "0.0 s".

use crate::diagnostics::{Diagnostic, DiagnosticKind, Span};

/// A key's plausible range in SI, and how the range reads in the message.
pub(crate) struct Limit {
    pub key: &'static str,
    /// The SI unit of the value in the message (empty for a plain number).
    pub si_unit: &'static str,
    pub lo: f64,
    pub hi: f64,
    pub shown: &'static str,
}

const fn limit(key: &'static str, si_unit: &'static str, lo: f64, hi: f64, shown: &'static str) -> Limit {
    Limit { key, si_unit, lo, hi, shown }
}

/// Every quantity with a plausible range (keys as the scene writes them).
pub(crate) const LIMITS: &[Limit] = &[
    limit("module", "m", 1e-5, 0.2, "0.01 mm to 200 mm"),
    limit("diametral_pitch", "1/m", 5.0, 1e5, "0.127 to 2540 1/in"),
    limit("face_width", "m", 1e-4, 5.0, "0.1 mm to 5 m"),
    limit("center_distance", "m", 1e-3, 20.0, "1 mm to 20 m"),
    limit("tip_diameter", "m", 1e-4, 40.0, "0.1 mm to 40 m"),
    limit("pinion_torque", "N*m", 1e-6, 1e8, "1e-6 N·m to 1e8 N·m"),
    limit("pinion_speed", "rad/s", 1e-4, 1.05e5, "0.001 rpm to 1 000 000 rpm"),
    // A drive's output speed is a magnitude (its sense follows from the chain), so it is positive
    // as a pinion's speed is: a bare `-80` is said to be negative before its missing unit.
    limit("output_speed", "rad/s", 1e-4, 1.05e5, "0.001 rpm to 1 000 000 rpm"),
    limit("youngs_modulus", "Pa", 1e8, 2e12, "0.1 GPa to 2000 GPa"),
    limit("inertia", "kg*m^2", 1e-12, 1e6, "1e-12 to 1e6 kg·m²"),
    limit("mass", "kg", 1e-6, 1e6, "1 mg to 1000 t"),
    limit("loa", "N/m", 1e4, 1e15, "1e4 to 1e15 N/m"),
    limit("oloa", "N/m", 1e4, 1e15, "1e4 to 1e15 N/m"),
    limit("per_length", "N/m^2", 1e6, 1e13, "1e6 to 1e13 N/m² (0.001 to 10 000 N/(mm·µm))"),
    limit("dynamic_viscosity", "Pa*s", 1e-5, 100.0, "0.01 mPa·s to 100 Pa·s"),
    limit("kinematic_viscosity", "m^2/s", 1e-8, 0.1, "0.01 cSt to 1e5 cSt"),
    limit("density", "kg/m^3", 100.0, 3e4, "100 to 30 000 kg/m³"),
    limit("pressure_viscosity", "1/Pa", 1e-10, 1e-6, "1e-10 to 1e-6 1/Pa"),
    limit("temperature", "K", 173.15, 673.15, "-100 °C to 400 °C"),
    limit("oil_temperature", "K", 233.15, 473.15, "-40 °C to 200 °C"),
    limit("nu_40", "m^2/s", 1e-6, 0.1, "1 cSt to 1e5 cSt"),
    limit("nu_100", "m^2/s", 1e-6, 0.1, "1 cSt to 1e5 cSt"),
    limit("density_15", "kg/m^3", 500.0, 2500.0, "500 to 2500 kg/m³"),
    limit("roughness_ra", "m", 0.0, 1e-3, "0 to 1 mm"),
    limit("roughness_rq", "m", 0.0, 1e-3, "0 to 1 mm"),
    limit("roughness_rz", "m", 0.0, 1e-2, "0 to 10 mm"),
    limit("single", "N/m", 1e4, 1e12, "1e4 to 1e12 N/m"),
    limit("double", "N/m", 1e4, 1e12, "1e4 to 1e12 N/m"),
    limit("triple", "N/m", 1e4, 1e12, "1e4 to 1e12 N/m"),
    limit("table", "N/m", 1e4, 1e12, "1e4 to 1e12 N/m"),
    limit("amplitudes", "m", 0.0, 1e-2, "0 to 10 mm"),
    // Friction-law arguments (a lubricated gear contact has μ below about 0.15, dry steel about 0.8).
    limit("mu", "", 0.0, 1.0, "0 to 1"),
    limit("mu_boundary", "", 0.0, 1.0, "0 to 1"),
    limit("mu_ehl", "", 0.0, 1.0, "0 to 1"),
    limit("phi", "1/m", 1.0, 1e9, "1 to 1e9 1/m"),
    limit("x_l", "", 0.1, 3.0, "0.1 to 3"),
    limit("filter_cutoff", "m", 1e-6, 1.0, "1 µm to 1 m"),
];

/// A value in SI for the message: plain for moderate magnitudes, in exponent form otherwise.
fn shown(x: f64, unit: &str) -> String {
    let number = if (1e-3..1e6).contains(&x.abs()) || x == 0.0 { format!("{x}") } else { format!("{x:e}") };
    format!("{number} {unit}").trim_end().to_string()
}

/// Checks an SI value of `key` against its plausible range; false (with a diagnostic) outside it.
/// Whether `key` is a quantity that is never negative (its plausible range starts above zero).
pub(crate) fn positive(key: &str) -> bool {
    LIMITS.iter().find(|l| l.key == key).is_some_and(|l| l.lo > 0.0)
}

pub(crate) fn plausible(key: &str, si: f64, span: Span, errors: &mut Vec<Diagnostic>) -> bool {
    let Some(l) = LIMITS.iter().find(|l| l.key == key) else { return true };
    // Zero and negative values of positive quantities get the sign checks' own messages.
    if (l.lo..=l.hi).contains(&si) || (si <= 0.0 && l.lo > 0.0) {
        return true;
    }
    errors.push(
        Diagnostic::new(
            DiagnosticKind::OutOfRange,
            span,
            format!("`{key}` = {} is outside its plausible range, {}", shown(si, l.si_unit), l.shown),
        )
        .hint("check the number, its exponent and its unit (`gearloss units` lists the units)"),
    );
    false
}
