//! Numerical building blocks shared by the physics: adaptive quadrature, bracketed root finding,
//! Chebyshev–Lobatto spectral integration and the small dense linear algebra of the propagators.

pub mod chebyshev;
pub mod collocation;
pub(crate) mod dense;
pub mod quadrature;
pub mod roots;
pub(crate) mod rounding;
