//! The friction, film and efficiency parts of the report (serde data).

use serde::{Deserialize, Serialize};

use super::finding::{Finding, Severity};
pub use super::law_values::{MuValue, Parameters};
use super::number::{m, Num, Q};
use crate::evaluate::records::RowKind;
use crate::evaluate::{Evaluation, LawEvaluation, PointEvaluation, Tally};
use crate::friction::Regime;
use crate::mesh::MeshProblem;
use crate::model::{Formulation, FrictionLawSpec};

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct MuRow {
    pub point: Option<String>,
    pub distance_from_t1: Q,
    pub mu: MuValue,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub regime: Option<Regime>,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ValidityInterval {
    pub from: Q,
    pub to: Q,
    pub reason: String,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ValidityReport {
    /// Contacts sampled along A–E: 241 evenly, the pitch point and both sides of B and D.
    pub samples: usize,
    /// How many of them lie outside the law's validity range.
    pub outside: usize,
    pub intervals: Vec<ValidityInterval>,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct EfficiencyReport {
    pub formulation: Formulation,
    pub mean_efficiency: Num,
    pub error_estimate: Num,
    pub power_loss: Q,
    pub min_efficiency: Num,
    pub max_efficiency: Num,
}

/// One law at one operating point.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct LawReport {
    pub law: crate::friction::catalog::LawId,
    /// As written in the scene, e.g. `coulomb(mu = 0.04)`.
    pub label: String,
    pub title: String,
    pub parameters: Parameters,
    pub diverges_at_pitch: bool,
    pub mu_along_loa: Vec<MuRow>,
    pub mean_abs_mu: Num,
    pub mean_abs_mu_error: Num,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub regime_switches_from_t1: Vec<Q>,
    pub validity: ValidityReport,
    pub efficiency: Vec<EfficiencyReport>,
    /// 1 − μ̄ H_V, μ̄ the mean |μ| over A–E (Ohlendorf's cross-check).
    pub ohlendorf_efficiency: Num,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct FilmRow {
    pub point: Option<String>,
    pub distance_from_t1: Q,
    pub central_film: Q,
    pub minimum_film: Q,
    /// He–Cho–Singh's film parameter Λ_HCS = h_c / R_comp · sqrt(L_x / (2 b_H)).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lambda: Option<Num>,
    /// The specific film thickness λ = h_min / σ, σ = sqrt(Rq1² + Rq2²).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub specific_film: Option<Num>,
}

/// One record per (operating point, law, formulation): the flat table of a sweep.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct EfficiencyRecord {
    /// The case (operating point) and its torque and speed indices in the sweeps, for grouping.
    pub case: usize,
    pub torque_index: usize,
    pub speed_index: usize,
    pub law: crate::friction::catalog::LawId,
    pub label: String,
    pub formulation: Formulation,
    pub pinion_torque: Q,
    pub pinion_speed: Q,
    pub mean_efficiency: Num,
    pub error_estimate: Num,
    pub power_loss: Q,
    pub parameters: Parameters,
    /// Helical pairs: ISO/TR 14179-2's own mesh loss P_VZP = P_in μ̄ H_V (Ohlendorf's H_V, μ̄ the
    /// record's mean |μ|) beside `power_loss`, the contact-line integral (`ohlendorf_power_loss`
    /// and `line_integral_ratio` in report.json).
    #[serde(default, flatten)]
    pub ohlendorf: Option<OhlendorfLoss>,
}

/// ISO/TR 14179-2's mesh loss beside the contact-line integral.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
pub struct OhlendorfLoss {
    /// P_in μ̄ H_V (W).
    #[serde(rename = "ohlendorf_power_loss")]
    pub power_loss: Q,
    /// The line integral's loss over it.
    pub line_integral_ratio: Num,
}

/// `coulomb(mu = 0.04)`: the law as the user wrote it (defaults left out).
pub fn law_label(spec: &FrictionLawSpec) -> String {
    spec.label()
}

pub fn parameters(law: &LawEvaluation) -> Parameters {
    Parameters(law.parameter_values())
}

pub fn law_report(spec: &FrictionLawSpec, pe: &PointEvaluation, law: &LawEvaluation) -> LawReport {
    LawReport {
        law: law.id,
        label: law_label(spec),
        title: law.title.into(),
        parameters: parameters(law),
        diverges_at_pitch: law.diverges_at_pitch,
        mu_along_loa: pe
            .table
            .iter()
            .enumerate()
            .map(|(i, (name, c))| MuRow {
                point: name.map(String::from),
                distance_from_t1: m(c.u),
                mu: law.table[i].map_or(MuValue::Text("diverges"), |v| MuValue::Value(Num(v))),
                regime: law.regimes.as_ref().map(|r| r[i]),
            })
            .collect(),
        mean_abs_mu: Num(law.mean_abs_mu.value),
        mean_abs_mu_error: Num(law.mean_abs_mu.error),
        regime_switches_from_t1: law.switch_points.iter().map(|u| m(*u)).collect(),
        validity: ValidityReport {
            samples: law.validity.samples,
            outside: law.validity.outside,
            intervals: law
                .validity
                .intervals
                .iter()
                .map(|(a, b, r)| ValidityInterval { from: m(*a), to: m(*b), reason: r.to_string() })
                .collect(),
        },
        efficiency: law
            .efficiency
            .iter()
            .map(|e| EfficiencyReport {
                formulation: e.formulation,
                mean_efficiency: Num(e.mean.value),
                error_estimate: Num(e.mean.error),
                power_loss: Q::new(e.power_loss, "W"),
                min_efficiency: Num(e.min),
                max_efficiency: Num(e.max),
            })
            .collect(),
        ohlendorf_efficiency: Num(law.ohlendorf_efficiency),
    }
}

pub fn film_rows(pe: &PointEvaluation) -> Option<Vec<FilmRow>> {
    pe.film.as_ref().map(|films| {
        pe.table
            .iter()
            .zip(films)
            .map(|((name, c), f)| FilmRow {
                point: name.map(String::from),
                distance_from_t1: m(c.u),
                central_film: m(f.central),
                minimum_film: m(f.minimum),
                lambda: f.lambda.map(Num),
                specific_film: f.specific.map(Num),
            })
            .collect()
    })
}

/// The efficiency records the report keeps (every point of a small sweep; the plotted ones of a
/// large one), from the run's tally.
pub fn efficiency_records(problem: &MeshProblem, eval: &Evaluation, tally: &Tally) -> Vec<EfficiencyRecord> {
    let helical = eval.geometry.helix_angle != 0.0;
    tally
        .kept
        .iter()
        .filter(|r| r.kind == RowKind::Efficiency)
        .filter_map(|r| {
            let spec = &problem.friction[r.law_index?];
            Some(EfficiencyRecord {
                case: r.point - 1,
                torque_index: r.torque_index,
                speed_index: r.speed_index,
                law: spec.law,
                label: r.label.clone(),
                formulation: if r.formulation == "internal" { Formulation::Internal } else { Formulation::External },
                pinion_torque: Q::new(r.pinion_torque, "N*m"),
                pinion_speed: Q::new(r.pinion_speed, "rad/s"),
                mean_efficiency: Num(r.mean_efficiency?),
                error_estimate: Num(r.mean_efficiency_error?),
                power_loss: Q::new(r.power_loss?, "W"),
                parameters: Parameters(r.parameters.clone()),
                ohlendorf: ohlendorf_loss(helical, r, eval.ohlendorf_loss_factor),
            })
        })
        .collect()
}

/// P_VZP = P_in μ̄ H_V (ISO/TR 14179-2 with Ohlendorf's H_V) of an efficiency row of a helical pair.
fn ohlendorf_loss(helical: bool, r: &crate::evaluate::records::SummaryRow, h_v: f64) -> Option<OhlendorfLoss> {
    let p = r.pinion_torque * r.pinion_speed * r.mean_abs_mu? * h_v;
    let line_integral = r.power_loss?;
    helical.then(|| OhlendorfLoss { power_loss: Q::new(p, "W"), line_integral_ratio: Num(line_integral / p) })
}

/// A law's note, with the operating points (1-based) it holds at unless it holds at all of them.
fn note_at_points(note: &crate::evaluate::tally::LawNote, points: usize) -> String {
    if note.count >= points {
        return note.text.clone();
    }
    let listed: Vec<String> = note.points.iter().map(|p| (p + 1).to_string()).collect();
    let more = if note.count > note.points.len() {
        format!(" and {} more", note.count - note.points.len())
    } else {
        String::new()
    };
    let s = if note.count == 1 { "" } else { "s" };
    format!("{} (at operating point{s} {}{more})", note.text, listed.join(", "))
}

/// Findings about the laws: their notes, validity, divergence handling, over every point of the run.
pub fn law_findings(problem: &MeshProblem, eval: &Evaluation, tally: &Tally) -> Vec<Finding> {
    let mut out: Vec<Finding> = Vec::new();
    let push = |out: &mut Vec<Finding>, severity, message: String| {
        if !out.iter().any(|f| f.message == message) {
            out.push(Finding { severity, message });
        }
    };
    if !eval.wants_friction {
        // Laws no analysis reads are a scene check's warning (`crate::scene::summary::unused_blocks`).
        return out;
    }
    let len = super::scene::units(problem).length();
    for (spec, law) in problem.friction.iter().zip(&tally.laws) {
        let label = law_label(spec);
        for note in &law.notes {
            let severity = if note.text.contains("LOW CONFIDENCE") || note.text.contains("underestimated") {
                Severity::Warning
            } else {
                Severity::Note
            };
            push(&mut out, severity, note_at_points(note, law.points));
        }
        if law.diverges_at_pitch {
            push(&mut out, Severity::Note, format!(
                "{label}: |μ| diverges at the pitch point; tables write `diverges` there, plots clip (marked ▲▼), means integrate the integrable singularity (adaptive Gauss–Kronrod split at P)"
            ));
        }
        if let Some((k, a, b)) = law.widest_cap {
            push(
                &mut out,
                Severity::Warning,
                format!(
                    "{label}: |μ| exceeds {} near the pitch point; the internal formulation caps it there (else R_p + Σ μ w T1C would vanish: self-locking). Widest band: {}–{} from T1 at operating point {} ({} of {} points affected)",
                    crate::efficiency::INTERNAL_MU_CAP,
                    len.cell(a, 6),
                    len.with(b, 6),
                    k + 1,
                    law.capped_points,
                    law.points
                ),
            );
        }
        if let Some(worst) = &law.worst {
            let where_: Vec<String> = worst
                .intervals
                .iter()
                .map(|(a, b, r)| format!("{}–{} ({r})", len.cell(*a, 3), len.with(*b, 3)))
                .collect();
            push(&mut out, Severity::Warning, format!(
                "{label}: outside its validity range at {} of {} operating points; worst at operating point {}: {} of {} samples along A–E, at {}",
                law.flagged_points,
                law.points,
                worst.point + 1,
                worst.outside,
                worst.samples,
                where_.join(", ")
            ));
        }
    }
    out
}

/// The laws whose `mu` takes two or more values in the report (a μ sweep), in order of appearance;
/// one pass over the records.
pub fn mu_swept_laws(records: &[EfficiencyRecord]) -> Vec<crate::friction::catalog::LawId> {
    let mut first: Vec<(crate::friction::catalog::LawId, f64, bool)> = Vec::new();
    for rec in records {
        let Some(mu) = rec.parameters.get("mu") else { continue };
        match first.iter_mut().find(|(law, _, _)| *law == rec.law) {
            Some((_, m, swept)) => *swept |= m.to_bits() != mu.to_bits(),
            None => first.push((rec.law, mu, false)),
        }
    }
    first.into_iter().filter(|(_, _, swept)| *swept).map(|(law, _, _)| law).collect()
}
