//! Lognormal fragility functions fitted by maximum likelihood (Baker 2015, *Efficient analytical fragility
//! function fitting using dynamic structural analysis*, Earthquake Spectra 31(1)).
//!
//! A fragility function is `P(exceed | IM = x) = Phi(ln(x / theta) / beta)`, with median `theta` (in the units
//! of the intensity measure) and logarithmic standard deviation `beta`. Two kinds of data:
//!
//! - **Multiple stripes**: at each intensity level `x_j`, `n_j` analyses of which `z_j` exceed the limit
//!   state. The likelihood is binomial, `prod_j C(n_j, z_j) p_j^z_j (1 - p_j)^(n_j - z_j)` with
//!   `p_j = Phi(ln(x_j / theta) / beta)` (Baker 2015, eq 11), maximised over `theta` and `beta`.
//! - **IDA**: for each record, the intensity at which it first exceeds the limit state. Their logarithms are
//!   normal: `ln theta` is their mean and `beta` their standard deviation (the maximum-likelihood values, over
//!   `n`; Baker 2015, eq 2-3). Records that never exceed within the levels analysed are right-censored at the
//!   highest level and enter the likelihood through `1 - Phi`.

use crate::Error;

/// A fitted lognormal fragility function.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Fragility {
    /// Median, in the units of the intensity measure.
    pub median: f64,
    /// Logarithmic standard deviation (dimensionless).
    pub beta: f64,
}

impl Fragility {
    /// The probability of exceeding the limit state at intensity `x`.
    pub fn probability(&self, x: f64) -> f64 {
        normal_cdf((x / self.median).ln() / self.beta)
    }
}

/// `erf(x)`: the Maclaurin series for `|x| < 2.5`, the continued fraction of `erfc` beyond (both to about
/// 1e-15 relative; Abramowitz & Stegun 7.1.5 and 7.1.14).
pub fn erf(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    let a = x.abs();
    if a < 2.5 {
        // erf x = 2/sqrt(pi) sum (-1)^n x^(2n+1) / (n! (2n+1)).
        let (mut term, mut sum, x2) = (a, a, a * a);
        for n in 1..200 {
            term *= -x2 / n as f64;
            let t = term / (2 * n + 1) as f64;
            sum += t;
            if t.abs() < 1e-17 * sum.abs() {
                break;
            }
        }
        (2.0 / std::f64::consts::PI.sqrt() * sum).copysign(x)
    } else {
        (1.0 - erfc_cf(a)).copysign(x)
    }
}

/// `erfc(a)` for `a >= 2.5` by its continued fraction (modified Lentz), which converges fast there.
fn erfc_cf(a: f64) -> f64 {
    if a > 27.0 {
        return 0.0;
    }
    // erfc a = exp(-a^2)/sqrt(pi) * 1/(a + (1/2)/(a + 1/(a + (3/2)/(a + 2/(a + ...))))).
    let tiny = 1e-300;
    let mut f = a;
    let (mut c, mut d) = (a, 0.0);
    for k in 1..500 {
        let num = k as f64 / 2.0;
        d = a + num * d;
        d = if d.abs() < tiny { tiny } else { d };
        c = a + num / c;
        c = if c.abs() < tiny { tiny } else { c };
        d = 1.0 / d;
        let delta = c * d;
        f *= delta;
        if (delta - 1.0).abs() < 1e-16 {
            break;
        }
    }
    (-a * a).exp() / std::f64::consts::PI.sqrt() / f
}

/// The standard normal cumulative distribution `Phi(z)`.
pub fn normal_cdf(z: f64) -> f64 {
    let x = z / std::f64::consts::SQRT_2;
    if x < -2.5 {
        0.5 * erfc_cf(-x)
    } else if x > 2.5 {
        1.0 - 0.5 * erfc_cf(x)
    } else {
        0.5 * (1.0 + erf(x))
    }
}

