//! Numerical building blocks shared by the physics: adaptive quadrature.

pub mod quadrature;
