//! Instantaneous and mean mesh efficiency, and friction power loss (Fernandes et al. §2.3–2.4,
//! generalised to μ varying along the line of action and any number of pairs in contact; physics
//! notes, "Efficiency").
//!
//! At time τ (in mesh periods, τ = 0 when a pair enters at A) the pairs in contact are at
//! u_k = T1A + p_b (τ + k), k = 0, 1, 2, while u_k < T1E. With R_p, R_w the base radii, i = z2/z1,
//! and per contact j the signed μ_j, force share w_j = 1/n (always: with `load_sharing = none` a
//! law sees the whole load, but the n forces of the balance still add up to F_bn), s_j = u_j − T1P, T1C_j = u_j, T2C_j = T1T2 − u_j:
//!
//! - external: η = 1 − (1/R_p + 1/R_w) Σ_j w_j μ_j s_j  (= 1 − friction power / input power);
//! - internal: η = (R_w + Σ_j μ_j w_j T2C_j) / (R_p + Σ_j μ_j w_j T1C_j) / i.
//!
//! Mean η̄ is the time mean over one mesh cycle, integrated piecewise between every zone boundary,
//! pitch-point passage and regime switch by adaptive Gauss–Kronrod to a relative tolerance of 1e-10;
//! the friction power loss is P = (1 − η̄) T_p ω_p.

use serde::Serialize;

use crate::friction::{FrictionLaw, LawContext};
use crate::geometry::contact::Sharing;
use crate::geometry::mesh::{LINE_NODES, MAX_CONTACTS};
use crate::geometry::ContactPoint;
use crate::numerics::quadrature::{integrate_singular, integrate_singular_n, Integral};
use crate::numerics::roots::{extrema, extrema_each};

/// The formulations of the output torque (Fernandes §2.3–2.4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Formulation {
    External,
    Internal,
}

impl Formulation {
    /// `external` or `internal`, as the scene writes it.
    pub fn name(self) -> &'static str {
        match self {
            Formulation::External => "external",
            Formulation::Internal => "internal",
        }
    }

    /// Its place in [external, internal], the order [`mean_efficiencies`] returns both in.
    pub fn index(self) -> usize {
        match self {
            Formulation::External => 0,
            Formulation::Internal => 1,
        }
    }
}

/// Relative tolerance of every mean.
pub const MEAN_TOLERANCE: f64 = 1e-10;

/// In the internal formulation, |μ| of a law that diverges at P is capped here: near P such a law
/// exceeds any physical value, and R_p + Σ μ w T1C would pass through zero (self-locking), making
/// η(τ) non-integrable. The band where the cap acts is found by [`internal_cap_band`] and reported.
pub const INTERNAL_MU_CAP: f64 = 1.0;

/// The largest |μ| the internal formulation (and the dynamics' friction term) uses for `law`:
/// [`INTERNAL_MU_CAP`] for a law that diverges at P, unbounded otherwise.
pub fn internal_mu_cap(law: &dyn FrictionLaw) -> f64 {
    if law.diverges_at_pitch() {
        INTERNAL_MU_CAP
    } else {
        f64::INFINITY
    }
}

/// The positions (from T1) around P between which a divergent law's |μ| exceeds [`INTERNAL_MU_CAP`].
pub fn internal_cap_band(ctx: &LawContext, law: &dyn FrictionLaw) -> Option<(f64, f64)> {
    if !law.diverges_at_pitch() {
        return None;
    }
    let p = ctx.geometry.points;
    let above = |u: f64| law.mu(&ctx.contact_at(u)).abs() > INTERNAL_MU_CAP;
    let edge = |from: f64| {
        // from: a point away from P where |μ| ≤ cap; bisect towards P.
        let (mut out, mut inn) = (from, p.p);
        for _ in 0..64 {
            let mid = 0.5 * (out + inn);
            if mid == out || mid == inn {
                break;
            }
            if above(mid) {
                inn = mid
            } else {
                out = mid
            }
        }
        out
    };
    let (lo, hi) = (edge(p.a), edge(p.e));
    (hi > lo && (above(0.5 * (lo + p.p)) || above(0.5 * (hi + p.p)))).then_some((lo, hi))
}

/// Instantaneous efficiency at time τ.
pub fn efficiency_at(ctx: &LawContext, law: &dyn FrictionLaw, formulation: Formulation, tau: f64) -> f64 {
    efficiency_of(ctx, law, formulation, &ctx.mesh().contacts_at(tau))
}

/// Efficiency for a given set of contacts.
pub fn efficiency_of(
    ctx: &LawContext,
    law: &dyn FrictionLaw,
    formulation: Formulation,
    contacts: &[ContactPoint],
) -> f64 {
    efficiencies_of(ctx, law, contacts)[formulation.index()]
}

