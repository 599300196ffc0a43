//! Eigen-decomposition of a small symmetric matrix by cyclic Jacobi rotations (Golub & Van Loan,
//! *Matrix Computations*, 4th ed., algorithm 8.5.3), with the threshold rule of Rutishauser's `jacobi`
//! (Handbook for Automatic Computation II, contribution II/1; Numerical Recipes, section 11.1). Chosen over
//! a library because the matrices are small (one row per floor), and Jacobi is accurate to rounding in
//! every eigenvalue, small ones included.
//!
//! Stopping rule. An off-diagonal element is set to zero, without a rotation, once it is negligible against
//! both its diagonal elements at the working precision: `|a_pp| + 100 |a_pq| == |a_pp|` and the same for
//! `a_qq`. Dropping it perturbs the matrix by less than `eps / 100 * min(|a_pp|, |a_qq|)` in that position,
//! which is within the bound `eps * sqrt(a_pp a_qq)` under which Jacobi keeps every eigenvalue of a positive
//! definite matrix to high relative accuracy (Demmel & Veselić, SIAM J. Matrix Anal. Appl. 13, 1992), so the
//! small eigenvalues lose nothing to the rule. The iteration stops after the first sweep in which no
//! rotation was needed; Jacobi converges quadratically, so that is a handful of sweeps (see the tests).

/// Sweeps after which [`symmetric`] gives up: a safeguard, never reached for finite symmetric input (an
/// 80-storey building takes 11).
const MAX_SWEEPS: usize = 60;

/// Result of [`symmetric`].
pub(super) struct Eigen {
    /// Eigenvalues, in no particular order.
    pub values: Vec<f64>,
    /// Row-major `n x n` matrix whose column `r` is the unit eigenvector of `values[r]`.
    pub vectors: Vec<f64>,
    /// Sweeps performed, the last one (which found nothing to rotate) included.
    pub sweeps: usize,
}

/// Eigenvalues and eigenvectors of the symmetric `n x n` row-major matrix `a` (destroyed: on return its
/// diagonal holds the eigenvalues and, once converged, the rest is zero).
pub(super) fn symmetric(a: &mut [f64], n: usize) -> Eigen {
    debug_assert_eq!(a.len(), n * n);
    // Transposed eigenvectors (row r is eigenvector r), so that rotations touch contiguous rows.
    let mut vt = vec![0.0; n * n];
    for i in 0..n {
        vt[i * n + i] = 1.0;
    }
    let mut sweeps = 0;
    while sweeps < MAX_SWEEPS {
        sweeps += 1;
        let mut rotations = 0usize;
        for p in 0..n {
            for q in p + 1..n {
                let apq = a[p * n + q];
                if apq == 0.0 {
                    continue;
                }
                let (app, aqq) = (a[p * n + p], a[q * n + q]);
                let g = 100.0 * apq.abs();
                if app.abs() + g == app.abs() && aqq.abs() + g == aqq.abs() {
                    a[p * n + q] = 0.0;
                    a[q * n + p] = 0.0;
                    continue;
                }
                rotations += 1;
                // Rotation that zeroes a[p][q] (the smaller of the two roots, for stability), with
                // hypot so that theta^2 cannot overflow.
                let theta = (aqq - app) / (2.0 * apq);
                let t = if theta == 0.0 {
                    1.0
                } else {
                    theta.signum() / (theta.abs() + theta.hypot(1.0))
                };
                let c = 1.0 / t.hypot(1.0);
                let s = t * c;
                // Rows p and q (contiguous), then columns p and q by symmetry; the 2 x 2 block is
                // diagonal by construction: set it so, with the diagonal by the short formulas (Numerical
                // Recipes, eq 11.1.14), which lose nothing to cancellation.
                let (row_p, row_q) = rows_mut(a, n, p, q);
                rotate(row_p, row_q, c, s);
                for k in 0..n {
                    a[k * n + p] = a[p * n + k];
                    a[k * n + q] = a[q * n + k];
                }
                a[p * n + p] = app - t * apq;
                a[q * n + q] = aqq + t * apq;
                a[p * n + q] = 0.0;
                a[q * n + p] = 0.0;
                let (vp, vq) = rows_mut(&mut vt, n, p, q);
                rotate(vp, vq, c, s);
            }
        }
        if rotations == 0 {
            break;
        }
    }
    Eigen {
        values: (0..n).map(|i| a[i * n + i]).collect(),
        vectors: (0..n * n).map(|k| vt[(k % n) * n + k / n]).collect(),
        sweeps,
    }
}

