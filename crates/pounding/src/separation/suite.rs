//! The probability of pounding against the gap over a suite of records (next-physics.md section 2): each
//! record's required gap `g_i` (its largest closing without contact), the empirical probability that a
//! record pounds at gap `g` (the fraction of `g_i > g`), and a lognormal fitted by maximum likelihood,
//! median `theta = exp(mean ln g_i)` and dispersion `beta` the standard deviation of `ln g_i` (over `n`).
//! Records whose floors never approach (`g_i = 0`) pound at no gap: the fit is to the others, scaled by
//! their fraction, `P(g) = (n+ / n) (1 - Phi(ln(g / theta) / beta))`.

use crate::error::check;
use crate::fragility::{normal_cdf, normal_quantile};
use crate::Error;

/// A lognormal fitted to the required gaps of a suite.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct GapFit {
    /// Median of the positive gaps, `exp(mean ln g_i)`, m.
    pub median: f64,
    /// Dispersion, the standard deviation of `ln g_i` (with `n`), dimensionless.
    pub dispersion: f64,
    /// Records whose floors approached (`g_i > 0`).
    pub approaching: usize,
    /// Records in all.
    pub records: usize,
}

impl GapFit {
    /// The maximum-likelihood lognormal of the positive `gaps` (m; at least two, not all equal).
    pub fn of(gaps: &[f64]) -> Result<Self, Error> {
        let logs: Vec<f64> = gaps.iter().filter(|g| **g > 0.0).map(|g| g.ln()).collect();
        let n = logs.len();
        if n < 2 {
            return Err(Error::Choice {
                name: "records",
                value: format!("{n} of {} approaching", gaps.len()),
                allowed: "at least two records whose floors approach, for a lognormal fit".into(),
            });
        }
        let mean = logs.iter().sum::<f64>() / n as f64;
        let var = logs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n as f64;
        Ok(Self {
            median: mean.exp(),
            dispersion: var.sqrt(),
            approaching: n,
            records: gaps.len(),
        })
    }

    /// The probability that a record of the suite pounds at gap `g` (m).
    pub fn probability(&self, g: f64) -> f64 {
        let share = self.approaching as f64 / self.records as f64;
        if g <= 0.0 {
            return share;
        }
        if self.dispersion == 0.0 {
            return if g < self.median { share } else { 0.0 };
        }
        share * (1.0 - normal_cdf((g / self.median).ln() / self.dispersion))
    }

    /// The gap (m) at which the probability is `p` (0 < p < 1): `theta exp(beta Phi^-1(1 - p n / n+))`, 0
    /// when fewer records approach than `p` asks.
    pub fn gap_for(&self, p: f64) -> Result<f64, Error> {
        check(
            "target_probability",
            p,
            p > 0.0 && p < 1.0,
            "0 < target_probability < 1",
        )?;
        let share = self.approaching as f64 / self.records as f64;
        if p >= share {
            return Ok(0.0);
        }
        Ok(self.median * (self.dispersion * normal_quantile(1.0 - p / share)).exp())
    }
}

/// The fraction of `gaps` (m) above `g`.
pub fn empirical_probability(gaps: &[f64], g: f64) -> f64 {
    gaps.iter().filter(|x| **x > g).count() as f64 / gaps.len().max(1) as f64
}

/// The smallest of the `gaps` (or 0) at which at most a fraction `p` of them lie above: the empirical gap
/// for the target, `g_(k)` with `k = ceil(n (1 - p))` of the sorted gaps.
pub fn empirical_gap_for(gaps: &[f64], p: f64) -> Result<f64, Error> {
    check(
        "target_probability",
        p,
        p > 0.0 && p < 1.0,
        "0 < target_probability < 1",
    )?;
    let mut g = gaps.to_vec();
    g.sort_by(f64::total_cmp);
    let k = (g.len() as f64 * (1.0 - p)).ceil() as usize;
    Ok(if k == 0 { 0.0 } else { g[k - 1].max(0.0) })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fit_is_the_closed_form_maximum_likelihood() {
        let gaps = [0.05, 0.08, 0.11, 0.07, 0.2, 0.09];
        let f = GapFit::of(&gaps).unwrap();
        let logs: Vec<f64> = gaps.iter().map(|g: &f64| g.ln()).collect();
        let m = logs.iter().sum::<f64>() / 6.0;
        let s = (logs.iter().map(|x| (x - m).powi(2)).sum::<f64>() / 6.0).sqrt();
        assert!((f.median - m.exp()).abs() < 1e-15 && (f.dispersion - s).abs() < 1e-15);
        // The gap for P gives back P.
        for p in [0.5, 0.1, 0.01] {
            let g = f.gap_for(p).unwrap();
            assert!((f.probability(g) - p).abs() < 1e-12, "{p}");
        }
        assert!((f.gap_for(0.5).unwrap() - f.median).abs() < 1e-15);
        // Empirical: 2 of 6 above 0.09; the gap for 1/3 is the 4th smallest.
        assert!((empirical_probability(&gaps, 0.09) - 1.0 / 3.0).abs() < 1e-15);
        assert_eq!(empirical_gap_for(&gaps, 1.0 / 3.0).unwrap(), 0.09);
    }
}
