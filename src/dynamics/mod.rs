//! Gear dynamics with sliding friction: the SDOF torsional model along the line of action
//! (Fernandes et al. eqs 3–20, physics notes "Dynamics"), the 6-DOF model on bearings, the exact, spectral
//! rank-one and Magnus propagators,
//! Floquet stability and periodic steady state, general ODE integrators with restarts at every
//! switch time, and the error-against-run-time study.
//!
//! ```text
//! SdofSystem (one mesh period as segments) ─▶ propagator (Φ_j, q_j per segment; exact, rank_one or Magnus)
//!        │                                          │
//!        │                                          ▼
//!        ├──▶ integrators (DOP853, DOPRI5, Radau5, Kværnø ESDIRK; restarts)   floquet (Φ(T), multipliers, X*(0))
//!        ▼                                          ▼
//!     numerics (error vs run time)             response (DTE, forces, dynamic factor, spectrum)
//! ```

pub(crate) mod airy;
pub(crate) mod analysis;
pub(crate) mod floquet;
pub(crate) mod free;
pub(crate) mod integrators;
pub(crate) mod model;
pub mod models;
pub mod numerics;
pub(crate) mod propagator;
pub(crate) mod rank_one;
pub(crate) mod response;
pub(crate) mod sdof;
pub(crate) mod six_dof;
pub(crate) mod six_dof_response;
pub(crate) mod spec;
pub(crate) mod trajectory;

pub use airy::{airy_propagation, airy_propagator, linear_on_segments};
pub use analysis::FormulationResult;
pub use floquet::Verdict;
pub use floquet::{Floquet, Multiplier};
pub use free::free_response;
pub use integrators::{integrate, Integrator};
pub use model::{PeriodicModel, Segment};
pub use propagator::{magnus_adaptive, period_segments, AffineSegment, Method};
pub use response::PeriodicResponse;
pub use sdof::{DynamicFormulation, SdofSystem, StiffnessModel};
pub use six_dof::{Bearing, SixDofSystem};
pub use six_dof_response::SixDofResponse;
pub use trajectory::Trajectory;
