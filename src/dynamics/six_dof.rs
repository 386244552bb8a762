//! The 6-DOF model of a gear pair on bearings with friction off the line of action
//! (He–Cho–Singh eqs 1–9 for spur pairs; He & Singh eqs 1–17 for helical pairs; physics notes,
//! "Multi-DOF models"), written on the same mesh as the SDOF model ([`SdofSystem`]).
//!
//! Degrees of freedom: θ_p, θ_g, the translations x_p, x_g along the line of action (from T1 to
//! T2: the pinion pushes the wheel in +x) and y_p, y_g off it (+y is the direction of the friction
//! force on the pinion in recess, μ > 0; the wheel gets the opposite force). Mesh deflection
//! δ = r_b1 θ_p − r_b2 θ_g + x_p − x_g (the DTE). Per pair i of n in contact k_i = k(t)/n and
//! c_i = c/n, so every pair carries N_i = (k(t) δ + c δ̇)/n: the total mesh force is N = k δ + c δ̇
//! (the tooth force of the SDOF model). Friction F_fi = μ_i N_i along y, moments −μ_i X_pi N_i on the
//! pinion and +μ_i X_gi N_i on the wheel (X_pi = T1C_i, X_gi = T2C_i, eq 5). Bearings: springs K and
//! dampers 2ζ_B sqrt(K m) with the gear's own mass, along x and y; T_w = T_p r_b2 / r_b1.
//!
//! The rigid-body rotation does not feed back (no torsional spring to ground), so it is removed:
//! the torsional coordinate is δ_θ = r_b1 θ_p − r_b2 θ_g, and the model has 10 states
//! X = [δ_θ, x_p, x_g, y_p, y_g, and their rates]. Eliminating θ_p, θ_g with J_p, J_g gives
//!
//! - m_e δ̈_θ = F0 − (1 − f(t)) N                (f and m_e exactly those of the SDOF model)
//! - m_p ẍ_p + c_xp ẋ_p + K_xp x_p = −N,        m_g ẍ_g + c_xg ẋ_g + K_xg x_g = +N
//! - m_p ÿ_p + c_yp ẏ_p + K_yp y_p = +μ̄ N,      m_g ÿ_g + c_yg ẏ_g + K_yg y_g = −μ̄ N
//!
//! with μ̄(t) = Σ_i μ_i/n, the mean signed μ of the pairs in contact (for a helical pair the
//! integral of μ over the contact lines per unit length, divided by cos β_b because N is the
//! transverse component of the normal force). With bearings → ∞ the x and y motions vanish and the
//! torsional equation is the SDOF internal formulation (the base one when μ = 0), with an error
//! like 1/K; with μ = 0 the y motions are exactly zero.

use nalgebra::{SMatrix, SVector};
use serde::Serialize;

use super::model::{PeriodicModel, Segment};
use super::sdof::SdofSystem;

/// The number of states: δ_θ, x_p, x_g, y_p, y_g and their rates.
pub(crate) const STATES: usize = 10;

/// One gear's bearing: stiffness along and off the line of action (N/m) and the damping ratio.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Bearing {
    pub loa: f64,
    pub oloa: f64,
    pub damping_ratio: f64,
}

/// The 6-DOF model at one operating point: the SDOF mesh (stiffness, friction, damping) plus the
/// gears' masses and bearings.
pub struct SixDofSystem<'a> {
    pub mesh: SdofSystem<'a>,
    /// [pinion, wheel] (kg).
    pub mass: [f64; 2],
    pub bearings: [Bearing; 2],
    /// The natural frequencies of the mean undamped system (Hz), ascending.
    pub frequencies: Vec<f64>,
}

impl<'a> SixDofSystem<'a> {
    pub fn new(mesh: SdofSystem<'a>, mass: [f64; 2], bearings: [Bearing; 2]) -> Self {
        let mut s = SixDofSystem { mesh, mass, bearings, frequencies: Vec::new() };
        s.frequencies = s.natural_frequencies();
        s
    }

    /// Ratio of the highest to the lowest natural frequency of the mean system: how stiff the
    /// system is for an integrator.
    pub fn stiffness_ratio(&self) -> Option<f64> {
        let lo = self.frequencies.iter().copied().find(|f| *f > 0.0)?;
        Some(self.frequencies.last()? / lo)
    }

    /// Bearing damping 2ζ_B sqrt(K m) for gear `i`, [along x, along y] (N·s/m).
    pub fn bearing_damping(&self, i: usize) -> [f64; 2] {
        let b = self.bearings[i];
        let z = 2.0 * b.damping_ratio;
        [z * (b.loa * self.mass[i]).sqrt(), z * (b.oloa * self.mass[i]).sqrt()]
    }

    /// μ̄(t) = Σ_i μ_i / n along y per unit of N (module doc), with the same cap as the SDOF model for
    /// laws that diverge at P.
    pub fn mean_mu(&self, t: f64) -> f64 {
        self.mesh.friction_terms(t)[1]
    }

