//! The lubricant at temperature, the loss budget of each efficiency record, and the efficiency map.

use serde::{Deserialize, Serialize};

use super::number::{Num, Q};
use crate::losses::parts::LossColumn;
use crate::losses::{Bearing, BudgetParts, Gearbox};

/// What the laws, films and losses read from the oil, and where it came from.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct LubricantReport {
    pub name: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub base: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub temperature: Option<Q>,
    pub dynamic_viscosity: Q,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kinematic_viscosity: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub density: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pressure_viscosity: Option<Q>,
    /// X_L of ISO/TR 14179-2 by base oil (a law's `x_l` overrides it there).
    pub lubricant_factor: Num,
    /// ν40, ν100, ρ15 and the viscosity index when the oil was given by grade or measured values.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub nu_40: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub nu_100: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub density_15: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub viscosity_index: Option<Num>,
    pub source: String,
}

/// The lubricant `l` as a mesh reads it (`t`: η, ν, ρ, α and X_L at the oil temperature, the
/// same for every mesh of a drive, which share one sump), with its data sheet values and where its
/// values come from: a pair's report and a drive's alike.
pub(crate) fn lubricant_report(l: &crate::model::Lubricant, t: &crate::tribology::Tribology) -> LubricantReport {
    let source = match &l.oil {
        Some(oil) => {
            format!("{}; ν by ASTM D341 (Walther) through ν40 and ν100, ρ by thermal expansion 7e-4 1/K", oil.source)
        }
        None => "given at the oil temperature in the scene".to_string(),
    };
    LubricantReport {
        name: l.name.clone(),
        base: l.kind.map(|b| b.words().to_string()),
        temperature: l.temperature.as_ref().map(|g| Q::new(g.value.value, "K")),
        dynamic_viscosity: Q::new(t.dynamic_viscosity, "Pa*s"),
        kinematic_viscosity: t.kinematic_viscosity.map(|v| Q::new(v, "m^2/s")),
        density: t.density().map(|rho| Q::new(rho, "kg/m^3")),
        pressure_viscosity: t.pressure_viscosity.map(|a| Q::new(a, "1/Pa")),
        lubricant_factor: Num(t.lubricant_factor),
        nu_40: l.oil.as_ref().map(|o| Q::new(o.nu_40, "m^2/s")),
        nu_100: l.oil.as_ref().map(|o| Q::new(o.nu_100, "m^2/s")),
        density_15: l.oil.as_ref().map(|o| Q::new(o.density_15, "kg/m^3")),
        viscosity_index: l.oil.as_ref().and_then(|o| o.viscosity_index()).map(Num),
        source,
    }
}

/// The budget beside an efficiency record's mesh loss, in W; parts the scene does not describe are absent.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct BudgetRecord {
    /// Each column the gearbox fills, written under its key ([`LossColumn::key`]).
    #[serde(flatten)]
    pub parts: PartPowers,
    pub total_loss: Q,
    pub total_efficiency: Num,
    /// Every bearing place in the scene's order (pinion shaft, then wheel shaft).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub bearings: Vec<BearingRecord>,
}

impl BudgetRecord {
    /// One column's power, when the gearbox fills it.
    pub fn part(&self, column: LossColumn) -> Option<Q> {
        self.parts.0.iter().find(|(c, _)| *c == column).map(|(_, q)| *q)
    }
}

/// The budget's column powers, in column order; written as one key per column.
#[derive(Debug, Clone, Default)]
pub struct PartPowers(pub Vec<(LossColumn, Q)>);

impl Serialize for PartPowers {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (c, q) in &self.0 {
            map.serialize_entry(c.key(), q)?;
        }
        map.end()
    }
}

impl<'de> Deserialize<'de> for PartPowers {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Columns;
        impl<'de> serde::de::Visitor<'de> for Columns {
            type Value = PartPowers;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("the loss budget's columns")
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<PartPowers, A::Error> {
                let mut parts = Vec::new();
                while let Some(key) = map.next_key::<String>()? {
                    match LossColumn::of_key(&key) {
                        Some(c) => parts.push((c, map.next_value::<Q>()?)),
                        None => {
                            map.next_value::<serde::de::IgnoredAny>()?;
                        }
                    }
                }
                parts.sort_by_key(|(c, _): &(LossColumn, Q)| *c);
                Ok(PartPowers(parts))
            }
        }
        d.deserialize_map(Columns)
    }
}

