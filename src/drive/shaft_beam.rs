//! A shaft as an elastic beam: cylinders along its own axial coordinate z, on any number of
//! supports (rigid, or radial springs), bent in both transverse planes by the gears' forces and by
//! the couples their axial forces make at the working pitch radius.
//!
//! Each plane is the same problem: a transverse displacement w(z) with slope θ, point forces F
//! and couples C (C the moment conjugate to θ: in the x–z plane M_y = −x F_z, in the y–z plane
//! −M_x = −y F_z). The beam is cut into elements at every section change, gear and support, so
//! that each element has one cross-section and no load inside; the cubic (Hermite) element of
//! Euler–Bernoulli theory is then exact at the nodes, and with the shear term
//! Φ = 12 EI/(κ G A L²) the element is the exact two-node Timoshenko element (Przemieniecki,
//! *Theory of Matrix Structural Analysis*, McGraw-Hill 1968, §5.6, eq. 5.116; Timoshenko & Gere,
//! *Mechanics of Materials*, the continuous beam). The shear coefficient of a hollow circle is
//! Cowper's, κ = 6(1+ν)(1+m²)² / ((7+6ν)(1+m²)² + (20+12ν)m²), m = d/D (G. R. Cowper, "The shear
//! coefficient in Timoshenko's beam theory", J. Appl. Mech. 33 (1966) 335–340, Table 1).
//!
//! A rigid support removes its displacement; a spring adds k to it. Reactions: a rigid place's
//! is the residual (K u − f) of its row, a spring's −k w. The reactions of every place but the two
//! outermost come from the beam; the outer two then follow from the shaft's equilibrium (ΣF = 0,
//! Σ (z F + C) = 0), so forces and moments balance to rounding whatever the stiffness solve did.
//!
//! ```
//! use gearloss::drive::shaft_beam::{solve, BeamTheory, PlaneLoad, ShaftBody, ShaftSection, Support};
//! // A uniform shaft on three rigid supports 100 mm apart, 1 kN at the middle of the first span:
//! // the three-moment equation gives 13/32, 22/32 and −3/32 of the load.
//! let body = ShaftBody::uniform(0.0, 0.2, 0.04, 210e9, 0.3, BeamTheory::EulerBernoulli);
//! let supports = [0.0, 0.1, 0.2].map(|at| Support { at, stiffness: None });
//! let load = PlaneLoad { at: 0.05, force: [1000.0, 0.0], couple: [0.0, 0.0] };
//! let s = solve(&body, &supports, &[load]).unwrap();
//! for (r, want) in s.reactions.iter().zip([13.0, 22.0, -3.0]) {
//!     assert!((r[0] + want / 32.0 * 1000.0).abs() < 1e-9);
//! }
//! ```

use nalgebra::DMatrix;

/// One hollow or solid cylinder of a shaft, on its own axial coordinate (m).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ShaftSection {
    pub from: f64,
    pub to: f64,
    pub outer_diameter: f64,
    /// 0 for a solid section.
    pub bore: f64,
}

impl ShaftSection {
    /// I = π (D⁴ − d⁴)/64 (m⁴).
    pub fn second_moment(&self) -> f64 {
        std::f64::consts::PI * (self.outer_diameter.powi(4) - self.bore.powi(4)) / 64.0
    }

    /// A = π (D² − d²)/4 (m²).
    pub fn area(&self) -> f64 {
        std::f64::consts::PI * (self.outer_diameter.powi(2) - self.bore.powi(2)) / 4.0
    }

    /// The bending section modulus W = I/(D/2) (m³): σ = M/W at the surface.
    pub fn section_modulus(&self) -> f64 {
        self.second_moment() / (self.outer_diameter / 2.0)
    }

