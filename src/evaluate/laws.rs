//! One friction law at one operating point: μ at the table rows and along the line of action, its
//! validity, regimes, mean |μ|, and the mean efficiency of each formulation asked for.

use serde::Serialize;

use super::cases::cycle_times;
use super::setup::Setup;
use crate::efficiency::{self, EfficiencyResult};
use crate::friction::catalog::LawId;
use crate::friction::{FrictionLaw, LawContext, Parameter, Regime};
use crate::geometry::contact::Sharing;
use crate::geometry::{ContactPoint, OperatingState};
use crate::model::Formulation;
use crate::numerics::quadrature::Integral;

/// Where a law left its validity range along the line of action.
#[derive(Debug, Clone, Default, Serialize)]
pub struct ValiditySummary {
    pub samples: usize,
    pub outside: usize,
    /// (from, to) along the line of action from T1 (m), with the first reason met there.
    pub intervals: Vec<(f64, f64, &'static str)>,
    /// The law's own notes at this state (where it reads an input at a bound of its range, e.g.
    /// ISO/TR 14179-2's F_bt/b raised to 150 N/mm): a drive's stages and a cycle's pieces report
    /// them; a pair's report reads them from the law itself.
    #[serde(skip)]
    pub notes: Vec<String>,
}

/// One friction law at one operating point. Outside the detail points only the summary is filled
/// (μ̄, efficiency, validity, the internal cap band); the table, regimes and curves stay empty.
#[derive(Debug, Clone, Serialize)]
pub struct LawEvaluation {
    pub id: LawId,
    pub title: &'static str,
    pub parameters: Vec<Parameter>,
    pub notes: Vec<String>,
    pub diverges_at_pitch: bool,
    /// Signed μ at the table rows; None where the law diverges (at P).
    pub table: Vec<Option<f64>>,
    /// Regime at the table rows (composite law only).
    pub regimes: Option<Vec<Regime>>,
    pub switch_points: Vec<f64>,
    /// Regime bands along the line of action between A, the switch points and E (composite only).
    pub regime_bands: Vec<(f64, f64, Regime)>,
    pub mean_abs_mu: Integral,
    pub validity: ValiditySummary,
    pub efficiency: Vec<EfficiencyResult>,
    /// 1 − μ̄ H_V with μ̄ = mean |μ| over A–E (Ohlendorf's cross-check).
    pub ohlendorf_efficiency: f64,
    /// Where the internal formulation caps |μ| at [`efficiency::INTERNAL_MU_CAP`] (from, to from T1).
    pub internal_cap_band: Option<(f64, f64)>,
    pub curves: Option<LawCurves>,
}

impl LawEvaluation {
    /// The law's parameters at the point, owned (for the record files and the report).
    pub fn parameter_values(&self) -> Vec<super::records::ParameterValue> {
        self.parameters
            .iter()
            .map(|p| super::records::ParameterValue { name: p.name.into(), value: p.value, unit: p.unit.into() })
            .collect()
    }

