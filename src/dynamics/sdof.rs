//! The SDOF torsional model of a spur pair (Fernandes et al. eqs 3–20; physics notes, "Dynamics"):
//!
//! x = DTE = R_p θ_p − R_w θ_w, m_e = J_p J_w / (J_p R_w² + J_w R_p²), F0 = T_p / R_p,
//! - base:     m_e ẍ + c ẋ + k(t) x = F0
//! - external: m_e ẍ + c ẋ + k(t) x = F0 (1 + f(t))
//! - internal: m_e ẍ + (1 − f(t)) (c ẋ + k(t) x) = F0
//!
//! f = (J_w R_p g_p − J_p R_w g_w)/(J_p R_w² + J_w R_p²), g_p = −Σ μ_j w_j T1C_j, g_w = Σ μ_j w_j T2C_j,
//! with w_j the load share of contact j and μ_j its signed coefficient of friction (any law of the
//! scene, evaluated along the cycle). c = 2ζ sqrt(m_e k̄), k̄ the time mean of k(t).
//!
//! One mesh period [0, T) is cut into segments at every switch time: zone boundaries (k jumps),
//! pitch-point passages (μ changes sign, f changes slope) and law regime switches. The state is
//! X = [x, ẋ]; in a segment, Ẋ = A(t) X + b(t).

use nalgebra::{Matrix2, SMatrix, SVector, Vector2};
use serde::Serialize;

use super::model::{PeriodicModel, Segment};
use crate::efficiency::break_times;
use crate::friction::{FrictionLaw, LawContext};
pub use crate::geometry::stiffness::StiffnessModel;

/// Which equation of motion.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DynamicFormulation {
    Base,
    External,
    Internal,
    /// The internal formulation with its stiffness term (1 − f) k replaced by straight chords between
    /// its values at the break times: He & Singh's eq 25, offered for comparison with the exact one.
    InternalChord,
}

impl DynamicFormulation {
    pub fn name(self) -> &'static str {
        match self {
            DynamicFormulation::Base => "base",
            DynamicFormulation::External => "external",
            DynamicFormulation::Internal => "internal",
            DynamicFormulation::InternalChord => "internal_chord",
        }
    }
}

/// The SDOF system at one operating point, with its friction law and formulation.
pub struct SdofSystem<'a> {
    pub ctx: LawContext<'a>,
    pub law: Option<&'a dyn FrictionLaw>,
    pub formulation: DynamicFormulation,
    pub stiffness: StiffnessModel,
    /// Inertias of pinion and wheel (kg·m²).
    pub inertia: [f64; 2],
    pub equivalent_mass: f64,
    pub damping: f64,
    pub static_force: f64,
    /// Mesh period T (s).
    pub period: f64,
    pub segments: Vec<Segment>,
    pub mean_stiffness: f64,
    /// False forces 4th-order Magnus even where the exact propagator applies (`solver = magnus`).
    pub allow_exact: bool,
    /// Static transmission error ε(t) = Σ a_n cos(2π n t/T + φ_n): (a_n in m, φ_n in rad), n = 1, 2, …
    pub transmission_error: Vec<(f64, f64)>,
}

impl<'a> SdofSystem<'a> {
    /// Builds the system; c = 2ζ sqrt(m_e k̄).
    pub fn new(
        ctx: LawContext<'a>,
        law: Option<&'a dyn FrictionLaw>,
        formulation: DynamicFormulation,
        stiffness: StiffnessModel,
        inertia: [f64; 2],
        damping_ratio: f64,
    ) -> Self {
        let g = ctx.geometry;
        let (rp, rw) = (g.base_radius[0], g.base_radius[1]);
        let m_e = inertia[0] * inertia[1] / (inertia[0] * rw * rw + inertia[1] * rp * rp);
        let period = g.mesh_period(ctx.state.pinion_speed);
        let mut taus = match law {
            Some(l) => break_times(&ctx, l),
            None => ctx.geometry.cycle_break_times(&[]),
        };
        taus.dedup_by(|a, b| (*a - *b).abs() < 1e-14);
        let segments: Vec<Segment> =
            taus.windows(2).map(|w| Segment { start: w[0] * period, end: w[1] * period }).collect();
        // k̄ over the period (exact for the rectangular model, trapezoid on 4096 points for a table).
        let mean_stiffness = stiffness.mean(ctx.geometry, &taus, period);
        SdofSystem {
            ctx,
            law,
            formulation,
            damping: 2.0 * damping_ratio * (m_e * mean_stiffness).sqrt(),
            stiffness,
            inertia,
            equivalent_mass: m_e,
            static_force: ctx.state.pinion_torque / rp,
            period,
            segments,
            mean_stiffness,
            allow_exact: true,
            transmission_error: Vec::new(),
        }
    }

    /// k(t) (N/m); t in seconds, periodic.
    pub fn stiffness_at(&self, t: f64) -> f64 {
        let tau = (t / self.period).rem_euclid(1.0);
        self.stiffness.at(self.ctx.geometry, tau)
    }

    /// f(t), the friction term of the external and internal formulations.
    pub fn friction_term(&self, t: f64) -> f64 {
        self.friction_terms(t)[0]
    }

