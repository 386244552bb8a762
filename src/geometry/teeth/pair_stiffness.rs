//! A pair's stiffness along the path of contact by the potential-energy method, and the mesh
//! stiffness of one cycle (physics: README, "Mesh stiffness from the teeth").
//!
//! Per unit face width, 1/k_w(s) = 1/k_h + Σ over both teeth (1/k_b + 1/k_s + 1/k_a + 1/k_f) at the
//! contact of position s from A (roll lengths ℓ₁ = T1A + s, ℓ₂ = T1T2 − T1A − s), with the
//! linearised Hertz stiffness k_h = π E′/4 per unit width (Yang & Lin, "Hertzian damping, tooth
//! friction and bending elasticity in gear impact dynamics", J. Mech. Trans. Autom. Des. 109 (1987)
//! 189–196). k_w is analytic on [0, g_α]; it is kept as its Chebyshev series, of the smallest degree
//! that reproduces the direct evaluation between the nodes to 1e-12 relative.
//!
//! A spur pair: k(s) = b k_w(s), K(s) = Σ_j k(s + j p_b). A helical pair by the slice method taken
//! to its limit: a contact line whose mid-face section is at s covers the transverse positions
//! q ∈ [s − b tan β_b/2, s + b tan β_b/2], a slice dz at q adds k_w(q) dz, dz = dq / tan β_b, so the
//! line's stiffness is ∫ k_w(q) dq / tan β_b over its part inside [0, g_α] (the series integrated
//! term by term: exact, no slice count to converge). The mean over a cycle is b ∫₀^{g_α} k_w ds / p_b
//! for both.

use super::compliance::ToothCompliance;
use super::outline::{OutlineProblem, ToothInput, ToothOutline};
use crate::geometry::elastic::reduced_modulus;
use crate::geometry::pair::PairGeometry;
use crate::numerics::chebyshev::{clenshaw, Lobatto, DEGREES};

/// The gear bodies behind the teeth, SI; [pinion, wheel].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bodies {
    pub young: [f64; 2],
    pub poisson: [f64; 2],
    /// Root radius r_f; default from the basic rack, h_fP = 1.25 m_n: r_f = r − (1.25 − x) m_n.
    pub root_radius: [Option<f64>; 2],
    /// Bore radius r_int (the fillet foundation's inner boundary); default r_f/2.
    pub bore_radius: [Option<f64>; 2],
}

/// Why a pair's stiffness cannot be computed.
#[derive(Debug, Clone, PartialEq)]
pub enum StiffnessProblem {
    Outline {
        gear: usize,
        problem: OutlineProblem,
    },
    /// The mate's tip reaches below this gear's form circle: it would run into the fillet.
    Interference {
        gear: usize,
        start_of_active_profile: f64,
        form_radius: f64,
    },
    /// The bore is at or above the root circle.
    BoreTooLarge {
        gear: usize,
        bore: f64,
        root: f64,
    },
}

impl Bodies {
    /// The default root radius of gear `i` of `g`: r − (1.25 − x) m_n.
    pub fn default_root_radius(g: &PairGeometry, i: usize) -> f64 {
        g.pitch_radius[i] - (1.25 - g.profile_shift[i]) * g.module
    }

    /// Root and bore radius of gear `i`, given or by default.
    pub fn radii(&self, g: &PairGeometry, i: usize) -> (f64, f64) {
        let root = self.root_radius[i].unwrap_or_else(|| Self::default_root_radius(g, i));
        (root, self.bore_radius[i].unwrap_or(0.5 * root))
    }
}

/// The pieces of the path k_w is re-expanded on, and their degree: k_w's series (degree ≤ 64) on an
/// eighth of the path has coefficients that fall by 8⁻ᵏ, below 1e-16 of k_w past degree 16.
const PIECES: usize = 32;
const PIECE_DEGREE: usize = 8;

