//! Synthetic ground motions: filtered white noise under a time envelope, reproducible from a seed.
//!
//! A stationary Gaussian white noise `w(t)` (two-sided spectral density `S0`, held constant over each step
//! `dt`) drives the Kanai–Tajimi filter (Kanai 1957; Tajimi 1960), a soil layer of circular frequency `wg`
//! (rad/s) and damping ratio `zg`: `x'' + 2 zg wg x' + wg^2 x = -w`, whose absolute acceleration
//! `a_kt = -(2 zg wg x' + wg^2 x)` has the spectral density
//! `S(w) = S0 (wg^4 + 4 zg^2 wg^2 w^2) / ((wg^2 - w^2)^2 + 4 zg^2 wg^2 w^2)`.
//! The Clough–Penzien variant (Clough & Penzien 1975) passes `a_kt` through a second filter `wf`, `zf`,
//! `y'' + 2 zf wf y' + wf^2 y = a_kt`, and keeps `a = a_kt - 2 zf wf y' - wf^2 y`, which multiplies the density
//! by `w^4 / ((wf^2 - w^2)^2 + 4 zf^2 wf^2 w^2)` and removes the unbounded low-frequency displacement of
//! Kanai–Tajimi. Both filters are stepped exactly (the closed form of each step, as the spectra are).
//!
//! The stationary motion is then multiplied by the envelope of Amin & Ang (1968): `(t / t1)^2` for `t < t1`,
//! 1 until `t2`, `exp(-c (t - t2))` after; and scaled so that its peak is the requested PGA.
//!
//! The noise comes from xoshiro256** (Blackman & Vigna 2018) seeded by SplitMix64, with Box–Muller normals: the
//! same seed gives the same record, bit for bit, on every platform.

use super::Record;
use crate::error::check;
use crate::ground_motion::spectrum::Step;
use crate::Error;

crate::named! {
    /// The filters of a synthetic motion, by name.
    pub enum FilterKind: "filter" {
        /// Kanai–Tajimi ([`Filter::KanaiTajimi`]).
        KanaiTajimi = "kanai-tajimi",
        /// Clough–Penzien ([`Filter::CloughPenzien`]).
        CloughPenzien = "clough-penzien",
    }
}

/// The filters of a synthetic motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Filter {
    /// Kanai–Tajimi: ground frequency `wg` (rad/s) and damping ratio `zg`.
    KanaiTajimi {
        /// Circular frequency of the soil filter, rad/s.
        wg: f64,
        /// Damping ratio of the soil filter (dimensionless).
        zg: f64,
    },
    /// Clough–Penzien: Kanai–Tajimi and a high-pass filter `wf` (rad/s), `zf`.
    CloughPenzien {
        /// Circular frequency of the soil filter, rad/s.
        wg: f64,
        /// Damping ratio of the soil filter (dimensionless).
        zg: f64,
        /// Circular frequency of the high-pass filter, rad/s.
        wf: f64,
        /// Damping ratio of the high-pass filter (dimensionless).
        zf: f64,
    },
}

/// A synthetic motion's parameters. Defaults: firm soil (Kanai–Tajimi `wg = 15.6` rad/s, `zg = 0.6`, with
/// Clough–Penzien `wf = 1.56` rad/s, `zf = 0.6`), 20 s at 0.01 s, envelope 2 s / 10 s / 0.3 per s, PGA 3 m/s^2.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Synthetic {
    /// The filters.
    pub filter: Filter,
    /// Duration, s.
    pub duration: f64,
    /// Time step, s.
    pub dt: f64,
    /// End of the envelope's rise, s.
    pub t1: f64,
    /// End of its strong phase, s.
    pub t2: f64,
    /// Decay rate after `t2`, 1/s.
    pub decay: f64,
    /// Peak ground acceleration the record is scaled to, m/s^2; `None` keeps the white noise's `S0 = 1`
    /// m^2/s^3 (a stationary test signal).
    pub pga: Option<f64>,
    /// Whether the envelope applies (false: the stationary process, for tests of its spectrum).
    pub envelope: bool,
}

impl Default for Synthetic {
    fn default() -> Self {
        SyntheticParams::default().synthetic()
    }
}

impl Filter {
    /// Its kind.
    pub fn kind(&self) -> FilterKind {
        match self {
            Filter::KanaiTajimi { .. } => FilterKind::KanaiTajimi,
            Filter::CloughPenzien { .. } => FilterKind::CloughPenzien,
        }
    }
}