    /// [f(t), μ̄(t)] from one pass over the contacts: the friction term and the mean signed μ of the
    /// contacts, Σ μ_j w_j (the friction force along the off-line direction per unit of the tooth
    /// force, as the 6-DOF model uses it); both per unit of normal force for a helical pair.
    pub fn friction_terms(&self, t: f64) -> [f64; 2] {
        if self.law.is_none() {
            return [0.0; 2];
        }
        let g = self.ctx.geometry;
        let (rp, rw) = (g.base_radius[0], g.base_radius[1]);
        let [jp, jw] = self.inertia;
        let tau = (t / self.period).rem_euclid(1.0);
        let (mut gp, mut gw, mut mu) = (0.0, 0.0, 0.0);
        // A law that diverges at P is capped as in the internal efficiency formulation
        // (crate::efficiency::INTERNAL_MU_CAP), so that 1 − f never vanishes. Each contact carries its
        // force share 1/n of the tooth force, whatever load its law sees (`load_sharing`).
        for c in &self.ctx.mesh().contacts_at(tau) {
            let m = self.friction_mu(c) * c.force_share;
            gp -= m * c.u;
            gw += m * (g.line_of_action_length - c.u);
            mu += m;
        }
        let f = (jw * rp * gp - jp * rw * gw) / (jp * rw * rw + jw * rp * rp);
        // Helical (He & Singh eqs 19–24): the moments are per unit normal force, F_e = F_bn cos β_b.
        [g.to_normal(f), g.to_normal(mu)]
    }

    /// The chord of (1 − f) k over the segment holding t (He & Singh eq 25): the straight line
    /// between its one-sided values at the segment's ends.
    pub fn chord_stiffness(&self, t: f64) -> f64 {
        let tl = t.rem_euclid(self.period);
        let j = self.segments.iter().position(|s| tl < s.end).unwrap_or(self.segments.len() - 1);
        let s = self.segments[j];
        let eps = 1e-9 * (s.end - s.start);
        let value = |x: f64| (1.0 - self.friction_term(x)) * self.stiffness_at(x);
        let (k0, k1) = (value(s.start + eps), value(s.end - eps));
        let frac = ((tl - s.start - eps) / (s.end - s.start - 2.0 * eps)).clamp(0.0, 1.0);
        k0 + (k1 - k0) * frac
    }

    /// ε(t), ε̇(t) and ε̈(t) of the static transmission error.
    pub fn transmission_error_at(&self, t: f64) -> (f64, f64, f64) {
        let w = 2.0 * std::f64::consts::PI / self.period;
        let mut e = (0.0, 0.0, 0.0);
        for (n, (a, phi)) in self.transmission_error.iter().enumerate() {
            let wn = w * (n + 1) as f64;
            let arg = wn * t + phi;
            e.0 += a * arg.cos();
            e.1 -= a * wn * arg.sin();
            e.2 -= a * wn * wn * arg.cos();
        }
        e
    }

    /// The system matrix and forcing at t: Ẋ = A X + b. The transmission error enters the base model
    /// as c(ẋ − ε̇) + k(x − ε) (Fernandes eq 3 with the notes' reading c(ẋ − ε̇)), and the same way in the
    /// elastic term of the friction formulations.
    pub fn matrices(&self, t: f64) -> ([[f64; 2]; 2], [f64; 2]) {
        let m = self.equivalent_mass;
        let k = self.stiffness_at(t);
        let c = self.damping;
        let f0 = self.static_force;
        let (e, de, _) = self.transmission_error_at(t);
        let excitation = k * e + c * de;
        match self.formulation {
            DynamicFormulation::Base => ([[0.0, 1.0], [-k / m, -c / m]], [0.0, (f0 + excitation) / m]),
            DynamicFormulation::External => {
                ([[0.0, 1.0], [-k / m, -c / m]], [0.0, (f0 * (1.0 + self.friction_term(t)) + excitation) / m])
            }
            DynamicFormulation::Internal => {
                let s = 1.0 - self.friction_term(t);
                ([[0.0, 1.0], [-s * k / m, -s * c / m]], [0.0, (f0 + s * excitation) / m])
            }
            DynamicFormulation::InternalChord => {
                let s = 1.0 - self.friction_term(t);
                let chord = self.chord_stiffness(t);
                ([[0.0, 1.0], [-chord / m, -s * c / m]], [0.0, (f0 + s * excitation) / m])
            }
        }
    }

    /// True when on every segment A is constant and b affine in t, so the exact propagator applies:
    /// base, or external with a law of constant magnitude (Coulomb, ISO/TR 14179-2), rectangular k.
    pub fn exact_applies(&self) -> bool {
        self.allow_exact
            && self.transmission_error.is_empty()
            && self.stiffness.is_piecewise_constant()
            && match self.formulation {
                DynamicFormulation::Base => true,
                DynamicFormulation::External => self.law.is_none_or(|l| l.constant_magnitude()),
                DynamicFormulation::Internal | DynamicFormulation::InternalChord => self.law.is_none(),
            }
    }

