//! The oil as the losses beside the mesh read it.

/// The oil at the oil temperature, as the losses beside the mesh read it (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oil {
    /// Kinematic viscosity ν (m²/s) and density ρ (kg/m³), where the lubricant gives them (its
    /// density or its ν): the bearings and the jets need them, and lowering refuses a gearbox with
    /// bearings or injection lubrication whose oil lacks them.
    pub nu: Option<f64>,
    pub rho: Option<f64>,
    /// Dynamic viscosity η (Pa·s).
    pub eta: f64,
    /// A mineral oil (SKF's μ_EHL of ball bearings depends on it).
    pub mineral: bool,
}