    /// Cowper's shear coefficient κ of a hollow circle (1966, Table 1); 6(1+ν)/(7+6ν) solid.
    pub fn shear_coefficient(&self, poisson_ratio: f64) -> f64 {
        let nu = poisson_ratio;
        let m2 = (self.bore / self.outer_diameter).powi(2);
        let a = (1.0 + m2).powi(2);
        6.0 * (1.0 + nu) * a / ((7.0 + 6.0 * nu) * a + (20.0 + 12.0 * nu) * m2)
    }
}

/// Which beam theory bends the shaft.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BeamTheory {
    /// Bending only (plane sections stay normal to the axis).
    EulerBernoulli,
    /// Bending and shear (Timoshenko; Cowper's κ).
    Timoshenko,
}

impl BeamTheory {
    pub fn name(self) -> &'static str {
        match self {
            BeamTheory::EulerBernoulli => "euler_bernoulli",
            BeamTheory::Timoshenko => "timoshenko",
        }
    }
}

/// A shaft's body: its contiguous sections (ordered along z) and its material.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ShaftBody {
    pub sections: Vec<ShaftSection>,
    pub material: String,
    /// E (Pa) and ν; G = E/(2(1+ν)).
    pub youngs_modulus: f64,
    pub poisson_ratio: f64,
    pub theory: BeamTheory,
}

impl ShaftBody {
    /// One solid cylinder of diameter `d` from `from` to `to` (m).
    pub fn uniform(from: f64, to: f64, d: f64, youngs_modulus: f64, poisson_ratio: f64, theory: BeamTheory) -> Self {
        ShaftBody {
            sections: vec![ShaftSection { from, to, outer_diameter: d, bore: 0.0 }],
            material: "steel".into(),
            youngs_modulus,
            poisson_ratio,
            theory,
        }
    }

    /// The section at `z`: the one whose span holds it, the later one at a boundary.
    pub fn section_at(&self, z: f64) -> Option<&ShaftSection> {
        self.sections.iter().rev().find(|s| s.from <= z && z <= s.to)
    }

    /// Whether the sections reach `z`.
    pub fn covers(&self, z: f64) -> bool {
        self.section_at(z).is_some()
    }
}

/// A bearing place as the beam sees it: where (m) and its radial stiffness (N/m; None: rigid).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Support {
    pub at: f64,
    pub stiffness: Option<f64>,
}

/// A load at `at` (m): the transverse force [F_x, F_y] (N) and the couples [C_x-plane, C_y-plane]
/// (N·m) conjugate to each plane's slope.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlaneLoad {
    pub at: f64,
    pub force: [f64; 2],
    pub couple: [f64; 2],
}

/// The beam's answer: its nodes (m), the displacement [w_x, w_y] (m) and the section rotation
/// [θ_x, θ_y] (rad, the slope of each plane) at each, and each support's reaction [R_x, R_y] (N,
/// on the shaft).
#[derive(Debug, Clone, PartialEq)]
pub struct BeamSolution {
    pub nodes: Vec<f64>,
    pub deflection: Vec<[f64; 2]>,
    pub slope: Vec<[f64; 2]>,
    pub reactions: Vec<[f64; 2]>,
}

impl BeamSolution {
    /// The node nearest `z` (every support, load and section change is one).
    pub fn node(&self, z: f64) -> usize {
        let mut best = 0;
        for (i, n) in self.nodes.iter().enumerate() {
            if (n - z).abs() < (self.nodes[best] - z).abs() {
                best = i;
            }
        }
        best
    }
}

/// Positions closer than this are one node (m).
const SAME_NODE: f64 = 1e-9;

/// The shaft `body` on `supports` under `loads`; None when the supports cannot hold the shaft
/// (fewer than two distinct places, or a point outside the sections).
pub fn solve(body: &ShaftBody, supports: &[Support], loads: &[PlaneLoad]) -> Option<BeamSolution> {
    let at: Vec<f64> = loads.iter().map(|l| l.at).collect();
    PreparedBeam::new(body, supports, &at)?.solve(loads)
}