/// The parameters of a synthetic record as a user gives them (`pounding record synth`, Python's
/// `synthetic`), each with its default: firm soil, 20 s at 0.01 s, envelope 2 s / 10 s / 0.3 per s, PGA
/// 3 m/s^2. The defaults of [`Synthetic::default`] are these.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(default, deny_unknown_fields))]
pub struct SyntheticParams {
    /// The filter (default `clough-penzien`).
    pub filter: FilterKind,
    /// Circular frequency of the soil filter, rad/s (default 15.6).
    pub wg: f64,
    /// Damping ratio of the soil filter (default 0.6).
    pub zg: f64,
    /// Circular frequency of the Clough–Penzien high-pass filter, rad/s (default 1.56).
    pub wf: f64,
    /// Its damping ratio (default 0.6).
    pub zf: f64,
    /// Duration, s (default 20).
    pub duration: f64,
    /// Time step, s (default 0.01).
    pub dt: f64,
    /// End of the envelope's rise, s (default 2).
    pub t1: f64,
    /// End of its strong phase, s (default 10).
    pub t2: f64,
    /// Decay rate after `t2`, 1/s (default 0.3).
    pub decay: f64,
    /// Peak ground acceleration the record is scaled to, m/s^2 (default 3).
    pub pga: f64,
}

impl Default for SyntheticParams {
    fn default() -> Self {
        Self {
            filter: FilterKind::CloughPenzien,
            wg: 15.6,
            zg: 0.6,
            wf: 1.56,
            zf: 0.6,
            duration: 20.0,
            dt: 0.01,
            t1: 2.0,
            t2: 10.0,
            decay: 0.3,
            pga: 3.0,
        }
    }
}

impl SyntheticParams {
    /// The motion they describe (under its envelope, scaled to the PGA).
    pub fn synthetic(&self) -> Synthetic {
        let (wg, zg) = (self.wg, self.zg);
        Synthetic {
            filter: match self.filter {
                FilterKind::KanaiTajimi => Filter::KanaiTajimi { wg, zg },
                FilterKind::CloughPenzien => Filter::CloughPenzien {
                    wg,
                    zg,
                    wf: self.wf,
                    zf: self.zf,
                },
            },
            duration: self.duration,
            dt: self.dt,
            t1: self.t1,
            t2: self.t2,
            decay: self.decay,
            pga: Some(self.pga),
            envelope: true,
        }
    }
}

/// xoshiro256** seeded through SplitMix64.
pub(super) struct Rng([u64; 4]);

impl Rng {
    pub(super) fn new(seed: u64) -> Self {
        let mut z = seed;
        let mut next = || {
            z = z.wrapping_add(0x9e3779b97f4a7c15);
            let mut x = z;
            x = (x ^ (x >> 30)).wrapping_mul(0xbf58476d1ce4e5b9);
            x = (x ^ (x >> 27)).wrapping_mul(0x94d049bb133111eb);
            x ^ (x >> 31)
        };
        Rng([next(), next(), next(), next()])
    }

    fn next_u64(&mut self) -> u64 {
        let s = &mut self.0;
        let result = s[1].wrapping_mul(5).rotate_left(7).wrapping_mul(9);
        let t = s[1] << 17;
        s[2] ^= s[0];
        s[3] ^= s[1];
        s[1] ^= s[2];
        s[0] ^= s[3];
        s[2] ^= t;
        s[3] = s[3].rotate_left(45);
        result
    }

    /// Uniform in (0, 1]: 53 random bits.
    pub(super) fn uniform(&mut self) -> f64 {
        ((self.next_u64() >> 11) + 1) as f64 / (1u64 << 53) as f64
    }

    /// Two independent standard normals (Box–Muller).
    fn normals(&mut self) -> (f64, f64) {
        let (u1, u2) = (self.uniform(), self.uniform());
        let r = (-2.0 * u1.ln()).sqrt();
        let (s, c) = (2.0 * std::f64::consts::PI * u2).sin_cos();
        (r * c, r * s)
    }
}

/// Largest number of samples of a synthetic record.
pub const MAX_SAMPLES: f64 = 1e7;

impl Filter {
    /// The two-sided spectral density of the filtered acceleration at circular frequency `w` (rad/s) for a
    /// white noise of density `S0 = 1` m^2/s^3 (the module's formulas), m^2/s^3.
    pub fn density(&self, w: f64) -> f64 {
        let (wg, zg) = match *self {
            Filter::KanaiTajimi { wg, zg } | Filter::CloughPenzien { wg, zg, .. } => (wg, zg),
        };
        let w2 = w * w;
        let kt = (wg.powi(4) + 4.0 * zg * zg * wg * wg * w2)
            / ((wg * wg - w2).powi(2) + 4.0 * zg * zg * wg * wg * w2);
        match *self {
            Filter::KanaiTajimi { .. } => kt,
            Filter::CloughPenzien { wf, zf, .. } => {
                kt * w2 * w2 / ((wf * wf - w2).powi(2) + 4.0 * zf * zf * wf * wf * w2)
            }
        }
    }
}

