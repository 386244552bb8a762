//! A shaft's `shaft_section`s (relation `assembly`: the shaft the assembly, each section a part)
//! read into the scene's `section(from, to, diameter, bore)`: `u_coordinate_on_shaft` the start,
//! `length`, `outer_diameter_begin/_end` and `inner_diameter_begin/_end`. A conical section (begin
//! ≠ end) becomes the cylinder of its mean diameters, said as chosen. The sections are used when
//! they join end to end and cover every gear and bearing of the shaft; otherwise they are left out
//! with the reason (a shaft on two places then stays the rigid beam; on more it cannot be imported).

use super::error::describe;
use super::error::RexsError;
use super::model::{Component, RexsModel};
use super::units::{quantity, Kind};

/// Section ends nearer than this join (mm).
const JOIN: f64 = 1e-6;

/// One section as the scene writes it (mm) and the REXS component it came from.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SectionData {
    pub id: u64,
    pub from: f64,
    pub to: f64,
    pub outer_diameter: f64,
    pub bore: f64,
}

/// The sections of `shaft` in order along it, when they make a beam over `points` (its gears' and
/// bearings' positions, mm); else the reason they do not.
pub(crate) fn read_sections(
    model: &RexsModel,
    shaft: &Component,
    points: &[f64],
    warnings: &mut Vec<String>,
) -> Result<Result<Vec<SectionData>, String>, RexsError> {
    let mut out = Vec::new();
    for r in model.relations_with("assembly", "assembly", shaft.id) {
        let Some(c) = r.role("part").and_then(|id| model.components.get(&id)) else { continue };
        if c.kind != "shaft_section" {
            continue;
        }
        let mm = |ids: &[&str]| quantity(c, ids, Kind::Length);
        let (Some(from), Some(length)) = (mm(&["u_coordinate_on_shaft"])?, mm(&["length"])?) else {
            return Ok(Err(format!("{} gives no `u_coordinate_on_shaft` or `length`", describe(c))));
        };
        let pair = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(a), Some(b)) => Some((a, b)),
            (Some(a), None) | (None, Some(a)) => Some((a, a)),
            (None, None) => None,
        };
        let Some(outer) = pair(mm(&["outer_diameter_begin"])?, mm(&["outer_diameter_end"])?) else {
            return Ok(Err(format!("{} gives no outer diameter", describe(c))));
        };
        let inner = pair(mm(&["inner_diameter_begin"])?, mm(&["inner_diameter_end"])?).unwrap_or((0.0, 0.0));
        if outer.0 != outer.1 || inner.0 != inner.1 {
            warnings.push(format!(
                "{}: a conical section (D {} → {} mm, d {} → {} mm) is imported as the cylinder of its mean diameters (chosen)",
                describe(c), outer.0, outer.1, inner.0, inner.1
            ));
        }
        let (d_out, d_in) = (0.5 * (outer.0 + outer.1), 0.5 * (inner.0 + inner.1));
        if length <= 0.0 || d_out <= 0.0 || !(0.0..d_out).contains(&d_in) {
            return Ok(Err(format!(
                "{} is not a shaft section (length {length} mm, D {d_out} mm, d {d_in} mm)",
                describe(c)
            )));
        }
        out.push(SectionData { id: c.id, from, to: from + length, outer_diameter: d_out, bore: d_in });
    }
    if out.is_empty() {
        return Ok(Err("the model gives no shaft sections".into()));
    }
    out.sort_by(|a, b| a.from.total_cmp(&b.from));
    if let Some(w) = out.windows(2).find(|w| (w[1].from - w[0].to).abs() > JOIN) {
        return Ok(Err(format!("its sections leave a gap or overlap between {} mm and {} mm", w[0].to, w[1].from)));
    }
    let (start, end) = (out[0].from, out[out.len() - 1].to);
    if let Some(p) = points.iter().find(|p| **p < start - JOIN || **p > end + JOIN) {
        return Ok(Err(format!("its sections ({start} to {end} mm) do not reach its gear or bearing at {p} mm")));
    }
    Ok(Ok(out))
}

/// The outer and inner diameter (mm) of shaft `shaft`'s section at `u` (mm on the shaft): the
/// section whose span holds it (a section without `u_coordinate_on_shaft` starts at 0), the mean
/// of a conical one; None when no section holds it.
pub(crate) fn diameters_at(model: &RexsModel, shaft: u64, u: f64) -> Result<Option<(f64, f64)>, RexsError> {
    for r in model.relations_with("assembly", "assembly", shaft) {
        let Some(c) = r.role("part").and_then(|id| model.components.get(&id)) else { continue };
        if c.kind != "shaft_section" {
            continue;
        }
        let mm = |ids: &[&str]| quantity(c, ids, Kind::Length);
        let from = mm(&["u_coordinate_on_shaft"])?.unwrap_or(0.0);
        let Some(length) = mm(&["length"])? else { continue };
        if u < from - JOIN || u > from + length + JOIN {
            continue;
        }
        let mean = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(a), Some(b)) => Some(0.5 * (a + b)),
            (a, b) => a.or(b),
        };
        let Some(outer) = mean(mm(&["outer_diameter_begin"])?, mm(&["outer_diameter_end"])?) else { continue };
        let inner = mean(mm(&["inner_diameter_begin"])?, mm(&["inner_diameter_end"])?).unwrap_or(0.0);
        if outer > 0.0 {
            return Ok(Some((outer, inner)));
        }
    }
    Ok(None)
}