/// A shaft's beam made ready for its loads: nodes, stiffness and the Cholesky factor of its free
/// part depend on the shaft alone (its sections, supports and gear positions), so a drive builds
/// them once and each pass of its fixed point only substitutes the loads.
#[derive(Debug, Clone)]
pub struct PreparedBeam {
    nodes: Vec<f64>,
    k: DMatrix<f64>,
    factor: nalgebra::Cholesky<f64, nalgebra::Dyn>,
    free: Vec<usize>,
    supports: Vec<Support>,
}

impl PreparedBeam {
    /// The beam of `body` on `supports` with loads at `load_positions` (m); None when the supports
    /// cannot hold it or a position lies outside the sections.
    pub fn new(body: &ShaftBody, supports: &[Support], load_positions: &[f64]) -> Option<PreparedBeam> {
        let nodes = node_positions(body, supports, load_positions)?;
        let n = nodes.len();
        let k = stiffness(body, &nodes)?;
        let mut k_free = k.clone();
        let mut fixed = vec![false; 2 * n];
        for s in supports {
            let i = nearest(&nodes, s.at);
            match s.stiffness {
                None => fixed[2 * i] = true,
                Some(c) => k_free[(2 * i, 2 * i)] += c,
            }
        }
        let free: Vec<usize> = (0..2 * n).filter(|&d| !fixed[d]).collect();
        let kr = DMatrix::from_fn(free.len(), free.len(), |a, b| k_free[(free[a], free[b])]);
        Some(PreparedBeam { factor: kr.cholesky()?, nodes, k, free, supports: supports.to_vec() })
    }

    /// The beam under `loads`; None when a load lies off the nodes it was made for.
    pub fn solve(&self, loads: &[PlaneLoad]) -> Option<BeamSolution> {
        let (nodes, n) = (&self.nodes, self.nodes.len());
        let mut f = DMatrix::<f64>::zeros(2 * n, 2);
        for l in loads {
            let i = nearest(nodes, l.at);
            if (nodes[i] - l.at).abs() >= SAME_NODE {
                return None;
            }
            for p in 0..2 {
                f[(2 * i, p)] += l.force[p];
                f[(2 * i + 1, p)] += l.couple[p];
            }
        }
        let fr = DMatrix::from_fn(self.free.len(), 2, |a, p| f[(self.free[a], p)]);
        let ur = self.factor.solve(&fr);
        let mut u = DMatrix::<f64>::zeros(2 * n, 2);
        for (a, &d) in self.free.iter().enumerate() {
            u[(d, 0)] = ur[(a, 0)];
            u[(d, 1)] = ur[(a, 1)];
        }
        let ku = &self.k * &u;
        let mut reactions: Vec<[f64; 2]> = self
            .supports
            .iter()
            .map(|s| {
                let d = 2 * nearest(nodes, s.at);
                match s.stiffness {
                    None => [ku[(d, 0)] - f[(d, 0)], ku[(d, 1)] - f[(d, 1)]],
                    Some(c) => [-c * u[(d, 0)], -c * u[(d, 1)]],
                }
            })
            .collect();
        balance_outer(&self.supports, loads, &mut reactions);
        Some(BeamSolution {
            deflection: (0..n).map(|i| [u[(2 * i, 0)], u[(2 * i, 1)]]).collect(),
            slope: (0..n).map(|i| [u[(2 * i + 1, 0)], u[(2 * i + 1, 1)]]).collect(),
            nodes: nodes.clone(),
            reactions,
        })
    }
}