/// One bearing place of the budget: what it is, where, what it carries and loses.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct BearingRecord {
    /// `pinion` or `wheel`.
    pub shaft: String,
    #[serde(rename = "type")]
    pub kind: String,
    /// `palmgren` or `skf`.
    pub model: String,
    pub count: usize,
    /// `at` along the shaft from the gear mid-plane, when given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub position: Option<Q>,
    /// Loads of one bearing (N).
    pub radial_load: Q,
    pub axial_load: Q,
    /// Losses of all `count` bearings (W).
    pub no_load: Q,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub load: Option<Q>,
}

/// The bearing places of a gearbox in the budget's order: (shaft name, bearing).
pub(crate) fn bearing_places(g: &Gearbox) -> impl Iterator<Item = (&'static str, &Bearing)> {
    g.bearings.iter().zip(["pinion", "wheel"]).flat_map(|(places, shaft)| places.iter().map(move |b| (shaft, b)))
}

pub(crate) fn budget_record(p: &BudgetParts, gearbox: Option<&Gearbox>) -> BudgetRecord {
    let w = |x: Option<f64>| x.map(|x| Q::new(x, "W"));
    let bearings = gearbox
        .map(|g| {
            bearing_places(g)
                .zip(&p.bearings)
                .map(|((shaft, b), l)| BearingRecord {
                    shaft: shaft.into(),
                    kind: b.kind.name().into(),
                    model: b.model_name().into(),
                    count: b.count,
                    position: b.position.map(|x| Q::new(x, "m")),
                    radial_load: Q::new(l.radial_load, "N"),
                    axial_load: Q::new(l.axial_load, "N"),
                    no_load: Q::new(l.no_load, "W"),
                    load: w(l.load),
                })
                .collect()
        })
        .unwrap_or_default();
    BudgetRecord {
        parts: PartPowers(p.parts.iter().map(|(c, v)| (*c, Q::new(*v, "W"))).collect()),
        total_loss: Q::new(p.total_loss, "W"),
        total_efficiency: Num(p.total_efficiency),
        bearings,
    }
}

/// The readings behind the budget's parts that this gearbox uses.
pub(crate) fn budget_readings(g: &Gearbox) -> Vec<String> {
    use crate::losses::Lubrication;
    let mut out = Vec::new();
    match g.lubrication {
        Some(Lubrication::Dip { .. }) => out.push("churning (Mauz, ISO/TR 14179-2): T_H is the stage's hydraulic loss torque read at the pinion shaft, P = T_H ω_1, at the pitch-line speed v_t = ω_1 r_w1 of the working pitch circle; it contains the dipping gears' windage".to_string()),
        Some(Lubrication::Injection { .. }) => {
            out.push("jet impulse ρ Q v_t (v_t + v_j) (Ariura et al.): the jet meets the teeth head-on; a jet into the mesh entry moving with the teeth would lose the smaller ρ Q v_t (v_t − v_j)".to_string());
            out.push("windage (Anderson & Loewenthal, NASA TP-1622): their pitch radius R read as the working pitch radius r_w of each gear".to_string());
        }
        None => {}
    }
    let places: Vec<&Bearing> = g.bearings.iter().flatten().collect();
    if places.iter().any(|b| b.skf.is_none()) {
        out.push("bearings (Palmgren): f_0, f_1, P_1 for oil-bath lubrication as SKF's General Catalogue 4000 E (1989) gives them and ISO/TR 14179-2 tabulates them; a tapered roller bearing's Y is its `y` (1.6 when not given)".to_string());
    }
    if places.iter().any(|b| b.skf.is_some()) {
        out.push("bearings (SKF model, SKF Rolling bearings catalogue 2018): the series' constants R1, R2, S1, S2 as the scene gives them; K_rs = 3e-8 (low oil level, jet); no drag or seal moment".to_string());
    }
    if places.iter().any(|b| b.position.is_some()) {
        out.push("bearing positions `at`: one common axial direction for both shafts from the gear mid-plane; the pinion's axial mesh force points to +at, the wheel's to −at; each shaft balanced by statics (3 forces, 2 moments)".to_string());
    } else if !places.is_empty() {
        out.push("bearing loads: no positions given, so each bearing of a shaft carries F_bt / (its number of bearings) and the axial moment is not taken up".to_string());
    }
    out
}
