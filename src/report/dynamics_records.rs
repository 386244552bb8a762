//! The dynamics record of one formulation at one operating point: Floquet numbers, the located
//! periodic response of whichever model ran, the gears on bearings (forces and displacements) where
//! the model has them, and the free response (peaks and Floquet-mode lines).

use serde::{Deserialize, Serialize};

use super::number::{m, Num, Q};
use crate::dynamics::analysis::{FormulationResult, GearResponse, ModelResponse};
use crate::dynamics::floquet::Verdict;
use crate::dynamics::propagator::Method;
use crate::dynamics::trajectory::Extremum;
use crate::dynamics::DynamicFormulation;

/// A located extremum: value and time in mesh periods.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
pub struct Located {
    pub value: Q,
    pub tau: Num,
}

fn located(e: crate::dynamics::trajectory::Extremum, unit: &'static str) -> Located {
    Located { value: Q::new(e.value, unit), tau: Num(e.time) }
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct SpectrumLine {
    pub order: usize,
    pub amplitude: Q,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct FormulationReport {
    pub formulation: DynamicFormulation,
    pub method: Method,
    pub spectral_radius: Num,
    /// [re, im] pairs.
    pub floquet_multipliers: Vec<[Num; 2]>,
    pub verdict: Verdict,
    pub monodromy_determinant: Num,
    /// exp(∫ tr A dt), which det Φ(T) must equal.
    pub liouville_determinant: Num,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dte_peak_to_peak: Option<Q>,
    /// Located extrema of the DTE (roots of ẋ = 0) with their times in mesh periods.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dte_min: Option<Located>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dte_max: Option<Located>,
    /// Time mean of the DTE (Gauss–Kronrod on the state) and its error estimate.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dte_mean: Option<Q>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dte_mean_error: Option<Q>,
    /// Located extrema of the tooth force F = c(ẋ − ε̇) + k(x − ε) (Fernandes eq 7).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tooth_force_min: Option<Located>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tooth_force_max: Option<Located>,
    /// max F / F0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dynamic_factor: Option<Num>,
    /// Mesh-period fractions [from, to] where the tooth force is negative (teeth separate), located.
    pub tooth_separation: Vec<[Num; 2]>,
    pub spectrum: Vec<SpectrumLine>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mean_dynamic_efficiency: Option<Num>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mean_dynamic_efficiency_error: Option<Num>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_dynamic_efficiency: Option<Num>,
    /// Peak |friction force the model applies| (external: μ F0 shares; internal: μ F shares) and peak
    /// |friction torque| on pinion and wheel over the cycle, located.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub peak_applied_friction_force: Option<Located>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub peak_friction_torque: Vec<Located>,
    /// External formulation: peak |Σ μ_j w_j F| (μ × tooth force), which its equation does not apply.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub peak_mu_times_tooth_force: Option<Located>,
    /// The free (homogeneous) response from the scene's initial state, when asked for.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub free_response: Option<FreeResponseReport>,
    /// 6-DOF model: the largest force on one pair (N/n, located), the mean friction force Σ μ_i N_i
    /// and per gear [pinion, wheel] the bearing forces and displacements.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pair_force_max: Option<Located>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub friction_force_mean: Option<Q>,
    /// 6-DOF: the largest friction force on one pair, max_i |μ_i N_i|, located.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pair_friction_force_max: Option<Located>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub gears: Vec<GearDynamicsReport>,
}

/// One gear of the 6-DOF model: bearing forces K x (LOA) and K y (OLOA) and displacements, located
/// extremes, integrated means with error estimates, the OLOA bearing force spectrum in mesh orders.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct GearDynamicsReport {
    pub gear: String,
    pub bearing_force_loa_peak_to_peak: Q,
    pub bearing_force_loa_mean: Q,
    pub bearing_force_oloa_peak_to_peak: Q,
    pub bearing_force_oloa_mean: Q,
    pub bearing_force_oloa_mean_error: Q,
    pub bearing_force_oloa_min: Located,
    pub bearing_force_oloa_max: Located,
    pub bearing_force_oloa_spectrum: Vec<SpectrumLine>,
    pub bearing_force_loa_spectrum: Vec<SpectrumLine>,
    pub loa_displacement_peak_to_peak: Q,
    pub oloa_displacement_peak_to_peak: Q,
}

/// The report record of one formulation: the Floquet numbers and whatever the model's response has
/// (a quantity the model does not compute is left out).
pub(super) fn formulation_report(r: &FormulationResult) -> FormulationReport {
    let x = r.response.as_ref();
    let at = |f: fn(&ModelResponse) -> Option<Extremum>, unit: &'static str| x.and_then(f).map(|e| located(e, unit));
    FormulationReport {
        formulation: r.formulation,
        method: r.method,
        spectral_radius: Num(r.spectral_radius),
        floquet_multipliers: r.multipliers.iter().map(|m| [Num(m.re), Num(m.im)]).collect(),
        verdict: r.verdict,
        monodromy_determinant: Num(r.determinant),
        liouville_determinant: Num(r.liouville),
        dte_peak_to_peak: x.map(|x| m(x.dte.peak_to_peak())),
        dte_min: x.map(|x| located(x.dte.min, "m")),
        dte_max: x.map(|x| located(x.dte.max, "m")),
        dte_mean: x.map(|x| m(x.dte.mean.value)),
        dte_mean_error: x.map(|x| m(x.dte.mean.error)),
        tooth_force_min: x.map(|x| located(x.tooth_force[0], "N")),
        tooth_force_max: x.map(|x| located(x.tooth_force[1], "N")),
        dynamic_factor: x.map(|x| Num(x.dynamic_factor)),
        tooth_separation: x.map_or_else(Vec::new, |x| x.separation.iter().map(|(a, b)| [Num(*a), Num(*b)]).collect()),
        spectrum: x.map_or_else(Vec::new, |x| lines(&x.dte.spectrum, "m")),
        mean_dynamic_efficiency: x.and_then(|x| x.mean_dynamic_efficiency.map(|i| Num(i.value))),
        mean_dynamic_efficiency_error: x.and_then(|x| x.mean_dynamic_efficiency.map(|i| Num(i.error))),
        max_dynamic_efficiency: x.and_then(|x| x.max_dynamic_efficiency.map(Num)),
        peak_applied_friction_force: at(|x| x.peak_friction_force, "N"),
        peak_friction_torque: x
            .and_then(|x| x.peak_friction_torque)
            .map_or_else(Vec::new, |t| t.iter().map(|e| located(*e, "N*m")).collect()),
        peak_mu_times_tooth_force: at(|x| x.peak_mu_times_tooth_force, "N"),
        free_response: r.free.as_ref().map(free_report),
        pair_force_max: at(|x| x.pair_force_max, "N"),
        friction_force_mean: x.and_then(|x| x.friction_force_mean).map(|v| Q::new(v, "N")),
        pair_friction_force_max: at(|x| x.pair_friction_force_max, "N"),
        gears: x.map_or_else(Vec::new, |x| x.gears.iter().map(|(name, g)| gear_dynamics(name, g)).collect()),
    }
}

/// Amplitudes of mesh orders 1, 2, … as report lines.
fn lines(amplitudes: &[f64], unit: &'static str) -> Vec<SpectrumLine> {
    amplitudes.iter().enumerate().map(|(o, a)| SpectrumLine { order: o + 1, amplitude: Q::new(*a, unit) }).collect()
}

fn gear_dynamics(name: &'static str, g: &GearResponse) -> GearDynamicsReport {
    let n = |x: f64| Q::new(x, "N");
    GearDynamicsReport {
        gear: name.into(),
        bearing_force_loa_peak_to_peak: n(g.bearing_force_loa.peak_to_peak()),
        bearing_force_loa_mean: n(g.bearing_force_loa.mean.value),
        bearing_force_oloa_peak_to_peak: n(g.bearing_force_oloa.peak_to_peak()),
        bearing_force_oloa_mean: n(g.bearing_force_oloa.mean.value),
        bearing_force_oloa_mean_error: n(g.bearing_force_oloa.mean.error),
        bearing_force_oloa_min: located(g.bearing_force_oloa.min, "N"),
        bearing_force_oloa_max: located(g.bearing_force_oloa.max, "N"),
        bearing_force_oloa_spectrum: lines(&g.bearing_force_oloa.spectrum, "N"),
        bearing_force_loa_spectrum: lines(&g.bearing_force_loa.spectrum, "N"),
        loa_displacement_peak_to_peak: m(g.displacement_loa[1].value - g.displacement_loa[0].value),
        oloa_displacement_peak_to_peak: m(g.displacement_oloa[1].value - g.displacement_oloa[0].value),
    }
}

/// The free response X(t + nT) = Φ(t, 0) Φ(T)ⁿ X(0) and its Floquet-mode spectrum lines.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct FreeResponseReport {
    pub x0: Q,
    pub v0: Q,
    pub periods: usize,
    /// Largest |DTE| over the window, located; time in mesh periods from the start.
    pub peak: Located,
    pub first_period_peak: Q,
    pub last_period_peak: Q,
    /// Largest lines first: frequency in mesh orders, one-sided amplitude at t = 0, its error
    /// estimate, growth per period |λ|.
    pub lines: Vec<FreeLine>,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct FreeLine {
    pub order: Num,
    pub amplitude: Q,
    pub amplitude_error: Q,
    pub growth_per_period: Num,
}

fn free_report(f: &crate::dynamics::free::FreeResponse) -> FreeResponseReport {
    FreeResponseReport {
        x0: m(f.initial[0]),
        v0: Q::new(f.initial[1], "m/s"),
        periods: f.periods,
        peak: located(f.peak, "m"),
        first_period_peak: m(f.first_period_peak),
        last_period_peak: m(f.last_period_peak),
        lines: f
            .lines
            .iter()
            .map(|l| FreeLine {
                order: Num(l.order),
                amplitude: m(l.amplitude),
                amplitude_error: m(l.error),
                growth_per_period: Num(l.growth),
            })
            .collect(),
    }
}
