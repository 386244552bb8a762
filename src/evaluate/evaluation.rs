//! Everything computed for one scene: the setup and the results at the detail points.

use serde::Serialize;

use super::contact_curves::ContactCurves;
use super::dynamics::DynamicsEvaluation;
use super::laws::LawEvaluation;
use super::setup::Setup;
use crate::geometry::{ContactPoint, OperatingState};
use crate::tribology::Film;

/// Everything computed for one scene: its [`Setup`] (read through `Deref`, so `eval.geometry` is
/// the setup's) and the results at the detail points.
#[derive(Debug, Clone)]
pub struct Evaluation {
    pub setup: Setup,
    pub points: Vec<PointEvaluation>,
    pub contact_curves: ContactCurves,
    /// The dynamics, when the scene asks for them.
    pub dynamics: Option<DynamicsEvaluation>,
    /// The teeth's stiffness and transmission error, when the scene asks for them.
    pub teeth: Option<super::teeth::TeethDetails>,
}

impl std::ops::Deref for Evaluation {
    type Target = Setup;

    fn deref(&self) -> &Setup {
        &self.setup
    }
}

/// Everything computed at one operating point.
#[derive(Debug, Clone, Serialize)]
pub struct PointEvaluation {
    /// Index into [`Setup::cases`].
    pub case: usize,
    pub state: OperatingState,
    /// T = 2π/(ω1 z1) (s).
    pub mesh_period: f64,
    /// The contact-state table: the named points A B P D E and equal steps between A and E.
    pub table: Vec<(Option<&'static str>, ContactPoint)>,
    /// Film thickness at the table rows, when computed.
    pub film: Option<Vec<Film>>,
    /// One entry per law of the scene, in the scene's order (empty when no analysis needs friction).
    pub laws: Vec<LawEvaluation>,
    /// Whether curves (for plots) were computed at this point.
    pub has_curves: bool,
}