    /// The mesh loss (W) and efficiency a gearbox budget charges for efficiency result `e` at input
    /// power `input`: ISO/TR 14179-2's P_in μ_mZ H_V for `iso_14179_2` on a helical pair
    /// ([`crate::efficiency::charges_iso_mesh_loss`]), else the result's line integral and η̄.
    pub fn charged_mesh(&self, e: &crate::efficiency::EfficiencyResult, eval: &Setup, input: f64) -> (f64, f64) {
        if crate::efficiency::charges_iso_mesh_loss(self.id, &eval.geometry) {
            let loss = crate::efficiency::iso_mesh_loss(input, self.mean_abs_mu.value, eval.ohlendorf_loss_factor);
            (loss, 1.0 - loss / input)
        } else {
            (e.power_loss, e.mean.value)
        }
    }
}

/// Sampled curves of one law for plots.
#[derive(Debug, Clone, Serialize)]
pub struct LawCurves {
    /// Signed μ at `Evaluation::curve_positions` (NaN where it diverges).
    pub mu: Vec<f64>,
    /// Local friction power loss at the same positions (W).
    pub power_loss: Vec<f64>,
    /// With `load_sharing = stiffness`: the same under equal sharing, to set beside it.
    pub power_loss_equal: Option<Vec<f64>>,
    /// η(τ) at `cycle_times` for each formulation.
    pub efficiency: Vec<(Formulation, Vec<f64>)>,
}

pub(crate) fn validity_summary(law: &dyn FrictionLaw, contacts: &[ContactPoint]) -> ValiditySummary {
    let mut intervals: Vec<(f64, f64, &'static str)> = Vec::new();
    let mut outside = 0;
    let mut open: Option<(f64, f64, &'static str)> = None;
    let diverges = law.diverges_at_pitch();
    for c in contacts {
        let verdict = law.validity(c).and_then(|()| {
            // At P a divergent law is reported as `diverges`, not as implausible.
            let at_pitch = diverges && c.s == 0.0;
            if at_pitch || law.mu(c).abs() <= law.plausible_max() {
                Ok(())
            } else {
                Err("|μ| above the law's plausible bound for a lubricated contact")
            }
        });
        match verdict {
            Err(reason) => {
                outside += 1;
                open = Some(match open {
                    Some((from, _, r)) => (from, c.u, r),
                    None => (c.u, c.u, reason),
                });
            }
            Ok(()) => {
                if let Some(i) = open.take() {
                    intervals.push(i);
                }
            }
        }
    }
    if let Some(i) = open {
        intervals.push(i);
    }
    ValiditySummary { samples: contacts.len(), outside, intervals, notes: law.notes() }
}

/// The regime between consecutive switch points (A, switches…, E), for laws that have regimes.
fn regime_bands(ctx: &LawContext, law: &dyn FrictionLaw) -> Vec<(f64, f64, Regime)> {
    let p = ctx.geometry.points;
    let mut edges = vec![p.a];
    edges.extend(law.switch_points());
    edges.push(p.e);
    edges.windows(2).filter_map(|w| law.regime(&ctx.contact_at(0.5 * (w[0] + w[1]))).map(|r| (w[0], w[1], r))).collect()
}

pub(super) fn evaluate_law(
    eval: &Setup,
    spec: &crate::model::FrictionLawSpec,
    state: OperatingState,
    table: &[(Option<&'static str>, ContactPoint)],
    detail: bool,
    curves: bool,
) -> LawEvaluation {
    let ctx = eval.law_context(state);
    let law = super::setup::law_at(spec, &ctx);
    let law = law.as_ref();
    let diverges = law.diverges_at_pitch();
    let value_at = |c: &ContactPoint| -> Option<f64> { (!(diverges && c.s == 0.0)).then(|| law.mu(c)) };
    let contacts: Vec<ContactPoint> = eval.positions.iter().map(|u| ctx.contact_at(*u)).collect();
    // The local friction power at each contact (0 where the law diverges, at P).
    let power_along = |ctx: &LawContext, contacts: &[ContactPoint]| -> Vec<f64> {
        let power = |c: &ContactPoint| efficiency::local_power_loss(ctx, law, c);
        contacts.iter().map(|c| if diverges && c.s == 0.0 { 0.0 } else { power(c) }).collect()
    };
    let taus = cycle_times();
    let efficiency = efficiency::evaluate_efficiencies(&ctx, law, &eval.formulations);
    let mean_abs_mu = efficiency::mean_abs_mu(&ctx, law);
    LawEvaluation {
        id: spec.law,
        title: spec.law.entry().title,
        parameters: law.parameters(),
        notes: law.notes(),
        diverges_at_pitch: diverges,
        table: if detail { table.iter().map(|(_, c)| value_at(c)).collect() } else { Vec::new() },
        regimes: law
            .regime(&table[0].1)
            .filter(|_| detail)
            .map(|_| table.iter().filter_map(|(_, c)| law.regime(c)).collect()),
        switch_points: law.switch_points(),
        regime_bands: if detail { regime_bands(&ctx, law) } else { Vec::new() },
        ohlendorf_efficiency: 1.0 - mean_abs_mu.value * efficiency::ohlendorf_loss_factor(&ctx),
        internal_cap_band: if eval.formulations.contains(&Formulation::Internal) {
            efficiency::internal_cap_band(&ctx, law)
        } else {
            None
        },
        mean_abs_mu,
        validity: validity_summary(law, &contacts),
        efficiency,
        curves: (detail && curves).then(|| LawCurves {
            mu: contacts.iter().map(|c| value_at(c).unwrap_or(f64::NAN)).collect(),
            power_loss: power_along(&ctx, &contacts),
            power_loss_equal: matches!(ctx.sharing, Sharing::Stiffness(_)).then(|| {
                let equal = LawContext { sharing: Sharing::Equal, ..ctx };
                power_along(&equal, &eval.positions.iter().map(|u| equal.contact_at(*u)).collect::<Vec<_>>())
            }),
            efficiency: eval
                .formulations
                .iter()
                .map(|f| (*f, taus.iter().map(|t| efficiency::efficiency_at(&ctx, law, *f, *t)).collect()))
                .collect(),
        }),
    }
}
