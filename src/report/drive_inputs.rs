//! The inputs of a drive's report: its stages with the sizes their meshes read, its shafts with
//! their bearing places and seals, the oil as the losses read it.

use serde::{Deserialize, Serialize};

use super::scene::InputRow;
use crate::drive::{Drive, Hand};
use crate::model::{Scene, SceneDrive};

/// A stage as the scene gives it, with the sizes its mesh reads.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct StageInputs {
    pub name: String,
    /// The shafts of [pinion, wheel] and the gears' `at` (mm).
    pub shafts: [String; 2],
    pub at_mm: [f64; 2],
    pub teeth: [u32; 2],
    /// z_wheel / z_pinion; a planetary stage's |ω| ratio of its two turning members.
    pub ratio: f64,
    pub normal_module_mm: f64,
    pub helix_angle_deg: f64,
    /// The pinion's hand ("right", "left"; "" for spur).
    pub pinion_hand: String,
    pub direction_deg: f64,
    pub centre_distance_mm: f64,
    pub face_width_mm: f64,
    pub working_pressure_angle_deg: f64,
    pub contact_ratio: f64,
    pub overlap_ratio: f64,
    pub lubrication: String,
    /// The stage kind's own inputs, for a kind that has them (a planetary stage: its `shafts`,
    /// `at_mm`, `teeth` are its two turning members' and the sun's and ring's; its sizes the
    /// sun–planet mesh's); in report.json under the kind's name.
    #[serde(flatten, default)]
    pub kind: Option<Box<crate::drive::KindInputs>>,
    /// How the mesh shares its load when not equally (`load_sharing = stiffness` with the reliefs
    /// as written, or `none`); absent for equal sharing.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub load_sharing: Option<String>,
    /// An internal stage: its wheel is a ring gear.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub internal: bool,
}

/// A shaft as the scene gives it.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ShaftInputs {
    pub name: String,
    /// "input", "output" or "".
    pub role: String,
    /// Each place: type, count, `at` (mm; 0 where `without_at`), whether it locates.
    pub bearings: Vec<(String, usize, f64, bool)>,
    /// The places have no `at` (a one-pair scene's shaft: each bearing carries an equal share).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub without_at: bool,
    /// Each seal: lip diameter (mm), count.
    pub seals: Vec<(f64, usize)>,
    /// A shaft with sections: the elastic beam it is solved as.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub beam: Option<ShaftBeamInputs>,
}

/// A shaft's body as the elastic beam reads it.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ShaftBeamInputs {
    pub material: String,
    pub youngs_modulus_gpa: f64,
    pub poisson_ratio: f64,
    /// "euler_bernoulli" or "timoshenko".
    pub theory: String,
    /// Each section: from, to, outer diameter, bore (mm).
    pub sections_mm: Vec<[f64; 4]>,
    /// Each bearing place: `at` (mm) and its radial stiffness (N/m; none: rigid).
    pub supports: Vec<SupportInputs>,
}

/// A bearing place as the elastic beam reads it.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct SupportInputs {
    pub at_mm: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radial_stiffness: Option<f64>,
}

pub(super) fn stage_inputs(drive: &SceneDrive, units: super::units::Units) -> Vec<StageInputs> {
    let layout = &drive.layout;
    layout
        .stages
        .iter()
        .zip(&drive.pairs)
        .zip(&drive.further_pairs)
        .map(|((s, pair), further)| {
            let g = pair.geometry().expect("lowering checked the pair");
            let further_geometry: Vec<_> = further.iter().filter_map(|p| p.geometry().ok()).collect();
            StageInputs {
                name: s.name.clone(),
                shafts: s.places.map(|p| layout.shafts[p.shaft].name.clone()),
                at_mm: s.places.map(|p| p.at * 1e3),
                teeth: s.teeth,
                // |ω| of the member on its first place over its second's (z_wheel/z_pinion of a pair).
                ratio: s.model().kinematics(s).torque_ratio(0),
                normal_module_mm: g.module * 1e3,
                helix_angle_deg: g.helix_angle.to_degrees(),
                pinion_hand: match s.hand {
                    Some(Hand::Right) => "right".into(),
                    Some(Hand::Left) => "left".into(),
                    None => String::new(),
                },
                direction_deg: s.direction.to_degrees(),
                centre_distance_mm: g.center_distance * 1e3,
                face_width_mm: g.face_width * 1e3,
                working_pressure_angle_deg: g.operating_pressure_angle.to_degrees(),
                contact_ratio: g.contact_ratio,
                overlap_ratio: g.overlap_ratio,
                lubrication: s.lubrication.as_ref().map_or_else(|| "none".to_string(), |l| lubrication_words(l, units)),
                kind: s.model().inputs(layout, s, &further_geometry.iter().collect::<Vec<_>>()).map(Box::new),
                load_sharing: sharing_words(pair),
                internal: pair.internal,
            }
        })
        .collect()
}

