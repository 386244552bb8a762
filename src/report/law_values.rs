//! The values a law's rows and parameters hold in the report: μ or the word `diverges`, and a
//! law's parameters as a map of name to number (with its unit where it has one), read back as written.

use serde::{Deserialize, Serialize};

use super::number::Num;
use crate::evaluate::records::ParameterValue;

/// μ at a row: a number, or the word `diverges` where the law is singular (at P).
#[derive(Debug, Clone, Copy, Serialize)]
#[serde(untagged)]
pub enum MuValue {
    Value(Num),
    Text(&'static str),
}

/// The words a [`MuValue`] may hold.
const MU_WORDS: &[&str] = &["diverges", "unstable"];

impl<'de> Deserialize<'de> for MuValue {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<MuValue, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Written {
            Number(Option<f64>),
            Word(String),
        }
        Ok(match Written::deserialize(d)? {
            Written::Number(x) => MuValue::Value(Num(x.unwrap_or(f64::NAN))),
            Written::Word(w) => MuValue::Text(
                MU_WORDS
                    .iter()
                    .find(|m| **m == w)
                    .ok_or_else(|| serde::de::Error::custom(format!("`{w}` is not a word for μ")))?,
            ),
        })
    }
}

impl MuValue {
    pub fn value(&self) -> Option<f64> {
        match self {
            MuValue::Value(n) => Some(n.0),
            MuValue::Text(_) => None,
        }
    }
}

/// A law's parameters as a JSON object in the law's own order: `{"mu": 0.04, "phi": {"value": 5e4, "unit": "1/m"}}`.
#[derive(Debug, Clone, Default)]
pub struct Parameters(pub Vec<ParameterValue>);

impl Parameters {
    /// The SI value of a parameter.
    pub fn get(&self, name: &str) -> Option<f64> {
        self.0.iter().find(|p| p.name == name).map(|p| p.value)
    }
}

impl Serialize for Parameters {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        #[derive(Serialize, Deserialize)]
        struct Dimensional<'a> {
            value: Num,
            unit: &'a str,
        }
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for p in &self.0 {
            if p.unit == "1" {
                map.serialize_entry(&p.name, &Num(p.value))?;
            } else {
                map.serialize_entry(&p.name, &Dimensional { value: Num(p.value), unit: &p.unit })?;
            }
        }
        map.end()
    }
}

impl<'de> Deserialize<'de> for Parameters {
    /// `{name: number}` for a plain number, `{name: {value, unit}}` for a dimensional one, in order.
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Parameters, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Value {
            Plain(Option<f64>),
            Dimensional { value: Option<f64>, unit: String },
        }
        struct Visit;
        impl<'de> serde::de::Visitor<'de> for Visit {
            type Value = Parameters;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a law's parameters")
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<Parameters, A::Error> {
                let mut out = Vec::new();
                while let Some((name, v)) = map.next_entry::<String, Value>()? {
                    let (value, unit) = match v {
                        Value::Plain(x) => (x, "1".to_string()),
                        Value::Dimensional { value, unit } => (value, unit),
                    };
                    out.push(ParameterValue { name, value: value.unwrap_or(f64::NAN), unit });
                }
                Ok(Parameters(out))
            }
        }
        d.deserialize_map(Visit)
    }
}