/// Minimises `f` over two variables by Nelder–Mead from `x0` with initial steps `step`, to a relative
/// tolerance of 1e-12 on the function.
fn nelder_mead(f: &dyn Fn([f64; 2]) -> f64, x0: [f64; 2], step: [f64; 2]) -> [f64; 2] {
    let mut s = [x0, [x0[0] + step[0], x0[1]], [x0[0], x0[1] + step[1]]];
    let mut v = s.map(f);
    for _ in 0..10_000 {
        // Order: best first.
        let mut idx = [0, 1, 2];
        idx.sort_by(|&a, &b| v[a].total_cmp(&v[b]));
        s = idx.map(|i| s[i]);
        v = idx.map(|i| v[i]);
        if (v[2] - v[0]).abs() <= 1e-12 * (v[0].abs() + 1e-300)
            && (s[2][0] - s[0][0]).abs() < 1e-10
            && (s[2][1] - s[0][1]).abs() < 1e-10
        {
            break;
        }
        let c = [(s[0][0] + s[1][0]) / 2.0, (s[0][1] + s[1][1]) / 2.0];
        let at = |t: f64| [c[0] + t * (s[2][0] - c[0]), c[1] + t * (s[2][1] - c[1])];
        let r = at(-1.0);
        let fr = f(r);
        if fr < v[0] {
            let e = at(-2.0);
            let fe = f(e);
            (s[2], v[2]) = if fe < fr { (e, fe) } else { (r, fr) };
        } else if fr < v[1] {
            (s[2], v[2]) = (r, fr);
        } else {
            let k = if fr < v[2] { at(-0.5) } else { at(0.5) };
            let fk = f(k);
            if fk < v[2].min(fr) {
                (s[2], v[2]) = (k, fk);
            } else {
                // Shrink towards the best.
                for i in 1..3 {
                    s[i] = [(s[i][0] + s[0][0]) / 2.0, (s[i][1] + s[0][1]) / 2.0];
                    v[i] = f(s[i]);
                }
            }
        }
    }
    s[0]
}

/// Checks a set of intensity levels: finite and > 0.
fn check_levels(xs: &[f64]) -> Result<(), Error> {
    for &x in xs {
        crate::error::check("intensity", x, x.is_finite() && x > 0.0, "intensity > 0")?;
    }
    Ok(())
}

/// The fragility function of multiple-stripe data: intensity levels `x` (> 0), analyses `n` and exceedances
/// `z` at each, by maximum likelihood (binomial). Needs at least one exceedance and one non-exceedance in all.
pub fn fit_stripes(x: &[f64], n: &[usize], z: &[usize]) -> Result<Fragility, Error> {
    check_levels(x)?;
    let total: usize = n.iter().sum();
    let exceed: usize = z.iter().sum();
    if x.len() != n.len() || x.len() != z.len() || z.iter().zip(n).any(|(z, n)| z > n) {
        return Err(Error::Choice {
            name: "stripes",
            value: format!(
                "{} levels, {} counts, {} exceedances",
                x.len(),
                n.len(),
                z.len()
            ),
            allowed: "one count and one exceedance count (<= the count) per level".into(),
        });
    }
    if exceed == 0 || exceed == total {
        return Err(Error::Choice {
            name: "stripes",
            value: format!("{exceed} of {total} analyses exceed"),
            allowed: "some analyses that exceed the limit state and some that do not (else the median is unbounded)".into(),
        });
    }
    // Perfectly separated data (no exceedance up to some level, only exceedances above it) have no maximum:
    // the likelihood grows as beta goes to 0 with the median anywhere between the two levels.
    let mut order: Vec<usize> = (0..x.len()).filter(|&j| n[j] > 0).collect();
    order.sort_by(|&a, &b| x[a].total_cmp(&x[b]));
    if let Some(k) = order.iter().position(|&j| z[j] > 0) {
        if order[k..].iter().all(|&j| z[j] == n[j]) {
            let below = if k > 0 { x[order[k - 1]] } else { 0.0 };
            return Err(Error::Choice {
                name: "stripes",
                value: format!("no exceedance up to {below}, only exceedances from {}", x[order[k]]),
                allowed: "data that overlap (the median lies between those levels, beta is not identifiable: analyse levels between them)".into(),
            });
        }
    }
    let nll = |p: [f64; 2]| -> f64 {
        let (ln_theta, beta) = (p[0], p[1].exp());
        let mut s = 0.0;
        for ((&x, &n), &z) in x.iter().zip(n).zip(z) {
            let u = (x.ln() - ln_theta) / beta;
            // ln Phi(u) and ln(1 - Phi(u)) = ln Phi(-u), each accurate in its own tail.
            let (lp, lq) = (normal_cdf(u).ln(), normal_cdf(-u).ln());
            s -= z as f64 * lp + (n - z) as f64 * lq;
        }
        if s.is_finite() {
            s
        } else {
            f64::MAX
        }
    };
    // Start from the level where about half exceed, beta 0.5.
    let mean_ln = x.iter().map(|v| v.ln()).sum::<f64>() / x.len() as f64;
    let p = nelder_mead(&nll, [mean_ln, 0.5f64.ln()], [0.3, 0.3]);
    Ok(Fragility {
        median: p[0].exp(),
        beta: p[1].exp(),
    })
}

