//! Nonlinear least squares for a few parameters: Levenberg–Marquardt with Marquardt's diagonal scaling
//! (Marquardt 1963, *J. SIAM* 11(2): 431–441), a central-difference Jacobian, and the covariance of the
//! estimate from it, `s^2 (J^T J)^-1` with `s^2 = RSS / (m - p)` (Bates & Watts 1988, ch. 2).

use crate::integrate::lu;
use crate::Error;

/// The estimate of a least-squares fit, in the parameters the residuals were written in.
#[derive(Clone, Debug, PartialEq)]
pub struct Solution {
    /// The parameters at the minimum.
    pub x: Vec<f64>,
    /// Their covariance (row-major, `p` x `p`): `s^2 (J^T J)^-1`; infinite with no more points than
    /// parameters (nothing left to estimate the scatter from).
    pub covariance: Vec<f64>,
    /// The residuals at the minimum.
    pub residuals: Vec<f64>,
    /// Sum of squared residuals.
    pub rss: f64,
    /// Iterations taken.
    pub iterations: usize,
}

impl Solution {
    /// Standard error of parameter `j`: the square root of its variance.
    pub fn std_error(&self, j: usize) -> f64 {
        let p = self.x.len();
        self.covariance[j * p + j].max(0.0).sqrt()
    }
}

/// Minimises the sum of squares of `m` residuals `r(x)` (`residuals(x, out)` writes them) from `x0`.
/// `scales` are the parameters' typical magnitudes, for the difference steps and the stopping test. A
/// trial point whose residuals cannot be computed (an error, or a value that is not finite) is rejected
/// like one that does not descend; an error at the starting point or while forming the Jacobian at an
/// accepted point is returned. `what` names the fit in the errors.
pub fn minimise<F>(
    mut residuals: F,
    x0: &[f64],
    scales: &[f64],
    m: usize,
    what: &'static str,
) -> Result<Solution, Error>
where
    F: FnMut(&[f64], &mut [f64]) -> Result<(), Error>,
{
    let p = x0.len();
    let mut x = x0.to_vec();
    let mut r = vec![0.0; m];
    residuals(&x, &mut r)?;
    let mut rss = sum_sq(&r);
    if !rss.is_finite() {
        return Err(not_identifiable(
            what,
            "the starting point gives no finite residuals",
        ));
    }
    let (mut jac, mut trial, mut rt) = (vec![0.0; m * p], vec![0.0; p], vec![0.0; m]);
    let mut lambda = 1e-3;
    let mut iterations = 0;
    jacobian(&mut residuals, &x, scales, &mut jac, m)?;
    while iterations < 200 && rss > 0.0 {
        iterations += 1;
        let (a, g) = normal_equations(&jac, &r, m, p);
        let mut accepted = false;
        while lambda < 1e16 {
            let mut lhs = a.clone();
            for j in 0..p {
                lhs[j * p + j] += lambda * a[j * p + j].max(1e-300);
            }
            let mut step: Vec<f64> = g.iter().map(|v| -v).collect();
            let mut piv = vec![0; p];
            if lu::factor(&mut lhs, &mut piv, p) {
                lu::solve(&lhs, &piv, &mut step);
                for j in 0..p {
                    trial[j] = x[j] + step[j];
                }
                let ok = residuals(&trial, &mut rt).is_ok();
                let t_rss = sum_sq(&rt);
                if ok && t_rss.is_finite() && t_rss <= rss {
                    let small = (0..p).all(|j| step[j].abs() <= 1e-12 * (x[j].abs() + scales[j]));
                    let flat = rss - t_rss <= 1e-15 * rss;
                    x.copy_from_slice(&trial);
                    r.copy_from_slice(&rt);
                    rss = t_rss;
                    lambda = (lambda / 10.0).max(1e-12);
                    accepted = true;
                    if small || flat {
                        return finish(residuals, x, r, rss, scales, iterations, what);
                    }
                    break;
                }
            }
            lambda *= 10.0;
        }
        if !accepted {
            // No step descends: the minimum to working precision.
            break;
        }
        jacobian(&mut residuals, &x, scales, &mut jac, m)?;
    }
    finish(residuals, x, r, rss, scales, iterations, what)
}

/// The solution at `x`, with the covariance from a fresh Jacobian.
fn finish<F>(
    mut residuals: F,
    x: Vec<f64>,
    r: Vec<f64>,
    rss: f64,
    scales: &[f64],
    iterations: usize,
    what: &'static str,
) -> Result<Solution, Error>
where
    F: FnMut(&[f64], &mut [f64]) -> Result<(), Error>,
{
    let (m, p) = (r.len(), x.len());
    let mut jac = vec![0.0; m * p];
    jacobian(&mut residuals, &x, scales, &mut jac, m)?;
    let (mut a, _) = normal_equations(&jac, &r, m, p);
    let mut piv = vec![0; p];
    if !lu::factor(&mut a, &mut piv, p) {
        return Err(not_identifiable(
            what,
            "the data do not determine every parameter (J^T J is singular)",
        ));
    }
    let s2 = if m > p {
        rss / (m - p) as f64
    } else {
        f64::INFINITY
    };
    let mut covariance = vec![0.0; p * p];
    for j in 0..p {
        let mut col = vec![0.0; p];
        col[j] = 1.0;
        lu::solve(&a, &piv, &mut col);
        for i in 0..p {
            covariance[i * p + j] = s2 * col[i];
        }
    }
    Ok(Solution {
        x,
        covariance,
        residuals: r,
        rss,
        iterations,
    })
}