/// A stage's load sharing in words when it is not the equal default: by the teeth's stiffness with
/// each gear's tip relief as written, or the whole load on every contact.
fn sharing_words(pair: &crate::model::GearPair) -> Option<String> {
    match pair.load_sharing {
        crate::model::LoadSharing::Equal => None,
        crate::model::LoadSharing::None => Some("none: every contact carries the whole load".into()),
        crate::model::LoadSharing::Stiffness => {
            let relief = |name: &str, g: &crate::model::Gear| {
                g.tip_relief.as_ref().map_or_else(
                    || format!("the {name} unrelieved"),
                    |r| {
                        format!(
                            "the {name}'s tip relief {} over {} ({})",
                            r.amount.written,
                            r.length.written,
                            r.shape.name()
                        )
                    },
                )
            };
            Some(format!(
                "stiffness: the pairs in contact share by the teeth's stiffness; {}, {}",
                relief("pinion", &pair.pinion),
                relief("wheel", &pair.wheel)
            ))
        }
    }
}

/// The stage's lubrication in words (a dip's sizes in in for a report in inch–pound units).
fn lubrication_words(l: &crate::losses::Lubrication, units: super::units::Units) -> String {
    match *l {
        crate::losses::Lubrication::Dip { immersion, axis_height, housing_width } if !units.is_si() => {
            let len = units.length();
            format!(
                "dip: immersion {} / {}, axis height {}, housing width {}",
                len.cell(immersion[0], 2),
                len.with(immersion[1], 2),
                len.with(axis_height, 2),
                len.with(housing_width, 2)
            )
        }
        crate::losses::Lubrication::Dip { immersion, axis_height, housing_width } => format!(
            "dip: immersion {} / {} mm, axis height {} mm, housing width {} mm",
            immersion[0] * 1e3,
            immersion[1] * 1e3,
            axis_height * 1e3,
            housing_width * 1e3
        ),
        crate::losses::Lubrication::Injection { flow, jet_speed } => {
            format!("injection: {} l/min at {} m/s", crate::numerics::rounding::sig(flow * 6e4), jet_speed)
        }
    }
}

pub(super) fn shaft_inputs(layout: &Drive) -> Vec<ShaftInputs> {
    layout
        .shafts
        .iter()
        .enumerate()
        .map(|(j, s)| ShaftInputs {
            name: s.name.clone(),
            role: if j == layout.input {
                "input"
            } else if j == layout.output {
                "output"
            } else {
                ""
            }
            .into(),
            bearings: s
                .bearings
                .iter()
                .enumerate()
                .map(|(i, b)| (b.kind.name().to_string(), b.count, b.position.unwrap_or(0.0) * 1e3, i == s.locating))
                .collect(),
            without_at: s.bearings.iter().any(|b| b.position.is_none()),
            seals: s.seals.iter().map(|x| (x.diameter * 1e3, x.count)).collect(),
            beam: s.body.as_ref().map(|b| ShaftBeamInputs {
                material: b.material.clone(),
                youngs_modulus_gpa: b.youngs_modulus * 1e-9,
                poisson_ratio: b.poisson_ratio,
                theory: b.theory.name().to_string(),
                sections_mm: b
                    .sections
                    .iter()
                    .map(|x| [x.from, x.to, x.outer_diameter, x.bore].map(|v| v * 1e3))
                    .collect(),
                supports: s
                    .bearings
                    .iter()
                    .enumerate()
                    .map(|(i, p)| SupportInputs {
                        at_mm: p.position.unwrap_or(0.0) * 1e3,
                        radial_stiffness: s.stiffness.get(i).copied().flatten(),
                    })
                    .collect(),
            }),
        })
        .collect()
}

