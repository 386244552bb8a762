//! One rolling bearing of a REXS model as the scene writes it: its gearloss type (from
//! `bearing_type`, else its designation, else chosen), its sizes (the model's diameters, else its
//! designation's dimension plan, else the parts it sits between: the inner part's section at its
//! place gives the bore, the outer part's bore or ISO 15's diameter series 2 the outside; chosen,
//! said) and its static load rating (the model's, the table's, else estimated; chosen, said).

use super::error::describe;
use super::error::RexsError;
use super::model::{Component, Relation, RexsModel};
use super::units::{flag, quantity, text, Kind};

/// A bearing as the scene writes it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct BearingData {
    pub id: u64,
    pub designation: String,
    /// gearloss's type name.
    pub kind: &'static str,
    pub bore: f64,
    pub outside: f64,
    pub static_load_rating: Option<f64>,
    pub at: f64,
    /// `axial_force_absorption` as written.
    pub axial: String,
    pub locating: bool,
    /// Where the sizes came from, in words.
    pub sizes_from: String,
    /// C₀ was estimated (chosen).
    pub c0_estimated: bool,
}

/// REXS `bearing_type` → gearloss's type.
const TYPES: &[(&str, &str)] = &[
    ("radial_grooved_ball_bearing", "deep_groove_ball"),
    ("radial_grooved_ball", "deep_groove_ball"),
    ("radial_angular_contact_ball_bearing", "angular_contact_ball"),
    ("angular_contact_ball_bearing", "angular_contact_ball"),
    ("four_point_contact_ball_bearing", "angular_contact_ball"),
    ("radial_roller_bearing", "cylindrical_roller"),
    ("radial_cylindrical_roller_bearing", "cylindrical_roller"),
    ("radial_tapered_roller_bearing", "tapered_roller"),
    ("radial_spherical_roller_bearing", "spherical_roller"),
    ("radial_self_aligning_roller_bearing", "spherical_roller"),
];

/// REXS bearing types gearloss has no type of its own for: the type whose Palmgren factors stand
/// in (chosen, said).
const STAND_INS: &[(&str, &str)] = &[
    ("radial_needle_roller_bearing", "cylindrical_roller"),
    ("crossed_roller_bearing", "cylindrical_roller"),
    ("radial_self_aligning_ball_bearing", "deep_groove_ball"),
];

/// Thrust bearings (REXS `axial_*`): they take no radial load, so they are no bearing place of the
/// shaft's beam; the shaft's axial force goes to its locating place (said).
pub(crate) fn is_thrust(bearing_type: Option<&str>, b: &Component) -> bool {
    bearing_type.is_some_and(|t| t.starts_with("axial_")) || flag(b, &["radial_force_absorption"]) == Some(false)
}

/// Component types that are rolling bearings.
pub(crate) const BEARING_KINDS: &[&str] =
    &["rolling_bearing_with_catalog_geometry", "rolling_bearing_with_detailed_geometry", "concept_bearing"];

/// The designation of a bearing: its `catalogue_designation` (`name` in REXS 1.0), or a concept
/// bearing's from its component name (`not a catalogue bearing: 33016 (Rolling bearing [35])`);
/// an XML designation of digits only is read as the number it looks like.
fn designation(b: &Component) -> String {
    if let Some(t) = text(b, &["catalogue_designation", "name"]) {
        return t.to_string();
    }
    // An XML designation of digits only (`6206`) reads as a number.
    if let Some(super::model::AttributeValue::Number(x)) =
        b.attribute(&["catalogue_designation", "name"]).map(|a| &a.value)
    {
        return format!("{x}");
    }
    let name = b.name.split(": ").nth(1).unwrap_or(&b.name);
    name.split(" (").next().unwrap_or(name).trim().to_string()
}

impl BearingData {
    /// Where its sizes and C₀ came from, as the scene's comment says it: `sizes from the model`,
    /// `… from its designation`, or `… from the parts it sits between; chosen: …`, and the C₀ estimate.
    pub(crate) fn source_note(&self) -> String {
        let sizes = if self.sizes_from == "the model" {
            "sizes from the model".to_string()
        } else if let Some(how) = self.sizes_from.strip_prefix("chosen: ") {
            format!("sizes from the parts it sits between; chosen: {how}")
        } else {
            "sizes from its designation".to_string()
        };
        let c0 = if self.c0_estimated { "; chosen: C_0 estimated from d and D" } else { "" };
        format!("{sizes}{c0}")
    }
}

/// Whether shaft `shaft` sits on a bearing (a `side` relation with it as the inner part).
pub(crate) fn sits_on_bearings(model: &RexsModel, shaft: u64) -> bool {
    model.relations_with("side", "inner_part", shaft).any(|r| {
        r.role("assembly")
            .and_then(|id| model.components.get(&id))
            .is_some_and(|b| BEARING_KINDS.contains(&b.kind.as_str()))
    })
}

