//! The propagator of a segment on which A(t) changes along one row only: A(t) = A0 + w(t) nᵀ with A0
//! and the row n constant on the segment and w(t) any smooth column (the 6-DOF model with friction:
//! f(t) and μ̄(t) scale the mesh force N = nᵀX, whose row holds the constant k and c of the segment).
//! Only the scalar N(t) is solved for, with ~3 nodes per oscillation of the fastest mode, where
//! 6th-order Magnus needs ~12 substeps of an 11 × 11 exponential for the same accuracy.
//!
//! With A0 = V Λ V⁻¹ (modal coordinates z = V⁻¹X, ŵ = V⁻¹w, n̂ = Vᵀn, b̂ = V⁻¹b), variation of constants
//! gives, on a piece [0, h] of the segment,
//!
//! - z_j(τ) = e^{λ_j τ} z_j(0) + ∫₀^τ e^{λ_j (τ−σ)} (ŵ_j(σ) N(σ) + b̂_j(σ)) dσ,
//! - N(τ) = Σ_j n̂_j z_j(τ): a scalar Volterra equation of the second kind for N.
//!
//! It is solved by collocation at the Chebyshev–Lobatto nodes τ_m of the piece
//! (Trefethen, *Spectral Methods in MATLAB*, SIAM 2000, ch. 12; [`crate::numerics::chebyshev`]):
//! (I − G) N = R, row i of G integrating e^{λ(τ_i − σ)} ŵ(σ) N(σ) from 0 to τ_i:
//! G_im = Σ_q S′_{2i,q} Re Σ_j n̂_j e^{λ_j (τ_i − σ_q)} P_qm ŵ_j(τ_m), with one
//! column of R per unit initial state (the free response Re Σ_j n̂_j e^{λ_j τ_i} (V⁻¹)_jc) and one for
//! b. The integrands e^{λ(τ_i − σ)} ŵ(σ) N(σ) oscillate up to twice the fastest mode, N itself
//! only up to it: so ŵN is taken as the polynomial through its values at the piece's nodes (P: its
//! values at the nodes between, [`crate::numerics::chebyshev::Lobatto::between`]) and integrated
//! on the Lobatto nodes σ_q of twice the degree (S′ their integration matrix; `quadrature`), and a
//! piece is at most [`MAX_PHASE`] radians of the fastest mode at degree [`PIECE_DEGREE`] (where
//! that polynomial reproduces the oscillation to 1e-13, measured and tested); a shorter span takes
//! the lowest degree that resolves it. The end state of every mode follows from the last row of
//! S′ the same way (Clenshaw–Curtis on the fine nodes). Where w is evaluated from the model at
//! every node (no series reproduces it on the segment) its own variation is unknown and the pieces
//! are kept half as long.
//!
//! Three structures, checked at the segment's Chebyshev nodes when it is built, make a
//! piece cheap: the mesh-driving part of ŵ keeps one modal direction, ŵ_j(t) = α_j φ(t), so that
//! G = M diag φ(τ_m) with M_im = Σ_q S′_{2i,q} Re Σ_j n̂_j α_j e^{λ_j (τ_i − σ_q)} P_qm and R the same for every
//! piece of a segment; b is constant; and w(t) is a Chebyshev series of the segment where one
//! reproduces it (else the model is evaluated at every node). The collocation systems are solved by
//! [`crate::numerics::dense::Augmented`].
//!
//! Everything runs on the scaled state X / scale (displacements and velocities of one size) so that V
//! is well conditioned; where A0's eigenvectors are not (cond V > [`MAX_CONDITION`], a defective or
//! nearly defective A0), or A(t) is found not to vary along n alone, no segment is built and the
//! caller keeps Magnus.

mod collocation;
mod complex;
mod quadrature;
mod segment;

pub(crate) use segment::RankOneSegment;