/// Rows `p < q` of the row-major `n`-column matrix `m`, both mutable.
fn rows_mut(m: &mut [f64], n: usize, p: usize, q: usize) -> (&mut [f64], &mut [f64]) {
    let (head, tail) = m.split_at_mut(q * n);
    (&mut head[p * n..(p + 1) * n], &mut tail[..n])
}

/// `(x, y) <- (c x - s y, s x + c y)`, element by element.
fn rotate(x: &mut [f64], y: &mut [f64], c: f64, s: f64) {
    for (xk, yk) in x.iter_mut().zip(y.iter_mut()) {
        let (a, b) = (*xk, *yk);
        *xk = c * a - s * b;
        *yk = s * a + c * b;
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn reconstructs_a_dense_symmetric_matrix() {
        let n = 5;
        let orig: Vec<f64> = (0..n * n)
            .map(|k| {
                let (i, j) = (k / n, k % n);
                1.0 / (1.0 + i as f64 + j as f64) + if i == j { 2.0 } else { 0.0 }
            })
            .collect();
        let mut a = orig.clone();
        let e = super::symmetric(&mut a, n);
        let (w, v) = (&e.values, &e.vectors);
        for i in 0..n {
            for j in 0..n {
                let r: f64 = (0..n).map(|k| v[i * n + k] * w[k] * v[j * n + k]).sum();
                assert!((r - orig[i * n + j]).abs() < 1e-13);
            }
        }
        assert!(e.sweeps <= 8, "{} sweeps", e.sweeps);
    }

    #[test]
    fn diagonal_and_indefinite_input() {
        // Already diagonal: one sweep that finds nothing to do.
        let mut a = vec![3.0, 0.0, 0.0, -1.0];
        let e = super::symmetric(&mut a, 2);
        assert_eq!((e.values, e.sweeps), (vec![3.0, -1.0], 1));
        // Indefinite, with a zero eigenvalue: [[1, 1], [1, 1]] has eigenvalues 0 and 2.
        let mut a = vec![1.0, 1.0, 1.0, 1.0];
        let e = super::symmetric(&mut a, 2);
        let mut w = e.values;
        w.sort_by(f64::total_cmp);
        assert!(w[0].abs() < 1e-15 && (w[1] - 2.0).abs() < 1e-15, "{w:?}");
        assert!(e.sweeps <= 3, "{} sweeps", e.sweeps);
    }

    #[test]
    fn small_eigenvalues_of_a_graded_matrix_to_relative_accuracy() {
        // D H D with H well conditioned and D graded over 12 orders of magnitude: the eigenvalues span 24
        // orders, and Jacobi finds the small ones to a few ulps relative (Demmel & Veselić 1992). The
        // reference is the exact 2 x 2 pattern: H = [[1, h], [h, 1]] scaled by d = (1, 1e-12) has
        // eigenvalues (1 + d^2 +- sqrt((1 - d^2)^2 + 4 h^2 d^2)) / 2, of product (1 - h^2) d^2.
        let (h, d) = (0.5f64, 1e-12f64);
        let mut a = vec![1.0, h * d, h * d, d * d];
        let e = super::symmetric(&mut a, 2);
        let mut w = e.values;
        w.sort_by(f64::total_cmp);
        assert!(
            (w[0] * w[1] / ((1.0 - h * h) * d * d) - 1.0).abs() < 1e-14,
            "{w:?}"
        );
    }
}