/// Reads bearing `b`, joined to its parts by the `side` relation `r`; `at` is its place on the
/// inner part (mm); `fallback` the type where neither `bearing_type` nor the designation names one
/// (a shaft's deep groove ball bearing, a planet's cylindrical roller bearing; chosen, said).
pub(crate) fn read_bearing(
    model: &RexsModel,
    r: &Relation,
    b: &Component,
    at: f64,
    fallback: &'static str,
    warnings: &mut Vec<String>,
) -> Result<BearingData, RexsError> {
    let designation = designation(b);
    let kind = match text(b, &["bearing_type"]) {
        Some(t) => match (TYPES.iter().find(|(r, _)| *r == t), STAND_INS.iter().find(|(r, _)| *r == t)) {
            (Some((_, g)), _) => *g,
            (None, Some((_, g))) => {
                warnings.push(format!("{}: a `{t}` is modelled as a {g} bearing (its Palmgren factors; chosen)", describe(b)));
                *g
            }
            (None, None) => {
                return Err(RexsError::at(b, format!("its `bearing_type` `{t}` has no gearloss type"), "gearloss's types: deep groove ball, angular contact ball, cylindrical, tapered and spherical roller (needle, crossed roller and self-aligning ball bearings stand in as one of them)"))
            }
        },
        None => match super::bearing_sizes::type_of(&designation) {
            Some(t) => t,
            None => {
                warnings.push(format!(
                    "{}: it gives no `bearing_type` and its designation `{designation}` names none: a {} bearing (chosen)",
                    describe(b),
                    fallback.replace('_', " ")
                ));
                fallback
            }
        },
    };
    let table = super::bearing_sizes::sizes(&designation);
    let given = (quantity(b, &["inner_diameter"], Kind::Length)?, quantity(b, &["outer_diameter"], Kind::Length)?);
    let (bore, outside, sizes_from) = match (given, &table) {
        ((Some(d), Some(big)), _) => (d, big, "the model".to_string()),
        (_, Some(s)) => (s.bore, s.outside, format!("derived from the designation `{designation}` (ISO bore code and dimension series)")),
        _ => match from_its_parts(model, r, b, at)? {
            Some(sizes) => sizes,
            None => {
                return Err(RexsError::at(
                    b,
                    format!("`inner_diameter` and `outer_diameter` are missing, its designation `{designation}` gives no sizes, and the shaft it sits on has no section at its place"),
                    "export the bearing with its diameters, a catalogue designation gearloss knows, or its shaft's sections",
                ))
            }
        },
    };
    if sizes_from != "the model" {
        warnings.push(format!("{}: d = {bore} mm, D = {outside} mm {sizes_from}", describe(b)));
    }
    let mut c0 = quantity(b, &["radial_static_load_rating", "static_capacity"], Kind::Force)?
        .or(table.as_ref().and_then(|s| s.static_load_rating));
    let needs_c0 = matches!(kind, "deep_groove_ball" | "angular_contact_ball" | "spherical_roller");
    let c0_estimated = needs_c0 && c0.is_none();
    if c0_estimated {
        let e = (super::bearing_sizes::estimated_static_rating(kind, bore, outside) * 10.0).round() / 10.0;
        warnings.push(format!(
            "{}: no `radial_static_load_rating`: C_0 = {} kN estimated from d and D (ISO 76's f_0 Z D_w² with the balls' size and count estimated; chosen)",
            describe(b),
            crate::numerics::rounding::sig(e)
        ));
        c0 = Some(e);
    }
    let axial = text(b, &["axial_force_absorption"]).unwrap_or("no_direction").to_string();
    Ok(BearingData {
        id: b.id,
        designation,
        kind,
        bore,
        outside,
        static_load_rating: c0,
        at,
        locating: axial == "both_directions",
        axial,
        sizes_from,
        c0_estimated,
    })
}

/// A bearing without sizes (a concept bearing of a design's early stage) sized by the parts it
/// sits between (chosen): the bore d is the inner part's outer diameter at its place (its shaft
/// section there); the outside D the outer part's bore at its place where that is a shaft with a
/// bore larger than d (a planet on its pin), else ISO 15's diameter series 2 of the smallest
/// standard bore not below d. None when the inner part has no section at the place.
fn from_its_parts(
    model: &RexsModel,
    r: &Relation,
    b: &Component,
    at: f64,
) -> Result<Option<(f64, f64, String)>, RexsError> {
    let Some(inner) = r.role("inner_part") else { return Ok(None) };
    let Some((bore, _)) = super::shaft_sections::diameters_at(model, inner, at)? else { return Ok(None) };
    let outer_at = quantity(b, &["u_coordinate_on_shaft_outer_side"], Kind::Length)?;
    let outer_bore = match (r.role("outer_part"), outer_at) {
        (Some(outer), Some(u)) if model.components.get(&outer).is_some_and(|c| c.kind == "shaft") => {
            super::shaft_sections::diameters_at(model, outer, u)?.map(|(_, d_i)| d_i).filter(|d_i| *d_i > bore)
        }
        _ => None,
    };
    Ok(match outer_bore {
        Some(outside) => Some((
            bore,
            outside,
            format!("chosen: d from shaft {inner}'s diameter, D from its outer part's bore"),
        )),
        None => super::bearing_sizes::series_2_outside(bore).map(|(standard, outside)| {
            (
                bore,
                outside,
                format!("chosen: d from shaft {inner}'s diameter at its place, D of ISO 15's diameter series 2 for d = {standard} mm"),
            )
        }),
    })
}
