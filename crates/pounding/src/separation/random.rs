//! The probability of pounding under a stationary random ground acceleration (next-physics.md section 2):
//! a white noise of two-sided spectral density `S0` (m^2/s^3, `E[a(t) a(t + tau)] = 2 pi S0 delta(tau)`),
//! optionally through a Kanai–Tajimi or Clough–Penzien filter. The closing `X = u_L - u_R` of each contact
//! level of two neighbours is a stationary Gaussian process whose variance, and that of its rate, come from
//! the stationary covariance of the linear structures ([`super::linear`]); `Cov(X, X') = 0`.
//!
//! Rice's formula gives the mean rate of up-crossings of the gap `g` by the closing,
//! `nu(g) = nu0 exp(-g^2 / (2 sigma^2))`, `nu0 = sigma' / (2 pi sigma)`, and the crossings taken as a Poisson
//! stream the probability of pounding within a duration `T`, `P = 1 - exp(-nu(g) T)`. Crossings of a
//! narrow-band closing come in clumps (one per envelope excursion), which the Poisson assumption counts
//! apart: Vanmarcke's (1975) correction, offered as [`Clumping::Vanmarcke`], replaces the rate by
//! `nu(g) (1 - exp(-sqrt(pi / 2) delta^1.2 r)) / (1 - exp(-r^2 / 2))`, `r = g / sigma`, with the bandwidth
//! `delta = sqrt(1 - l1^2 / (l0 l2))` of the closing's one-sided spectral moments `l0, l1, l2`, and lowers `P`.

use super::linear::{state_space, stationary_covariance, StateSpace};
use crate::analysis::{Scenario, SiteKind};
use crate::error::check;
use crate::ground_motion::synthetic::Filter;
use crate::Error;
use std::f64::consts::PI;

crate::named! {
    /// How the up-crossings of the gap are counted.
    pub enum Clumping: "clumping" {
        /// Independent crossings, a Poisson stream (the default).
        Poisson = "poisson",
        /// Vanmarcke's (1975) correction for crossings that come in clumps (narrow-band closings).
        Vanmarcke = "vanmarcke",
    }
}

/// The stationary random ground acceleration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WhiteNoise {
    /// Two-sided spectral density of the white noise, m^2/s^3 (> 0).
    pub s0: f64,
    /// The filter that shapes it into the ground acceleration, if any.
    pub filter: Option<Filter>,
}

/// The closing of one contact level as a stationary process, and what follows from it.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Crossing {
    /// Standard deviation of the closing `u_L - u_R`, m.
    pub sigma: f64,
    /// Standard deviation of its rate, m/s.
    pub sigma_rate: f64,
    /// Mean rate of up-crossings of zero, `sigma_rate / (2 pi sigma)`, 1/s.
    pub nu0: f64,
    /// Vanmarcke's bandwidth `delta` of the closing (dimensionless, 0 for a narrow band, near 1 for a broad
    /// one); computed with [`Clumping::Vanmarcke`] only.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub delta: Option<f64>,
}

impl Crossing {
    /// The closing of standard deviation `sigma` (m) and rate `sigma_rate` (m/s).
    pub fn new(sigma: f64, sigma_rate: f64) -> Self {
        Self {
            sigma,
            sigma_rate,
            nu0: sigma_rate / (2.0 * PI * sigma),
            delta: None,
        }
    }

    /// Mean rate of up-crossings of the gap `g` (m) by the closing, 1/s, counted as `clumping` says.
    pub fn rate(&self, g: f64, clumping: Clumping) -> f64 {
        let r = g / self.sigma;
        let rice = self.nu0 * (-0.5 * r * r).exp();
        match (clumping, self.delta) {
            (Clumping::Vanmarcke, Some(delta)) if r > 0.0 => {
                let clumps = -(-(PI / 2.0).sqrt() * delta.powf(1.2) * r).exp_m1();
                rice * clumps / -(-0.5 * r * r).exp_m1()
            }
            _ => rice,
        }
    }

    /// Probability of at least one up-crossing of `g` (m) within `duration` (s): `1 - exp(-nu(g) T)`.
    pub fn probability(&self, g: f64, duration: f64, clumping: Clumping) -> f64 {
        -(-self.rate(g, clumping) * duration).exp_m1()
    }

    /// The gap (m) whose probability of pounding within `duration` (s) is `p` (0 < p < 1): for Poisson
    /// crossings `sigma sqrt(2 ln(nu0 T / -ln(1 - p)))`, 0 where even a zero gap is crossed less likely
    /// than `p`; with clumps, the root of [`Crossing::probability`] (it falls with the gap).
    pub fn gap_for(&self, p: f64, duration: f64, clumping: Clumping) -> f64 {
        let lam = -(-p).ln_1p() / duration;
        let ratio = self.nu0 / lam;
        if ratio <= 1.0 {
            return 0.0;
        }
        let poisson = self.sigma * (2.0 * ratio.ln()).sqrt();
        if clumping == Clumping::Poisson || self.delta.is_none() {
            return poisson;
        }
        // The clumped rate is below Rice's: the gap lies below the Poisson one.
        let f = |g: f64| self.rate(g, clumping) - lam;
        let (fa, fb) = (f(0.0), f(poisson));
        if fa <= 0.0 {
            return 0.0;
        }
        crate::integrate::brent_root(f, 0.0, poisson, fa, fb, 1e-12 * poisson).unwrap_or(poisson)
    }
}

