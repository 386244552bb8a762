//! The oil as the losses beside the mesh read it.

/// The oil at the oil temperature, as the losses beside the mesh read it (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oil {
    /// Kinematic viscosity ν (m²/s), density ρ (kg/m³), dynamic viscosity η (Pa·s).
    pub nu: f64,
    pub rho: f64,
    pub eta: f64,
    /// A mineral oil (SKF's μ_EHL of ball bearings depends on it).
    pub mineral: bool,
}