impl Synthetic {
    pub(super) fn check(&self) -> Result<(), Error> {
        let (wg, zg, high) = match self.filter {
            Filter::KanaiTajimi { wg, zg } => (wg, zg, None),
            Filter::CloughPenzien { wg, zg, wf, zf } => (wg, zg, Some((wf, zf))),
        };
        check("wg", wg, wg > 0.0 && wg <= 1e3, "0 < wg <= 1000 (rad/s)")?;
        check("zg", zg, zg > 0.0 && zg < 1.0, "0 < zg < 1")?;
        if let Some((wf, zf)) = high {
            check("wf", wf, wf > 0.0 && wf < wg, "0 < wf < wg (rad/s)")?;
            check("zf", zf, zf > 0.0 && zf < 1.0, "0 < zf < 1")?;
        }
        check(
            "dt",
            self.dt,
            (1e-4..=0.1).contains(&self.dt),
            "1e-4 <= dt <= 0.1 (s)",
        )?;
        check(
            "duration",
            self.duration,
            self.duration >= 10.0 * self.dt && self.duration / self.dt <= MAX_SAMPLES,
            "10 dt <= duration <= 1e7 dt (s)",
        )?;
        check("t1", self.t1, self.t1 > 0.0, "t1 > 0 (s)")?;
        check("t2", self.t2, self.t2 >= self.t1, "t2 >= t1 (s)")?;
        check("decay", self.decay, self.decay >= 0.0, "decay >= 0 (1/s)")?;
        if let Some(p) = self.pga {
            check("pga", p, p > 0.0 && p <= 1e3, "0 < pga <= 1000 (m/s^2)")?;
        }
        // With an envelope, the signal must rise at all within the duration.
        Ok(())
    }

    /// The envelope at `t`, s.
    pub(super) fn envelope(&self, t: f64) -> f64 {
        if t < self.t1 {
            (t / self.t1).powi(2)
        } else if t <= self.t2 {
            1.0
        } else {
            (-self.decay * (t - self.t2)).exp()
        }
    }

