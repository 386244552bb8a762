//! The catalogue of friction laws: each law's typed identity ([`LawId`]), the name a scene writes,
//! its arguments and what it needs from the scene, and its own constructor.
//!
//! Lowering checks `friction { ... }` against this table and produces [`FrictionLawSpec`]s; evaluation
//! builds a law for an operating point with [`FrictionLawSpec::build`]. The laws live one per file.

use super::friction_law::FrictionLaw;
use super::law_context::LawContext;
pub use super::law_id::LawId;
pub use super::needs::{MissingInput, Needs};
use crate::diagnostics::Span;
use crate::quantity::Dimension;

impl LawId {
    /// The catalogue entry of this law.
    pub fn entry(self) -> &'static LawEntry {
        &LAWS[self as usize]
    }
}

/// A friction law named in the `friction` block (or the dynamics block), with its arguments as given.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FrictionLawSpec {
    pub law: LawId,
    /// (argument name, SI value, as written)
    pub arguments: Vec<(String, f64, String)>,
    pub span: Span,
}

impl FrictionLawSpec {
    /// `coulomb(mu = 0.04)`: the law as the user wrote it (defaults left out).
    pub fn label(&self) -> String {
        let args: Vec<String> =
            self.arguments.iter().filter(|(_, _, w)| w != "default").map(|(n, _, w)| format!("{n} = {w}")).collect();
        if args.is_empty() {
            self.law.name().to_string()
        } else {
            format!("{}({})", self.law.name(), args.join(", "))
        }
    }

    pub fn argument(&self, name: &str) -> Option<f64> {
        self.arguments.iter().find(|(n, _, _)| n == name).map(|(_, v, _)| *v)
    }

    /// The argument in SI: lowering fills in every default and checks every required one, so an
    /// absent argument here is an input the law cannot do without.
    fn arg(&self, name: &str) -> Result<f64, MissingInput> {
        self.argument(name).ok_or_else(|| MissingInput { law: self.law, key: name.to_string() })
    }

    /// Names the law in a need its constructor found unmet.
    fn missing(&self) -> impl Fn(Needs) -> MissingInput + '_ {
        |n| MissingInput { law: self.law, key: n.key().to_string() }
    }

    /// Builds the law for one operating point, by the constructor of its catalogue entry; an input
    /// the law needs and the scene lacks (lowering reports it first, with its span) is a [`MissingInput`].
    pub fn build(&self, ctx: &LawContext) -> BuiltLaw {
        (self.law.entry().build)(self, ctx)
    }
}

/// What a law does when a scene leaves an argument out.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ArgumentDefault {
    /// The scene must give it.
    Required,
    /// This value, in SI.
    Value(f64),
    /// The law derives it from the scene (its docs say how); absent from the law's arguments.
    Derived,
}

/// A law built for one operating point, or the input it lacks.
pub type BuiltLaw = Result<Box<dyn FrictionLaw>, MissingInput>;

/// One argument of a law: name, dimension, what it takes when left out.
#[derive(Debug, Clone, Copy)]
pub struct LawArgument {
    pub name: &'static str,
    pub dimension: Dimension,
    pub default: ArgumentDefault,
    pub what: &'static str,
}

/// One entry of the catalogue.
#[derive(Debug, Clone, Copy)]
pub struct LawEntry {
    pub id: LawId,
    pub title: &'static str,
    pub arguments: &'static [LawArgument],
    pub needs: &'static [Needs],
    /// Where the formula comes from (the equation or table it implements).
    pub source: &'static str,
    /// Builds the law at one operating point from the lowered arguments.
    pub build: fn(&FrictionLawSpec, &LawContext) -> BuiltLaw,
}

const fn arg(name: &'static str, dimension: Dimension, default: ArgumentDefault, what: &'static str) -> LawArgument {
    LawArgument { name, dimension, default, what }
}

use ArgumentDefault::{Derived, Required, Value};
use Needs::*;