/// Both formulations for a given set of contacts, with one evaluation of μ per contact:
/// [external, internal].
pub fn efficiencies_of(ctx: &LawContext, law: &dyn FrictionLaw, contacts: &[ContactPoint]) -> [f64; 2] {
    let g = ctx.geometry;
    // Arms of the normal force, r_b cos β_b (He & Singh eq 8; r_b for a spur pair).
    let (rp, rw) = (g.normal_force_arm(0), g.normal_force_arm(1));
    let cap = internal_mu_cap(law);
    let mut sum = 0.0;
    let (mut num, mut den) = (rw, rp);
    for c in contacts {
        let mu = law.mu(c);
        sum += c.force_share * mu * c.s;
        let m = mu.clamp(-cap, cap) * c.force_share;
        num += m * (g.line_of_action_length - c.u);
        den += m * c.u;
    }
    [1.0 - (1.0 / rp + 1.0 / rw) * sum, num / den / g.gear_ratio]
}

/// Times in (0, 1) where the integrand changes form: zone boundaries, pitch passages, law switches.
/// With `load_sharing = stiffness` and tip relief, also where a spur pair's load bends
/// ([`crate::geometry::teeth::load_sharing::LoadSharing::spur_kink_times`]).
pub fn break_times(ctx: &LawContext, law: &dyn FrictionLaw) -> Vec<f64> {
    let mut times = ctx.geometry.cycle_break_times(&law.switch_points());
    if let Sharing::Stiffness(model) = ctx.sharing {
        times.extend(model.spur_kink_times(ctx.geometry.sharing_force(&ctx.state)));
        times.sort_by(f64::total_cmp);
        times.dedup();
    }
    times
}

/// η̄ over one mesh cycle, with its error estimate.
pub fn mean_efficiency(ctx: &LawContext, law: &dyn FrictionLaw, formulation: Formulation) -> Integral {
    mean_efficiencies(ctx, law)[formulation.index()]
}

/// η̄ of both formulations in one pass over shared quadrature nodes: [external, internal], each to
/// [`MEAN_TOLERANCE`]. Every law is treated as singular at P: the t⁴ map is exact for the
/// polynomial pieces of the Coulomb laws and removes the |s|^q kinks of the others.
pub fn mean_efficiencies(ctx: &LawContext, law: &dyn FrictionLaw) -> [Integral; 2] {
    mean_efficiencies_between(ctx, law, &break_times(ctx, law))
}

/// As [`mean_efficiencies`], with the cycle's break times known ([`break_times`]).
fn mean_efficiencies_between(ctx: &LawContext, law: &dyn FrictionLaw, breaks: &[f64]) -> [Integral; 2] {
    if ctx.geometry.is_helical() {
        return mean_efficiencies_along_lines(ctx, law);
    }
    let mesh = ctx.mesh();
    let buffer = std::cell::RefCell::new([ContactPoint::default(); MAX_CONTACTS]);
    integrate_singular_n(
        |tau, d| {
            let items = &mut *buffer.borrow_mut();
            let n = mesh.fill_pair_contacts(tau, d, items);
            efficiencies_of(ctx, law, &items[..n])
        },
        breaks,
        &ctx.geometry.pitch_times(),
        MEAN_TOLERANCE,
    )
}

/// η̄ of a helical pair: the time integral over the cycle (adaptive Gauss–Kronrod between the break
/// times, graded at the times a line end passes the pitch line) of η(τ), whose line integrals use
/// [`LINE_NODES`] and 2 × [`LINE_NODES`] graded Gauss–Legendre points per piece of line
/// ([`crate::geometry::Mesh::line_contacts`]). The doubled rule gives the value; the error estimate
/// is the larger of the time quadrature's and the difference of the two rules (0 up to rounding for
/// the Coulomb laws, whose line integrands are polynomials the rules integrate exactly).
pub fn mean_efficiencies_along_lines(ctx: &LawContext, law: &dyn FrictionLaw) -> [Integral; 2] {
    let mesh = ctx.mesh();
    let [e1, i1, e2, i2] = integrate_singular_n(
        |tau, _| {
            let [a, b] = efficiencies_of(ctx, law, &mesh.line_contacts(tau, LINE_NODES));
            let [c, d] = efficiencies_of(ctx, law, &mesh.line_contacts(tau, 2 * LINE_NODES));
            [a, b, c, d]
        },
        &break_times(ctx, law),
        &ctx.geometry.pitch_times(),
        MEAN_TOLERANCE,
    );
    let combine = |coarse: Integral, fine: Integral| Integral {
        value: fine.value,
        error: fine.error.max((fine.value - coarse.value).abs()),
        evaluations: fine.evaluations,
    };
    [combine(e1, e2), combine(i1, i2)]
}

