//! The loss budget as record columns: the names a scene's gearbox gives (the parts it describes, the
//! total, then four columns per bearing place in the scene's order, pinion shaft first), and
//! [`BudgetParts`] read and written as those flat columns in `records.csv` and `records.jsonl`.
//!
//! ```
//! use gearloss::losses::columns::names;
//! use gearloss::losses::{Bearing, BearingType, Gearbox};
//! let b = Bearing { kind: BearingType::CylindricalRoller, mean_diameter: 0.05, count: 1,
//!                   static_load_rating: None, f0: None, f1: None, y: None, position: None, skf: None };
//! let g = Gearbox { lubrication: None, bearings: [vec![b], vec![]], seals: [vec![], vec![]] };
//! assert_eq!(names(&g), ["bearings_no_load_W", "bearings_load_W", "total_loss_W", "total_efficiency",
//!     "bearing_1_radial_load_N", "bearing_1_axial_load_N", "bearing_1_no_load_W", "bearing_1_load_W"]);
//! ```

use serde::de::{Deserializer, MapAccess, Visitor};
use serde::ser::{SerializeMap, Serializer};
use serde::{Deserialize, Serialize};

use super::budget::{BearingLoads, BudgetParts};
use super::gearbox::Gearbox;
use super::parts::LossColumn;

/// The four columns of bearing place `i` (1-based), after its prefix `bearing_{i}_`.
const BEARING_FIELDS: [&str; 4] = ["radial_load_N", "axial_load_N", "no_load_W", "load_W"];

/// The column names: the parts `present` (in column order), the total, four per bearing place.
fn column_names(present: impl Iterator<Item = LossColumn>, places: usize) -> Vec<String> {
    let parts = present.map(|c| format!("{}_W", c.key()));
    let mut out: Vec<String> = parts.chain(["total_loss_W".into(), "total_efficiency".into()]).collect();
    for i in 1..=places {
        out.extend(BEARING_FIELDS.iter().map(|f| format!("bearing_{i}_{f}")));
    }
    out
}

/// The budget columns of a scene with this gearbox, in the order [`values`] gives their values.
pub fn names(g: &Gearbox) -> Vec<String> {
    column_names(g.columns().into_iter(), g.bearings.iter().map(Vec::len).sum())
}

/// The budget's values in the order of [`names`] for the gearbox that gave them (no names built:
/// the record files write these for every row of a sweep).
pub fn values(p: &BudgetParts) -> impl Iterator<Item = Option<f64>> + '_ {
    let parts = p.parts.iter().map(|(_, v)| Some(*v));
    let bearings = p.bearings.iter().flat_map(|b| [Some(b.radial_load), Some(b.axial_load), Some(b.no_load), b.load]);
    parts.chain([Some(p.total_loss), Some(p.total_efficiency)]).chain(bearings)
}

/// The budget's values with their column names.
pub fn cells(p: &BudgetParts) -> Vec<(String, Option<f64>)> {
    column_names(p.parts.iter().map(|(c, _)| *c), p.bearings.len()).into_iter().zip(values(p)).collect()
}

impl Serialize for BudgetParts {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let cells = cells(self);
        let mut map = s.serialize_map(Some(cells.len()))?;
        for (name, value) in &cells {
            // A missing load-dependent bearing loss is left out, as the parts are.
            if let Some(v) = value {
                map.serialize_entry(name, v)?;
            }
        }
        map.end()
    }
}

impl<'de> Deserialize<'de> for BudgetParts {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_map(PartsVisitor)
    }
}

struct PartsVisitor;

impl<'de> Visitor<'de> for PartsVisitor {
    type Value = BudgetParts;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("the loss budget's columns")
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<BudgetParts, A::Error> {
        let mut p = BudgetParts::default();
        let (mut total, mut efficiency) = (None, None);
        while let Some(key) = map.next_key::<String>()? {
            // Other columns of the row (when flattened into it) are not the budget's.
            let Ok(value) = map.next_value::<Option<f64>>() else { continue };
            let value = value.unwrap_or(f64::NAN);
            match key.as_str() {
                _ if LossColumn::of_record(&key).is_some() => {
                    p.parts.extend(LossColumn::of_record(&key).map(|c| (c, value)));
                }
                "total_loss_W" => total = Some(value),
                "total_efficiency" => efficiency = Some(value),
                _ => {
                    if let Some((i, field)) = bearing_column(&key) {
                        if p.bearings.len() < i {
                            let empty = BearingLoads { radial_load: 0.0, axial_load: 0.0, no_load: 0.0, load: None };
                            p.bearings.resize(i, empty);
                        }
                        let b = &mut p.bearings[i - 1];
                        match field {
                            0 => b.radial_load = value,
                            1 => b.axial_load = value,
                            2 => b.no_load = value,
                            _ => b.load = Some(value),
                        }
                    }
                }
            }
        }
        p.parts.sort_by_key(|(c, _)| *c);
        p.total_loss = total.ok_or_else(|| serde::de::Error::missing_field("total_loss_W"))?;
        p.total_efficiency = efficiency.ok_or_else(|| serde::de::Error::missing_field("total_efficiency"))?;
        Ok(p)
    }
}

/// `bearing_{i}_{field}` → (i, the field's index in [`BEARING_FIELDS`]).
fn bearing_column(key: &str) -> Option<(usize, usize)> {
    let rest = key.strip_prefix("bearing_")?;
    let (i, field) = rest.split_once('_')?;
    let i: usize = i.parse().ok().filter(|&i| i >= 1)?;
    Some((i, BEARING_FIELDS.iter().position(|f| *f == field)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Written as columns and read back, a budget is the same, a missing load-dependent loss included.
    #[test]
    fn round_trip() {
        let b = |x: f64, load| BearingLoads { radial_load: x, axial_load: 0.5 * x, no_load: 2.0, load };
        let p = BudgetParts {
            parts: vec![
                (LossColumn::GearNoLoad, 10.0),
                (LossColumn::BearingsNoLoad, 4.0),
                (LossColumn::BearingsLoad, 3.25),
            ],
            total_loss: 120.5,
            total_efficiency: 0.987,
            bearings: vec![b(1000.0, Some(1.5)), b(1200.0, None), b(800.0, Some(1.75))],
        };
        let text = serde_json::to_string(&p).unwrap();
        assert!(!text.contains("seals") && !text.contains("bearing_2_load_W"), "{text}");
        assert_eq!(serde_json::from_str::<BudgetParts>(&text).unwrap(), p);
        assert!(serde_json::from_str::<BudgetParts>(r#"{"gear_no_load_W": 1.0}"#).is_err());
    }
}
