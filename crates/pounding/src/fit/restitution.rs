//! Restitution measured against the impact velocity, `(v_i, e)` pairs from drop or pendulum tests: the
//! material damping constant of the Hunt–Crossley law, Thornton's yield velocity, one constant `e`, or the
//! table itself, smoothed (docs/contact-models.md section 2.8; next-physics.md section 1).
//!
//! Each fit is least squares on `e` (the measured quantity, with its scatter), and each parameter's
//! uncertainty its standard error from the fit's Jacobian ([`super::least_squares`]).

use super::least_squares::minimise;
use super::{Estimate, Fit};
use crate::contact::exact::thornton_e;
use crate::contact::{material_e, RestitutionTable};
use crate::integrate::brent_root;
use crate::Error;

/// Checked `(v_i` m/s, `e)` pairs: at least `min` of them, `v_i > 0` finite, `0 < e <= 1`. The error names
/// the first row that is not, as `data` row k (from 1).
pub fn check_points(points: &[(f64, f64)], min: usize) -> Result<(), Error> {
    if points.len() < min {
        return Err(Error::Choice {
            name: "data",
            value: crate::words::count(points.len(), "row", None),
            allowed: format!(
                "at least {} (v_i m/s, e)",
                crate::words::count(min, "row", None)
            ),
        });
    }
    for (k, &(v, e)) in points.iter().enumerate() {
        let allowed = if !(v.is_finite() && v > 0.0) {
            "an impact velocity v_i > 0 (m/s) in the first column"
        } else if !(e > 0.0 && e <= 1.0) {
            "0 < e <= 1 in the second column"
        } else {
            continue;
        };
        return Err(Error::Choice {
            name: "data",
            value: format!(
                "row {} [{}, {}]",
                k + 1,
                crate::words::number(v),
                crate::words::number(e)
            ),
            allowed: allowed.into(),
        });
    }
    Ok(())
}

/// The material damping constant `c = D/K` (s/m) of `F = K d^n (1 + c d')` whose restitution
/// `e = material_e(c v_i)` fits the points best. Independent of `K`, `n` and the masses, so it serves every
/// model of the Hunt–Crossley family. At least two points; every `e = 1` has no damping to fit.
pub fn damping_constant(points: &[(f64, f64)]) -> Result<Fit, Error> {
    check_points(points, 2)?;
    // A start from each point's own c (the relation inverted), their median.
    let mut own: Vec<f64> = points
        .iter()
        .filter(|p| p.1 < 1.0)
        .filter_map(|&(v, e)| chi_for(e).map(|chi| chi / v))
        .collect();
    if own.is_empty() {
        return Err(Error::Choice {
            name: "data",
            value: "every e = 1".into(),
            allowed: "some e < 1: an elastic material has no damping constant".into(),
        });
    }
    let c0 = median(&mut own);
    // In ln c, so that c stays positive.
    let s = minimise(
        |x, out| {
            let c = x[0].exp();
            for (o, &(v, e)) in out.iter_mut().zip(points) {
                *o = material_e(c * v) - e;
            }
            Ok(())
        },
        &[c0.ln()],
        &[1.0],
        points.len(),
        "data",
    )?;
    let c = s.x[0].exp();
    Ok(Fit::new(
        vec![Estimate::new(
            "damping_constant",
            c,
            c * s.std_error(0),
            "s/m",
        )],
        &s.residuals,
        points.iter().map(|p| p.1),
        s.iterations,
    ))
}

/// Thornton's yield velocity `v_y` (m/s): the `e(v_i / v_y)` of elastic–perfectly-plastic spheres
/// ([`thornton_e`]) that fits the points best. At least two points, some with `e < 1`.
pub fn yield_velocity(points: &[(f64, f64)]) -> Result<Fit, Error> {
    check_points(points, 2)?;
    let mut own: Vec<f64> = points
        .iter()
        .filter(|p| p.1 < 1.0)
        .filter_map(|&(v, e)| speed_for(e).map(|s| v / s))
        .collect();
    if own.is_empty() {
        return Err(Error::Choice {
            name: "data",
            value: "every e = 1".into(),
            allowed: "some e < 1: below the yield velocity Thornton's spheres are elastic".into(),
        });
    }
    let v0 = median(&mut own);
    let s = minimise(
        |x, out| {
            let v_y = x[0].exp();
            for (o, &(v, e)) in out.iter_mut().zip(points) {
                *o = thornton_e(v / v_y) - e;
            }
            Ok(())
        },
        &[v0.ln()],
        &[1.0],
        points.len(),
        "data",
    )?;
    let v_y = s.x[0].exp();
    Ok(Fit::new(
        vec![Estimate::new(
            "yield_velocity",
            v_y,
            v_y * s.std_error(0),
            "m/s",
        )],
        &s.residuals,
        points.iter().map(|p| p.1),
        s.iterations,
    ))
}

/// One `e` for every impact velocity: the mean, and its standard error `sd / sqrt(n)` (for a model whose
/// `e` does not depend on `v_i`). At least one point (two for an uncertainty).
pub fn constant(points: &[(f64, f64)]) -> Result<Fit, Error> {
    check_points(points, 1)?;
    let n = points.len() as f64;
    let mean = points.iter().map(|p| p.1).sum::<f64>() / n;
    let residuals: Vec<f64> = points.iter().map(|p| mean - p.1).collect();
    let se = if points.len() > 1 {
        (residuals.iter().map(|r| r * r).sum::<f64>() / (n - 1.0) / n).sqrt()
    } else {
        f64::INFINITY
    };
    Ok(Fit::new(
        vec![Estimate::new("e", mean, se, "")],
        &residuals,
        points.iter().map(|p| p.1),
        0,
    ))
}

