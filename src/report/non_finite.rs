//! The report's values that are not finite numbers: found by walking report.json's text as a
//! stream (a serde visitor that keeps only the path it stands on), never by building the whole
//! report as a `serde_json::Value` tree — that tree was the peak of a large sweep's memory.

use std::fmt::{self, Write};

use serde::de::{DeserializeSeed, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};

/// Paths of every value in the report that is not a finite number (serialised as `null`), in the
/// order report.json holds them; `point` (an optional label) and `curves` (a plot's gaps where a
/// law diverges, by design) are not looked into.
///
/// ```
/// # use gearloss::report::non_finite_paths;
/// # let report: gearloss::Report = serde_json::from_str(&std::fs::read_to_string(
/// #     concat!(env!("CARGO_MANIFEST_DIR"), "/reports/fzg_type_c/stages/pair/report.json")).unwrap()).unwrap();
/// assert!(non_finite_paths(&report).is_empty());
/// ```
pub fn non_finite_paths<T: serde::Serialize>(report: &T) -> Vec<String> {
    let mut out = Vec::new();
    if let Ok(text) = serde_json::to_string(report) {
        let mut path = String::new();
        let mut de = serde_json::Deserializer::from_str(&text);
        // (The text is serde_json's own: it reads back; a failure would only shorten the list.)
        let _ = Walk { path: &mut path, out: &mut out }.deserialize(&mut de);
    }
    out
}

/// The walk at one value: `path` is where it stands (grown and cut back as it goes down and up).
struct Walk<'a> {
    path: &'a mut String,
    out: &'a mut Vec<String>,
}

impl<'de> DeserializeSeed<'de> for Walk<'_> {
    type Value = ();
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Walk<'_> {
    type Value = ();

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("report.json")
    }

    fn visit_unit<E: serde::de::Error>(self) -> Result<(), E> {
        self.out.push(self.path.clone());
        Ok(())
    }

    fn visit_none<E: serde::de::Error>(self) -> Result<(), E> {
        self.visit_unit()
    }

    fn visit_bool<E: serde::de::Error>(self, _: bool) -> Result<(), E> {
        Ok(())
    }
    fn visit_i64<E: serde::de::Error>(self, _: i64) -> Result<(), E> {
        Ok(())
    }
    fn visit_u64<E: serde::de::Error>(self, _: u64) -> Result<(), E> {
        Ok(())
    }
    fn visit_f64<E: serde::de::Error>(self, _: f64) -> Result<(), E> {
        Ok(())
    }
    fn visit_str<E: serde::de::Error>(self, _: &str) -> Result<(), E> {
        Ok(())
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        let len = self.path.len();
        let mut i = 0usize;
        loop {
            let _ = write!(self.path, "[{i}]");
            let more = seq.next_element_seed(Walk { path: &mut *self.path, out: &mut *self.out })?;
            self.path.truncate(len);
            if more.is_none() {
                return Ok(());
            }
            i += 1;
        }
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        let len = self.path.len();
        while let Some(key) = map.next_key::<String>()? {
            if key == "point" || key == "curves" {
                map.next_value::<IgnoredAny>()?;
                continue;
            }
            self.path.push('.');
            self.path.push_str(&key);
            map.next_value_seed(Walk { path: &mut *self.path, out: &mut *self.out })?;
            self.path.truncate(len);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Nulls are found where they are, with their paths; `point` and `curves` are not looked into.
    #[test]
    fn finds_nulls_with_their_paths() {
        let text = r#"{"a":[1.0,null,{"b":null,"point":null}],"curves":[null],"c":{"d":[[2,null]]},"e":"x"}"#;
        let (mut path, mut out) = (String::new(), Vec::new());
        let mut de = serde_json::Deserializer::from_str(text);
        Walk { path: &mut path, out: &mut out }.deserialize(&mut de).unwrap();
        assert_eq!(out, [".a[1]", ".a[2].b", ".c.d[0][1]"]);
        assert!(path.is_empty());
    }
}
