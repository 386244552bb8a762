//! The catalogue of stage kinds: each kind's typed identity, name, file and how its kinematics is
//! built from a stage of the drive.

use super::kind_id::StageKindId;
use super::parallel::Parallel;
use super::planetary::PlanetaryLayout;
use super::stage_kinematics::StageKinematics;

impl StageKindId {
    pub fn entry(self) -> &'static StageKindEntry {
        &STAGE_KINDS[self as usize]
    }
}

/// One stage kind of the catalogue.
#[derive(Clone, Copy)]
pub struct StageKindEntry {
    pub id: StageKindId,
    pub name: &'static str,
    /// Its file in `src/drive/kinematics/`.
    pub file: &'static str,
    pub title: &'static str,
    /// The kinematics of a stage of this kind from its [pinion, wheel] teeth and, for a planetary
    /// stage, its layout.
    pub kinematics: fn([u32; 2], Option<&PlanetaryLayout>) -> Box<dyn StageKinematics>,
}

/// Every stage kind.
pub const STAGE_KINDS: &[StageKindEntry] = &[
    StageKindEntry {
        id: StageKindId::Parallel,
        name: "parallel",
        file: "parallel.rs",
        title: "an external pair on parallel shafts: ω_wheel = −ω_pinion z_pinion/z_wheel",
        kinematics: |teeth, _| Box::new(Parallel { teeth }),
    },
    StageKindEntry {
        id: StageKindId::Planetary,
        name: "planetary",
        file: "planetary.rs",
        title: "sun, planets on a carrier, ring; one member held: Willis, n_s − i₀ n_r − (1 − i₀) n_c = 0",
        kinematics: |_, p| Box::new(p.expect("a planetary stage has its layout").kinematics()),
    },
];
