//! Ground motions that lose coherence with distance: records at several supports generated together from the
//! spectrum of a synthetic motion ([`super::synthetic`]) and a coherency model, by the spectral representation
//! (Shinozuka & Deodatis 1991; Deodatis 1996, `docs/structures.md`, "Ground motion that differs between
//! supports").
//!
//! The supports stand at positions `x_j` (m) along a line. Their stationary accelerations have the two-sided
//! cross-spectral densities `S_jk(w) = S(w) gamma(w, |x_j - x_k|)`, with `S` the filter's density and `gamma` the
//! lagged coherency of the model. With `Gamma(w) = L L^T` (Cholesky), support `j`'s motion is
//!
//! `a_j(t) = sum_(m <= j) sum_l 2 sqrt(S(w_l) dw) L_jm(w_l) cos(w_l t + phi_ml)`
//!
//! with independent phases `phi_ml` uniform on [0, 2 pi) and `w_l = l dw`, `dw = 2 pi / (n dt)` up to the
//! Nyquist frequency: each pair's cross-spectrum is the target's, exactly in expectation. Each is then put
//! under the synthetic motion's envelope, and all are scaled by one factor (which keeps their coherency): the
//! one that gives the first support the synthetic motion's PGA. The wave's passage is not in `gamma` (lagged
//! coherency): a support's delay (`delay`, or `distance / apparent_velocity`) adds it.

use super::synthetic::{Rng, Synthetic};
use super::Record;
use crate::error::check;
use crate::Error;
use std::f64::consts::PI;

crate::named! {
    /// The coherency models, by name.
    pub enum CoherencyKind: "model" {
        /// Luco & Wong (1986) ([`Coherency::LucoWong`]).
        LucoWong = "luco-wong",
        /// Harichandran & Vanmarcke (1986) ([`Coherency::HarichandranVanmarcke`]).
        HarichandranVanmarcke = "harichandran-vanmarcke",
    }
}

/// A lagged-coherency model `gamma(w, d)`: how alike two supports `d` m apart move at circular frequency `w`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Coherency {
    /// Luco & Wong (1986): `gamma = exp(-(alpha w d)^2)`.
    LucoWong {
        /// Incoherence, s/m (the ratio of a dimensionless incoherence to the shear-wave velocity).
        alpha: f64,
    },
    /// Harichandran & Vanmarcke (1986): `gamma = A exp(-2 d (1 - A + a A) / (a theta)) + (1 - A) exp(-2 d (1 - A
    /// + a A) / theta)`, `theta(w) = k (1 + (w / (2 pi f0))^b)^(-1/2)`.
    HarichandranVanmarcke {
        /// `A` (dimensionless).
        a_big: f64,
        /// `a` (dimensionless).
        a: f64,
        /// `k`, m.
        k: f64,
        /// `f0`, Hz.
        f0: f64,
        /// `b` (dimensionless).
        b: f64,
    },
}

impl Coherency {
    /// Harichandran & Vanmarcke's model with their values for event 20 of the SMART-1 array (A = 0.736,
    /// a = 0.147, k = 5210 m, f0 = 1.09 Hz, b = 2.78).
    pub const SMART1_EVENT20: Coherency = Coherency::HarichandranVanmarcke {
        a_big: 0.736,
        a: 0.147,
        k: 5210.0,
        f0: 1.09,
        b: 2.78,
    };

    /// Harichandran & Vanmarcke's model with the parameters given, each absent one [`Self::SMART1_EVENT20`]'s.
    pub fn harichandran_vanmarcke(
        a_big: Option<f64>,
        a: Option<f64>,
        k: Option<f64>,
        f0: Option<f64>,
        b: Option<f64>,
    ) -> Coherency {
        let Coherency::HarichandranVanmarcke {
            a_big: a_big0,
            a: a0,
            k: k0,
            f0: f00,
            b: b0,
        } = Self::SMART1_EVENT20
        else {
            unreachable!("SMART1_EVENT20 is Harichandran and Vanmarcke's model")
        };
        Coherency::HarichandranVanmarcke {
            a_big: a_big.unwrap_or(a_big0),
            a: a.unwrap_or(a0),
            k: k.unwrap_or(k0),
            f0: f0.unwrap_or(f00),
            b: b.unwrap_or(b0),
        }
    }