/// Positions along the line of action where a law's integrand changes form (for means over A–E).
/// With `load_sharing = stiffness` and tip relief, also where a pair's load bends: the positions a
/// pair holds at the cycle's kink times ([`crate::geometry::teeth::load_sharing::LoadSharing::spur_kink_times`]).
pub fn break_positions(ctx: &LawContext, law: &dyn FrictionLaw) -> Vec<f64> {
    let g = ctx.geometry;
    let p = g.points;
    let mut v = vec![p.a, p.p, p.e];
    v.extend(g.pair_change_points().iter().map(|(_, u)| *u));
    v.extend(law.switch_points());
    if let Sharing::Stiffness(model) = ctx.sharing {
        for tau in model.spur_kink_times(g.sharing_force(&ctx.state)) {
            let along = (0..MAX_CONTACTS).map(|j| p.a + g.base_pitch * (tau + j as f64));
            v.extend(along.filter(|u| *u > p.a && *u < p.e));
        }
    }
    v
}

/// Mean |μ| over the path of contact A–E (a length mean).
pub fn mean_abs_mu(ctx: &LawContext, law: &dyn FrictionLaw) -> Integral {
    let p = ctx.geometry.points;
    let singular = [p.p];
    let contact = |u: f64, d: Option<f64>| d.map_or_else(|| ctx.contact_at(u), |d| ctx.contact_at_offset(d));
    let i =
        integrate_singular(|u, d| law.mu(&contact(u, d)).abs(), &break_positions(ctx, law), &singular, MEAN_TOLERANCE);
    Integral { value: i.value / (p.e - p.a), error: i.error / (p.e - p.a), evaluations: i.evaluations }
}

/// The gear loss factor H_V (geometry only, `crate::geometry::loss_factor::loss_factor`):
/// Ohlendorf's closed form H_V = π(u+1)/(z1 u cos β_b) · (1 − ε_α + ε_1² + ε_2²) (spur: cos β_b = 1)
/// where the pitch point lies in single contact, else the path integral under equal sharing that it
/// closes (ε_1 or ε_2 above 1: a ring mesh's long recess).
///
/// For a helical pair 1 − μ H_V is the mean efficiency of a *slice* model (equal load sharing within
/// each transverse slice of the face), not of constant stiffness density along the contact lines,
/// which puts more load where more line length is and so weights the ends of the path (physics
/// notes, "Helical pairs"): the two agree as β → 0 and when ε_β is an integer.
pub fn ohlendorf_loss_factor(ctx: &LawContext) -> f64 {
    crate::geometry::loss_factor::loss_factor(ctx.geometry)
}

/// Local friction power loss of one contact, |μ| F v_s (W), with F = its force share of F_bn.
pub fn local_power_loss(ctx: &LawContext, law: &dyn FrictionLaw, c: &ContactPoint) -> f64 {
    let force = c.force_share * ctx.geometry.normal_load(&ctx.state);
    law.mu(c).abs() * force * c.sliding_velocity
}

/// The mean friction power loss P = (1 − η̄) T_p ω_p (W) of one formulation, without the range of
/// η(τ) that [`evaluate_efficiencies`] also locates: what the thermal balance reads at every
/// temperature it tries. The same quadrature as [`mean_efficiencies`], so the same number.
pub fn mean_power_loss(ctx: &LawContext, law: &dyn FrictionLaw, formulation: Formulation) -> f64 {
    power_loss(ctx, mean_efficiency(ctx, law, formulation).value)
}

/// Whether a gearbox budget, the thermal balance and the efficiency map charge ISO/TR 14179-2's own
/// mesh loss P_VZP = P_in μ_mZ H_V (ISO/TR 14179-2:2001 §6.2, with Ohlendorf's loss factor H_V) rather
/// than the law's line integral: for the law `iso_14179_2` on a helical pair. The standard's μ_mZ was
/// fitted together with H_V, which is the mean loss of a slice model (each transverse slice shares its
/// load equally between its own pairs); the contact-line integral with a constant stiffness density
/// weights the ends of the path and reads 10–20 % higher at β = 15°. A spur pair under equal sharing
/// gives the same number both ways (H_V is that integral), so its reports keep the line integral.
pub fn charges_iso_mesh_loss(law: crate::friction::LawId, g: &crate::geometry::PairGeometry) -> bool {
    law == crate::friction::LawId::Iso14179_2 && g.is_helical()
}