    /// The largest |μ_i| × its force share among the pairs in contact at t: the friction force of the
    /// most loaded pair per unit of N (for a helical pair, the largest line's share of Σ μ dl / L).
    pub fn largest_pair_mu(&self, t: f64) -> f64 {
        let m = &self.mesh;
        if m.law.is_none() {
            return 0.0;
        }
        let g = m.ctx.geometry;
        let tau = (t / m.period).rem_euclid(1.0);
        if g.is_helical() {
            // Per line: the share of the friction force carried by its quadrature points.
            // The points come line by line: LINE_NODES per piece, two pieces when a line crosses P.
            let contacts = m.ctx.mesh().contacts_at(tau);
            let (mut start, mut largest) = (0, 0.0f64);
            for l in g.contact_lines(tau).iter() {
                let pieces = crate::geometry::mesh::line_pieces(l.u[0].min(l.u[1]), l.u[0].max(l.u[1]), g.points.p);
                let end = (start + pieces * crate::geometry::mesh::LINE_NODES).min(contacts.len());
                let sum: f64 = contacts[start..end].iter().map(|c| m.friction_mu(c) * c.force_share).sum();
                largest = largest.max(sum.abs());
                start = end;
            }
            return g.to_normal(largest);
        }
        m.ctx.mesh().contacts_at(tau).iter().map(|c| (m.friction_mu(c) * c.force_share).abs()).fold(0.0, f64::max)
    }

    /// The mesh deflection δ and its rate from a state.
    pub fn deflection(x: &SVector<f64, STATES>) -> (f64, f64) {
        (x[0] + x[1] - x[2], x[5] + x[6] - x[7])
    }

    /// The total mesh force N = k(t) δ + c δ̇ (N); `tp` is the time at which k is read.
    pub fn mesh_force(&self, tp: f64, x: &SVector<f64, STATES>) -> f64 {
        let (d, v) = Self::deflection(x);
        self.mesh.stiffness_at(tp) * d + self.mesh.damping * v
    }

    /// The row of N = k (δ_θ + x_p − x_g) + c (their rates) over the 10 states, for stiffness k.
    pub fn mesh_force_row(&self, k: f64) -> SVector<f64, STATES> {
        let mut row = SVector::<f64, STATES>::zeros();
        for (j, sign) in [(0, 1.0), (1, 1.0), (2, -1.0)] {
            row[j] = k * sign;
            row[j + 5] = self.mesh.damping * sign;
        }
        row
    }

    /// The natural frequencies (Hz) of the undamped mean system (k = k̄, μ = 0), ascending.
    pub fn natural_frequencies(&self) -> Vec<f64> {
        let m = &self.mesh;
        let k = m.mean_stiffness;
        // Mass-normalised stiffness of [δ_θ, x_p, x_g] with N = k (δ_θ + x_p − x_g); the y block is
        // two independent oscillators.
        let inv = [1.0 / m.equivalent_mass, 1.0 / self.mass[0], 1.0 / self.mass[1]];
        let coupling = [1.0, 1.0, -1.0];
        let mut a = nalgebra::Matrix3::<f64>::zeros();
        for r in 0..3 {
            for c in 0..3 {
                // ẍ_r = −(sign_r) k (row of δ) / m_r, with the x_p and x_g equations carrying −N and +N.
                a[(r, c)] = inv[r] * coupling[r] * k * coupling[c];
            }
        }
        a[(1, 1)] += self.bearings[0].loa / self.mass[0];
        a[(2, 2)] += self.bearings[1].loa / self.mass[1];
        // Symmetrise with the masses: A = M⁻¹ K, eigenvalues of M^-1/2 K M^-1/2.
        let s = [m.equivalent_mass.sqrt(), self.mass[0].sqrt(), self.mass[1].sqrt()];
        let mut sym = a;
        for r in 0..3 {
            for c in 0..3 {
                sym[(r, c)] = a[(r, c)] * s[r] / s[c];
            }
        }
        let sym = 0.5 * (sym + sym.transpose());
        let mut w2: Vec<f64> = sym.symmetric_eigenvalues().iter().copied().collect();
        w2.push(self.bearings[0].oloa / self.mass[0]);
        w2.push(self.bearings[1].oloa / self.mass[1]);
        let mut f: Vec<f64> = w2.iter().map(|w| w.max(0.0).sqrt() / (2.0 * std::f64::consts::PI)).collect();
        f.sort_by(f64::total_cmp);
        f
    }
}

