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

/// A seismic hazard curve: the mean annual rate (1/yr) at which the intensity measure exceeds each level
/// (in its units), read log-log between points (a power law on each segment).
#[derive(Clone, Debug, PartialEq)]
pub struct HazardCurve {
    points: Vec<(f64, f64)>,
}

impl HazardCurve {
    /// The curve of `points` `(IM, annual rate)`: at least two, IM increasing and > 0, rates > 0 and
    /// decreasing. The error names the first row that is not.
    pub fn new(points: Vec<(f64, f64)>) -> Result<Self, Error> {
        let bad = |k: usize, allowed: &str| {
            let (x, r) = points[k];
            Err(Error::Choice {
                name: "hazard",
                value: format!(
                    "row {} [{}, {}]",
                    k + 1,
                    crate::words::number(x),
                    crate::words::number(r)
                ),
                allowed: allowed.to_string(),
            })
        };
        if points.len() < 2 {
            return Err(Error::Choice {
                name: "hazard",
                value: crate::words::count(points.len(), "row", None),
                allowed: "at least 2 rows of intensity and annual exceedance rate (1/yr)".into(),
            });
        }
        for (k, &(x, r)) in points.iter().enumerate() {
            if !(x.is_finite() && x > 0.0 && r.is_finite() && r > 0.0) {
                return bad(
                    k,
                    "an intensity > 0 and an annual rate > 0 (1/yr) in each row",
                );
            }
            if k > 0 && x <= points[k - 1].0 {
                return bad(k, "intensities increasing, row after row");
            }
            if k > 0 && r >= points[k - 1].1 {
                return bad(
                    k,
                    "annual rates decreasing as the intensity grows (a hazard curve)",
                );
            }
        }
        Ok(Self { points })
    }

    /// The rows, `(IM, 1/yr)`.
    pub fn points(&self) -> &[(f64, f64)] {
        &self.points
    }

    /// The mean annual frequency (1/yr) of exceeding a limit state with fragility `f`:
    /// `lambda = int P(im) |d lambda_IM(im)|` over the tabulated intensities, each segment a power law
    /// integrated by 16-point Gauss–Legendre quadrature in `ln im`, plus the rate beyond the last row,
    /// `lambda_IM(im_max) P(im_max)`, counted as exceeding with the probability at the last row (the curve
    /// says nothing beyond it). Intensities below the first row count only through it.
    pub fn mean_annual_frequency(&self, f: &Fragility) -> f64 {
        self.integrate(&|x| f.probability(x))
    }

    /// `int p(im) |d lambda_IM(im)|` for any exceedance probability `p`, as [`Self::mean_annual_frequency`].
    pub fn integrate(&self, p: &dyn Fn(f64) -> f64) -> f64 {
        let mut total = 0.0;
        for w in self.points.windows(2) {
            let ((x0, r0), (x1, r1)) = (w[0], w[1]);
            // lambda(im) = r0 (im / x0)^-k on the segment; |d lambda| = k lambda d(ln im).
            let k = (r0 / r1).ln() / (x1 / x0).ln();
            let (a, b) = (x0.ln(), x1.ln());
            for (t, wt) in GAUSS_16 {
                for sign in [-1.0, 1.0] {
                    let u = 0.5 * (a + b) + sign * 0.5 * (b - a) * t;
                    let x = u.exp();
                    let lam = r0 * (x / x0).powf(-k);
                    total += 0.5 * (b - a) * wt * k * lam * p(x);
                }
            }
        }
        let (xl, rl) = self.points[self.points.len() - 1];
        total + rl * p(xl)
    }
}

/// Gauss–Legendre nodes (positive half) and weights, 16 points (Abramowitz & Stegun table 25.4).
const GAUSS_16: [(f64, f64); 8] = [
    (0.095_012_509_837_637_44, 0.189_450_610_455_068_5),
    (0.281_603_550_779_258_9, 0.182_603_415_044_923_6),
    (0.458_016_777_657_227_4, 0.169_156_519_395_002_5),
    (0.617_876_244_402_643_8, 0.149_595_988_816_576_7),
    (0.755_404_408_355_003, 0.124_628_971_255_533_9),
    (0.865_631_202_387_831_7, 0.095_158_511_682_492_78),
    (0.944_575_023_073_232_6, 0.062_253_523_938_647_89),
    (0.989_400_934_991_649_9, 0.027_152_459_411_754_09),
];

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

