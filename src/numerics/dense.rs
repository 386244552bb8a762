//! Small dense linear algebra the propagators need beyond nalgebra's: the eigenvectors of a real
//! non-symmetric matrix (nalgebra gives its eigenvalues only) and a blocked dense solve for the
//! collocation systems.

use nalgebra::{Complex, DMatrix, DVector, SMatrix};

type C64 = Complex<f64>;

/// Eigenvalues and unit eigenvectors of a real matrix: the values from the real Schur form, each
/// vector by two steps of inverse iteration; a conjugate pair's vectors are conjugates, the member
/// with Im λ > 0 first. None when the values do not pair up or an iteration fails.
pub(crate) fn eigen<const N: usize>(a: &SMatrix<f64, N, N>) -> Option<(Vec<C64>, DMatrix<C64>)> {
    let values = DMatrix::from_fn(N, N, |i, j| a[(i, j)]).complex_eigenvalues();
    let ac = DMatrix::<C64>::from_fn(N, N, |i, j| C64::new(a[(i, j)], 0.0));
    let mut lambda = Vec::with_capacity(N);
    let mut columns: Vec<DVector<C64>> = Vec::with_capacity(N);
    for (k, l) in values.iter().enumerate() {
        if l.im < 0.0 {
            continue;
        }
        // Nudged off the exact value so that the shifted matrix stays invertible.
        let shift = *l + C64::new(1e-13, 1e-13) * l.norm().max(1e-300);
        let lu = (&ac - DMatrix::<C64>::identity(N, N) * shift).lu();
        let mut x = DVector::<C64>::from_fn(N, |i, _| C64::new(1.0 + ((i * 7 + k * 3) % 11) as f64 * 0.1, 0.0));
        for _ in 0..2 {
            x = lu.solve(&x)?;
            x /= C64::new(x.norm(), 0.0);
        }
        if !x.iter().all(|c| c.re.is_finite() && c.im.is_finite()) {
            return None;
        }
        lambda.push(*l);
        columns.push(x.clone());
        if l.im > 0.0 {
            lambda.push(l.conj());
            columns.push(x.map(|c| c.conj()));
        }
    }
    if lambda.len() != N {
        return None;
    }
    Some((lambda, DMatrix::from_columns(&columns)))
}

/// One block column of the rows below, top to bottom.
type Column<'a> = std::iter::StepBy<std::slice::Iter<'a, [f64; 4]>>;

/// A square system with several right-hand sides, A X = B, stored row-major as [A | B] in blocks
/// of four (each part padded to whole blocks) so that the row operations of the elimination run
/// on whole blocks: the collocation systems of the spectral propagator (n ≤ 65, a few right-hand
/// sides), where a general LU's set-up and column-wise solves cost more than the arithmetic.
#[derive(Debug, Clone)]
pub(crate) struct Augmented {
    n: usize,
    cols: usize,
    /// Blocks per row of A and of the whole row.
    a_blocks: usize,
    row_blocks: usize,
    data: Vec<[f64; 4]>,
}

impl Augmented {
    /// n equations, `cols` right-hand sides, all zero.
    pub(crate) fn zeros(n: usize, cols: usize) -> Self {
        let a_blocks = n.div_ceil(4);
        let row_blocks = a_blocks + cols.div_ceil(4);
        Augmented { n, cols, a_blocks, row_blocks, data: vec![[0.0; 4]; n * row_blocks] }
    }

    /// Row i of [A | B] as one slice, padding included: A_ij at j, B_ic at [`Augmented::b_offset`] + c.
    pub(crate) fn row_mut(&mut self, i: usize) -> &mut [f64] {
        self.data[i * self.row_blocks..(i + 1) * self.row_blocks].as_flattened_mut()
    }

    /// Where B starts in a row of [`Augmented::row_mut`].
    pub(crate) fn b_offset(&self) -> usize {
        4 * self.a_blocks
    }

    /// The row X_i· (after [`Augmented::solve`]).
    pub(crate) fn x_row(&self, i: usize) -> &[f64] {
        let start = i * self.row_blocks + self.a_blocks;
        &self.data[start..(i + 1) * self.row_blocks].as_flattened()[..self.cols]
    }