/// Inch–pound when every stage's pair is sized in inches, else SI.
pub(super) fn drive_unit_system(drive: &SceneDrive) -> super::number::UnitSystem {
    use super::number::UnitSystem;
    let inch = |g: &crate::model::GearPair| super::scene::pair_unit_system(g) == UnitSystem::Inch;
    if !drive.pairs.is_empty() && drive.pairs.iter().all(inch) {
        UnitSystem::Inch
    } else {
        UnitSystem::Si
    }
}

/// Every input the drive's stages, oil and housing were given, as written and in SI, as a pair's
/// Scene table lists its own (`super::scene::pair_inputs`): each stage's pair keyed from the
/// stage's name (`first.gears.module`, `first.pinion.teeth`; a planetary stage's `sun`, `planet`
/// and, from its second mesh, `ring`), then the lubricant, each stage's lubrication (a scene of one
/// pair's as `gearbox.lubrication`), each shaft's bearing places and seals, and the housing.
pub(super) fn scene_inputs(scene: &Scene, drive: &SceneDrive) -> Vec<InputRow> {
    let mut rows = Vec::new();
    for (k, stage) in drive.layout.stages.iter().enumerate() {
        let meshes = stage.model().mesh_gears();
        let prefix = format!("{}.", stage.name);
        super::scene::pair_inputs(&mut rows, &drive.pairs[k], (&prefix, meshes[0]));
        // A further mesh adds its wheel (its pinion is a gear of the stage's own pair or of an
        // earlier mesh): a planetary stage's ring.
        for (pair, names) in drive.further_pairs[k].iter().zip(meshes.iter().skip(1)) {
            super::scene::gear_inputs(&mut rows, &format!("{prefix}{}", names[1]), &pair.wheel);
        }
    }
    if let Some(l) = &scene.lubricant {
        super::scene::lubricant_inputs(&mut rows, l);
    }
    // Each stage's lubrication and each shaft's bearing places and seals, as the drive holds them
    // (a scene of one pair's keyed `gearbox.lubrication`, as the pair's own report keys them).
    let inch = !drive_unit_system(drive).is_si();
    for stage in &drive.layout.stages {
        if let Some(l) = &stage.lubrication {
            let owner = if drive.one_pair { "gearbox" } else { stage.name.as_str() };
            super::gearbox_inputs::lubrication_inputs(&mut rows, owner, l, inch);
        }
    }
    for shaft in &drive.layout.shafts {
        super::gearbox_inputs::shaft_inputs(&mut rows, &shaft.name, (&shaft.bearings, &shaft.seals), inch);
    }
    if let Some(h) = &scene.housing {
        super::gearbox_inputs::housing_inputs(&mut rows, h);
    }
    rows
}

/// (what, value, unit) of the sump's oil temperature (the lubricant's values are its
/// [`super::losses::LubricantReport`]).
pub(super) fn oil_rows(scene: &Scene) -> Vec<(String, f64, String)> {
    let mut out = Vec::new();
    // At `oil_temperature = equilibrium` the oil is read at the first row's balance (at ambient when
    // it has none); each row of the sweep at its own.
    let ambient = scene.housing.as_ref().map(|h| h.ambient);
    match (&scene.operating.oil_temperature, scene.operating.equilibrium, ambient) {
        (Some(t), Some(_), _) => out.push((
            "oil temperature (the balance of point 1; each row at its own θ*)".into(),
            t.value.value - 273.15,
            "degC".into(),
        )),
        (None, Some(_), Some(a)) => out.push((
            "oil temperature (ambient: point 1 finds no balance; each row at its own θ*)".into(),
            a - 273.15,
            "degC".into(),
        )),
        (Some(t), None, _) => out.push(("oil temperature".into(), t.value.value - 273.15, "degC".into())),
        _ => {}
    }
    out
}
