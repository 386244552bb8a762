//! The names of the friction laws a scene may ask for, their arguments and what they need from the scene.
//!
//! Lowering checks `friction { ... }` against this table; the laws themselves live one per file.

use crate::scene::units::Dimension;

/// Something a law reads from the scene, named by the key the user writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Needs {
    /// `roughness_ra` on both gears.
    RoughnessRa,
    /// `roughness_rq` on both gears.
    RoughnessRq,
    /// `roughness_rz` on both gears.
    RoughnessRz,
    /// `density` or `kinematic_viscosity` on the lubricant.
    KinematicViscosity,
    /// `pressure_viscosity` on the lubricant.
    PressureViscosity,
    /// A `lubricant` block at all.
    Lubricant,
}

impl Needs {
    pub fn key(self) -> &'static str {
        match self {
            Needs::RoughnessRa => "roughness_ra",
            Needs::RoughnessRq => "roughness_rq",
            Needs::RoughnessRz => "roughness_rz",
            Needs::KinematicViscosity => "kinematic_viscosity",
            Needs::PressureViscosity => "pressure_viscosity",
            Needs::Lubricant => "lubricant",
        }
    }
}

/// One argument of a law: name, dimension, default in SI (None: required).
#[derive(Debug, Clone, Copy)]
pub struct LawArgument {
    pub name: &'static str,
    pub dimension: Dimension,
    pub default: Option<f64>,
    pub what: &'static str,
}

/// One entry of the catalogue.
#[derive(Debug, Clone, Copy)]
pub struct LawEntry {
    pub id: &'static str,
    pub title: &'static str,
    pub arguments: &'static [LawArgument],
    pub needs: &'static [Needs],
}

const fn arg(name: &'static str, dimension: Dimension, default: Option<f64>, what: &'static str) -> LawArgument {
    LawArgument { name, dimension, default, what }
}

use Needs::*;

/// Every law a `.gear` file can name.
pub const LAWS: &[LawEntry] = &[
    LawEntry {
        id: "coulomb",
        title: "Coulomb (Model I)",
        arguments: &[arg("mu", Dimension::NONE, None, "coefficient of friction")],
        needs: &[],
    },
    LawEntry {
        id: "benedict_kelley",
        title: "Benedict–Kelley (He–Cho–Singh eq 14)",
        arguments: &[],
        needs: &[Lubricant, RoughnessRa],
    },
    LawEntry {
        id: "benedict_kelley_bernard",
        title: "Benedict–Kelley (Bernard Table 1)",
        arguments: &[],
        needs: &[Lubricant, RoughnessRq],
    },
    LawEntry { id: "xu", title: "Xu et al. (Model III)", arguments: &[], needs: &[Lubricant, RoughnessRa] },
    LawEntry {
        id: "smoothed_coulomb",
        title: "smoothed Coulomb (Model IV)",
        arguments: &[
            arg("mu", Dimension::NONE, None, "coefficient of friction"),
            arg("phi", Dimension::RECIPROCAL_LENGTH, Some(50e3), "smoothing factor Φ"),
        ],
        needs: &[],
    },
    LawEntry {
        id: "composite",
        title: "composite (Model V)",
        arguments: &[
            arg("filter_cutoff", Dimension::LENGTH, Some(0.8e-3), "roughness filter cut-off L_x"),
            arg("mu", Dimension::NONE, Some(f64::NAN), "Model IV magnitude (default: mean |μ_BK| over A–E)"),
            arg("phi", Dimension::RECIPROCAL_LENGTH, Some(50e3), "Model IV smoothing factor Φ"),
        ],
        needs: &[Lubricant, RoughnessRa, RoughnessRq, PressureViscosity],
    },
    LawEntry { id: "misharin", title: "Misharin", arguments: &[], needs: &[Lubricant, KinematicViscosity] },
    LawEntry {
        id: "odonoghue_cameron",
        title: "O'Donoghue–Cameron",
        arguments: &[],
        needs: &[Lubricant, RoughnessRa, KinematicViscosity],
    },
    LawEntry {
        id: "drozdov_gavrikov",
        title: "Drozdov–Gavrikov (low confidence)",
        arguments: &[],
        needs: &[Lubricant, KinematicViscosity],
    },
    LawEntry {
        id: "iso_14179_2",
        title: "ISO/TR 14179-2 (Niemann–Schlenk)",
        arguments: &[],
        needs: &[Lubricant, RoughnessRa],
    },
    LawEntry {
        id: "matsumoto",
        title: "Matsumoto (mixed regime)",
        arguments: &[
            arg("mu_boundary", Dimension::NONE, Some(0.1), "boundary friction coefficient"),
            arg("mu_ehl", Dimension::NONE, Some(0.02), "full-film friction coefficient"),
        ],
        needs: &[Lubricant, RoughnessRz, PressureViscosity],
    },
];

pub fn entry(id: &str) -> Option<&'static LawEntry> {
    LAWS.iter().find(|l| l.id == id)
}
