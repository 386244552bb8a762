//! One gear of a REXS model (`cylindrical_gear`, or a planetary stage's `ring_gear`): its teeth,
//! module, helix, face width, flank data, the shaft it sits on and its place there.

use super::error::describe;
use super::error::RexsError;
use super::model::{Component, RexsModel};
use super::stage_data::GearData;
use super::units::{quantity, required, Kind};

/// Reads gear `g`; `internal` for a ring (its tip diameter lies inside its reference circle). A
/// ring may sit in the casing itself (an `assembly` of the casing, or a `side` relation to it):
/// its `shaft` is then the casing's id.
pub(crate) fn read_gear(
    model: &RexsModel,
    g: &Component,
    internal: bool,
    warnings: &mut Vec<String>,
) -> Result<GearData, RexsError> {
    let teeth = required(g, &["number_of_teeth"], Kind::Number)?;
    let module = required(g, &["normal_module"], Kind::Length)?;
    let helix_angle = quantity(g, &["helix_angle_reference_diameter", "helix_angle"], Kind::Angle)?.unwrap_or(0.0);
    let face_width = required(g, &["face_width"], Kind::Length)?;
    let flank = model
        .relations_with("flank", "gear", g.id)
        .next()
        .and_then(|r| r.role("left").or(r.role("right")))
        .map(|id| &model.components[&id]);
    let on_flank = |ids: &[&str], kind| -> Result<Option<f64>, RexsError> {
        match flank {
            Some(f) => Ok(quantity(f, ids, kind)?.or(quantity(g, ids, kind)?)),
            None => quantity(g, ids, kind),
        }
    };
    let pressure_angle = on_flank(&["normal_pressure_angle"], Kind::Angle)?.ok_or_else(|| {
        RexsError::at(
            g,
            "`normal_pressure_angle` is missing (on the gear and its flanks)",
            "export the gear's flank geometry",
        )
    })?;
    let given_shift = on_flank(&["addendum_modification_coefficient"], Kind::Number)?;
    let profile_shift = given_shift.unwrap_or(0.0);
    let is_shaft = |id: Option<u64>| {
        id.and_then(|id| model.components.get(&id))
            .is_some_and(|c| c.kind == "shaft" || (internal && c.kind == "gear_casing"))
    };
    // A gear is a part of its shaft (`assembly`), or sits on it through a shaft–hub connection (a
    // `side` relation: the connection the assembly, the shaft its inner part, the gear its outer).
    let shaft = model
        .relations
        .iter()
        .find(|r| r.kind == "assembly" && r.role("part") == Some(g.id) && is_shaft(r.role("assembly")))
        .and_then(|r| r.role("assembly"))
        .or_else(|| {
            model
                .relations
                .iter()
                .find(|r| r.kind == "side" && r.role("outer_part") == Some(g.id) && is_shaft(r.role("inner_part")))
                .and_then(|r| r.role("inner_part"))
        })
        .ok_or_else(|| {
            RexsError::at(
                g,
                "no `assembly` relation, and no shaft–hub connection (`side`), puts it on a shaft",
                "every gear is a part of its shaft, or sits on it through a connection",
            )
        })?;
    // REXS 1.0 gives a gear's `u_coordinate_on_shaft` at its face start; later versions at its
    // mid-plane, which gearloss's `at` is.
    let face_start = model.version == "1.0";
    let at =
        quantity(g, &["u_coordinate_on_shaft"], Kind::Length)?
            .map(|u| if face_start { u + 0.5 * face_width } else { u });
    let from_vectors = match (
        super::units::vector(g, "support_vector"),
        super::units::vector(&model.components[&shaft], "support_vector"),
    ) {
        (Some(a), Some(b)) => Some(a[0] - b[0]),
        _ => None,
    };
    let at = match (at, from_vectors) {
        (Some(u), Some(v)) if (u - v).abs() > 1e-6 => {
            warnings.push(format!("{}: `u_coordinate_on_shaft` {u} mm differs from its support vector's {v} mm; the support vector is used", describe(g)));
            v
        }
        (Some(u), _) => u,
        (None, Some(v)) => v,
        (None, None) => {
            return Err(RexsError::at(
                g,
                "`u_coordinate_on_shaft` is missing",
                "export the gear's position on its shaft",
            ))
        }
    };
    let reference = module * teeth / helix_angle.to_radians().cos();
    // A ring's tip diameter may be written signed (ISO 21771: negative for an internal gear).
    let tip = quantity(g, &["tip_diameter"], Kind::Length)?.map(|d| if internal { d.abs() } else { d });
    let plausible = |da: f64| {
        if internal {
            da < reference && da > reference - 4.0 * module
        } else {
            da > reference && da < reference + 4.0 * module
        }
    };
    let tip_diameter = match tip {
        Some(da) if plausible(da) => Some(da),
        Some(da) => {
            warnings.push(format!("{}: `tip_diameter` {da} mm is not plausible (d = {:.3} mm, m_n = {module} mm); left out, the tip follows from the profile shift", describe(g), reference));
            None
        }
        None => None,
    };
    Ok(GearData {
        id: g.id,
        teeth: teeth.round() as u32,
        module,
        helix_angle,
        face_width,
        pressure_angle,
        profile_shift,
        profile_shift_given: given_shift.is_some(),
        profile_shift_note: None,
        tip_diameter,
        shaft,
        at,
    })
}