/// The points as a table `e(v_i)`, smoothed: grouped into at most `rows` rows of about equal counts by
/// velocity (each row the mean `v_i` and mean `e` of its group; all points with `rows = None`, equal
/// velocities merged), and with `monotone` made non-increasing in `v_i` by pooling adjacent rows that rise
/// (the pool-adjacent-violators algorithm, weighted by counts: the least-squares non-increasing fit). Also
/// each row's standard error (`sd / sqrt(count)` of its group; infinite for a group of one).
pub fn table(
    points: &[(f64, f64)],
    rows: Option<usize>,
    monotone: bool,
) -> Result<(RestitutionTable, Vec<f64>), Error> {
    check_points(points, 1)?;
    if rows == Some(0) {
        return Err(Error::Choice {
            name: "rows",
            value: "0".into(),
            allowed: "at least 1 row".into(),
        });
    }
    let mut sorted = points.to_vec();
    sorted.sort_by(|a, b| a.0.total_cmp(&b.0));
    // Groups: runs of equal velocity first, then merged into `rows` groups of about equal counts.
    let mut groups: Vec<Vec<(f64, f64)>> = Vec::new();
    for p in sorted {
        match groups.last_mut() {
            Some(g) if g[0].0 == p.0 => g.push(p),
            _ => groups.push(vec![p]),
        }
    }
    if let Some(r) = rows.filter(|&r| r < groups.len()) {
        // A group joins row floor(points before it * r / all points): rows of about equal counts.
        let total = points.len();
        let mut merged: Vec<Vec<(f64, f64)>> = Vec::new();
        let (mut before, mut last) = (0, usize::MAX);
        for g in groups {
            let row = before * r / total;
            before += g.len();
            if row == last {
                if let Some(m) = merged.last_mut() {
                    m.extend(g);
                }
            } else {
                merged.push(g);
                last = row;
            }
        }
        groups = merged;
    }
    // (mean v, mean e, count, sum of squares about the mean e)
    let mut pooled: Vec<(f64, f64, f64, f64)> = Vec::new();
    for g in &groups {
        let n = g.len() as f64;
        let v = g.iter().map(|p| p.0).sum::<f64>() / n;
        let e = g.iter().map(|p| p.1).sum::<f64>() / n;
        let ss = g.iter().map(|p| (p.1 - e).powi(2)).sum::<f64>();
        pooled.push((v, e, n, ss));
        // Pool adjacent violators: a row above the one before joins it (velocity and e weighted by counts).
        while monotone
            && pooled.len() > 1
            && pooled[pooled.len() - 1].1 > pooled[pooled.len() - 2].1
        {
            let b = pooled.pop().unwrap_or_default();
            if let Some(a) = pooled.last_mut() {
                let n = a.2 + b.2;
                let e = (a.1 * a.2 + b.1 * b.2) / n;
                // Sums of squares about the pooled mean.
                let ss = a.3 + a.2 * (a.1 - e).powi(2) + b.3 + b.2 * (b.1 - e).powi(2);
                *a = ((a.0 * a.2 + b.0 * b.2) / n, e, n, ss);
            }
        }
    }
    let errors = pooled
        .iter()
        .map(|&(_, _, n, ss)| {
            if n > 1.0 {
                (ss / (n - 1.0) / n).sqrt()
            } else {
                f64::INFINITY
            }
        })
        .collect();
    let t = RestitutionTable::new(pooled.iter().map(|r| (r.0, r.1)).collect())?;
    Ok((t, errors))
}

/// `chi` whose material restitution is `e` (0 < e < 1), if found.
pub(crate) fn chi_for(e: f64) -> Option<f64> {
    // material_e falls from 1 at chi = 0; e = 0.05 needs chi of a few tens.
    let hi = 1e4;
    brent_root(
        |c| material_e(c) - e,
        0.0,
        hi,
        1.0 - e,
        material_e(hi) - e,
        1e-14,
    )
}

/// `v_i / v_y` whose Thornton restitution is `e` (0 < e < 1), if found.
pub(crate) fn speed_for(e: f64) -> Option<f64> {
    let hi = 1e12;
    brent_root(
        |s| thornton_e(s) - e,
        1.0,
        hi,
        1.0 - e,
        thornton_e(hi) - e,
        1e-12,
    )
}

fn median(x: &mut [f64]) -> f64 {
    x.sort_by(f64::total_cmp);
    let n = x.len();
    if n % 2 == 1 {
        x[n / 2]
    } else {
        0.5 * (x[n / 2 - 1] + x[n / 2])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pooling_makes_a_table_non_increasing_and_keeps_the_mean() {
        let pts = [(0.1, 0.8), (0.2, 0.85), (0.3, 0.7), (0.4, 0.72), (0.5, 0.6)];
        let (t, _) = table(&pts, None, true).unwrap();
        let e: Vec<f64> = t.points().iter().map(|p| p.1).collect();
        assert!(e.windows(2).all(|w| w[1] <= w[0]), "{e:?}");
        // The least-squares non-increasing fit pools (0.8, 0.85) and (0.7, 0.72): their means.
        assert_eq!(e.len(), 3);
        assert!((e[0] - 0.825).abs() < 1e-15 && (e[1] - 0.71).abs() < 1e-15);
        // Rows: groups of about equal counts by velocity.
        let (t2, err) = table(&pts, Some(2), false).unwrap();
        assert_eq!(t2.points().len(), 2);
        assert!(err.iter().all(|e| e.is_finite()));
    }
}
