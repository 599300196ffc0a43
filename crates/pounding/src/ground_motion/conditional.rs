//! Records at supports conditioned on one recorded motion: the record stays at the first support, and the
//! others get motions whose lagged coherency with it and with each other is the model's, with the record's
//! own Fourier amplitudes (the spectral representation conditioned on one support: Hao, Oliveira & Penzien
//! 1989; Zerva 2009, *Spatial variation of seismic ground motions*, section 3.4; `docs/structures.md`,
//! "Ground motion that differs between supports").
//!
//! The record's `n` samples are one period of their discrete Fourier transform, `X_l` at `w_l = l dw`,
//! `dw = 2 pi / (n dt)`. With `Gamma(w) = L L^T` (Cholesky, the record's support first), support `j`'s
//! transform is
//!
//! `Y_jl = L_j1(w_l) X_l + |X_l| sum_(2 <= m <= j) L_jm(w_l) e^(i phi_ml)`
//!
//! with independent phases `phi_ml` uniform on [0, 2 pi), below the Nyquist frequency (the mean and the
//! Nyquist term take the coherent part only). Over the phases, `E[Y_jl X_l*] = gamma_1j(w_l) |X_l|^2` and
//! `E[Y_jl Y_kl*] = gamma_jk(w_l) |X_l|^2`: the coherencies are the model's and every support has the record's
//! power, exactly in expectation. The coherent part is a filter of the record and keeps its time shape; the
//! random part is stationary, so it is put under the record's envelope: the moving root mean square of the
//! record over `window` seconds, normalised to a mean square of 1 over the record (which keeps each
//! support's expected energy the record's), less the envelope times the line that leaves its sum and first
//! moment at 0: the envelope moves some of the random part's power to the lowest frequencies, which would
//! make the support's velocity and displacement drift. The wave's passage is not in `gamma` (lagged coherency): a support's delay adds it.

use super::coherency::{check_positions, cholesky, Coherency, MAX_SAMPLES};
use super::synthetic::Rng;
use super::Record;
use crate::error::check;
use crate::Error;
use std::f64::consts::PI;

/// Records at supports along a line conditioned on a record at the first.
#[derive(Clone, Debug, PartialEq)]
pub struct Conditioned {
    /// The recorded motion, at `positions[0]`.
    pub record: Record,
    /// The coherency model.
    pub coherency: Coherency,
    /// The supports' positions along the line, m (the record's first).
    pub positions: Vec<f64>,
    /// Length of the moving window of the record's envelope, s (0: the simulated parts stay stationary).
    pub window: f64,
    /// Frequency below which the simulated parts hold nothing, Hz (a half-cosine taper from half of it): the
    /// supports' displacements then differ by what their coherent parts make, not by the drift of random
    /// components at periods longer than any structure's (0: none).
    pub low_cut: f64,
}

impl Conditioned {
    /// One record per position (named `name-1`, `name-2`, ...; the first is the record's samples), from
    /// `seed`: the same seed gives the same records, bit for bit.
    pub fn records(&self, name: &str, seed: u64) -> Result<Vec<Record>, Error> {
        self.coherency.check()?;
        check_positions(&self.positions)?;
        check(
            "window",
            self.window,
            (0.0..=1e3).contains(&self.window),
            "0 <= window <= 1000 (s; 0 for no envelope)",
        )?;
        check(
            "low_cut",
            self.low_cut,
            (0.0..=10.0).contains(&self.low_cut),
            "0 <= low_cut <= 10 (Hz; 0 for none)",
        )?;
        let (a1, dt, t0) = (
            self.record.accelerations(),
            self.record.dt(),
            self.record.t0() - self.record.delay(),
        );
        let n = a1.len();
        if n > MAX_SAMPLES {
            return Err(Error::Choice {
                name: "record",
                value: format!("{n} samples"),
                allowed: format!("at most {MAX_SAMPLES} samples (a shorter record)"),
            });
        }
        let envelope = envelope(a1, (self.window / dt).round() as usize);
        let np = self.positions.len();
        let dw = 2.0 * PI / (n as f64 * dt);
        let mut rng = Rng::new(seed);
        let mut chol = vec![0.0; np * np];
        let (mut coherent, mut random) = (vec![vec![0.0; n]; np], vec![vec![0.0; n]; np]);
        let (mut yc, mut yr) = (vec![(0.0, 0.0); np], vec![(0.0, 0.0); np]);
        for l in 0..=n / 2 {
            let w = l as f64 * dw;
            cholesky(&self.coherency, &self.positions, w, &mut chol);
            let x = dft(a1, w * dt);
            let magnitude = x.0.hypot(x.1) * taper(w / (2.0 * PI), self.low_cut);
            // The mean and the Nyquist term are real: their coherent part only.
            let below_nyquist = l > 0 && 2 * l < n;
            for j in 1..np {
                let c = chol[j * np];
                yc[j] = (c * x.0, c * x.1);
                yr[j] = (0.0, 0.0);
            }
            if below_nyquist {
                for m in 1..np {
                    let (sn, cs) = (2.0 * PI * rng.uniform()).sin_cos();
                    for (j, y) in yr.iter_mut().enumerate().skip(m) {
                        let h = magnitude * chol[j * np + m];
                        y.0 += h * cs;
                        y.1 += h * sn;
                    }
                }
            }
            // Inverse transform: each frequency below Nyquist counts twice (its conjugate).
            let weight = if below_nyquist { 2.0 } else { 1.0 } / n as f64;
            for j in 1..np {
                add_cosine(&mut coherent[j], yc[j], w * dt, weight);
                add_cosine(&mut random[j], yr[j], w * dt, weight);
            }
        }
        let mut out = Vec::with_capacity(np);
        out.push(Record::new(format!("{name}-1"), dt, t0, a1.to_vec())?);
        for j in 1..np {
            let mut shaped: Vec<f64> = (0..n).map(|k| envelope[k] * random[j][k]).collect();
            if self.window > 0.0 {
                level_off(&mut shaped, &envelope);
            }
            let a: Vec<f64> = (0..n).map(|k| coherent[j][k] + shaped[k]).collect();
            out.push(Record::new(format!("{name}-{}", j + 1), dt, t0, a)?);
        }
        Ok(out)
    }
}

