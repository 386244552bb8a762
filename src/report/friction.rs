//! The friction, film and efficiency parts of the report (serde data).

use serde::Serialize;

use super::number::{m, Num, Q};
use super::{Finding, Severity};
use crate::evaluate::{Evaluation, LawEvaluation, PointEvaluation};
use crate::friction::{Parameter, Regime};
use crate::model::{Formulation, FrictionLawSpec, Scene};

/// μ at a row: a number, or the word `diverges` where the law is singular (at P).
#[derive(Debug, Clone, Copy, Serialize)]
#[serde(untagged)]
pub enum MuValue {
    Value(Num),
    Text(&'static str),
}

impl MuValue {
    pub fn value(&self) -> Option<f64> {
        match self {
            MuValue::Value(n) => Some(n.0),
            MuValue::Text(_) => None,
        }
    }
}

/// A law's parameters as a JSON object in the law's own order: `{"mu": 0.04, "phi": {"value": 5e4, "unit": "1/m"}}`.
#[derive(Debug, Clone, Default)]
pub struct Parameters(pub Vec<(&'static str, super::SiValue)>);

impl Parameters {
    /// The SI value of a parameter.
    pub fn get(&self, name: &str) -> Option<f64> {
        self.0.iter().find(|(n, _)| *n == name).map(|(_, v)| v.si())
    }
}

impl Serialize for Parameters {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in &self.0 {
            map.serialize_entry(k, v)?;
        }
        map.end()
    }
}

#[derive(Debug, Clone, Serialize)]
pub struct MuRow {
    pub point: Option<&'static str>,
    pub distance_from_t1: Q,
    pub mu: MuValue,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub regime: Option<Regime>,
}

#[derive(Debug, Clone, Serialize)]
pub struct ValidityInterval {
    pub from: Q,
    pub to: Q,
    pub reason: &'static str,
}

#[derive(Debug, Clone, Serialize)]
pub struct ValidityReport {
    /// Points sampled evenly along A–E.
    pub samples: usize,
    /// How many of them lie outside the law's validity range.
    pub outside: usize,
    pub intervals: Vec<ValidityInterval>,
}

#[derive(Debug, Clone, Serialize)]
pub struct EfficiencyReport {
    pub formulation: Formulation,
    pub mean_efficiency: Num,
    pub error_estimate: Num,
    pub power_loss: Q,
    pub min_efficiency: Num,
    pub max_efficiency: Num,
}

/// One law at one operating point.
#[derive(Debug, Clone, Serialize)]
pub struct LawReport {
    pub law: crate::friction::catalog::LawId,
    /// As written in the scene, e.g. `coulomb(mu = 0.04)`.
    pub label: String,
    pub title: &'static str,
    pub parameters: Parameters,
    pub diverges_at_pitch: bool,
    pub mu_along_loa: Vec<MuRow>,
    pub mean_abs_mu: Num,
    pub mean_abs_mu_error: Num,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub regime_switches_from_t1: Vec<Q>,
    pub validity: ValidityReport,
    pub efficiency: Vec<EfficiencyReport>,
    /// 1 − μ̄ H_V, μ̄ the mean |μ| over A–E (Ohlendorf's cross-check).
    pub ohlendorf_efficiency: Num,
}

#[derive(Debug, Clone, Serialize)]
pub struct FilmRow {
    pub point: Option<&'static str>,
    pub distance_from_t1: Q,
    pub central_film: Q,
    pub minimum_film: Q,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lambda: Option<Num>,
}

/// One record per (operating point, law, formulation): the flat table of a sweep.
#[derive(Debug, Clone, Serialize)]
pub struct EfficiencyRecord {
    /// The case (operating point) and its torque and speed indices in the sweeps, for grouping.
    #[serde(skip)]
    pub case: usize,
    #[serde(skip)]
    pub torque_index: usize,
    #[serde(skip)]
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
}

/// `coulomb(mu = 0.04)`: the law as the user wrote it (defaults left out).
pub fn law_label(spec: &FrictionLawSpec) -> String {
    let args: Vec<String> =
        spec.arguments.iter().filter(|(_, _, w)| w != "default").map(|(n, _, w)| format!("{n} = {w}")).collect();
    if args.is_empty() {
        spec.law.name().to_string()
    } else {
        format!("{}({})", spec.law.name(), args.join(", "))
    }
}

fn parameter(p: &Parameter) -> (&'static str, super::SiValue) {
    let value = if p.unit == "1" {
        super::SiValue::Plain(Num(p.value))
    } else {
        super::SiValue::Dimensional(Q::new(p.value, p.unit))
    };
    (p.name, value)
}

pub fn parameters(law: &LawEvaluation) -> Parameters {
    Parameters(law.parameters.iter().map(parameter).collect())
}

pub fn law_report(spec: &FrictionLawSpec, pe: &PointEvaluation, law: &LawEvaluation) -> LawReport {
    LawReport {
        law: law.id,
        label: law_label(spec),
        title: law.title,
        parameters: parameters(law),
        diverges_at_pitch: law.diverges_at_pitch,
        mu_along_loa: pe
            .table
            .iter()
            .enumerate()
            .map(|(i, (name, c))| MuRow {
                point: *name,
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
                .map(|(a, b, r)| ValidityInterval { from: m(*a), to: m(*b), reason: r })
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
                point: *name,
                distance_from_t1: m(c.u),
                central_film: m(f.central),
                minimum_film: m(f.minimum),
                lambda: f.lambda.map(Num),
            })
            .collect()
    })
}

pub fn efficiency_records(scene: &Scene, eval: &Evaluation) -> Vec<EfficiencyRecord> {
    let mut out = Vec::new();
    for pe in &eval.points {
        for (spec, law) in scene.friction.iter().zip(&pe.laws) {
            for e in &law.efficiency {
                let case = &eval.cases[pe.case];
                out.push(EfficiencyRecord {
                    case: pe.case,
                    torque_index: case.torque_index,
                    speed_index: case.speed_index,
                    law: law.id,
                    label: law_label(spec),
                    formulation: e.formulation,
                    pinion_torque: Q::new(pe.state.pinion_torque, "N*m"),
                    pinion_speed: Q::new(pe.state.pinion_speed, "rad/s"),
                    mean_efficiency: Num(e.mean.value),
                    error_estimate: Num(e.mean.error),
                    power_loss: Q::new(e.power_loss, "W"),
                    parameters: parameters(law),
                });
            }
        }
    }
    out
}

/// Findings about the laws: their notes, validity, divergence handling.
pub fn law_findings(scene: &Scene, eval: &Evaluation) -> Vec<Finding> {
    let mut out: Vec<Finding> = Vec::new();
    let push = |out: &mut Vec<Finding>, severity, message: String| {
        if !out.iter().any(|f| f.message == message) {
            out.push(Finding { severity, message });
        }
    };
    if eval.points.first().is_none_or(|p| p.laws.is_empty()) {
        if !scene.friction.is_empty() {
            push(&mut out, Severity::Note, "friction laws are listed but no analysis asks for them (add `friction_along_loa` or `efficiency` to `analyses`)".into());
        }
        return out;
    }
    for (i, spec) in scene.friction.iter().enumerate() {
        let label = law_label(spec);
        let laws: Vec<&LawEvaluation> = eval.points.iter().map(|p| &p.laws[i]).collect();
        for law in &laws {
            for note in &law.notes {
                let severity = if note.contains("LOW CONFIDENCE") || note.contains("underestimated") {
                    Severity::Warning
                } else {
                    Severity::Note
                };
                push(&mut out, severity, note.clone());
            }
        }
        if laws.iter().any(|l| l.diverges_at_pitch) {
            push(&mut out, Severity::Note, format!(
                "{label}: |μ| diverges at the pitch point; tables write `diverges` there, plots clip (marked ▲▼), means integrate the integrable singularity (adaptive Gauss–Kronrod split at P)"
            ));
        }
        let bands: Vec<(usize, (f64, f64))> =
            laws.iter().enumerate().filter_map(|(k, l)| l.internal_cap_band.map(|b| (k, b))).collect();
        if let Some((k, (a, b))) = bands.iter().max_by(|x, y| (x.1 .1 - x.1 .0).total_cmp(&(y.1 .1 - y.1 .0))) {
            push(
                &mut out,
                Severity::Warning,
                format!(
                    "{label}: |μ| exceeds {} near the pitch point; the internal formulation caps it there (else R_p + Σ μ w T1C would vanish: self-locking). Widest band: {:.6}–{:.6} mm from T1 at operating point {} ({} of {} points affected)",
                    crate::efficiency::INTERNAL_MU_CAP,
                    a * 1e3,
                    b * 1e3,
                    k + 1,
                    bands.len(),
                    laws.len()
                ),
            );
        }
        let flagged: Vec<(usize, &LawEvaluation)> =
            laws.iter().enumerate().filter(|(_, l)| l.validity.outside > 0).map(|(k, l)| (k, *l)).collect();
        if !flagged.is_empty() {
            let (k, worst) = flagged.iter().max_by_key(|(_, l)| l.validity.outside).copied().expect("non-empty");
            let where_: Vec<String> = worst
                .validity
                .intervals
                .iter()
                .map(|(a, b, r)| format!("{:.3}–{:.3} mm ({r})", a * 1e3, b * 1e3))
                .collect();
            push(&mut out, Severity::Warning, format!(
                "{label}: outside its validity range at {} of {} operating points; worst at operating point {}: {} of {} samples along A–E, at {}",
                flagged.len(),
                laws.len(),
                k + 1,
                worst.validity.outside,
                worst.validity.samples,
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
