//! Exact calibration from the exact relations ([`super::exact`]): the damping parameter that makes the
//! delivered `e_post` equal the requested `e_pre` to 1e-10, by root finding. All parameters are
//! dimensionless. Jankowski's law has no closed form: its calibration integrates impacts
//! ([`crate::calibration`]).

use super::{
    bilinear_law, damping, exact, hertz_max_penetration, papi_factors, BilinearLoop, Reading,
    Tension,
};
use crate::integrate::brent_root;
use crate::Error;

/// Required agreement between `e_post` and `e_pre` after calibration.
pub const E_TOLERANCE: f64 = 1e-10;

/// Root of `e_post(p) = e` for a decreasing `e_post` on `[0, hi]`, widening `hi` while needed.
pub(crate) fn solve_decreasing(
    what: &'static str,
    e: f64,
    mut hi: f64,
    mut e_post: impl FnMut(f64) -> Result<f64, Error>,
) -> Result<f64, Error> {
    if e == 1.0 {
        return Ok(0.0);
    }
    let f0 = e_post(0.0)? - e;
    let mut fhi = e_post(hi)? - e;
    let mut tries = 0;
    while fhi > 0.0 {
        hi *= 4.0;
        fhi = e_post(hi)? - e;
        tries += 1;
        if tries > 40 {
            return Err(Error::Calibration {
                what,
                e,
                reason: "no damping value delivers so small an e".into(),
            });
        }
    }
    finish(what, e, 0.0, hi, f0, fhi, e_post)
}

fn finish(
    what: &'static str,
    e: f64,
    lo: f64,
    hi: f64,
    flo: f64,
    fhi: f64,
    mut e_post: impl FnMut(f64) -> Result<f64, Error>,
) -> Result<f64, Error> {
    let mut failure = None;
    let root = brent_root(
        |p| match e_post(p) {
            Ok(v) => v - e,
            Err(err) => {
                failure = Some(err);
                f64::NAN
            }
        },
        lo,
        hi,
        flo,
        fhi,
        1e-15 * hi.abs().max(1.0),
    );
    if let Some(err) = failure {
        return Err(err);
    }
    let root = root.ok_or_else(|| Error::Calibration {
        what,
        e,
        reason: if (flo + fhi).is_finite() {
            format!(
                "e_post ranges from {:.6} to {:.6} for {what} in [{lo}, {hi}]",
                flo + e,
                fhi + e
            )
        } else {
            // So small an e puts the impact's scales beyond f64 at an end of the bracket.
            format!("the impact cannot be integrated at an end of {what} in [{lo}, {hi}]")
        },
    })?;
    let miss = (e_post(root)? - e).abs();
    if miss > E_TOLERANCE {
        return Err(Error::Calibration {
            what,
            e,
            reason: format!("root found misses e by {miss:e}"),
        });
    }
    Ok(root)
}

/// Exact damping ratio `zeta` of a linear contact: damped in both phases (Kelvin–Voigt, with the tension
/// rule) or in approach only (Mahmoud & Jankowski). With tension allowed the Anagnostopoulos formula is
/// already exact and is returned as is.
pub fn exact_zeta(e: f64, restitution_damped: bool, tension: Tension) -> Result<f64, Error> {
    if restitution_damped && tension == Tension::Allow {
        return Ok(damping::zeta_anagnostopoulos(e));
    }
    solve_decreasing("zeta", e, 1.0, |z| {
        Ok(if restitution_damped {
            exact::kv_e_post(z, tension)
        } else {
            exact::mj_e_post(z)
        })
    })
}

/// Exact Hunt–Crossley factor `chi` (same in both phases).
pub fn exact_chi(e: f64) -> Result<f64, Error> {
    solve_decreasing("chi", e, 1.0 / e, |c| Ok(exact::hc_e_post(c, c)))
}

/// The `alpha` of Papi & Toopchi-Nezhad (2022) calibrated exactly: the root of `e_post(alpha) = e` in [0, 1] (for `e = 1` any
/// alpha works and 1 is returned).
pub fn papi_alpha(e: f64, reading: Reading) -> Result<f64, Error> {
    if e == 1.0 {
        return Ok(1.0);
    }
    let f = |a: f64| {
        let (chi, chi_r) = papi_factors(e, a, reading);
        Ok(exact::hc_e_post(chi, chi_r))
    };
    let (f0, f1) = (f(0.0)? - e, f(1.0)? - e);
    finish("alpha", e, 0.0, 1.0, f0, f1, f)
}

/// Exact design restitution `e_d` of the bilinear loop: the `e` to put into the dissipated-energy formula so
/// that the impact delivers `e`, for exponent `n`, yield ratio `a` and `d_m` equal to `ratio` times the
/// elastic Hertz penetration.
pub fn exact_e_design(e: f64, n: f64, a: f64, ratio: f64) -> Result<f64, Error> {
    let d_m = ratio * hertz_max_penetration(1.0, n, 1.0, 1.0, 1.0);
    let f = |e_d: f64| {
        let BilinearLoop { k1, k2, d_y } = bilinear_law(1.0, n, e_d, a, d_m);
        Ok(exact::bilinear_e_post(k1, k2, d_y, 0.5))
    };
    if e == 1.0 {
        return Ok(1.0);
    }
    let (lo, hi) = (1e-9, 1.0);
    let (flo, fhi) = (f(lo)? - e, f(hi)? - e);
    finish("e_design", e, lo, hi, flo, fhi, f)
}