impl PeriodicModel<STATES> for SixDofSystem<'_> {
    fn name(&self) -> &'static str {
        "six_dof"
    }

    fn description(&self) -> &'static str {
        "6-DOF model (He–Cho–Singh eqs 1–9): rotation, line-of-action (x) and off-line-of-action (y) translations of both gears on their bearings; DTE = r_b1 θ_p − r_b2 θ_g + x_p − x_g, mesh force N = k(t) δ + c δ̇ shared by the n pairs in contact, friction μ_i N_i along y (pinion +, wheel −) with moment arms T1C_i and T2C_i. The rigid-body rotation is removed: 10 vibratory states; ρ is theirs. Periodic steady state from Floquet theory; exact propagator where the coefficients are constant on a segment, 4th-order Magnus elsewhere."
    }

    fn period(&self) -> f64 {
        self.mesh.period
    }

    fn segments(&self) -> &[Segment] {
        &self.mesh.segments
    }

    fn system(&self, t: f64) -> (SMatrix<f64, STATES, STATES>, SVector<f64, STATES>) {
        let m = &self.mesh;
        let k = m.stiffness_at(t);
        let [f, mu] = m.friction_terms(t);
        let mut a = SMatrix::<f64, STATES, STATES>::zeros();
        for i in 0..5 {
            a[(i, i + 5)] = 1.0;
        }
        let n_row = self.mesh_force_row(k);
        // Rows of the accelerations: (coefficient of N, mass) per coordinate.
        let per_n = [
            -(1.0 - f) / m.equivalent_mass,
            -1.0 / self.mass[0],
            1.0 / self.mass[1],
            mu / self.mass[0],
            -mu / self.mass[1],
        ];
        for (r, w) in per_n.iter().enumerate() {
            for j in 0..STATES {
                a[(r + 5, j)] += w * n_row[j];
            }
        }
        let [cp, cg] = [self.bearing_damping(0), self.bearing_damping(1)];
        let b = self.bearings;
        for (r, (kk, cc, mass)) in [
            (1, (b[0].loa, cp[0], self.mass[0])),
            (2, (b[1].loa, cg[0], self.mass[1])),
            (3, (b[0].oloa, cp[1], self.mass[0])),
            (4, (b[1].oloa, cg[1], self.mass[1])),
        ] {
            a[(r + 5, r)] -= kk / mass;
            a[(r + 5, r + 5)] -= cc / mass;
        }
        let mut rhs = SVector::<f64, STATES>::zeros();
        rhs[5] = m.static_force / m.equivalent_mass;
        (a, rhs)
    }

    /// A is constant on a segment without friction and with a rectangular stiffness.
    fn segment_is_affine(&self, _segment: usize) -> bool {
        self.mesh.allow_exact && self.mesh.law.is_none() && self.mesh.stiffness.is_piecewise_constant()
    }

    /// With a piecewise-constant stiffness A varies on a segment only through f(t) and μ̄(t), which
    /// scale the mesh force N = k δ + c δ̇: its row (k of the segment, c) is the varying row.
    fn varying_row(&self, segment: usize) -> Option<SVector<f64, STATES>> {
        if !self.mesh.allow_exact || !self.mesh.stiffness.is_piecewise_constant() {
            return None;
        }
        let s = self.mesh.segments[segment];
        let row = self.mesh_force_row(self.mesh.stiffness_at(0.5 * (s.start + s.end)));
        Some(row)
    }

    /// ∫ tr A dt with tr A = −(1 − f) c/m_e − c/m_p − c/m_g − (c_xp + c_yp)/m_p − (c_xg + c_yg)/m_g
    /// (the diagonal of [`PeriodicModel::system`]): only f(t) is integrated (adaptive Gauss–Kronrod to
    /// 1e-13 between the switch times), without building A.
    fn trace_integral(&self) -> f64 {
        let m = &self.mesh;
        let c = m.damping;
        let [cp, cg] = [self.bearing_damping(0), self.bearing_damping(1)];
        let constant = c / m.equivalent_mass + (c + cp[0] + cp[1]) / self.mass[0] + (c + cg[0] + cg[1]) / self.mass[1];
        let f = crate::numerics::quadrature::integrate(|t| m.friction_term(t), &self.breaks(), 1e-13).value;
        -constant * m.period + c / m.equivalent_mass * f
    }

    /// Displacements in units of the static deflection F0/k̄, velocities times ω_n.
    fn state_scale(&self) -> SVector<f64, STATES> {
        let s = self.mesh.state_scale();
        let mut out = SVector::<f64, STATES>::zeros();
        for i in 0..5 {
            out[i] = s[0];
            out[i + 5] = s[1];
        }
        out
    }

    /// The fastest free oscillation of the mean system.
    fn highest_frequency(&self, _t: f64) -> f64 {
        2.0 * std::f64::consts::PI * self.frequencies.last().copied().unwrap_or(0.0)
    }

    fn smooth_cuts(&self) -> Vec<f64> {
        self.mesh.smooth_cuts()
    }

    /// The DTE δ = δ_θ + x_p − x_g.
    fn observed(&self, x: &SVector<f64, STATES>) -> f64 {
        Self::deflection(x).0
    }
}

impl SixDofSystem<'_> {
    /// The static state at rest under the mean stiffness, where the numerics study starts:
    /// δ_θ = F0/k̄ + F0/K_xp + F0/K_xg (so that δ = F0/k̄), x_p = −F0/K_xp, x_g = F0/K_xg, y = 0.
    pub fn static_state(&self) -> SVector<f64, STATES> {
        let f0 = self.mesh.static_force;
        let (xp, xg) = (-f0 / self.bearings[0].loa, f0 / self.bearings[1].loa);
        let mut x = SVector::<f64, STATES>::zeros();
        x[0] = f0 / self.mesh.mean_stiffness - xp + xg;
        x[1] = xp;
        x[2] = xg;
        x
    }
}
