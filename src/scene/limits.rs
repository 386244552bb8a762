//! Plausible ranges of the scene's quantities, in one table: a value outside its range is an error
//! with the value, the range and the key's position, before any work is done. The ranges are wide
//! (from watch gears to mill drives) and exist so that a typo in a unit or an exponent gives a clear
//! message instead of a run that overflows, loops in a plot or reports a mesh period of "0.0 s".

use crate::diagnostics::{Diagnostic, DiagnosticKind, Span};

/// A key's plausible range in SI, and how the range reads in the message.
pub struct Limit {
    pub key: &'static str,
    pub lo: f64,
    pub hi: f64,
    pub shown: &'static str,
}

const fn limit(key: &'static str, lo: f64, hi: f64, shown: &'static str) -> Limit {
    Limit { key, lo, hi, shown }
}

/// Every quantity with a plausible range (keys as the scene writes them).
pub const LIMITS: &[Limit] = &[
    limit("module", 1e-5, 0.2, "0.01 mm to 200 mm"),
    limit("diametral_pitch", 5.0, 1e5, "0.127 to 2540 1/in"),
    limit("face_width", 1e-4, 5.0, "0.1 mm to 5 m"),
    limit("center_distance", 1e-3, 20.0, "1 mm to 20 m"),
    limit("tip_diameter", 1e-4, 40.0, "0.1 mm to 40 m"),
    limit("pinion_torque", 1e-6, 1e8, "1e-6 N·m to 1e8 N·m"),
    limit("pinion_speed", 1e-4, 1.05e5, "0.001 rpm to 1 000 000 rpm"),
    limit("youngs_modulus", 1e8, 2e12, "0.1 GPa to 2000 GPa"),
    limit("inertia", 1e-12, 1e6, "1e-12 to 1e6 kg·m²"),
    limit("dynamic_viscosity", 1e-5, 1e4, "0.01 mPa·s to 1e4 Pa·s"),
    limit("kinematic_viscosity", 1e-8, 1.0, "0.01 cSt to 1e6 cSt"),
    limit("density", 100.0, 3e4, "100 to 30 000 kg/m³"),
    limit("pressure_viscosity", 1e-10, 1e-6, "1e-10 to 1e-6 1/Pa"),
    limit("temperature", 173.15, 673.15, "-100 °C to 400 °C"),
    limit("roughness_ra", 0.0, 1e-3, "0 to 1 mm"),
    limit("roughness_rq", 0.0, 1e-3, "0 to 1 mm"),
    limit("roughness_rz", 0.0, 1e-2, "0 to 10 mm"),
    limit("single", 1e4, 1e12, "1e4 to 1e12 N/m"),
    limit("double", 1e4, 1e12, "1e4 to 1e12 N/m"),
    limit("triple", 1e4, 1e12, "1e4 to 1e12 N/m"),
    limit("table", 1e4, 1e12, "1e4 to 1e12 N/m"),
    limit("amplitudes", 0.0, 1e-2, "0 to 10 mm"),
];

/// Checks an SI value of `key` against its plausible range; false (with a diagnostic) outside it.
pub fn plausible(key: &str, si: f64, span: Span, errors: &mut Vec<Diagnostic>) -> bool {
    let Some(l) = LIMITS.iter().find(|l| l.key == key) else { return true };
    // Zero and negative values of positive quantities get the sign checks' own messages.
    if (l.lo..=l.hi).contains(&si) || (si <= 0.0 && l.lo > 0.0) {
        return true;
    }
    errors.push(
        Diagnostic::new(
            DiagnosticKind::OutOfRange,
            span,
            format!("`{key}` = {si:e} (SI) is outside its plausible range, {}", l.shown),
        )
        .hint("check the number, its exponent and its unit (`gearloss units` lists the units)"),
    );
    false
}