    /// Its kind.
    pub fn kind(&self) -> CoherencyKind {
        match self {
            Coherency::LucoWong { .. } => CoherencyKind::LucoWong,
            Coherency::HarichandranVanmarcke { .. } => CoherencyKind::HarichandranVanmarcke,
        }
    }

    /// The lagged coherency at circular frequency `w` (rad/s) between supports `d` m apart (dimensionless).
    pub fn gamma(&self, w: f64, d: f64) -> f64 {
        match *self {
            Coherency::LucoWong { alpha } => (-(alpha * w * d).powi(2)).exp(),
            Coherency::HarichandranVanmarcke { a_big, a, k, f0, b } => {
                let theta = k / (1.0 + (w / (2.0 * PI * f0)).powf(b)).sqrt();
                let r = 2.0 * d * (1.0 - a_big + a * a_big);
                a_big * (-r / (a * theta)).exp() + (1.0 - a_big) * (-r / theta).exp()
            }
        }
    }

    pub(super) fn check(&self) -> Result<(), Error> {
        match *self {
            Coherency::LucoWong { alpha } => {
                check(
                    "alpha",
                    alpha,
                    alpha > 0.0 && alpha <= 1.0,
                    "0 < alpha <= 1 (s/m)",
                )?;
            }
            Coherency::HarichandranVanmarcke { a_big, a, k, f0, b } => {
                check("A", a_big, a_big > 0.0 && a_big <= 1.0, "0 < A <= 1")?;
                check("a", a, a > 0.0 && a <= 1.0, "0 < a <= 1")?;
                check("k", k, k > 0.0 && k.is_finite(), "k > 0 (m)")?;
                check("f0", f0, f0 > 0.0 && f0.is_finite(), "f0 > 0 (Hz)")?;
                check("b", b, b > 0.0 && b <= 10.0, "0 < b <= 10")?;
            }
        }
        Ok(())
    }
}

/// Largest number of samples of each record (`duration / dt`): the sum over frequencies costs samples x
/// frequencies per support.
pub const MAX_SAMPLES: usize = 50_000;

/// Largest number of supports generated together.
pub const MAX_SUPPORTS: usize = 50;

/// Records at supports along a line that lose coherence with distance.
#[derive(Clone, Debug, PartialEq)]
pub struct Spatial {
    /// The spectrum, envelope, duration, step and PGA (of the first support).
    pub synthetic: Synthetic,
    /// The coherency model.
    pub coherency: Coherency,
    /// The supports' positions along the line, m.
    pub positions: Vec<f64>,
}

