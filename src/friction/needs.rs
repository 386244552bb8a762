//! What a law reads from the scene beyond its own arguments ([`Needs`]), and the error of a law
//! built without it ([`MissingInput`]). Lowering checks a scene against the catalogue rows' needs,
//! with spans; each law's constructor reads its inputs through [`Needs::of`].

use super::law_id::LawId;

/// An input a law needs that the scene does not give: an argument or one of its [`Needs`].
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("`{}` needs `{key}`, which the scene does not give", law.name())]
pub struct MissingInput {
    pub law: LawId,
    pub key: String,
}

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
    /// The value a scene gives for this need (from [`crate::tribology::Tribology`]), or the need.
    pub fn of(self, given: Option<f64>) -> Result<f64, Needs> {
        given.ok_or(self)
    }

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
