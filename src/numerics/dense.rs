//! Small dense linear algebra the propagators need beyond nalgebra's: the eigenvectors of a real
//! non-symmetric matrix (nalgebra gives its eigenvalues only) and a row-major dense solve for the
//! collocation systems.

use nalgebra::{Complex, DMatrix, DVector, SMatrix};

type C64 = Complex<f64>;

/// Eigenvalues and unit eigenvectors of a real matrix: the values from the real Schur form, each
/// vector by two steps of inverse iteration; a conjugate pair's vectors are conjugates, the member
/// with Im λ > 0 first. None when the values do not pair up or an iteration fails.
pub fn eigen<const N: usize>(a: &SMatrix<f64, N, N>) -> Option<(Vec<C64>, DMatrix<C64>)> {
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

/// Solves A X = B (A n×n, B n×cols, both row-major) by Gaussian elimination with partial pivoting,
/// the right-hand sides eliminated along. For the collocation systems here (n ≤ 65, a few
/// right-hand sides) this is several times faster than a general LU and its column-wise solves.
pub fn solve_dense(mut a: Vec<f64>, n: usize, mut b: Vec<f64>, cols: usize) -> Vec<f64> {
    for k in 0..n {
        let pivot_row = (k..n).max_by(|i, j| a[i * n + k].abs().total_cmp(&a[j * n + k].abs())).unwrap_or(k);
        if pivot_row != k {
            for j in 0..n {
                a.swap(k * n + j, pivot_row * n + j);
            }
            for j in 0..cols {
                b.swap(k * cols + j, pivot_row * cols + j);
            }
        }
        let pivot = a[k * n + k];
        let (top, bottom) = a.split_at_mut((k + 1) * n);
        let pivot_a = &top[k * n + k + 1..(k + 1) * n];
        let (btop, bbottom) = b.split_at_mut((k + 1) * cols);
        let pivot_b = &btop[k * cols..];
        for i in 0..n - k - 1 {
            let f = bottom[i * n + k] / pivot;
            if f == 0.0 {
                continue;
            }
            for (x, y) in bottom[i * n + k + 1..(i + 1) * n].iter_mut().zip(pivot_a) {
                *x -= f * y;
            }
            for (x, y) in bbottom[i * cols..(i + 1) * cols].iter_mut().zip(pivot_b) {
                *x -= f * y;
            }
        }
    }
    for k in (0..n).rev() {
        let (head, tail) = b.split_at_mut((k + 1) * cols);
        let row = &mut head[k * cols..];
        for (j, solved) in tail.chunks_exact(cols).enumerate() {
            let akj = a[k * n + k + 1 + j];
            for (x, y) in row.iter_mut().zip(solved) {
                *x -= akj * y;
            }
        }
        let inv = 1.0 / a[k * n + k];
        row.iter_mut().for_each(|x| *x *= inv);
    }
    b
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

    /// Against nalgebra's LU with a non-trivial pivot order, to 1e-13.
    #[test]
    fn dense_solve_matches_lu() {
        let n = 7;
        let a =
            DMatrix::<f64>::from_fn(n, n, |i, j| ((i * 5 + j * 3) % 7) as f64 - 2.5 + if i == j { 0.1 } else { 0.0 });
        let b = DMatrix::<f64>::from_fn(n, 2, |i, j| (i + 2 * j) as f64);
        let x = solve_dense(
            (0..n * n).map(|k| a[(k / n, k % n)]).collect(),
            n,
            (0..n * 2).map(|k| b[(k / 2, k % 2)]).collect(),
            2,
        );
        let y = a.lu().solve(&b).expect("regular");
        for k in 0..n * 2 {
            assert!((x[k] - y[(k / 2, k % 2)]).abs() < 1e-13 * y.abs().max(), "{k}");
        }
    }
}
