//! Dense LU factorisation with partial pivoting, in place and without allocating: the linear solves of the
//! implicit stepper ([`super::Rosenbrock`]) on the small systems of a pounding row.

/// Factors the `n` x `n` row-major matrix `a` in place into `P A = L U` (unit lower `L` below the diagonal,
/// `U` on and above it), writing the row exchanges into `piv`. Returns false when a pivot is zero or not
/// finite (the matrix is singular to working precision), leaving `a` unusable.
pub fn factor(a: &mut [f64], piv: &mut [usize], n: usize) -> bool {
    for k in 0..n {
        let mut p = k;
        let mut best = a[k * n + k].abs();
        for i in k + 1..n {
            let v = a[i * n + k].abs();
            if v > best {
                best = v;
                p = i;
            }
        }
        piv[k] = p;
        if !(best.is_finite() && best > 0.0) {
            return false;
        }
        if p != k {
            for j in 0..n {
                a.swap(k * n + j, p * n + j);
            }
        }
        let inv = 1.0 / a[k * n + k];
        for i in k + 1..n {
            let l = a[i * n + k] * inv;
            a[i * n + k] = l;
            if l != 0.0 {
                for j in k + 1..n {
                    a[i * n + j] -= l * a[k * n + j];
                }
            }
        }
    }
    true
}

/// Solves `A x = b` in place (`b` becomes `x`) with the factors of [`factor`].
pub fn solve(a: &[f64], piv: &[usize], b: &mut [f64]) {
    let n = b.len();
    for (k, &p) in piv.iter().enumerate() {
        b.swap(k, p);
    }
    for i in 1..n {
        let mut s = b[i];
        for j in 0..i {
            s -= a[i * n + j] * b[j];
        }
        b[i] = s;
    }
    for i in (0..n).rev() {
        let mut s = b[i];
        for j in i + 1..n {
            s -= a[i * n + j] * b[j];
        }
        b[i] = s / a[i * n + i];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_system_that_needs_pivoting() {
        // A zero in the first pivot position forces a row exchange; x = (1, 2, 3) by construction.
        let a0 = [0.0, 2.0, 1.0, 1.0, 1.0, 1.0, 4.0, -1.0, 2.0];
        let x = [1.0, 2.0, 3.0];
        let mut b: Vec<f64> = (0..3)
            .map(|i| (0..3).map(|j| a0[i * 3 + j] * x[j]).sum())
            .collect();
        let mut a = a0;
        let mut piv = [0; 3];
        assert!(factor(&mut a, &mut piv, 3));
        solve(&a, &piv, &mut b);
        for (bi, xi) in b.iter().zip(x) {
            assert!((bi - xi).abs() < 1e-14, "{b:?}");
        }
    }

    #[test]
    fn a_singular_matrix_is_reported() {
        let mut a = [1.0, 2.0, 2.0, 4.0];
        assert!(!factor(&mut a, &mut [0; 2], 2));
    }
}
