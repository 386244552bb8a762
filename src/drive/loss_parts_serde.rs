//! report.json's form of a point's loss parts ([`super::point::LossParts`]): one object with the
//! meshes' loss under `meshes` and each loss-part column's under its key, in column order
//! (`crate::losses::parts::COLUMNS`); read back the same way, every key required.

use std::fmt;

use serde::de::{self, MapAccess, Visitor};
use serde::ser::SerializeMap;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::point::LossParts;
use crate::losses::parts::{COLUMNS, COLUMN_COUNT};

impl Serialize for LossParts {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(1 + COLUMN_COUNT))?;
        map.serialize_entry("meshes", &self.meshes)?;
        for (c, p) in COLUMNS.iter().zip(&self.parts) {
            map.serialize_entry(c.key, p)?;
        }
        map.end()
    }
}

impl<'de> Deserialize<'de> for LossParts {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<LossParts, D::Error> {
        deserializer.deserialize_map(LossPartsVisitor)
    }
}

struct LossPartsVisitor;

impl<'de> Visitor<'de> for LossPartsVisitor {
    type Value = LossParts;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("the loss parts: meshes and every loss-part column")
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<LossParts, A::Error> {
        let mut meshes = None;
        let mut parts = [None; COLUMN_COUNT];
        while let Some(key) = map.next_key::<String>()? {
            match COLUMNS.iter().position(|c| c.key == key) {
                Some(i) => parts[i] = Some(map.next_value::<f64>()?),
                None if key == "meshes" => meshes = Some(map.next_value::<f64>()?),
                None => {
                    map.next_value::<de::IgnoredAny>()?;
                }
            }
        }
        let mut out =
            LossParts { meshes: meshes.ok_or_else(|| de::Error::missing_field("meshes"))?, ..LossParts::default() };
        for (i, p) in parts.into_iter().enumerate() {
            out.parts[i] = p.ok_or_else(|| de::Error::missing_field(COLUMNS[i].key))?;
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The form is the one the five named fields had, and reads back to the same parts.
    #[test]
    fn written_as_meshes_and_each_column_and_read_back() {
        let l = LossParts { meshes: 1.5, parts: [2.0, 3.0, 4.0, 5.0] };
        let text = serde_json::to_string(&l).unwrap();
        assert_eq!(text, r#"{"meshes":1.5,"gear_no_load":2.0,"bearings_no_load":3.0,"bearings_load":4.0,"seals":5.0}"#);
        assert_eq!(serde_json::from_str::<LossParts>(&text).unwrap(), l);
        assert!(serde_json::from_str::<LossParts>(r#"{"meshes":1.5}"#).is_err());
    }
}