/// Every section change, support and load position, sorted, near ones merged; None when one lies
/// outside the sections or fewer than two distinct supports hold the shaft.
fn node_positions(body: &ShaftBody, supports: &[Support], loads: &[f64]) -> Option<Vec<f64>> {
    let mut z: Vec<f64> = body.sections.iter().flat_map(|s| [s.from, s.to]).collect();
    let points = supports.iter().map(|s| s.at).chain(loads.iter().copied());
    for p in points {
        if !p.is_finite() || !body.covers(p) {
            return None;
        }
        z.push(p);
    }
    z.sort_by(f64::total_cmp);
    z.dedup_by(|b, a| (*b - *a).abs() < SAME_NODE);
    let mut at: Vec<usize> = supports.iter().map(|s| nearest(&z, s.at)).collect();
    at.sort_unstable();
    at.dedup();
    (at.len() >= 2 && z.len() >= 2).then_some(z)
}

fn nearest(nodes: &[f64], z: f64) -> usize {
    let i = nodes.partition_point(|n| *n < z);
    match i {
        0 => 0,
        i if i == nodes.len() => i - 1,
        i if (nodes[i] - z).abs() < (z - nodes[i - 1]).abs() => i,
        i => i - 1,
    }
}

/// The assembled stiffness [w₀, θ₀, w₁, θ₁, …] of the elements between `nodes`; each element has
/// the section at its middle (Przemieniecki's Timoshenko element; Φ = 0 Euler–Bernoulli).
fn stiffness(body: &ShaftBody, nodes: &[f64]) -> Option<DMatrix<f64>> {
    let n = nodes.len();
    let e = body.youngs_modulus;
    let g = e / (2.0 * (1.0 + body.poisson_ratio));
    let mut k = DMatrix::<f64>::zeros(2 * n, 2 * n);
    for i in 0..n - 1 {
        let l = nodes[i + 1] - nodes[i];
        let s = body.section_at(0.5 * (nodes[i] + nodes[i + 1]))?;
        let ei = e * s.second_moment();
        let phi = match body.theory {
            BeamTheory::EulerBernoulli => 0.0,
            BeamTheory::Timoshenko => 12.0 * ei / (s.shear_coefficient(body.poisson_ratio) * g * s.area() * l * l),
        };
        let c = ei / ((1.0 + phi) * l.powi(3));
        let ke = [
            [12.0, 6.0 * l, -12.0, 6.0 * l],
            [6.0 * l, (4.0 + phi) * l * l, -6.0 * l, (2.0 - phi) * l * l],
            [-12.0, -6.0 * l, 12.0, -6.0 * l],
            [6.0 * l, (2.0 - phi) * l * l, -6.0 * l, (4.0 + phi) * l * l],
        ];
        for (a, row) in ke.iter().enumerate() {
            for (b, v) in row.iter().enumerate() {
                k[(2 * i + a, 2 * i + b)] += c * v;
            }
        }
    }
    Some(k)
}

/// The two outermost places' reactions from the shaft's equilibrium in each plane, the others'
/// (from the beam) taken as loads: R_b = (z_a S₀ − S₁)/(z_b − z_a), R_a = −S₀ − R_b with
/// S₀ = ΣF and S₁ = Σ (z F + C) over the loads and the inner reactions.
fn balance_outer(supports: &[Support], loads: &[PlaneLoad], reactions: &mut [[f64; 2]]) {
    let (mut a, mut b) = (0, 0);
    for (i, s) in supports.iter().enumerate() {
        if s.at < supports[a].at {
            a = i;
        }
        if s.at > supports[b].at {
            b = i;
        }
    }
    let (za, zb) = (supports[a].at, supports[b].at);
    // p is the plane: it indexes the loads' forces and couples and the reactions alike.
    #[allow(clippy::needless_range_loop)]
    for p in 0..2 {
        let (mut s0, mut s1) = (0.0, 0.0);
        for l in loads {
            s0 += l.force[p];
            s1 += l.at * l.force[p] + l.couple[p];
        }
        for (i, s) in supports.iter().enumerate().filter(|(i, _)| *i != a && *i != b) {
            s0 += reactions[i][p];
            s1 += s.at * reactions[i][p];
        }
        let rb = (za * s0 - s1) / (zb - za);
        reactions[b][p] = rb;
        reactions[a][p] = -s0 - rb;
    }
}
