//! The catalogue of dynamic models: each model's typed identity, the name a scene writes
//! (`model = six_dof`) and the report prints, its file and a one-line title.

use super::gear_dynamics::{GearDynamics, ModelInputs};
pub(crate) use super::model_id::DynamicModelId;
use super::{sdof, six_dof};
use crate::dynamics::DynamicFormulation;

impl DynamicModelId {
    /// The catalogue entry of this model.
    pub fn entry(self) -> &'static DynamicModelEntry {
        &MODELS[self as usize]
    }

    pub fn name(self) -> &'static str {
        self.entry().name
    }
}

/// One model of the catalogue.
#[derive(Debug, Clone, Copy)]
pub struct DynamicModelEntry {
    pub id: DynamicModelId,
    /// The name a scene writes in its `dynamics` block (`model = sdof`).
    pub name: &'static str,
    /// Its file in `src/dynamics/models/`.
    pub file: &'static str,
    pub title: &'static str,
    /// How the report and messages call it ("SDOF").
    pub label: &'static str,
    /// Whether it stands the gears on bearings (a scene then gives `bearings` and the gears' masses).
    pub on_bearings: bool,
    /// The formulations it takes, and why when not all of them.
    pub formulations: &'static [DynamicFormulation],
    pub formulations_reason: &'static str,
    /// Its constructor; `None` when the scene lacks an input the model needs (lowering refuses a
    /// scene that asks for dynamics without them, naming the key).
    pub build: fn(&ModelInputs) -> Option<Box<dyn GearDynamics>>,
}

/// Every dynamic model.
pub const MODELS: &[DynamicModelEntry] = &[
    DynamicModelEntry {
        id: DynamicModelId::Sdof,
        name: "sdof",
        file: "sdof.rs",
        title: "torsional SDOF model along the line of action (Fernandes et al.)",
        label: "SDOF",
        on_bearings: false,
        formulations: &[
            DynamicFormulation::Base,
            DynamicFormulation::External,
            DynamicFormulation::Internal,
            DynamicFormulation::InternalChord,
        ],
        formulations_reason: "",
        build: sdof::build,
    },
    DynamicModelEntry {
        id: DynamicModelId::SixDof,
        name: "six_dof",
        file: "six_dof.rs",
        title: "rotation and both translations of each gear on its bearings (He–Cho–Singh; He & Singh)",
        label: "6-DOF",
        on_bearings: true,
        formulations: &[DynamicFormulation::Base, DynamicFormulation::Internal],
        formulations_reason: "friction acts through the mesh force",
        build: six_dof::build,
    },
];

/// The entry a scene names, if any.
pub(crate) fn entry(name: &str) -> Option<&'static DynamicModelEntry> {
    MODELS.iter().find(|m| m.name == name)
}
