//! The mesh stiffness of a pair over one mesh cycle: rectangular (one value per number of pairs in
//! contact, given or estimated by ISO 6336-1) or a table over the cycle (given inline or from a CSV
//! file). The dynamics read k(τ) from here.

use serde::Serialize;

use super::pair::PairGeometry;

/// Mesh stiffness over one mesh cycle.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum StiffnessModel {
    /// Rectangular: stiffness with 1, 2 and 3 pairs in contact (N/m).
    PairsInContact { single: f64, double: f64, triple: f64 },
    /// Values at equally spaced times over one mesh period, t = 0 when a pair enters at A,
    /// linearly interpolated (periodic).
    Table(Vec<f64>),
    /// Constant stiffness density k along the contact lines (N/m²): k(τ) = k cos²β_b L(τ), the
    /// transverse mesh stiffness of He & Singh's K_e at μ = 0 (eq 24 with eqs 19–21). For a spur
    /// pair L = n b, so k(τ) = n k b: k b is the stiffness of one pair.
    PerLength { density: f64, cos2_base_helix: f64 },
}

impl StiffnessModel {
    /// k at time fraction τ ∈ [0, 1) with n pairs in contact.
    pub fn at(&self, tau: f64, pairs: usize) -> f64 {
        match self {
            StiffnessModel::PerLength { .. } => f64::NAN,
            StiffnessModel::PairsInContact { single, double, triple } => match pairs {
                0 | 1 => *single,
                2 => *double,
                _ => *triple,
            },
            StiffnessModel::Table(k) => {
                let n = k.len();
                let x = tau.rem_euclid(1.0) * n as f64;
                let i = (x.floor() as usize).min(n - 1);
                let frac = x - i as f64;
                k[i] * (1.0 - frac) + k[(i + 1) % n] * frac
            }
        }
    }

    /// dk/dτ at τ (per mesh period): 0 for the rectangular model, the slope of the table cell.
    pub fn slope(&self, tau: f64) -> f64 {
        match self {
            StiffnessModel::PerLength { .. } => f64::NAN,
            StiffnessModel::PairsInContact { .. } => 0.0,
            StiffnessModel::Table(k) => {
                let n = k.len();
                let i = ((tau.rem_euclid(1.0) * n as f64).floor() as usize).min(n - 1);
                (k[(i + 1) % n] - k[i]) * n as f64
            }
        }
    }

    pub fn is_piecewise_constant(&self) -> bool {
        match self {
            StiffnessModel::PairsInContact { .. } => true,
            StiffnessModel::PerLength { cos2_base_helix, .. } => *cos2_base_helix == 1.0,
            StiffnessModel::Table(_) => false,
        }
    }

    /// k at τ for the pair `g` (N/m): [`StiffnessModel::at`] with the pairs in contact at τ, or
    /// k cos²β_b L(τ) for a stiffness density.
    pub fn on_pair(&self, g: &PairGeometry, tau: f64) -> f64 {
        match self {
            StiffnessModel::PerLength { density, cos2_base_helix } => density * cos2_base_helix * g.contact_length(tau),
            _ => self.at(tau, g.pairs_at(tau)),
        }
    }

    /// dk/dτ at τ for the pair `g` (per mesh period).
    pub fn slope_on_pair(&self, g: &PairGeometry, tau: f64) -> f64 {
        match self {
            StiffnessModel::PerLength { density, cos2_base_helix } => {
                density * cos2_base_helix * g.contact_length_rate(tau)
            }
            _ => self.slope(tau),
        }
    }

    /// A stiffness density k (N/m²) on the pair `g`.
    pub fn per_length(density: f64, g: &PairGeometry) -> StiffnessModel {
        let c = if g.is_helical() { g.base_helix_angle.cos().powi(2) } else { 1.0 };
        StiffnessModel::PerLength { density, cos2_base_helix: c }
    }
}

/// The ISO 6336-1 single-pair stiffness per face width c' (N/(mm·µm)) (physics notes).
pub fn iso_6336_single_stiffness(g: &PairGeometry) -> f64 {
    let (z1, z2) = (g.teeth[0] as f64, g.teeth[1] as f64);
    let [x1, x2] = g.profile_shift;
    let q = 0.04723 + 0.15551 / z1 + 0.25791 / z2 - 0.00635 * x1 - 0.11654 * x1 / z1 - 0.00193 * x2 - 0.24188 * x2 / z2
        + 0.00529 * x1 * x1
        + 0.00182 * x2 * x2;
    let (c_m, c_r) = (0.8, 1.0);
    let h_fp = 1.25;
    let c_b = (1.0 + 0.5 * (1.2 - h_fp)) * (1.0 - 0.02 * (20.0 - g.pressure_angle.to_degrees()));
    c_m * c_r * c_b / q
}

impl StiffnessModel {
    /// The ISO 6336-1 estimate, rectangular with k_n = n c' b (physics notes, "Mesh stiffness").
    /// For a helical pair, a stiffness density whose mean transverse mesh stiffness per unit face
    /// width, K̄/b = k cos β_b ε_α, equals ISO's c_γα = c'(0.75 ε_α + 0.25), with c' including cos β.
    pub fn iso_6336(g: &PairGeometry) -> StiffnessModel {
        if g.is_helical() {
            let c_prime = iso_6336_single_stiffness(g) * g.helix_angle.cos() * 1e9; // N/m²
            let c_gamma = c_prime * (0.75 * g.contact_ratio + 0.25);
            return StiffnessModel::per_length(c_gamma / (g.contact_ratio * g.base_helix_angle.cos()), g);
        }
        // c' in N/(mm·µm) times b in mm: N/µm, ×1e6: N/m.
        let k = iso_6336_single_stiffness(g) * g.face_width * 1e3 * 1e6;
        StiffnessModel::PairsInContact { single: k, double: 2.0 * k, triple: 3.0 * k }
    }
}