    /// The tooth normal force of Fernandes eq 7, F = c (ẋ − ε̇) + k (x − ε), in every formulation
    /// (the internal formulation's (1 − f) factor belongs to its equation of motion, not to F).
    /// `tp` is the time at which k is read (a one-sided limit at a stiffness step), `t` the state's.
    pub fn tooth_force(&self, t: f64, tp: f64, x: &[f64; 2]) -> f64 {
        let (e, de, _) = self.transmission_error_at(t);
        self.stiffness_at(tp) * (x[0] - e) + self.damping * (x[1] - de)
    }

    /// dF/dt of [`SdofSystem::tooth_force`]: k'(x − ε) + k(ẋ − ε̇) + c(ẍ − ε̈), with ẍ from the
    /// equation of motion on the segment that `tp` lies in.
    pub fn tooth_force_rate(&self, t: f64, tp: f64, x: &[f64; 2]) -> f64 {
        let (e, de, dde) = self.transmission_error_at(t);
        let (a, b) = self.matrices(tp);
        let acc = a[1][0] * x[0] + a[1][1] * x[1] + b[1];
        let tau = (tp / self.period).rem_euclid(1.0);
        let k_rate = self.stiffness.slope(self.ctx.geometry, tau) / self.period;
        k_rate * (x[0] - e) + self.stiffness_at(tp) * (x[1] - de) + self.damping * (acc - dde)
    }

    /// The signed μ the model uses for a contact: the law's value, capped at ±
    /// [`crate::efficiency::INTERNAL_MU_CAP`] for a law that diverges at P (as in [`SdofSystem::friction_term`]).
    pub fn friction_mu(&self, c: &crate::geometry::ContactPoint) -> f64 {
        let Some(law) = self.law else { return 0.0 };
        let cap = crate::efficiency::internal_mu_cap(law);
        law.mu(c).clamp(-cap, cap)
    }

    /// X = [F0/k̄, 0]: the static deflection at rest, where the numerics study starts.
    pub fn static_state(&self) -> Vector2<f64> {
        Vector2::new(self.static_force / self.mean_stiffness, 0.0)
    }

    /// The undamped natural frequency at the mean stiffness, f_n = sqrt(k̄/m_e)/2π (Hz).
    pub fn natural_frequency(&self) -> f64 {
        (self.mean_stiffness / self.equivalent_mass).sqrt() / (2.0 * std::f64::consts::PI)
    }
}

impl PeriodicModel<2> for SdofSystem<'_> {
    fn name(&self) -> &'static str {
        "sdof"
    }

    fn description(&self) -> &'static str {
        "SDOF torsional model along the line of action (Fernandes et al.); x = DTE = R_p θ_p − R_w θ_w. Periodic steady state from Floquet theory, (I − Φ(T)) X(0) = q(T); the exact propagator (matrix exponential) where the coefficients are constant on a segment, 4th-order Magnus elsewhere."
    }

    fn period(&self) -> f64 {
        self.period
    }

    fn segments(&self) -> &[Segment] {
        &self.segments
    }

    fn system(&self, t: f64) -> (SMatrix<f64, 2, 2>, SVector<f64, 2>) {
        let (a, b) = self.matrices(t);
        (Matrix2::new(a[0][0], a[0][1], a[1][0], a[1][1]), Vector2::new(b[0], b[1]))
    }

    fn segment_is_affine(&self, _segment: usize) -> bool {
        self.exact_applies()
    }

    /// x_s = F0/k̄ and x_s ω_n with ω_n = sqrt(k̄/m_e).
    fn state_scale(&self) -> SVector<f64, 2> {
        let xs = self.static_force / self.mean_stiffness;
        Vector2::new(xs, xs * (self.mean_stiffness / self.equivalent_mass).sqrt())
    }

    /// sqrt(|A₂₁|) = sqrt(k(t)/m_e) (times sqrt(1 − f) in the internal formulation).
    fn highest_frequency(&self, t: f64) -> f64 {
        self.matrices(t).0[1][0].abs().sqrt()
    }

    /// The nodes of a stiffness table, where k'(t) jumps.
    fn smooth_cuts(&self) -> Vec<f64> {
        self.stiffness.smooth_cuts().into_iter().map(|x| x * self.period).collect()
    }

    /// ‖Φ‖ + ‖q‖ k̄/F0 (q in units of the static deflection).
    fn propagation_size(&self, phi: &SMatrix<f64, 2, 2>, q: &SVector<f64, 2>) -> f64 {
        phi.norm() + q.norm() / self.static_force.abs().max(1e-300) * self.mean_stiffness
    }

    /// −c T/m_e (base, external) or −∫(1 − f) c/m_e dt (internal).
    fn trace_integral(&self) -> f64 {
        let c = self.damping / self.equivalent_mass;
        match self.formulation {
            DynamicFormulation::Internal | DynamicFormulation::InternalChord => {
                crate::numerics::quadrature::integrate(|t| -(1.0 - self.friction_term(t)) * c, &self.breaks(), 1e-13)
                    .value
            }
            _ => -c * self.period,
        }
    }
}
