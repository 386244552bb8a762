//! The scene at its first operating point's thermal balance (`oil_temperature = equilibrium`).

use crate::model::Scene;

/// At `oil_temperature = equilibrium`: the scene with its lubricant at the balance of its first
/// operating point (first law, first formulation), where its tables, curves, film and dynamics are
/// read; the scene itself otherwise, or when that point finds no balance. A scene of one pair finds
/// it as its one-stage drive does (`super::drive_thermal::at_first_balance`: the drive's walk at
/// the first point with the oil moved to θ).
pub(crate) fn at_first_balance(scene: &Scene) -> std::borrow::Cow<'_, Scene> {
    match &scene.drive {
        Some(drive) => super::drive_thermal::at_first_balance(scene, drive),
        None => std::borrow::Cow::Borrowed(scene),
    }
}