/// ISO/TR 14179-2's P_VZP = P_in μ_mZ H_V (W), μ_mZ the law's mean |μ| (constant along the path).
pub fn iso_mesh_loss(input: f64, mean_abs_mu: f64, h_v: f64) -> f64 {
    input * mean_abs_mu * h_v
}

/// [`iso_mesh_loss`] at the context's point, μ_mZ read at the end of contact (the law's |μ| is the
/// same at every contact off the pitch point).
pub fn iso_mesh_loss_at(ctx: &LawContext, law: &dyn FrictionLaw, h_v: f64) -> f64 {
    let mu = law.mu(&ctx.contact_at(ctx.geometry.points.e)).abs();
    iso_mesh_loss(ctx.state.pinion_torque * ctx.state.pinion_speed, mu, h_v)
}

/// The mesh loss the budget charges at the context's point (W): [`iso_mesh_loss_at`] where
/// [`charges_iso_mesh_loss`] says so, else the law's line integral [`mean_power_loss`].
pub fn charged_mesh_loss(ctx: &LawContext, law: &dyn FrictionLaw, formulation: Formulation, h_v: f64) -> f64 {
    charged_mesh_losses(ctx, law, h_v)[formulation.index()]
}

/// [`charged_mesh_loss`] in both formulations, [external, internal], from one integration of the
/// mesh cycle (the line integral gives both at once; ISO/TR 14179-2's own loss is the same in both).
pub fn charged_mesh_losses(ctx: &LawContext, law: &dyn FrictionLaw, h_v: f64) -> [f64; 2] {
    if charges_iso_mesh_loss(law.id(), ctx.geometry) {
        [iso_mesh_loss_at(ctx, law, h_v); 2]
    } else {
        mean_efficiencies(ctx, law).map(|m| power_loss(ctx, m.value))
    }
}

/// P = (1 − η̄) T_p ω_p (W) at the context's operating point.
fn power_loss(ctx: &LawContext, mean_efficiency: f64) -> f64 {
    (1.0 - mean_efficiency) * ctx.state.pinion_torque * ctx.state.pinion_speed
}

/// Mean efficiency result of one law and formulation at one operating point.
#[derive(Debug, Clone, Serialize)]
pub struct EfficiencyResult {
    pub formulation: Formulation,
    pub mean: Integral,
    /// P = (1 − η̄) T_p ω_p (W).
    pub power_loss: f64,
    pub min: f64,
    pub max: f64,
}

/// Evaluates η̄, the power loss and the range of η(τ) for the requested formulations, sharing the
/// quadrature nodes between them. The range is located ([`crate::numerics::roots::extrema`]): on
/// each piece between break times, roots of dη/dτ bracketed on 32 nodes, plus the one-sided limits
/// at every break (η jumps where a pair enters or leaves).
pub fn evaluate_efficiencies(
    ctx: &LawContext,
    law: &dyn FrictionLaw,
    formulations: &[Formulation],
) -> Vec<EfficiencyResult> {
    if formulations.is_empty() {
        return Vec::new();
    }
    let breaks = break_times(ctx, law);
    let means = mean_efficiencies_between(ctx, law, &breaks);
    // η(τ) of both formulations at an instant from one set of contacts: a spur pair's pairs written
    // into one buffer (not a `Contacts` built, zeroed and moved each time), a helical pair's lines.
    let mesh = ctx.mesh();
    let items = std::cell::RefCell::new([ContactPoint::default(); MAX_CONTACTS]);
    let eta = |tau: f64| {
        if ctx.geometry.is_helical() {
            return efficiencies_of(ctx, law, &mesh.contacts_at(tau));
        }
        let items = &mut *items.borrow_mut();
        let n = mesh.fill_pair_contacts(tau, None, items);
        efficiencies_of(ctx, law, &items[..n])
    };
    // Both formulations' extremes read the same instants on the same grid: located together.
    let ranges: [Option<crate::numerics::roots::Extremes>; 2] = match formulations {
        [one] => {
            let k = one.index();
            let mut r = [None; 2];
            r[k] = Some(extrema(|tau| eta(tau)[k], &breaks, 32, 1e-12));
            r
        }
        _ => extrema_each(eta, &breaks, 32, 1e-12).map(Some),
    };
    formulations
        .iter()
        .map(|f| {
            let k = f.index();
            let ((min, _), (max, _)) = ranges[k].unwrap_or_else(|| unreachable!("every asked formulation is located"));
            EfficiencyResult { formulation: *f, power_loss: power_loss(ctx, means[k].value), mean: means[k], min, max }
        })
        .collect()
}