/// The pair's stiffness (spur or helical) over the path of contact.
#[derive(Debug, Clone)]
pub struct PairStiffness {
    pub teeth: [ToothCompliance; 2],
    /// k_h = π E′/4 per unit width (N/m²).
    pub hertz: f64,
    pub face_width: f64,
    /// T1A and T1T2 (m).
    pub start_roll: f64,
    pub line_of_action: f64,
    /// g_α = AE (m).
    pub path: f64,
    /// p_bt (m).
    pub base_pitch: f64,
    /// b tan β_b: the transverse extent of a contact line (0 for spur).
    pub lead: f64,
    /// k_w over s ∈ [0, g_α] as a Chebyshev series in s/g_α.
    series: Vec<f64>,
    /// The same k_w on [`PIECES`] equal pieces of the path, a short series each (the hot loops of
    /// load sharing read it: a third of the work of the whole series, the same values to 1e-14).
    pieces: Vec<Vec<f64>>,
    /// The series of dk_w/ds.
    derivative: Vec<f64>,
    /// ∫₀^s k_w, ∫₀^s q k_w and ∫₀^s q² k_w, as series (the helical line loads under relief
    /// integrate k_w against the relief's polynomial in closed form).
    integral: Vec<f64>,
    moments: [Vec<f64>; 2],
    /// ∫₀^s k_w, ∫₀^s q k_w, ∫₀^s q² k_w on the [`PIECES`] pieces, as `pieces` holds k_w (the
    /// helical line loads under relief read them at every step of their gap's solve).
    integral_pieces: [Vec<Vec<f64>>; 3],
    pub degree: usize,
    /// Relative error estimate of k_w: the teeth's quadratures and the series' fit.
    pub relative_error: f64,
}

impl PairStiffness {
    /// Both teeth's outlines, or every reason the pair's stiffness cannot be computed: what
    /// lowering checks (cheap: no quadrature).
    pub fn outlines(g: &PairGeometry, b: &Bodies) -> Result<[ToothOutline; 2], Vec<StiffnessProblem>> {
        let mut problems = Vec::new();
        let mut outlines = Vec::new();
        let sap = [g.points.a, g.line_of_action_length - g.points.e];
        for (i, sap) in sap.into_iter().enumerate() {
            let (root, bore) = b.radii(g, i);
            if bore >= root {
                problems.push(StiffnessProblem::BoreTooLarge { gear: i, bore, root });
            }
            let input = ToothInput {
                teeth: g.teeth[i],
                transverse_module: g.transverse_module,
                normal_module: g.module,
                pressure_angle: g.transverse_pressure_angle,
                shift: g.profile_shift[i] * g.module,
                tip_radius: g.tip_radius[i],
                root_radius: root,
            };
            match ToothOutline::new(input) {
                Err(problem) => problems.push(StiffnessProblem::Outline { gear: i, problem }),
                Ok(o) if sap < o.roll_of(o.form_radius) * (1.0 - 1e-12) => {
                    problems.push(StiffnessProblem::Interference {
                        gear: i,
                        start_of_active_profile: g.base_radius[i].hypot(sap),
                        form_radius: o.form_radius,
                    });
                }
                Ok(o) => outlines.push(o),
            }
        }
        match <[ToothOutline; 2]>::try_from(outlines) {
            Ok(both) if problems.is_empty() => Ok(both),
            _ => Err(problems),
        }
    }

    /// The stiffness of the pair `g` with the bodies `b`, or why it cannot be computed.
    pub fn new(g: &PairGeometry, b: &Bodies) -> Result<Self, Vec<StiffnessProblem>> {
        let outlines = Self::outlines(g, b)?;
        let teeth = [0, 1].map(|i| ToothCompliance::new(outlines[i], b.young[i], b.poisson[i], b.radii(g, i).1));
        let e_r = reduced_modulus(b.young, b.poisson);
        let mut pair = PairStiffness {
            teeth,
            hertz: std::f64::consts::PI * e_r / 4.0,
            face_width: g.face_width,
            start_roll: g.points.a,
            line_of_action: g.line_of_action_length,
            path: g.points.e - g.points.a,
            base_pitch: g.base_pitch,
            lead: g.line_lead(),
            series: Vec::new(),
            pieces: Vec::new(),
            derivative: Vec::new(),
            integral: Vec::new(),
            moments: [Vec::new(), Vec::new()],
            integral_pieces: [Vec::new(), Vec::new(), Vec::new()],
            degree: 0,
            relative_error: 0.0,
        };
        pair.fit();
        Ok(pair)
    }

    /// Compliance parts of both teeth at position s, per unit width: [pinion, wheel].
    pub fn tooth_parts(&self, s: f64) -> [super::compliance::ToothParts; 2] {
        [self.teeth[0].at(self.start_roll + s), self.teeth[1].at(self.line_of_action - self.start_roll - s)]
    }

    /// k_w(s) evaluated directly (N/m²).
    pub fn per_width_direct(&self, s: f64) -> f64 {
        let [p, w] = self.tooth_parts(s);
        1.0 / (1.0 / self.hertz + p.total() + w.total())
    }

