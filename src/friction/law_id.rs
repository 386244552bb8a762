//! The typed identity of each law of the catalogue, and the name a scene writes for it.

use serde::Serialize;

/// The typed identity of a law of the catalogue (serialised as its scene name).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LawId {
    Coulomb,
    BenedictKelley,
    BenedictKelleyBernard,
    Xu,
    SmoothedCoulomb,
    Composite,
    Misharin,
    ODonoghueCameron,
    DrozdovGavrikov,
    Iso14179_2,
    Matsumoto,
}

impl LawId {
    /// The name a scene writes (`coulomb`), also used in report.json.
    pub fn name(self) -> &'static str {
        match self {
            LawId::Coulomb => "coulomb",
            LawId::BenedictKelley => "benedict_kelley",
            LawId::BenedictKelleyBernard => "benedict_kelley_bernard",
            LawId::Xu => "xu",
            LawId::SmoothedCoulomb => "smoothed_coulomb",
            LawId::Composite => "composite",
            LawId::Misharin => "misharin",
            LawId::ODonoghueCameron => "odonoghue_cameron",
            LawId::DrozdovGavrikov => "drozdov_gavrikov",
            LawId::Iso14179_2 => "iso_14179_2",
            LawId::Matsumoto => "matsumoto",
        }
    }
}

impl std::fmt::Display for LawId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl Serialize for LawId {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}