/// The standard normal quantile `Phi^-1(p)`, 0 < p < 1: Acklam's rational approximation (relative error
/// 1.15e-9) polished by one Halley step on [`normal_cdf`], to about 1e-15.
pub fn normal_quantile(p: f64) -> f64 {
    const A: [f64; 6] = [
        -3.969683028665376e1,
        2.209460984245205e2,
        -2.759285104469687e2,
        1.383_577_518_672_69e2,
        -3.066479806614716e1,
        2.506628277459239,
    ];
    const B: [f64; 5] = [
        -5.447609879822406e1,
        1.615858368580409e2,
        -1.556989798598866e2,
        6.680131188771972e1,
        -1.328068155288572e1,
    ];
    const C: [f64; 6] = [
        -7.784894002430293e-3,
        -3.223964580411365e-1,
        -2.400758277161838,
        -2.549732539343734,
        4.374664141464968,
        2.938163982698783,
    ];
    const D: [f64; 4] = [
        7.784695709041462e-3,
        3.224671290700398e-1,
        2.445134137142996,
        3.754408661907416,
    ];
    let tail = |q: f64| {
        let t = (-2.0 * q.ln()).sqrt();
        (((((C[0] * t + C[1]) * t + C[2]) * t + C[3]) * t + C[4]) * t + C[5])
            / ((((D[0] * t + D[1]) * t + D[2]) * t + D[3]) * t + 1.0)
    };
    let x = if p < 0.02425 {
        tail(p)
    } else if p > 1.0 - 0.02425 {
        -tail(1.0 - p)
    } else {
        let q = p - 0.5;
        let r = q * q;
        (((((A[0] * r + A[1]) * r + A[2]) * r + A[3]) * r + A[4]) * r + A[5]) * q
            / (((((B[0] * r + B[1]) * r + B[2]) * r + B[3]) * r + B[4]) * r + 1.0)
    };
    // Halley's step on Phi(x) - p.
    let e = normal_cdf(x) - p;
    let u = e * (2.0 * std::f64::consts::PI).sqrt() * (0.5 * x * x).exp();
    x - u / (1.0 + 0.5 * x * u)
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

    /// A power-law hazard `k0 IM^-k` with a lognormal fragility has the closed form
    /// `k0 theta^-k exp(k^2 beta^2 / 2)` (Cornell et al. 2002); a finely tabulated curve gives it.
    #[test]
    fn a_power_law_hazard_gives_the_closed_form_frequency() {
        let (k0, k, theta, beta) = (4.0e-4, 2.5, 3.0, 0.45);
        let points: Vec<(f64, f64)> = (0..=400)
            .map(|j| {
                let x = theta * 10f64.powf(-3.0 + 6.0 * f64::from(j) / 400.0);
                (x, k0 * x.powf(-k))
            })
            .collect();
        let h = HazardCurve::new(points).unwrap();
        let got = h.mean_annual_frequency(&Fragility {
            median: theta,
            beta,
        });
        let want = k0 * theta.powf(-k) * (k * k * beta * beta / 2.0).exp();
        assert!((got / want - 1.0).abs() < 1e-4, "{got} vs {want}");
    }

    #[test]
    fn bad_hazard_curves_name_their_row() {
        for (rows, says) in [
            (vec![(1.0, 1e-2)], "at least 2 rows"),
            (vec![(1.0, 1e-2), (2.0, 2e-2)], "row 2 [2, 0.02]"),
            (vec![(1.0, 1e-2), (0.5, 1e-3)], "increasing"),
            (vec![(1.0, 1e-2), (2.0, 0.0)], "row 2"),
        ] {
            let msg = HazardCurve::new(rows).unwrap_err().to_string();
            assert!(msg.starts_with("hazard = ") && msg.contains(says), "{msg}");
        }
    }

    /// Quantiles of the standard normal (Abramowitz & Stegun table 26.5 / scipy.stats.norm.ppf values), and
    /// the round trip through `normal_cdf`.
    #[test]
    fn normal_quantiles_are_tabulated_values() {
        for (p, z) in [
            (0.5, 0.0),
            (0.975, 1.959963984540054),
            (0.9, 1.2815515655446004),
            (0.01, -2.3263478740408408),
            (1e-6, -4.753424308822899),
        ] {
            assert!(
                (normal_quantile(p) - z).abs() < 1e-12,
                "{p}: {}",
                normal_quantile(p)
            );
        }
        for k in 1..1000 {
            let p = f64::from(k) / 1000.0;
            assert!((normal_cdf(normal_quantile(p)) - p).abs() < 4e-15, "{p}");
        }
    }

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
