//! The setup of an evaluation: what every operating point reads.

use super::cases::{Case, CURVE_SAMPLES};
use crate::friction::LawContext;
use crate::geometry::contact::Sharing;
use crate::geometry::{ContactPoint, OperatingState, PairGeometry};
use crate::model::{Formulation, LoadSharing};
use crate::tribology::{FilmInputs, Tribology};

/// What every operating point of a scene reads: geometry, materials, lubricant, the fixed sample
/// positions and the detail cases ([`super::prepare::prepare`] builds it once). The laws, the stream of a
/// sweep and the map take this, not the [`super::evaluation::Evaluation`] that holds their results.
#[derive(Debug, Clone)]
pub struct Setup {
    /// The operating points reported in full (the plan's detail points).
    pub cases: Vec<Case>,
    /// The contact-state table's positions (A..E in equal steps with B, P, D).
    pub table_rows: Vec<(Option<&'static str>, f64)>,
    /// [`Setup::curve_positions`], computed once.
    pub positions: Vec<f64>,
    /// Whether an analysis needs the friction laws.
    pub wants_friction: bool,
    pub geometry: PairGeometry,
    /// E' (Pa).
    pub reduced_modulus: f64,
    pub sharing: LoadSharing,
    /// The pair's stiffness and reliefs, for `load_sharing = stiffness` (built once per geometry).
    pub stiffness_sharing: Option<crate::geometry::teeth::load_sharing::LoadSharing>,
    pub tribology: Tribology,
    /// Ohlendorf's gear loss factor H_V (geometry only).
    pub ohlendorf_loss_factor: f64,
    /// Formulations evaluated (empty when the scene asks for no efficiency).
    pub formulations: Vec<Formulation>,
    /// Film-thickness inputs when the film is computed (α known and asked for or needed).
    pub film_inputs: Option<(FilmInputs, Option<(f64, f64)>)>,
}

impl Setup {
    pub fn sharing(&self) -> Sharing<'_> {
        match (self.sharing, &self.stiffness_sharing) {
            (LoadSharing::None, _) => Sharing::Whole,
            (LoadSharing::Stiffness, Some(model)) => Sharing::Stiffness(model),
            // (Lowering has checked that the teeth can be built when the scene shares by stiffness.)
            (LoadSharing::Equal | LoadSharing::Stiffness, _) => Sharing::Equal,
        }
    }

    /// The friction-law context at an operating point.
    pub fn law_context(&self, state: OperatingState) -> LawContext<'_> {
        LawContext { geometry: &self.geometry, state, tribology: self.tribology, sharing: self.sharing() }
    }

    /// The contact state at `u` for an operating point, as the friction laws and the efficiency read
    /// it ([`crate::geometry::Mesh::contact_at`]): a spur pair's pairs in contact with their shares; a
    /// helical pair's contact under the mean load per unit line length F_bn / L̄ (the tables and plots
    /// of the contact show what μ is read at).
    pub fn contact_at(&self, u: f64, state: &OperatingState) -> ContactPoint {
        self.law_context(*state).contact_at(u)
    }

    /// `curve_positions` of the pair's geometry: where its curves are drawn and a law's validity is read.
    pub fn curve_positions(&self) -> Vec<f64> {
        curve_positions(&self.geometry)
    }
}

/// Evenly spaced positions from A to E ([`CURVE_SAMPLES`] of them) with the pitch point and every
/// point where the number of pairs changes (B and D for ε_α < 2) taken from both sides: where a
/// pair's curves are drawn (the jumps of the load share vertical) and a law's validity is read, on
/// a pair alone and on every stage's mesh of a drive alike.
pub(crate) fn curve_positions(g: &PairGeometry) -> Vec<f64> {
    let p = &g.points;
    let eps = 1e-9 * (p.e - p.a);
    let mut u: Vec<f64> =
        (0..CURVE_SAMPLES).map(|i| p.a + (p.e - p.a) * i as f64 / (CURVE_SAMPLES - 1) as f64).collect();
    u.push(p.p);
    for (_, c) in g.pair_change_points() {
        u.push(c);
        // The side on which the number of pairs differs from the point itself (B: before, D: after).
        u.extend([c - eps, c + eps].into_iter().filter(|v| g.pairs_in_contact(*v) != g.pairs_in_contact(c)));
    }
    u.sort_by(f64::total_cmp);
    u
}

/// The contact-state table of one operating point.
pub fn contact_table(eval: &Setup, state: &OperatingState) -> Vec<(Option<&'static str>, ContactPoint)> {
    eval.table_rows.iter().map(|(name, u)| (*name, eval.contact_at(*u, state))).collect()
}

/// The law of `spec` at `ctx`. Lowering refuses a scene that lacks an input a law needs (the
/// catalogue's `needs`, checked with the law's span), and whether a scene gives an input does not
/// change between operating points: a [`crate::friction::catalog::MissingInput`] here is a defect
/// of gearloss, not of the scene, and stops the run loudly rather than putting NaN in a report.
pub(crate) fn law_at(spec: &crate::model::FrictionLawSpec, ctx: &LawContext) -> Box<dyn crate::friction::FrictionLaw> {
    spec.build(ctx).unwrap_or_else(|missing| panic!("lowering let a law through without its input: {missing}"))
}