impl Spatial {
    /// One record per position (named `name-1`, `name-2`, ...), from `seed`: the same seed gives the same
    /// records, bit for bit.
    pub fn records(&self, name: &str, seed: u64) -> Result<Vec<Record>, Error> {
        let s = &self.synthetic;
        s.check()?;
        self.coherency.check()?;
        check_positions(&self.positions)?;
        let np = self.positions.len();
        let n = (s.duration / s.dt).round() as usize;
        if n > MAX_SAMPLES {
            return Err(Error::Choice {
                name: "duration",
                value: format!("{} s at dt {} s ({n} samples)", s.duration, s.dt),
                allowed: format!(
                    "at most {MAX_SAMPLES} samples per record (a shorter duration or a larger dt)"
                ),
            });
        }
        let dt = s.dt;
        let dw = 2.0 * PI / (n as f64 * dt);
        // Frequencies strictly below Nyquist (n / 2), where the samples tell cosines apart.
        let nl = (n - 1) / 2;
        let mut rng = Rng::new(seed);
        let mut acc = vec![vec![0.0; n]; np];
        let mut chol = vec![0.0; np * np];
        // Each frequency's complex amplitude per support, then its cosine over the samples by rotation.
        let mut amp = vec![(0.0, 0.0); np];
        for l in 1..=nl {
            let w = l as f64 * dw;
            cholesky(&self.coherency, &self.positions, w, &mut chol);
            let scale = 2.0 * (s.filter.density(w) * dw).sqrt();
            amp.iter_mut().for_each(|a| *a = (0.0, 0.0));
            for m in 0..np {
                let phi = 2.0 * PI * rng.uniform();
                let (sn, cs) = phi.sin_cos();
                for (j, a) in amp.iter_mut().enumerate().skip(m) {
                    let h = scale * chol[j * np + m];
                    a.0 += h * cs;
                    a.1 += h * sn;
                }
            }
            // cos(w t_k + phi) = Re(e^(i phi) e^(i w t_k)), t_k = k dt (k from 1).
            let (rs, rc) = (w * dt).sin_cos();
            for (j, &(ac, asn)) in amp.iter().enumerate() {
                let (mut c, mut sn) = (rc, rs);
                for x in acc[j].iter_mut() {
                    *x += ac * c - asn * sn;
                    (c, sn) = (c * rc - sn * rs, sn * rc + c * rs);
                }
            }
        }
        if s.envelope {
            for a in acc.iter_mut() {
                for (k, x) in a.iter_mut().enumerate() {
                    *x *= s.envelope((k + 1) as f64 * dt);
                }
            }
        }
        if let Some(p) = s.pga {
            let peak = acc[0].iter().fold(0.0f64, |m, a| m.max(a.abs()));
            if peak > 0.0 {
                let f = p / peak;
                acc.iter_mut().flatten().for_each(|a| *a *= f);
            }
        }
        acc.into_iter()
            .enumerate()
            .map(|(j, a)| Record::new(format!("{name}-{}", j + 1), dt, dt, a))
            .collect()
    }
}

/// Checks the supports' positions: 1 to [`MAX_SUPPORTS`], finite, within 1e6 m.
pub(super) fn check_positions(positions: &[f64]) -> Result<(), Error> {
    let np = positions.len();
    if np == 0 || np > MAX_SUPPORTS {
        return Err(Error::Choice {
            name: "positions",
            value: format!("{np} positions"),
            allowed: format!("1 to {MAX_SUPPORTS} supports"),
        });
    }
    if let Some(x) = positions.iter().find(|x| !x.is_finite() || x.abs() > 1e6) {
        return Err(Error::Choice {
            name: "positions",
            value: crate::words::number(*x),
            allowed: "positions along the line within 1e6 m (m)".into(),
        });
    }
    Ok(())
}

/// The Cholesky factor (lower, row-major) of the coherency matrix of supports at `x` (m) at circular
/// frequency `w` (rad/s); a pivot that vanishes (two supports at one point move alike) leaves its column zero.
pub(super) fn cholesky(coherency: &Coherency, x: &[f64], w: f64, l: &mut [f64]) {
    let n = x.len();
    l.iter_mut().for_each(|v| *v = 0.0);
    for i in 0..n {
        for j in 0..=i {
            let g = if i == j {
                1.0
            } else {
                coherency.gamma(w, (x[i] - x[j]).abs())
            };
            let s: f64 = (0..j).map(|k| l[i * n + k] * l[j * n + k]).sum();
            if i == j {
                l[i * n + i] = (g - s).max(0.0).sqrt();
            } else if l[j * n + j] > 1e-9 {
                l[i * n + j] = (g - s) / l[j * n + j];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn harichandran_vanmarcke_is_one_at_no_distance_and_falls_with_it() {
        let c = Coherency::SMART1_EVENT20;
        assert!((c.gamma(10.0, 0.0) - 1.0).abs() < 1e-15);
        assert!(c.gamma(10.0, 100.0) > c.gamma(10.0, 200.0));
        assert!(c.gamma(5.0, 100.0) > c.gamma(30.0, 100.0));
        let lw = Coherency::LucoWong { alpha: 2.5e-4 };
        assert!((lw.gamma(20.0, 200.0) - (-1.0f64).exp()).abs() < 1e-15);
    }
}