/// `J^T J` and `J^T r` (row-major `J`, `m` x `p`).
fn normal_equations(jac: &[f64], r: &[f64], m: usize, p: usize) -> (Vec<f64>, Vec<f64>) {
    let mut a = vec![0.0; p * p];
    let mut g = vec![0.0; p];
    for i in 0..m {
        let row = &jac[i * p..(i + 1) * p];
        for j in 0..p {
            g[j] += row[j] * r[i];
            for k in 0..p {
                a[j * p + k] += row[j] * row[k];
            }
        }
    }
    (a, g)
}

/// The Jacobian of the residuals at `x` by central differences, steps `eps^(1/3)` of each parameter's
/// magnitude (truncation and round-off balanced).
fn jacobian<F>(
    residuals: &mut F,
    x: &[f64],
    scales: &[f64],
    jac: &mut [f64],
    m: usize,
) -> Result<(), Error>
where
    F: FnMut(&[f64], &mut [f64]) -> Result<(), Error>,
{
    let p = x.len();
    let (mut xp, mut rp, mut rm) = (x.to_vec(), vec![0.0; m], vec![0.0; m]);
    for j in 0..p {
        let h = 6e-6 * x[j].abs().max(scales[j]);
        xp[j] = x[j] + h;
        residuals(&xp, &mut rp)?;
        xp[j] = x[j] - h;
        residuals(&xp, &mut rm)?;
        xp[j] = x[j];
        for i in 0..m {
            jac[i * p + j] = (rp[i] - rm[i]) / (2.0 * h);
        }
    }
    Ok(())
}

fn sum_sq(r: &[f64]) -> f64 {
    r.iter().map(|v| v * v).sum()
}

fn not_identifiable(what: &'static str, why: &str) -> Error {
    Error::Choice {
        name: what,
        value: "these data".into(),
        allowed: format!("data that fix the fit: {why}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An exponential decay `y = a exp(-b t)` sampled without noise: the fit returns `(a, b)` to round-off,
    /// with a zero covariance.
    #[test]
    fn recovers_an_exponential_exactly_from_clean_samples() {
        let (a, b) = (3.0, 0.7);
        let t: Vec<f64> = (0..20).map(|k| 0.25 * f64::from(k)).collect();
        let y: Vec<f64> = t.iter().map(|t| a * (-b * t).exp()).collect();
        let s = minimise(
            |x, out| {
                for (k, o) in out.iter_mut().enumerate() {
                    *o = x[0] * (-x[1] * t[k]).exp() - y[k];
                }
                Ok(())
            },
            &[1.0, 0.1],
            &[1.0, 1.0],
            t.len(),
            "data",
        )
        .unwrap();
        assert!(
            (s.x[0] - a).abs() < 1e-10 && (s.x[1] - b).abs() < 1e-10,
            "{:?}",
            s.x
        );
        assert!(s.std_error(0) < 1e-8);
    }

    /// A straight line through noisy points: least squares has the closed form of linear regression, and
    /// the standard error of the slope is `s / sqrt(sum (t - mean)^2)`.
    #[test]
    fn a_line_matches_linear_regression_and_its_standard_error() {
        let t: Vec<f64> = (0..12).map(f64::from).collect();
        let noise = [
            0.3, -0.2, 0.1, 0.4, -0.5, 0.0, 0.2, -0.1, -0.3, 0.5, -0.4, 0.1,
        ];
        let y: Vec<f64> = t
            .iter()
            .zip(noise)
            .map(|(t, n)| 2.0 + 0.5 * t + n)
            .collect();
        let s = minimise(
            |x, out| {
                for (k, o) in out.iter_mut().enumerate() {
                    *o = x[0] + x[1] * t[k] - y[k];
                }
                Ok(())
            },
            &[0.0, 0.0],
            &[1.0, 1.0],
            t.len(),
            "data",
        )
        .unwrap();
        let n = t.len() as f64;
        let (tm, ym) = (t.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
        let sxx: f64 = t.iter().map(|t| (t - tm) * (t - tm)).sum();
        let sxy: f64 = t.iter().zip(&y).map(|(t, y)| (t - tm) * (y - ym)).sum();
        let slope = sxy / sxx;
        let icept = ym - slope * tm;
        let rss: f64 = t
            .iter()
            .zip(&y)
            .map(|(t, y)| (y - icept - slope * t).powi(2))
            .sum();
        let se = (rss / (n - 2.0) / sxx).sqrt();
        assert!((s.x[1] - slope).abs() < 1e-9 && (s.x[0] - icept).abs() < 1e-9);
        assert!(
            (s.std_error(1) - se).abs() < 1e-6 * se,
            "{} vs {se}",
            s.std_error(1)
        );
    }
}