/// The fragility function of IDA data: the intensity at which each record first exceeds the limit state
/// (`Some`), or `None` for a record that never did up to `censor` (the highest intensity analysed). Without
/// censored records this is the closed form (mean and standard deviation, over `n`, of the logarithms).
pub fn fit_ida(first: &[Option<f64>], censor: f64) -> Result<Fragility, Error> {
    let seen: Vec<f64> = first.iter().flatten().copied().collect();
    check_levels(&seen)?;
    if seen.len() < 2 {
        return Err(Error::Choice {
            name: "records",
            value: format!("{} records exceed", seen.len()),
            allowed: "at least two records that exceed the limit state within the levels analysed"
                .into(),
        });
    }
    let logs: Vec<f64> = seen.iter().map(|v| v.ln()).collect();
    let n = logs.len() as f64;
    let mean = logs.iter().sum::<f64>() / n;
    let sd = (logs.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / n).sqrt();
    let censored = first.len() - seen.len();
    if sd == 0.0 {
        return Err(Error::Choice {
            name: "records",
            value: format!("every record first exceeds at {}", seen[0]),
            allowed: "first exceedances at different intensities (beta is 0 otherwise: analyse levels between)".into(),
        });
    }
    if censored == 0 {
        return Ok(Fragility {
            median: mean.exp(),
            beta: sd,
        });
    }
    check_levels(&[censor])?;
    let ln_c = censor.ln();
    let nll = |p: [f64; 2]| -> f64 {
        let (mu, beta) = (p[0], p[1].exp());
        // The density of ln IM (constants dropped) and the survival of the censored records.
        let s: f64 = logs
            .iter()
            .map(|l| beta.ln() + 0.5 * ((l - mu) / beta).powi(2))
            .sum::<f64>()
            - censored as f64 * normal_cdf(-(ln_c - mu) / beta).ln();
        if s.is_finite() {
            s
        } else {
            f64::MAX
        }
    };
    let p = nelder_mead(&nll, [mean, sd.max(0.05).ln()], [0.3, 0.3]);
    Ok(Fragility {
        median: p[0].exp(),
        beta: p[1].exp(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn erf_and_phi_match_tabulated_values() {
        // Abramowitz & Stegun table 7.1 and standard normal tables.
        assert!((erf(0.5) - 0.520_499_877_813_046_5).abs() < 1e-15);
        assert!((erf(1.0) - 0.842_700_792_949_714_9).abs() < 1e-15);
        assert!((erf(2.0) - 0.995_322_265_018_952_7).abs() < 1e-15);
        assert!((erf(3.0) - 0.999_977_909_503_001_4).abs() < 1e-15);
        assert!((normal_cdf(1.0) - 0.841_344_746_068_542_9).abs() < 1e-15);
        assert!((normal_cdf(-3.0) / 0.001_349_898_031_630_094_5 - 1.0).abs() < 1e-13);
        // Far tail: Phi(-8) = 6.220960574271785e-16.
        assert!((normal_cdf(-8.0) / 6.220_960_574_271_785e-16 - 1.0).abs() < 1e-12);
        assert_eq!(erf(-1.0), -erf(1.0));
    }

    /// A deterministic stream of uniforms in (0, 1) (SplitMix64).
    fn uniforms(seed: u64) -> impl FnMut() -> f64 {
        let mut z = seed;
        move || {
            z = z.wrapping_add(0x9e3779b97f4a7c15);
            let mut x = z;
            x = (x ^ (x >> 30)).wrapping_mul(0xbf58476d1ce4e5b9);
            x = (x ^ (x >> 27)).wrapping_mul(0x94d049bb133111eb);
            x ^= x >> 31;
            ((x >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        }
    }

    #[test]
    fn stripes_drawn_from_a_known_fragility_give_it_back_within_the_sampling_error() {
        let truth = Fragility {
            median: 0.8,
            beta: 0.4,
        };
        let levels: Vec<f64> = (1..=15).map(|i| 0.1 * i as f64).collect();
        let n = vec![200usize; levels.len()];
        let mut u = uniforms(3);
        let z: Vec<usize> = levels
            .iter()
            .map(|&x| (0..200).filter(|_| u() < truth.probability(x)).count())
            .collect();
        let fit = fit_stripes(&levels, &n, &z).unwrap();
        // 3000 analyses: standard errors about 1 % on the median and 3 % on beta (Baker 2015, Fig. 6 scale).
        assert!((fit.median / truth.median - 1.0).abs() < 0.04, "{fit:?}");
        assert!((fit.beta / truth.beta - 1.0).abs() < 0.12, "{fit:?}");
    }

    #[test]
    fn ida_data_give_the_lognormal_moments_and_handle_censoring() {
        // Without censoring: the mean and standard deviation of the logarithms, exactly.
        let first = [Some(0.5), Some(1.0), Some(2.0)];
        let f = fit_ida(&first, 3.0).unwrap();
        assert!((f.median - 1.0).abs() < 1e-12);
        assert!((f.beta - (2.0f64.ln().powi(2) * 2.0 / 3.0).sqrt()).abs() < 1e-12);
        // Drawn from a known lognormal, 400 records, those above 2.0 censored.
        let truth = Fragility {
            median: 1.2,
            beta: 0.5,
        };
        let mut u = uniforms(11);
        let draws: Vec<Option<f64>> = (0..400)
            .map(|_| {
                // Inverse CDF by bisection on Phi.
                let p = u();
                let (mut lo, mut hi) = (-10.0, 10.0);
                for _ in 0..200 {
                    let mid = 0.5 * (lo + hi);
                    if normal_cdf(mid) < p {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let x = truth.median * (truth.beta * 0.5 * (lo + hi)).exp();
                (x <= 2.0).then_some(x)
            })
            .collect();
        assert!(draws.iter().any(Option::is_none));
        let f = fit_ida(&draws, 2.0).unwrap();
        assert!((f.median / truth.median - 1.0).abs() < 0.06, "{f:?}");
        assert!((f.beta / truth.beta - 1.0).abs() < 0.12, "{f:?}");
    }

    #[test]
    fn data_that_cannot_give_a_median_are_refused() {
        assert!(fit_stripes(&[1.0, 2.0], &[10, 10], &[0, 0]).is_err());
        assert!(fit_stripes(&[1.0, 2.0], &[10, 10], &[10, 10]).is_err());
        assert!(fit_stripes(&[1.0, -2.0], &[10, 10], &[1, 5]).is_err());
        assert!(fit_ida(&[Some(1.0), None, None], 2.0).is_err());
        // Perfect separation between 1 and 2: no maximum of the likelihood.
        assert!(fit_stripes(&[0.5, 1.0, 2.0, 3.0], &[5, 5, 5, 5], &[0, 0, 5, 5]).is_err());
        assert!(fit_stripes(&[0.5, 1.0, 2.0, 3.0], &[5, 5, 5, 5], &[0, 1, 5, 5]).is_ok());
        assert!(fit_ida(&[Some(1.0), Some(1.0)], 2.0).is_err());
    }
}
