//! The tally of a run: what the report needs from every operating point, in a size that does not
//! grow with the sweep. Points are folded in sweep order; two tallies of consecutive ranges of
//! points fold into the tally of their union ([`Tally::absorb`]), so the shards of a sharded run
//! merge into exactly the tally of a single run (ties go to the later point, as in one pass).

use serde::{Deserialize, Serialize};

use super::records::{RowKind, SummaryRow};
use crate::efficiency::EfficiencyResult;
use crate::geometry::ContactPoint;

/// b_H / R above which the half-space (line-contact) assumption of Hertz's formulas fails.
pub(crate) const HALF_WIDTH_LIMIT: f64 = 0.1;

/// Findings of one kind listed one by one before only their count is given.
pub(crate) const LISTED_FINDINGS: usize = 20;
/// Distinct notes kept per law.
pub(crate) const KEPT_NOTES: usize = 32;

/// A result outside what the formulas allow, at one operating point.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Implausible {
    /// Hertz half-width above R/10 at a table row: (b_H, R/10, u from T1, named point).
    HalfWidth { half_width: f64, limit: f64, u: f64, named: Option<String> },
    /// Efficiency outside [0, 1].
    Efficiency { law: String, formulation: String, mean: f64, min: f64, max: f64 },
    /// Power loss above the input power.
    PowerLoss { law: String, formulation: String, loss: f64, input: f64 },
}

/// One implausible result with its operating point (0-based) and label.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ImplausibleAt {
    pub point: usize,
    pub label: String,
    pub what: Implausible,
}

/// The worst validity record of a law: the point (0-based) with the most samples outside.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct WorstValidity {
    pub point: usize,
    pub outside: usize,
    pub samples: usize,
    /// (from, to) from T1 (m) and the reason.
    pub intervals: Vec<(f64, f64, String)>,
}

/// Operating points listed with a note before only their count is given.
pub(crate) const NOTE_POINTS: usize = 8;

/// A law's note and the operating points (0-based) it was made at: the first [`NOTE_POINTS`] of
/// them, and how many in all.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LawNote {
    pub text: String,
    pub points: Vec<usize>,
    pub count: usize,
}

/// One law over the points.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct LawTally {
    pub points: usize,
    /// Distinct notes in order of appearance, at most [`KEPT_NOTES`], each with its points.
    pub notes: Vec<LawNote>,
    pub diverges_at_pitch: bool,
    /// Points where the internal formulation caps |μ|, and the widest band (point, from, to).
    pub capped_points: usize,
    pub widest_cap: Option<(usize, f64, f64)>,
    /// Points with samples outside the validity range, and the worst.
    pub flagged_points: usize,
    pub worst: Option<WorstValidity>,
}

impl LawTally {
    fn absorb(&mut self, o: LawTally) {
        self.points += o.points;
        for n in o.notes {
            if let Some(m) = self.notes.iter_mut().find(|m| m.text == n.text) {
                m.count += n.count;
                let room = NOTE_POINTS.saturating_sub(m.points.len());
                m.points.extend(n.points.into_iter().take(room));
            } else if self.notes.len() < KEPT_NOTES {
                self.notes.push(n);
            }
        }
        self.diverges_at_pitch |= o.diverges_at_pitch;
        self.capped_points += o.capped_points;
        let width = |w: &Option<(usize, f64, f64)>| w.map(|(_, a, b)| b - a);
        if o.widest_cap.is_some() && (self.widest_cap.is_none() || width(&o.widest_cap) >= width(&self.widest_cap)) {
            self.widest_cap = o.widest_cap;
        }
        self.flagged_points += o.flagged_points;
        if let Some(w) = o.worst {
            if self.worst.as_ref().is_none_or(|s| w.outside >= s.outside) {
                self.worst = Some(w);
            }
        }
    }
}

/// A located value over the sweep's points: the value and its point (0-based).
pub(crate) type AtPoint = (f64, usize);

/// Extremes of one law and formulation over the sweep's points (exact over the evaluated points).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepExtremes {
    pub label: String,
    pub formulation: String,
    pub min_efficiency: Option<AtPoint>,
    pub max_efficiency: Option<AtPoint>,
    pub max_power_loss: Option<AtPoint>,
}

fn lower(a: &mut Option<AtPoint>, b: Option<AtPoint>, below: bool) {
    if let Some(b) = b.filter(|b| b.0.is_finite()) {
        let better = match a {
            None => true,
            Some(a) => (below && b.0 < a.0) || (!below && b.0 > a.0),
        };
        if better {
            *a = Some(b);
        }
    }
}

/// One dynamic formulation over the points.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DynamicsTally {
    pub formulation: String,
    pub points: usize,
    /// Points whose spectral radius exceeds 1 (no steady state).
    pub unstable_points: usize,
    pub max_spectral_radius: Option<AtPoint>,
}

/// What the report needs from every point.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Tally {
    pub points: usize,
    pub rows: usize,
    /// Record values that are not finite numbers (empty CSV cells, `null` in JSON Lines), and the first.
    pub non_finite: usize,
    pub first_non_finite: Option<(usize, String)>,
    /// The rows of the points the report tabulates and plots ([`super::plan::Plan::kept`]).
    pub kept: Vec<SummaryRow>,
    pub laws: Vec<LawTally>,
    pub implausible_count: usize,
    /// The first `LISTED_FINDINGS` implausible results.
    pub implausible: Vec<ImplausibleAt>,
    pub extremes: Vec<SweepExtremes>,
    pub dynamics: Vec<DynamicsTally>,
}