    /// Gaussian elimination with partial pivoting, the right-hand sides eliminated along, then
    /// back substitution: B is replaced by X. (Entries left of the pivot column inside its block
    /// are updated too; they are never read again.) Where the processor has AVX the same
    /// operations run four to an instruction: separate multiplies and subtractions, no fused
    /// ones, so that both give the same bits.
    pub(crate) fn solve(&mut self) {
        #[cfg(target_arch = "x86_64")]
        if std::is_x86_feature_detected!("avx") {
            // SAFETY: the processor has AVX (detected just above).
            unsafe { self.solve_avx() };
            return;
        }
        self.eliminate_and_substitute(subtract_multiple, substitute_block);
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    fn solve_avx(&mut self) {
        use std::arch::x86_64::{_mm256_loadu_pd, _mm256_mul_pd, _mm256_set1_pd, _mm256_storeu_pd, _mm256_sub_pd};
        self.eliminate_and_substitute(
            |x, y, f| {
                let f = _mm256_set1_pd(f);
                for (x, y) in x.iter_mut().zip(y) {
                    // SAFETY: both point to four f64 of a block ([f64; 4]); unaligned loads and stores.
                    unsafe {
                        let product = _mm256_mul_pd(f, _mm256_loadu_pd(y.as_ptr()));
                        _mm256_storeu_pd(x.as_mut_ptr(), _mm256_sub_pd(_mm256_loadu_pd(x.as_ptr()), product));
                    }
                }
            },
            |x, coefficients, solved, inverse| {
                // SAFETY: x and every solved block are four f64 ([f64; 4]); unaligned loads and stores.
                unsafe {
                    let mut acc = _mm256_loadu_pd(x.as_ptr());
                    for (f, y) in coefficients.iter().zip(solved) {
                        acc = _mm256_sub_pd(acc, _mm256_mul_pd(_mm256_set1_pd(*f), _mm256_loadu_pd(y.as_ptr())));
                    }
                    _mm256_storeu_pd(x.as_mut_ptr(), _mm256_mul_pd(acc, _mm256_set1_pd(inverse)));
                }
            },
        );
    }

    /// The elimination and back substitution, with `update(x, y, f)`: x −= f y over whole blocks,
    /// and `substitute(x, f, y, inverse)`: x −= f_j y_j in order of j, then x ×= inverse (one
    /// block of a row of X, kept in a register while the solved rows are subtracted).
    #[inline(always)]
    fn eliminate_and_substitute(
        &mut self,
        update: impl Fn(&mut [[f64; 4]], &[[f64; 4]], f64),
        substitute: impl Fn(&mut [f64; 4], &[f64], Column, f64),
    ) {
        let (n, w, ab) = (self.n, self.row_blocks, self.a_blocks);
        let at = |data: &[[f64; 4]], i: usize, j: usize| data[i * w + j / 4][j % 4];
        for k in 0..n {
            let p = (k..n).max_by(|i, j| at(&self.data, *i, k).abs().total_cmp(&at(&self.data, *j, k).abs()));
            let p = p.unwrap_or(k);
            if p != k {
                let (low, high) = self.data.split_at_mut(p * w);
                low[k * w..(k + 1) * w].swap_with_slice(&mut high[..w]);
            }
            let inverse = 1.0 / at(&self.data, k, k);
            let first = (k + 1) / 4;
            let (top, bottom) = self.data.split_at_mut((k + 1) * w);
            let pivot_row = &top[k * w + first..(k + 1) * w];
            for row in bottom.chunks_exact_mut(w) {
                let f = row[k / 4][k % 4] * inverse;
                if f != 0.0 {
                    update(&mut row[first..], pivot_row, f);
                }
            }
        }
        for k in (0..n).rev() {
            let (head, tail) = self.data.split_at_mut((k + 1) * w);
            let (a, b) = head[k * w..].split_at_mut(ab);
            let (coefficients, inverse) = (&a.as_flattened()[k + 1..n], 1.0 / a.as_flattened()[k]);
            for (c, x) in b.iter_mut().enumerate() {
                substitute(x, coefficients, tail.get(ab + c..).unwrap_or_default().iter().step_by(w), inverse);
            }
        }
    }
}

/// x −= f_j y_j in order of j, then x ×= inverse.
fn substitute_block(x: &mut [f64; 4], f: &[f64], y: Column, inverse: f64) {
    for (f, y) in f.iter().zip(y) {
        for l in 0..4 {
            x[l] -= f * y[l];
        }
    }
    x.iter_mut().for_each(|v| *v *= inverse);
}

/// x −= f y, block by block.
fn subtract_multiple(x: &mut [[f64; 4]], y: &[[f64; 4]], f: f64) {
    for (x, y) in x.iter_mut().zip(y) {
        for l in 0..4 {
            x[l] -= f * y[l];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A damped oscillator pair and a real mode: A v = λ v to 1e-12, conjugate values paired.
    #[test]
    fn eigenpairs_of_a_damped_system() {
        let a = SMatrix::<f64, 3, 3>::new(0.0, 1.0, 0.0, -4.0, -0.2, 0.5, 0.0, 0.0, -3.0);
        let (values, v) = eigen(&a).expect("distinct eigenvalues");
        assert_eq!(values.len(), 3);
        let ac = a.map(|x| C64::new(x, 0.0));
        for (j, l) in values.iter().enumerate() {
            let col = v.column(j);
            let lhs = DMatrix::from_fn(3, 3, |r, c| ac[(r, c)]) * col;
            assert!((lhs - col * *l).norm() < 1e-12, "mode {j}");
        }
        assert!((values[0] - values[1].conj()).norm() < 1e-15 && values[0].im > 0.0);
    }

    /// Against nalgebra's LU with a non-trivial pivot order, to 1e-13: sizes inside one block and
    /// across several (the pivot rows then swap whole padded rows).
    #[test]
    fn dense_solve_matches_lu() {
        for (n, cols) in [(7, 2), (25, 7)] {
            let a = DMatrix::<f64>::from_fn(n, n, |i, j| {
                ((i * 37 + j * j * 101) % 97) as f64 / 97.0 - 0.5 + if i == j { 0.1 } else { 0.0 }
            });
            let b = DMatrix::<f64>::from_fn(n, cols, |i, j| (i + 2 * j) as f64);
            let mut system = Augmented::zeros(n, cols);
            let offset = system.b_offset();
            for i in 0..n {
                let row = system.row_mut(i);
                for j in 0..n {
                    row[j] = a[(i, j)];
                }
                for c in 0..cols {
                    row[offset + c] = b[(i, c)];
                }
            }
            system.solve();
            let y = a.lu().solve(&b).expect("regular");
            for i in 0..n {
                for (c, x) in system.x_row(i).iter().enumerate() {
                    assert!((x - y[(i, c)]).abs() < 1e-13 * y.abs().max(), "n {n}: {i} {c}");
                }
            }
        }
    }
}
