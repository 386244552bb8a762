//! Numbers in reports: dimensional values as `{"value": SI, "unit": "SI unit"}`, all rounded to
//! ten significant digits so that output does not change with the last bit of a libm call.

use serde::{Deserialize, Serialize, Serializer};

pub use crate::numerics::rounding::{round_sig, SIGNIFICANT_DIGITS};

/// A plain (dimensionless) number, rounded when serialised; non-finite becomes `null`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl Serialize for Num {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if self.0.is_finite() {
            s.serialize_f64(round_sig(self.0))
        } else {
            s.serialize_none()
        }
    }
}

impl<'de> Deserialize<'de> for Num {
    /// A number, or `null` for one that was not finite (read back as NaN).
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Num, D::Error> {
        Ok(Num(Option::<f64>::deserialize(d)?.unwrap_or(f64::NAN)))
    }
}

/// Every SI unit a report writes (a [`Q`] read back takes its unit from here; the round trip of every
/// scene in `specs/` is a test).
pub const UNITS: &[&str] = &[
    "1",
    "1/Pa",
    "1/m",
    "1/s",
    "Hz",
    "J",
    "K",
    "N",
    "N*m",
    "N*s/m",
    "N/m",
    "N/m^2",
    "Pa",
    "Pa*s",
    "W",
    "kg",
    "kg*m^2",
    "kg/m^3",
    "m",
    "m/s",
    "m/s^2",
    "m^2/s",
    "m^3/s",
    "rad",
    "rad/s",
    "s",
    "m^2",
    "J/K",
    "W/K",
    "W/(m^2*K)",
];

/// A dimensional value in SI with its unit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Q {
    pub value: Num,
    pub unit: &'static str,
}

impl<'de> Deserialize<'de> for Q {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Q, D::Error> {
        #[derive(Deserialize)]
        struct Written {
            value: Num,
            unit: String,
        }
        let w = Written::deserialize(d)?;
        let unit = UNITS
            .iter()
            .find(|u| **u == w.unit)
            .ok_or_else(|| serde::de::Error::custom(format!("unit `{}` is not one a report writes", w.unit)))?;
        Ok(Q { value: w.value, unit })
    }
}

impl Q {
    pub fn new(value: f64, unit: &'static str) -> Q {
        Q { value: Num(value), unit }
    }
    pub fn si(&self) -> f64 {
        self.value.0
    }
}

/// A unit the user wrote, for display in tables and plots: the value in it is SI / factor (the
/// factor in full precision, so that values shown in it read back the same).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct DisplayUnit {
    pub name: String,
    /// SI per unit.
    pub factor: f64,
}

impl DisplayUnit {
    /// N·m, the torque unit of reports written before torques were shown as written.
    pub fn newton_metre() -> DisplayUnit {
        DisplayUnit { name: "N*m".into(), factor: 1.0 }
    }

    /// Whether this is N·m (a drive's report then leaves its torque unit out of report.json).
    pub fn is_newton_metre(&self) -> bool {
        self.name == "N*m"
    }

    /// rpm, the speed unit of drive reports written before speeds were shown as written.
    pub fn rpm() -> DisplayUnit {
        DisplayUnit { name: "rpm".into(), factor: std::f64::consts::PI / 30.0 }
    }

    /// Whether this is rpm (a drive's report then leaves its speed unit out of report.json).
    pub fn is_rpm(&self) -> bool {
        self.name == "rpm"
    }

    /// The name as tables print it: `lbf*in` → `lbf·in`.
    pub fn shown(&self) -> String {
        self.name.replace('*', "·")
    }

    /// The unit a sweep was written in.
    pub fn of<T>(sweep: &crate::model::Sweep<T>) -> DisplayUnit {
        DisplayUnit { name: sweep.unit.clone(), factor: sweep.factor }
    }

    /// A value in this unit, to the ten significant digits report.json keeps (so that a speed
    /// written as 500 rpm reads 500, not 500.0000000016, from its rounded SI value).
    pub fn value(&self, q: &Q) -> f64 {
        self.of_si(q.si())
    }

    /// An SI value in this unit, to ten significant digits.
    pub fn of_si(&self, si: f64) -> f64 {
        round_sig(si / self.factor)
    }
}

/// `1500 lbf·in, 1800 rpm`: a torque and a speed (SI) in the units the scene wrote them in, each to
/// the significant digits tables use.
pub fn operating_point_words(torque_unit: &DisplayUnit, speed_unit: &DisplayUnit, torque: &Q, speed: &Q) -> String {
    use crate::numerics::rounding::sig;
    let (t, n) = (torque_unit, speed_unit);
    format!("{} {}, {} {}", sig(t.value(torque)), t.shown(), sig(n.value(speed)), n.shown())
}

/// Shorthands for the SI units used in reports.
pub fn m(x: f64) -> Q {
    Q::new(x, "m")
}
pub fn rad(x: f64) -> Q {
    Q::new(x, "rad")
}
pub fn pa(x: f64) -> Q {
    Q::new(x, "Pa")
}
pub fn mps(x: f64) -> Q {
    Q::new(x, "m/s")
}

/// The unit system report.md shows results in (report.json stays SI): inch–pound when the scene
/// sizes its pair in inch units, SI otherwise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum UnitSystem {
    #[default]
    Si,
    Inch,
}

impl UnitSystem {
    pub fn is_si(&self) -> bool {
        *self == UnitSystem::Si
    }
}
