//! Lowering of a pair's tooth system in the `gears` block: module (or diametral pitch), pressure
//! angle and helix angle, given as normal values (ISO 21771, AGMA) or with the `transverse_*` keys
//! (m_n = m_t cos β, tan α_n = tan α_t cos β), and the hand of the helix.

use uom::si::length::meter;

use super::fields::positive;
use super::fields::Fields;
use crate::diagnostics::{Diagnostic, DiagnosticKind};
use crate::model::*;

/// The keys that give the module, one of which is needed.
const MODULE_KEYS: [&str; 4] = ["module", "diametral_pitch", "transverse_module", "transverse_diametral_pitch"];

/// The lowered tooth system; None where a value had an error (already reported).
pub(super) struct ToothSystem {
    pub helix_angle: Option<Given<Angle>>,
    pub hand: Option<String>,
    /// The normal module.
    pub module: Option<Given<Length>>,
    pub module_source: ModuleSource,
    /// The normal pressure angle.
    pub pressure_angle: Option<Given<Angle>>,
    pub transverse_pressure_angle: Option<Given<Angle>>,
}

pub(super) fn lower_tooth_system(f: &Fields, errors: &mut Vec<Diagnostic>) -> ToothSystem {
    let helix_angle = lower_helix_angle(f, errors);
    let hand = f.name("hand", &["left", "right"], errors).map(|n| n.text.clone());
    let cos_beta = helix_angle.as_ref().map_or(1.0, |b| b.value.value.cos());
    let beta_written = helix_angle.as_ref().map_or(String::new(), |b| b.written.clone());
    let (module, module_source) = lower_module(f, cos_beta, &beta_written, errors);
    if helix_angle.is_none() {
        for key in ["transverse_module", "transverse_diametral_pitch", "transverse_pressure_angle"] {
            if let Some((k, _)) = f.values.get(key) {
                errors.push(
                    Diagnostic::new(DiagnosticKind::MissingKey, k.span, format!("`{key}` needs a `helix_angle`"))
                        .hint("transverse values belong to a helical pair: add `helix_angle = 15 deg`, or give the normal value (for a spur pair they are the same)"),
                );
            }
        }
    }
    let (pressure_angle, transverse_pressure_angle) = lower_pressure_angle(f, cos_beta, &beta_written, errors);
    ToothSystem { helix_angle, hand, module, module_source, pressure_angle, transverse_pressure_angle }
}

/// `helix_angle`, within 0° to 45°.
fn lower_helix_angle(f: &Fields, errors: &mut Vec<Diagnostic>) -> Option<Given<Angle>> {
    let helix_angle: Option<Given<Angle>> = f.optional("helix_angle", errors);
    helix_angle.and_then(|b| {
        let deg = b.value.value.to_degrees();
        if (0.0..=45.0).contains(&deg) {
            Some(b)
        } else {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    b.span,
                    format!("helix angle {deg:.4}° is outside 0° to 45°"),
                )
                .hint(if deg < 0.0 {
                    "give the helix angle as a positive value and the hand as `hand = left` or `hand = right`"
                } else {
                    "industrial helical gears use 8° to 30°; above 45° the axial force exceeds the tangential force"
                }),
            );
            None
        }
    })
}

/// The normal module from exactly one of `module`, `diametral_pitch` (normal values),
/// `transverse_module` or `transverse_diametral_pitch` (m_n = m_t cos β, m_n = cos β / P_dt), with
/// how it was given.
fn lower_module(
    f: &Fields,
    cos_beta: f64,
    beta_written: &str,
    errors: &mut Vec<Diagnostic>,
) -> (Option<Given<Length>>, ModuleSource) {
    let given: Vec<&str> = MODULE_KEYS.iter().copied().filter(|k| f.has(k)).collect();
    match given.as_slice() {
        [] => (positive(f.required("module", "4.5 mm", errors), "module", errors), ModuleSource::Module),
        [_, second, ..] => {
            let (key, _) = f.values[*second];
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::DuplicateKey,
                    key.span,
                    format!("the module is given twice: `{}` and `{second}`", given[0]),
                )
                .hint("give one of `module`, `diametral_pitch` (normal values) or `transverse_module`, `transverse_diametral_pitch`"),
            );
            (None, ModuleSource::Module)
        }
        ["module"] => (positive(f.optional("module", errors), "module", errors), ModuleSource::Module),
        ["transverse_module"] => {
            let m: Option<Given<Length>> =
                positive(f.optional("transverse_module", errors), "transverse_module", errors);
            match m {
                Some(m) => (
                    Some(Given {
                        value: Length::new::<meter>(m.value.get::<meter>() * cos_beta),
                        written: format!("({}) · cos({beta_written})", m.written),
                        span: m.span,
                    }),
                    ModuleSource::TransverseModule(m),
                ),
                None => (None, ModuleSource::Module),
            }
        }
        [key] => {
            let transverse = *key == "transverse_diametral_pitch";
            let p: Option<Given<ReciprocalLength>> = positive(f.optional(key, errors), key, errors);
            match p {
                Some(p) => {
                    let factor = if transverse { cos_beta } else { 1.0 };
                    let m = Given {
                        value: Length::new::<meter>(factor / p.value.value),
                        written: if transverse {
                            format!("cos({beta_written})/({})", p.written)
                        } else {
                            format!("1/({})", p.written)
                        },
                        span: p.span,
                    };
                    let source = if transverse {
                        ModuleSource::TransverseDiametralPitch(p)
                    } else {
                        ModuleSource::DiametralPitch(p)
                    };
                    (Some(m), source)
                }
                None => (None, ModuleSource::Module),
            }
        }
    }
}

/// The normal pressure angle, from `pressure_angle` or `transverse_pressure_angle`
/// (tan α_n = tan α_t cos β), within 10° to 35°; and the transverse one when that was given.
fn lower_pressure_angle(
    f: &Fields,
    cos_beta: f64,
    beta_written: &str,
    errors: &mut Vec<Diagnostic>,
) -> (Option<Given<Angle>>, Option<Given<Angle>>) {
    let (pressure_angle, transverse_pressure_angle) =
        match (f.has("pressure_angle"), f.has("transverse_pressure_angle")) {
            (true, true) => {
                let (key, _) = f.values["transverse_pressure_angle"];
                errors.push(
                    Diagnostic::new(
                        DiagnosticKind::DuplicateKey,
                        key.span,
                        "both `pressure_angle` and `transverse_pressure_angle` are given",
                    )
                    .hint("give one of them: tan α_n = tan α_t cos β"),
                );
                (None, None)
            }
            (false, true) => {
                let t: Option<Given<Angle>> = f.optional("transverse_pressure_angle", errors);
                let normal = t.as_ref().map(|t| Given {
                    value: Angle::new::<uom::si::angle::radian>((t.value.value.tan() * cos_beta).atan()),
                    written: format!("atan(tan({}) · cos({beta_written}))", t.written),
                    span: t.span,
                });
                (normal, t)
            }
            _ => (f.required("pressure_angle", "20 deg", errors), None),
        };
    let pressure_angle = pressure_angle.and_then(|a| {
        let deg = a.value.value.to_degrees();
        if (10.0..=35.0).contains(&deg) {
            Some(a)
        } else {
            errors.push(
                Diagnostic::new(
                    DiagnosticKind::OutOfRange,
                    a.span,
                    format!("pressure angle {deg:.4}° is outside 10° to 35°"),
                )
                .hint("standard pressure angles are 14.5°, 20° and 25°"),
            );
            None
        }
    });
    (pressure_angle, transverse_pressure_angle)
}