    /// The record of seed `seed`, named `name`: samples every `dt` from `t = dt` (the ground at rest at 0).
    pub fn record(&self, name: &str, seed: u64) -> Result<Record, Error> {
        self.check()?;
        let n = (self.duration / self.dt).round() as usize;
        let dt = self.dt;
        // White noise of two-sided density S0 = 1 m^2/s^3 held over dt: variance 2 pi S0 / dt.
        let sigma = (2.0 * std::f64::consts::PI / dt).sqrt();
        let mut rng = Rng::new(seed);
        let (wg, zg) = match self.filter {
            Filter::KanaiTajimi { wg, zg } | Filter::CloughPenzien { wg, zg, .. } => (wg, zg),
        };
        let (mut x, mut v) = (0.0, 0.0);
        let (mut y, mut yv) = (0.0, 0.0);
        let mut a_prev = 0.0;
        let mut acc = Vec::with_capacity(n);
        let mut spare = None;
        for k in 1..=n {
            let w = match spare.take() {
                Some(z) => z,
                None => {
                    let (z1, z2) = rng.normals();
                    spare = Some(z2);
                    z1
                }
            } * sigma;
            // x'' + 2 zg wg x' + wg^2 x = -w: the spectra's oscillator under a "ground acceleration" w.
            let st = Step::new(wg, zg, x, v, w, w, dt);
            (x, v) = st.at(dt);
            let a_kt = -(2.0 * zg * wg * v + wg * wg * x);
            let a = match self.filter {
                Filter::KanaiTajimi { .. } => a_kt,
                Filter::CloughPenzien { wf, zf, .. } => {
                    // y'' + 2 zf wf y' + wf^2 y = a_kt, linear in time over the step: the oscillator under
                    // a "ground acceleration" -a_kt.
                    let st = Step::new(wf, zf, y, yv, -a_prev, -a_kt, dt);
                    (y, yv) = st.at(dt);
                    a_prev = a_kt;
                    a_kt - 2.0 * zf * wf * yv - wf * wf * y
                }
            };
            let t = k as f64 * dt;
            acc.push(if self.envelope {
                a * self.envelope(t)
            } else {
                a
            });
        }
        if let Some(p) = self.pga {
            let peak = acc.iter().fold(0.0f64, |m, a| m.max(a.abs()));
            if peak > 0.0 {
                let f = p / peak;
                acc.iter_mut().for_each(|a| *a *= f);
            }
        }
        Record::new(name, dt, dt, acc)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn the_same_seed_gives_the_same_record_and_another_seed_another() {
        let s = Synthetic::default();
        let a = s.record("a", 7).unwrap();
        let b = s.record("a", 7).unwrap();
        let c = s.record("a", 8).unwrap();
        assert_eq!(
            a.accelerations()
                .iter()
                .map(|x| x.to_bits())
                .collect::<Vec<_>>(),
            b.accelerations()
                .iter()
                .map(|x| x.to_bits())
                .collect::<Vec<_>>()
        );
        assert_ne!(a.accelerations(), c.accelerations());
        let pga = a.accelerations().iter().fold(0.0f64, |m, x| m.max(x.abs()));
        assert!((pga - 3.0).abs() < 1e-12);
        assert_eq!(a.npts(), 2000);
    }

    #[test]
    fn xoshiro_matches_its_reference_output() {
        // The first outputs of xoshiro256** from the state [1, 2, 3, 4], worked by hand from the published
        // algorithm (Blackman & Vigna 2018): 9 rotl(5 s1, 7) with s1 = 2, then 0, then s1 = 262149.
        let mut r = Rng([1, 2, 3, 4]);
        let first: Vec<u64> = (0..3).map(|_| r.next_u64()).collect();
        assert_eq!(first, vec![11520, 0, 1509978240]);
    }

    /// The mean periodogram of many stationary realisations against the filter's density (times the
    /// sinc^2 of the noise held over dt): `S(w) = 2 pi / T |A(w)|^2` estimated over `m` seeds.
    fn mean_periodogram(filter: Filter, freqs: &[f64], seeds: u64) -> Vec<f64> {
        let s = Synthetic {
            filter,
            duration: 60.0,
            dt: 0.01,
            pga: None,
            envelope: false,
            ..Synthetic::default()
        };
        let mut sum = vec![0.0; freqs.len()];
        for seed in 0..seeds {
            // Seeds far from each other's: independent streams.
            let seed = seed * 0x9e37_79b9;
            let r = s.record("s", seed).unwrap();
            let a = r.accelerations();
            // Skip the first 10 s: the filters start from rest.
            let skip = 1000;
            let t_len = (a.len() - skip) as f64 * s.dt;
            for (f, w) in freqs.iter().enumerate() {
                let (mut re, mut im) = (0.0, 0.0);
                for (k, x) in a[skip..].iter().enumerate() {
                    let (sn, cs) = (w * k as f64 * s.dt).sin_cos();
                    re += x * cs * s.dt;
                    im -= x * sn * s.dt;
                }
                // Two-sided density: |A|^2 / (2 pi T).
                sum[f] += (re * re + im * im) / (2.0 * PI * t_len);
            }
        }
        sum.iter().map(|x| x / seeds as f64).collect()
    }

    #[test]
    fn the_mean_spectrum_of_many_seeds_follows_the_filter() {
        let (wg, zg, wf, zf) = (15.6f64, 0.6f64, 1.56f64, 0.6f64);
        let kt = |w: f64| {
            (wg.powi(4) + 4.0 * zg * zg * wg * wg * w * w)
                / ((wg * wg - w * w).powi(2) + 4.0 * zg * zg * wg * wg * w * w)
        };
        let cp = |w: f64| w.powi(4) / ((wf * wf - w * w).powi(2) + 4.0 * zf * zf * wf * wf * w * w);
        let held = |w: f64| {
            let x = w * 0.01 / 2.0;
            (x.sin() / x).powi(2)
        };
        // Each estimate averages 9 neighbouring Fourier frequencies (spacing 2 pi / 50 s) over 48 seeds: 432
        // nearly independent exponential ordinates, a relative standard error of 4.8 %.
        let centres = [3.0, 8.0, 15.6, 25.0, 40.0];
        let df = 2.0 * PI / 50.0;
        let freqs: Vec<f64> = centres
            .iter()
            .flat_map(|c| (-4..=4).map(move |j| c + j as f64 * df))
            .collect();
        let seeds = 48;
        for (filter, shape) in [
            (Filter::KanaiTajimi { wg, zg }, &kt as &dyn Fn(f64) -> f64),
            (Filter::CloughPenzien { wg, zg, wf, zf }, &|w: f64| {
                kt(w) * cp(w)
            }),
        ] {
            let est = mean_periodogram(filter, &freqs, seeds);
            for (c, (ws, es)) in centres.iter().zip(freqs.chunks(9).zip(est.chunks(9))) {
                let e = es.iter().sum::<f64>() / 9.0;
                let theory = ws.iter().map(|w| shape(*w) * held(*w)).sum::<f64>() / 9.0;
                // Four standard errors.
                assert!(
                    (e / theory - 1.0).abs() < 0.2,
                    "{filter:?} at {c} rad/s: {e} against {theory}"
                );
            }
        }
    }
}