/// `sum_k a_k e^(-i theta k)`: the discrete Fourier transform of `a` at `theta = w dt` (rad per sample), by
/// rotation.
fn dft(a: &[f64], theta: f64) -> (f64, f64) {
    let (rs, rc) = theta.sin_cos();
    let (mut c, mut s) = (1.0, 0.0);
    let (mut re, mut im) = (0.0, 0.0);
    for x in a {
        re += x * c;
        im -= x * s;
        (c, s) = (c * rc - s * rs, s * rc + c * rs);
    }
    (re, im)
}

/// Takes from `m` (a random part under the envelope `e`) the envelope times the line `c0 + c1 k` that leaves
/// its sum and its first moment `sum k m_k` at 0: the part then adds nothing to the support's velocity and
/// displacement at the record's end (an envelope moves some of a stationary part's power to the lowest
/// frequencies: a drift), and stays at rest where the envelope is.
fn level_off(m: &mut [f64], e: &[f64]) {
    let (mut s0, mut s1, mut s2, mut r0, mut r1) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for (k, (x, w)) in m.iter().zip(e).enumerate() {
        let k = k as f64;
        (s0, s1, s2) = (s0 + w, s1 + w * k, s2 + w * k * k);
        (r0, r1) = (r0 + x, r1 + x * k);
    }
    let det = s0 * s2 - s1 * s1;
    if det.abs() <= f64::EPSILON * s0 * s2 {
        return;
    }
    let (c0, c1) = ((r0 * s2 - r1 * s1) / det, (s0 * r1 - s1 * r0) / det);
    for (k, (x, w)) in m.iter_mut().zip(e).enumerate() {
        *x -= w * (c0 + c1 * k as f64);
    }
}

/// The weight of the simulated parts at frequency `f` (Hz) under a low cut at `cut` (Hz): 0 up to `cut / 2`,
/// 1 from `cut`, a half cosine between.
fn taper(f: f64, cut: f64) -> f64 {
    if f >= cut {
        1.0
    } else if f <= 0.5 * cut {
        0.0
    } else {
        0.5 - 0.5 * (PI * (f - 0.5 * cut) / (0.5 * cut)).cos()
    }
}

/// Adds `weight Re(y e^(i theta k))` to each sample `k` of `out`.
fn add_cosine(out: &mut [f64], y: (f64, f64), theta: f64, weight: f64) {
    if y == (0.0, 0.0) {
        return;
    }
    let (rs, rc) = theta.sin_cos();
    let (mut c, mut s) = (1.0, 0.0);
    for o in out.iter_mut() {
        *o += weight * (y.0 * c - y.1 * s);
        (c, s) = (c * rc - s * rs, s * rc + c * rs);
    }
}

/// The record's envelope: the root mean square of `a` over a centred window of `width` samples (cut at the
/// record's ends), scaled to a mean square of 1 over the record; all ones for a width below 2 or a record
/// at rest.
fn envelope(a: &[f64], width: usize) -> Vec<f64> {
    let n = a.len();
    if width < 2 {
        return vec![1.0; n];
    }
    // Prefix sums of a^2: each window's mean square in constant time.
    let mut prefix = vec![0.0; n + 1];
    for (k, x) in a.iter().enumerate() {
        prefix[k + 1] = prefix[k] + x * x;
    }
    let half = width / 2;
    let msq: Vec<f64> = (0..n)
        .map(|k| {
            let (lo, hi) = (k.saturating_sub(half), (k + half + 1).min(n));
            (prefix[hi] - prefix[lo]) / (hi - lo) as f64
        })
        .collect();
    let mean = msq.iter().sum::<f64>() / n as f64;
    if mean <= 0.0 {
        return vec![1.0; n];
    }
    msq.iter().map(|m| (m / mean).sqrt()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The transform and its inverse (coherent part of a support at the record's point) give the record back.
    #[test]
    fn the_transform_and_its_inverse_give_the_record_back() {
        let a: Vec<f64> = (0..101).map(|k| ((k * k) % 17) as f64 - 8.0).collect();
        let n = a.len();
        let mut back = vec![0.0; n];
        for l in 0..=n / 2 {
            let theta = 2.0 * PI * l as f64 / n as f64;
            let weight = if l > 0 && 2 * l < n { 2.0 } else { 1.0 } / n as f64;
            add_cosine(&mut back, dft(&a, theta), theta, weight);
        }
        for (x, y) in a.iter().zip(&back) {
            assert!((x - y).abs() < 1e-12, "{x} vs {y}");
        }
    }

    /// The envelope's mean square is 1; it is flat for a stationary signal and follows a burst.
    #[test]
    fn the_envelope_has_a_mean_square_of_one_and_follows_the_record() {
        let burst: Vec<f64> = (0..1000)
            .map(|k| {
                if (300..500).contains(&k) {
                    (k as f64).sin()
                } else {
                    0.0
                }
            })
            .collect();
        let e = envelope(&burst, 50);
        let ms = e.iter().map(|x| x * x).sum::<f64>() / 1000.0;
        assert!((ms - 1.0).abs() < 1e-12, "{ms}");
        assert_eq!(e[100], 0.0);
        assert!(e[400] > 2.0);
        assert_eq!(envelope(&burst, 1), vec![1.0; 1000]);
    }
}