    fn fit(&mut self) {
        let g = self.path;
        let mut best = None;
        for &degree in &DEGREES[1..] {
            let l = Lobatto::get(degree);
            let values: Vec<f64> = l.nodes.iter().map(|s| self.per_width_direct(g * s)).collect();
            let between = l.between.transpose() * nalgebra::DVector::from_column_slice(&values);
            let worst = (0..degree)
                .map(|j| {
                    let s = 0.5 * (1.0 - (std::f64::consts::PI * (2 * j + 1) as f64 / (2 * degree) as f64).cos());
                    let direct = self.per_width_direct(g * s);
                    (between[j] - direct).abs() / direct
                })
                .fold(0.0, f64::max);
            let done = worst < 1e-12 || degree == *DEGREES.last().unwrap();
            best = Some((l.coefficients(&values), degree, worst));
            if done {
                break;
            }
        }
        let (c, degree, worst) = best.expect("a degree");
        self.derivative = super::compliance_series::derivative(&c, g);
        self.integral = super::compliance_series::antiderivative(&c, g);
        // q k_w and q² k_w are polynomials of degree + 1 and + 2: exact through the nodes of the
        // largest degree.
        let top = Lobatto::get(*DEGREES.last().unwrap());
        self.moments = [1, 2].map(|p| {
            let values: Vec<f64> = top.nodes.iter().map(|s| (g * s).powi(p) * clenshaw(&c, *s)).collect();
            super::compliance_series::antiderivative(&top.coefficients(&values), g)
        });
        let pieces_of = |series: &[f64]| -> Vec<Vec<f64>> {
            let l = Lobatto::get(PIECE_DEGREE);
            (0..PIECES)
                .map(|i| {
                    let values: Vec<f64> =
                        l.nodes.iter().map(|t| clenshaw(series, (i as f64 + t) / PIECES as f64)).collect();
                    l.coefficients(&values)
                })
                .collect()
        };
        self.pieces = pieces_of(&c);
        self.integral_pieces = [&self.integral, &self.moments[0], &self.moments[1]].map(|series| pieces_of(series));
        self.series = c;
        self.degree = degree;
        self.relative_error = worst + self.teeth[0].relative_error + self.teeth[1].relative_error;
    }

    /// An upper bound of k_w over the path: Σ|c_k| of its series (N/m²).
    pub fn per_width_bound(&self) -> f64 {
        self.series.iter().map(|c| c.abs()).sum()
    }

    /// k_w(s) from the series (N/m²), s ∈ [0, g_α]: on its piece.
    pub fn per_width(&self, s: f64) -> f64 {
        self.on_pieces(&self.pieces, s)
    }

    /// A function re-expanded on the [`PIECES`] pieces, at s ∈ [0, g_α] (clamped).
    fn on_pieces(&self, pieces: &[Vec<f64>], s: f64) -> f64 {
        let x = (s / self.path * PIECES as f64).clamp(0.0, PIECES as f64);
        let i = (x as usize).min(PIECES - 1);
        clenshaw(&pieces[i], x - i as f64)
    }

    /// k_w(s) from the whole series (what the pieces re-expand).
    pub fn per_width_series(&self, s: f64) -> f64 {
        clenshaw(&self.series, s / self.path)
    }

    fn integral_to(&self, s: f64) -> f64 {
        self.on_pieces(&self.integral_pieces[0], s)
    }

    /// ∫ₐᵇ q^p k_w(q) dq for p = 0, 1, 2 (a, b in [0, g_α]), read on the pieces.
    pub fn weighted_integral(&self, a: f64, b: f64) -> [f64; 3] {
        [0, 1, 2].map(|p| self.on_pieces(&self.integral_pieces[p], b) - self.on_pieces(&self.integral_pieces[p], a))
    }

    /// [`Self::weighted_integral`] from the whole series (what the pieces re-expand).
    pub fn weighted_integral_series(&self, a: f64, b: f64) -> [f64; 3] {
        let at = |c: &[f64], q: f64| clenshaw(c, (q / self.path).clamp(0.0, 1.0));
        [&self.integral, &self.moments[0], &self.moments[1]].map(|c| at(c, b) - at(c, a))
    }

    pub fn is_helical(&self) -> bool {
        self.lead > 0.0
    }

    /// The range of positions (mid-face for a helical pair) over which a pair is in contact.
    pub fn engagement(&self) -> [f64; 2] {
        [-0.5 * self.lead, self.path + 0.5 * self.lead]
    }