/// One contact level of a pair of neighbours under the random ground acceleration.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LevelCrossing {
    /// Floors (of the left building, of the right), from 1.
    pub floors: (usize, usize),
    /// The contact's gap at rest, m.
    pub gap: f64,
    /// The closing's statistics.
    pub crossing: Crossing,
    /// Probability of pounding within the duration at the contact's gap.
    pub probability: f64,
    /// The gap for the target probability, m (with a target).
    pub gap_for_target: Option<f64>,
}

/// The contact levels of a pair of neighbours under the random ground acceleration.
#[derive(Clone, Debug, PartialEq)]
pub struct PairCrossing {
    /// Index of the left building.
    pub left: usize,
    /// Index of the right building.
    pub right: usize,
    /// Its levels.
    pub levels: Vec<LevelCrossing>,
}

/// The probability of pounding of every contact level of every pair of neighbours of `s` within
/// `duration` (s) under `noise`, and, with `target` (0 < P < 1), the gap for it. The structures are linear
/// (inelastic storeys at their initial stiffness, [`super::linear`]); contacts and devices take no part.
pub fn pounding_probability(
    s: &Scenario,
    noise: &WhiteNoise,
    duration: f64,
    target: Option<f64>,
    clumping: Clumping,
) -> Result<Vec<PairCrossing>, Error> {
    check("duration", duration, duration > 0.0, "duration > 0 (s)")?;
    if let Some(p) = target {
        check(
            "target_probability",
            p,
            p > 0.0 && p < 1.0,
            "0 < target_probability < 1",
        )?;
    }
    let sys = state_space(s, noise.filter);
    let cov = stationary_covariance(&sys, noise.s0)?;
    let mut pairs = Vec::new();
    for site in s.sites() {
        let SiteKind::Between { left, right } = site.kind else {
            continue;
        };
        let levels = site
            .levels
            .iter()
            .map(|level| {
                let (i, j) = (level.left.unwrap_or(1), level.right.unwrap_or(1));
                let (a, b) = (sys.offsets[left] + i - 1, sys.offsets[right] + j - 1);
                let var = |p: usize, q: usize| {
                    let n = sys.n;
                    cov[p * n + p] + cov[q * n + q] - 2.0 * cov[p * n + q]
                };
                let d = sys.dofs;
                let mut crossing = Crossing::new(var(a, b).sqrt(), var(d + a, d + b).sqrt());
                if clumping == Clumping::Vanmarcke {
                    crossing.delta = Some(bandwidth(&sys, (a, b)));
                }
                LevelCrossing {
                    floors: (i, j),
                    gap: site.gap,
                    crossing,
                    probability: crossing.probability(site.gap, duration, clumping),
                    gap_for_target: target.map(|p| crossing.gap_for(p, duration, clumping)),
                }
            })
            .collect();
        pairs.push(PairCrossing {
            left,
            right,
            levels,
        });
    }
    Ok(pairs)
}

/// Vanmarcke's bandwidth `delta = sqrt(1 - l1^2 / (l0 l2))` of the closing `u_a - u_b`, from its one-sided
/// spectral moments `l_k = int_0^inf w^k G(w) dw`, `G(w) = 2 |H(w)|^2 2 pi s0`, by adaptive Simpson
/// quadrature of the transfer function `H(w) = c (i w I - A)^-1 b` (the common factor cancels).
fn bandwidth(sys: &StateSpace, (a, b): (usize, usize)) -> f64 {
    bandwidth_of(sys, |z| (z[a].0 - z[b].0, z[a].1 - z[b].1))
}

/// The bandwidth of the output `out(H)` (a complex number from the states' transfer functions).
fn bandwidth_of(sys: &StateSpace, out: impl Fn(&[(f64, f64)]) -> (f64, f64)) -> f64 {
    // The three moments at once, in log frequency (dw = w dx), over eighteen decades about the system's
    // frequencies: a displacement's spectrum falls as w^-4, so the tails beyond are below 1e-9 of each.
    let f = |x: f64| -> [f64; 3] {
        let w = x.exp();
        let (re, im) = out(&resolvent(sys, w));
        let g = w * (re * re + im * im);
        [g, g * w, g * w * w]
    };
    let (lo, hi) = ((sys.frequency * 1e-9).ln(), (sys.frequency * 1e9).ln());
    let l = adaptive_simpson(&f, lo, hi, 1e-11, 40);
    (1.0 - l[1] * l[1] / (l[0] * l[2])).max(0.0).sqrt()
}

