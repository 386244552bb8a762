//! Numerical building blocks shared by the physics: adaptive quadrature, bracketed root finding,
//! Chebyshev–Lobatto spectral integration and the small dense linear algebra of the propagators.

pub(crate) mod chebyshev;
pub(crate) mod collocation;
pub(crate) mod dense;
pub(crate) mod quadrature;
pub(crate) mod roots;
pub(crate) mod rounding;
pub use chebyshev::Lobatto;
pub use collocation::Collocation;
pub use quadrature::{gauss_legendre, integrate, integrate_pieces_n, Integral};
pub use roots::{bracketed_roots, brent, extrema, extrema_each};