    /// Where a series over one pair's engagement reads its last value: the end itself for a helical
    /// pair (its line leaves the path continuously, k → 0), and for a spur pair the left limit at E,
    /// read at the largest double below g_α (the pair is still in contact at E; [`Self::pair_at`]
    /// is read on the half-open [0, g_α), so at g_α itself it gives the 0 of the next instant).
    /// Piecewise polynomial in s, the value there is the left limit to a unit in the last place.
    pub fn inside_end(&self, s: f64) -> f64 {
        let [_, hi] = self.engagement();
        if self.is_helical() || s < hi || hi <= 0.0 {
            s
        } else {
            f64::from_bits(hi.to_bits() - 1)
        }
    }

    /// The stiffness of one tooth pair (N/m) whose position (mid-face section) is s; 0 out of contact.
    pub fn pair_at(&self, s: f64) -> f64 {
        if !self.is_helical() {
            return if (0.0..self.path).contains(&s) { self.face_width * self.per_width(s) } else { 0.0 };
        }
        let lo = (s - 0.5 * self.lead).max(0.0);
        let hi = (s + 0.5 * self.lead).min(self.path);
        if hi <= lo {
            return 0.0;
        }
        self.face_width / self.lead * (self.integral_to(hi) - self.integral_to(lo))
    }

    /// d(pair_at)/ds (N/m²).
    pub fn pair_slope(&self, s: f64) -> f64 {
        if !self.is_helical() {
            return if (0.0..self.path).contains(&s) {
                self.face_width * clenshaw(&self.derivative, s / self.path)
            } else {
                0.0
            };
        }
        let (lo, hi) = (s - 0.5 * self.lead, s + 0.5 * self.lead);
        if hi <= 0.0 || lo >= self.path {
            return 0.0;
        }
        let end = |q: f64| if (0.0..self.path).contains(&q) { self.per_width(q) } else { 0.0 };
        self.face_width / self.lead * (end(hi) - end(lo))
    }

    /// The positions s + j p_b of the pairs in contact when one pair is at s.
    pub fn pairs_with(&self, s: f64) -> Vec<f64> {
        let [lo, hi] = self.engagement();
        let first = ((lo - s) / self.base_pitch).ceil() as i64;
        let mut out = Vec::new();
        let mut j = first;
        loop {
            let q = s + j as f64 * self.base_pitch;
            if q >= hi {
                break;
            }
            if q >= lo && self.pair_at(q) > 0.0 {
                out.push(q);
            }
            j += 1;
        }
        out
    }

    /// The mesh stiffness K (N/m) when a pair is at s.
    pub fn mesh_at(&self, s: f64) -> f64 {
        self.pairs_with(s).iter().map(|q| self.pair_at(*q)).sum()
    }

    /// dK/ds (N/m²) when a pair is at s.
    pub fn mesh_slope(&self, s: f64) -> f64 {
        self.pairs_with(s).iter().map(|q| self.pair_slope(*q)).sum()
    }

    /// The mean mesh stiffness over a cycle, b ∫₀^{g_α} k_w ds / p_b (N/m), exact for the series.
    pub fn mean(&self) -> f64 {
        self.face_width * self.integral_to(self.path) / self.base_pitch
    }

    /// The position of the reference pair at time τ of the mesh cycle (τ = 0 when a pair enters
    /// at A; for a helical pair when a line's leading end enters): s = p_b τ − b tan β_b/2.
    pub fn position_at(&self, tau: f64) -> f64 {
        self.base_pitch * tau - 0.5 * self.lead
    }

    /// The positions of a pair where it (or an end of its contact line) enters or leaves the
    /// path: where its stiffness jumps (spur) or its slope does (helical).
    pub fn contact_ends(&self) -> Vec<f64> {
        if self.is_helical() {
            vec![-0.5 * self.lead, 0.5 * self.lead, self.path - 0.5 * self.lead, self.path + 0.5 * self.lead]
        } else {
            vec![0.0, self.path]
        }
    }

    /// The positions in one cycle [s0, s0 + p_b) where a pair (or a line end) enters or leaves.
    pub fn contact_changes(&self, s0: f64) -> Vec<f64> {
        let mut out: Vec<f64> = self
            .contact_ends()
            .iter()
            .map(|e| s0 + (e - s0).rem_euclid(self.base_pitch))
            .filter(|x| *x > s0 && *x < s0 + self.base_pitch)
            .collect();
        out.sort_by(f64::total_cmp);
        out.dedup_by(|a, b| (*a - *b).abs() < 1e-15 * self.path);
        out
    }
}