impl Tally {
    /// Folds the tally of the points that follow this tally's points.
    pub fn absorb(&mut self, o: Tally) {
        self.points += o.points;
        self.rows += o.rows;
        self.non_finite += o.non_finite;
        if self.first_non_finite.is_none() {
            self.first_non_finite = o.first_non_finite;
        }
        self.kept.extend(o.kept);
        if self.laws.len() < o.laws.len() {
            self.laws.resize(o.laws.len(), LawTally::default());
        }
        for (a, b) in self.laws.iter_mut().zip(o.laws) {
            a.absorb(b);
        }
        self.implausible_count += o.implausible_count;
        let room = LISTED_FINDINGS.saturating_sub(self.implausible.len());
        self.implausible.extend(o.implausible.into_iter().take(room));
        for e in o.extremes {
            match self.extremes.iter_mut().find(|x| x.label == e.label && x.formulation == e.formulation) {
                Some(x) => {
                    lower(&mut x.min_efficiency, e.min_efficiency, true);
                    lower(&mut x.max_efficiency, e.max_efficiency, false);
                    lower(&mut x.max_power_loss, e.max_power_loss, false);
                }
                None => self.extremes.push(e),
            }
        }
        for d in o.dynamics {
            match self.dynamics.iter_mut().find(|x| x.formulation == d.formulation) {
                Some(x) => {
                    x.points += d.points;
                    x.unstable_points += d.unstable_points;
                    lower(&mut x.max_spectral_radius, d.max_spectral_radius, false);
                }
                None => self.dynamics.push(d),
            }
        }
    }

    /// The tally of one point: its rows (kept when `keep`), its laws and its implausible results.
    pub fn of_point(
        point: usize,
        rows: &[SummaryRow],
        keep: bool,
        laws: Vec<LawTally>,
        implausible: Vec<ImplausibleAt>,
    ) -> Tally {
        let mut t = Tally { points: 1, rows: rows.len(), laws, ..Default::default() };
        let at = |x: Option<f64>| x.filter(|x| x.is_finite()).map(|x| (x, point));
        for row in rows {
            for column in row.non_finite() {
                t.non_finite += 1;
                if t.first_non_finite.is_none() {
                    t.first_non_finite = Some((point, column.to_string()));
                }
            }
            match row.kind {
                RowKind::Efficiency => t.extremes.push(SweepExtremes {
                    label: row.label.clone(),
                    formulation: row.formulation.clone(),
                    min_efficiency: at(row.mean_efficiency),
                    max_efficiency: at(row.mean_efficiency),
                    max_power_loss: at(row.power_loss),
                }),
                RowKind::Dynamics => t.dynamics.push(DynamicsTally {
                    formulation: row.formulation.clone(),
                    points: 1,
                    unstable_points: usize::from(row.spectral_radius.is_some_and(|r| r > 1.0 + 1e-9)),
                    max_spectral_radius: at(row.spectral_radius),
                }),
                RowKind::Friction | RowKind::TransmissionError => {}
            }
        }
        if keep {
            t.kept = rows.to_vec();
        }
        t.implausible_count = implausible.len();
        t.implausible = implausible;
        t.implausible.truncate(LISTED_FINDINGS);
        t
    }
}

/// Of `contacts` (each with its name, `B`, where it has one), the one whose Hertzian half-width is
/// furthest beyond its limit (a fraction of the reduced radius), if any is beyond it: a pair's
/// contact table at each point and each stage mesh's of a drive's row.
pub(crate) fn furthest_beyond_half_width<'a>(
    contacts: impl IntoIterator<Item = (Option<&'a str>, ContactPoint)>,
) -> Option<(Option<&'a str>, ContactPoint)> {
    contacts.into_iter().filter(|(_, c)| c.hertz_half_width > HALF_WIDTH_LIMIT * c.reduced_radius).max_by(|a, b| {
        (a.1.hertz_half_width / a.1.reduced_radius).total_cmp(&(b.1.hertz_half_width / b.1.reduced_radius))
    })
}

/// How far past [0, 1] an efficiency may lie and still be rounding: 4 units in the last place of
/// 1 (8.9e-16). η = 1 − P/P_in is computed from integrals whose last bits are rounding; one step
/// above 1 is not a law giving negative friction.
pub(crate) const EFFICIENCY_ULPS: f64 = 4.0 * f64::EPSILON;

/// Whether an efficiency lies outside [0, 1] by more than rounding (`EFFICIENCY_ULPS`): a pair's
/// and a drive's stage meshes' alike.
pub(crate) fn outside_unit_interval(eta: f64) -> bool {
    !(-EFFICIENCY_ULPS..=1.0 + EFFICIENCY_ULPS).contains(&eta)
}

/// An efficiency outside [0, 1] (beyond `EFFICIENCY_ULPS`) or a power loss above the input power.
pub fn implausible_efficiency(law: &str, e: &EfficiencyResult, input: f64) -> Vec<Implausible> {
    let mut out = Vec::new();
    let f = e.formulation.name().to_string();
    let bad = outside_unit_interval;
    if bad(e.mean.value) || bad(e.min) || bad(e.max) {
        out.push(Implausible::Efficiency {
            law: law.into(),
            formulation: f.clone(),
            mean: e.mean.value,
            min: e.min,
            max: e.max,
        });
    }
    if e.power_loss > input {
        out.push(Implausible::PowerLoss { law: law.into(), formulation: f, loss: e.power_loss, input });
    }
    out
}