/// `(i w I - A)^-1 b` as `(re, im)` pairs, by Gaussian elimination of the real form
/// `[[-A, -w I], [w I, -A]] [re; im] = [b; 0]`.
fn resolvent(sys: &StateSpace, w: f64) -> Vec<(f64, f64)> {
    let n = sys.n;
    let m = 2 * n;
    let mut big = vec![0.0; m * m];
    for i in 0..n {
        for j in 0..n {
            big[i * m + j] = -sys.a[i * n + j];
            big[(n + i) * m + n + j] = -sys.a[i * n + j];
        }
        big[i * m + n + i] = -w;
        big[(n + i) * m + i] = w;
    }
    let mut rhs = vec![0.0; m];
    rhs[..n].copy_from_slice(&sys.b);
    let mut piv = vec![0; m];
    if !crate::integrate::lu::factor(&mut big, &mut piv, m) {
        return vec![(0.0, 0.0); n];
    }
    crate::integrate::lu::solve(&big, &piv, &mut rhs);
    (0..n).map(|i| (rhs[i], rhs[n + i])).collect()
}

type Moments = [f64; 3];

fn simpson(h: f64, a: &Moments, m: &Moments, b: &Moments) -> Moments {
    std::array::from_fn(|k| h / 6.0 * (a[k] + 4.0 * m[k] + b[k]))
}

/// Adaptive Simpson quadrature of the three integrands of `f` on `[a, b]`, each to a relative tolerance
/// `tol` of its integral, at most `depth` halvings of each of a fine first grid (so that narrow resonance
/// peaks are not stepped over).
fn adaptive_simpson(f: &dyn Fn(f64) -> Moments, a: f64, b: f64, tol: f64, depth: u32) -> Moments {
    let pieces = 1000;
    let h = (b - a) / pieces as f64;
    let mut parts = Vec::with_capacity(pieces);
    let mut whole = [0.0; 3];
    for k in 0..pieces {
        let (x0, x1) = (a + h * k as f64, a + h * (k + 1) as f64);
        let (f0, fm, f1) = (f(x0), f(0.5 * (x0 + x1)), f(x1));
        let s = simpson(h, &f0, &fm, &f1);
        for (w, v) in whole.iter_mut().zip(&s) {
            *w += v.abs();
        }
        parts.push((x0, x1, f0, fm, f1, s));
    }
    let tols: Moments = std::array::from_fn(|k| tol * whole[k] / pieces as f64);
    let mut total = [0.0; 3];
    for (x0, x1, f0, fm, f1, s) in parts {
        let r = refine(f, (x0, x1), (&f0, &fm, &f1), s, tols, depth);
        for (t, v) in total.iter_mut().zip(&r) {
            *t += v;
        }
    }
    total
}

fn refine(
    f: &dyn Fn(f64) -> Moments,
    (a, b): (f64, f64),
    (fa, fm, fb): (&Moments, &Moments, &Moments),
    whole: Moments,
    tol: Moments,
    depth: u32,
) -> Moments {
    let m = 0.5 * (a + b);
    let (flm, frm) = (f(0.5 * (a + m)), f(0.5 * (m + b)));
    let left = simpson(m - a, fa, &flm, fm);
    let right = simpson(b - m, fm, &frm, fb);
    let err: Moments = std::array::from_fn(|k| left[k] + right[k] - whole[k]);
    if depth == 0 || (0..3).all(|k| err[k].abs() <= 15.0 * tol[k]) {
        std::array::from_fn(|k| left[k] + right[k] + err[k] / 15.0)
    } else {
        let half = tol.map(|t| t / 2.0);
        let l = refine(f, (a, m), (fa, &flm, fm), left, half, depth - 1);
        let r = refine(f, (m, b), (fm, &frm, fb), right, half, depth - 1);
        std::array::from_fn(|k| l[k] + r[k])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An oscillator under white noise: `l1 / sqrt(l0 l2) = (1 - (2/pi) atan(z / sqrt(1 - z^2))) /
    /// sqrt(1 - z^2)` (Lutes & Sarkani 2004, eq 7.59 form), so `delta` is known in closed form.
    #[test]
    fn an_oscillators_bandwidth_is_the_closed_form() {
        for (w, z) in [(6.0, 0.05), (30.0, 0.02), (2.0, 0.2)] {
            let sys = StateSpace {
                n: 2,
                a: vec![0.0, 1.0, -w * w, -2.0 * z * w],
                b: vec![0.0, -1.0],
                dofs: 1,
                offsets: vec![0],
                frequency: w,
            };
            let q = 1.0 - z * z;
            let ratio = (1.0 - 2.0 / PI * (z / q.sqrt()).atan()) / q.sqrt();
            let exact = (1.0 - ratio * ratio).sqrt();
            let got = bandwidth_of(&sys, |x| x[0]);
            assert!((got - exact).abs() < 1e-7, "w {w} z {z}: {got} vs {exact}");
        }
    }
}
