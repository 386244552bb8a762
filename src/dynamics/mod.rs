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

pub mod airy;
pub mod analysis;
pub mod floquet;
pub mod free;
pub mod integrators;
pub mod model;
pub mod models;
pub mod numerics;
pub mod propagator;
pub(crate) mod rank_one;
pub mod response;
pub(crate) mod sdof;
pub mod six_dof;
pub mod six_dof_response;
pub(crate) mod spec;
pub mod trajectory;

pub use floquet::{Floquet, Multiplier};
pub use model::{PeriodicModel, Segment};
pub use sdof::{DynamicFormulation, SdofSystem, StiffnessModel};
