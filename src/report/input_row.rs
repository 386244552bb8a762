//! One row of the report's inputs table: a key, what was written, the value in SI.

use serde::{Deserialize, Serialize};

use super::number::{Num, Q};

/// One input of the scene, as written and in SI (a plain number when dimensionless).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct InputRow {
    pub key: String,
    pub written: String,
    pub si: SiValue,
}

/// A dimensional value with its unit, or a plain number.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
#[serde(untagged)]
pub enum SiValue {
    Plain(Num),
    Dimensional(Q),
}

impl SiValue {
    pub fn si(&self) -> f64 {
        match self {
            SiValue::Plain(n) => n.0,
            SiValue::Dimensional(q) => q.si(),
        }
    }
    pub fn unit(&self) -> &'static str {
        match self {
            SiValue::Plain(_) => "",
            SiValue::Dimensional(q) => q.unit,
        }
    }
}