/// Every law a `.gear` file can name.
pub const LAWS: &[LawEntry] = &[
    LawEntry {
        id: LawId::Coulomb,
        title: "Coulomb (Model I)",
        arguments: &[arg("mu", Dimension::NONE, Required, "coefficient of friction")],
        needs: &[],
        source: "He, Cho & Singh (2008) eq 10; Fernandes et al. §2.1",
        build: |s, _| Ok(Box::new(super::coulomb::Coulomb { mu: s.arg("mu")? })),
    },
    LawEntry {
        id: LawId::BenedictKelley,
        title: "Benedict–Kelley (He–Cho–Singh eq 14)",
        arguments: &[],
        needs: &[Lubricant, RoughnessRa],
        source: "Benedict & Kelley (1961) as He, Cho & Singh (2008) eq 14 write it",
        build: |s, ctx| Ok(Box::new(super::benedict_kelley::BenedictKelley::new(&ctx.tribology).map_err(s.missing())?)),
    },
    LawEntry {
        id: LawId::BenedictKelleyBernard,
        title: "Benedict–Kelley (Bernard Table 1)",
        arguments: &[],
        needs: &[Lubricant, RoughnessRq],
        source: "Benedict & Kelley (1961) as Bernard et al. (2016) Table 1 write it",
        build: |s, ctx| {
            Ok(Box::new(
                super::benedict_kelley_bernard::BenedictKelleyBernard::new(&ctx.tribology).map_err(s.missing())?,
            ))
        },
    },
    LawEntry {
        id: LawId::Xu,
        title: "Xu et al. (Model III)",
        arguments: &[],
        needs: &[Lubricant, RoughnessRa],
        source: "Xu et al. (2007) as He, Cho & Singh (2008) eq 18 write it",
        build: |s, ctx| Ok(Box::new(super::xu::Xu::new(&ctx.tribology).map_err(s.missing())?)),
    },
    LawEntry {
        id: LawId::SmoothedCoulomb,
        title: "smoothed Coulomb (Model IV)",
        arguments: &[
            arg("mu", Dimension::NONE, Required, "coefficient of friction"),
            arg("phi", Dimension::RECIPROCAL_LENGTH, Value(50e3), "smoothing factor Φ"),
        ],
        needs: &[],
        source: "Duan & Singh, as He, Cho & Singh (2008) eq 19 write it",
        build: |s, _| Ok(Box::new(super::smoothed_coulomb::SmoothedCoulomb { mu: s.arg("mu")?, phi: s.arg("phi")? })),
    },
    LawEntry {
        id: LawId::Composite,
        title: "composite (Model V)",
        arguments: &[
            arg("filter_cutoff", Dimension::LENGTH, Value(0.8e-3), "roughness filter cut-off L_x"),
            arg("mu", Dimension::NONE, Derived, "Model IV magnitude (default: mean |μ_BK| over A–E)"),
            arg("phi", Dimension::RECIPROCAL_LENGTH, Value(50e3), "Model IV smoothing factor Φ"),
        ],
        needs: &[Lubricant, RoughnessRa, RoughnessRq, PressureViscosity],
        source: "He, Cho & Singh (2008) eqs 20–21 (Λ picks Models IV, II, III)",
        build: |s, ctx| {
            let law = super::composite::Composite::new(ctx, s.arg("filter_cutoff")?, s.argument("mu"), s.arg("phi")?);
            Ok(Box::new(law.map_err(s.missing())?))
        },
    },
    LawEntry {
        id: LawId::Misharin,
        title: "Misharin",
        arguments: &[],
        needs: &[Lubricant, KinematicViscosity],
        source: "Misharin, as Bernard et al. (2016) Table 1 write it",
        build: |s, ctx| Ok(Box::new(super::misharin::Misharin::new(&ctx.tribology).map_err(s.missing())?)),
    },
    LawEntry {
        id: LawId::ODonoghueCameron,
        title: "O'Donoghue–Cameron",
        arguments: &[],
        needs: &[Lubricant, RoughnessRa, KinematicViscosity],
        source: "O'Donoghue & Cameron, as Bernard et al. (2016) Table 1 write it",
        build: |s, ctx| {
            Ok(Box::new(super::odonoghue_cameron::ODonoghueCameron::new(&ctx.tribology).map_err(s.missing())?))
        },
    },
    LawEntry {
        id: LawId::DrozdovGavrikov,
        title: "Drozdov–Gavrikov (low confidence)",
        arguments: &[],
        needs: &[Lubricant, KinematicViscosity],
        source: "Drozdov & Gavrikov, as Bernard et al. (2016) Table 1 print it (garbled there; one reading)",
        build: |s, ctx| {
            Ok(Box::new(super::drozdov_gavrikov::DrozdovGavrikov::new(&ctx.tribology).map_err(s.missing())?))
        },
    },
    LawEntry {
        id: LawId::Iso14179_2,
        title: "ISO/TR 14179-2 (Niemann–Schlenk)",
        // Left out, X_L is read from the lubricant's base oil.
        arguments: &[arg("x_l", Dimension::NONE, Derived, "lubricant factor X_L (default: the lubricant's)")],
        needs: &[Lubricant, RoughnessRa],
        source: "ISO/TR 14179-2:2001 (Niemann & Schlenk mean μ_mZ)",
        build: |s, ctx| Ok(Box::new(super::iso_14179_2::Iso14179_2::new(ctx, s.argument("x_l")).map_err(s.missing())?)),
    },
    LawEntry {
        id: LawId::Matsumoto,
        title: "Matsumoto (mixed regime)",
        arguments: &[
            arg("mu_boundary", Dimension::NONE, Value(0.1), "boundary friction coefficient"),
            arg("mu_ehl", Dimension::NONE, Value(0.02), "full-film friction coefficient"),
        ],
        needs: &[Lubricant, RoughnessRz, PressureViscosity],
        source: "Matsumoto mixed-regime blend ξ = 0.5 log10(Rz/h_min) with Dowson–Higginson h_min",
        build: |s, ctx| {
            let law = super::matsumoto::Matsumoto::new(&ctx.tribology, s.arg("mu_boundary")?, s.arg("mu_ehl")?);
            Ok(Box::new(law.map_err(s.missing())?))
        },
    },
];

/// The entry a scene names, by its written name.
pub fn entry(name: &str) -> Option<&'static LawEntry> {
    LAWS.iter().find(|l| l.id.name() == name)
}

impl<'de> serde::Deserialize<'de> for LawId {
    /// A law's scene name, read back through the catalogue.
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<LawId, D::Error> {
        let name = String::deserialize(d)?;
        entry(&name)
            .map(|e| e.id)
            .ok_or_else(|| serde::de::Error::custom(format!("`{name}` is not a law of the catalogue")))
    }
}
