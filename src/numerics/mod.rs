//! Numerical building blocks shared by the physics: adaptive quadrature and bracketed root finding.

pub mod quadrature;
pub mod roots;
