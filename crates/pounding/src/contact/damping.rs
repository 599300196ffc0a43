//! Published damping formulas: the damping parameter each model derives from the coefficient of restitution
//! `e` (dimensionless). Sources are given per function; see also `docs/contact-models.md`.

use std::f64::consts::PI;

/// Anagnostopoulos (2004) equivalent damping ratio, Papi & Toopchi-Nezhad (2022) eq (4): `zeta = -ln e / sqrt(pi^2 + ln^2 e)`.
/// Exact for a linear Kelvin–Voigt contact that may pull (tension) and separates at `d = 0`.
pub fn zeta_anagnostopoulos(e: f64) -> f64 {
    let l = e.ln();
    -l / (PI * PI + l * l).sqrt()
}

/// Mahmoud & Jankowski (2011) damping ratio of the modified linear viscoelastic model, Papi & Toopchi-Nezhad (2022) eq (5):
/// `zeta = (1 - e^2) / (e (e (pi - 2) + 2))`.
pub fn zeta_mahmoud_jankowski(e: f64) -> f64 {
    (1.0 - e * e) / (e * (e * (PI - 2.0) + 2.0))
}

/// Ye, Li & Zhu (2009), Papi & Toopchi-Nezhad (2022) eq (6): `chi = 3 (1 - e) / (2 e)`.
pub fn chi_ye(e: f64) -> f64 {
    1.5 * (1.0 - e) / e
}

/// Hunt & Crossley (1975): `chi = 3 (1 - e) / 2`.
pub fn chi_hunt_crossley(e: f64) -> f64 {
    1.5 * (1.0 - e)
}

/// Herbert & McWhannell (1977): `chi = 6 (1 - e) / ((2e - 1)^2 + 3)`.
pub fn chi_herbert_mcwhannell(e: f64) -> f64 {
    6.0 * (1.0 - e) / ((2.0 * e - 1.0).powi(2) + 3.0)
}

/// Lee & Wang (1983): `chi = 3 (1 - e) / 4`.
pub fn chi_lee_wang(e: f64) -> f64 {
    0.75 * (1.0 - e)
}

/// Lankarani & Nikravesh (1990): `chi = 3 (1 - e^2) / 4`.
pub fn chi_lankarani_nikravesh(e: f64) -> f64 {
    0.75 * (1.0 - e * e)
}

/// Gonthier et al. (2004): `chi = (1 - e^2) / e`.
pub fn chi_gonthier(e: f64) -> f64 {
    (1.0 - e * e) / e
}

/// Zhiying & Qishao (2006): `chi = 3 (1 - e^2) exp(2 (1 - e)) / 4`.
pub fn chi_zhiying_qishao(e: f64) -> f64 {
    0.75 * (1.0 - e * e) * (2.0 * (1.0 - e)).exp()
}

/// Flores et al. (2011), also Ye, Li & Zhu (2009) as used by OpenSees `Hertzdamp`: `chi = 8 (1 - e) / (5 e)`.
pub fn chi_flores(e: f64) -> f64 {
    1.6 * (1.0 - e) / e
}

/// Jankowski (2005) nonlinear viscoelastic damping ratio:
/// `xi = (9 sqrt 5 / 2) (1 - e^2) / (e (e (9 pi - 16) + 16))`.
pub fn xi_jankowski(e: f64) -> f64 {
    4.5 * 5f64.sqrt() * (1.0 - e * e) / (e * (e * (9.0 * PI - 16.0) + 16.0))
}

/// Papi & Toopchi-Nezhad (2022) eq (7): `chi = (3/2) (1 - e^2) / (alpha + e^2)`.
pub fn chi_papi(e: f64, alpha: f64) -> f64 {
    1.5 * (1.0 - e * e) / (alpha + e * e)
}

/// Papi & Toopchi-Nezhad (2022) eq (8) as printed: `alpha = e + 1` for `0.1 <= e < 0.8`, `1` for `0.8 <= e <= 1`. It contradicts the
/// paper's own range `0 <= alpha <= 1` and is probably a misprint; it is kept as printed (for `e < 0.1`, outside
/// the printed range, the first branch is extended).
pub fn alpha_eq8(e: f64) -> f64 {
    if e < 0.8 {
        e + 1.0
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_damping_at_e_equal_one() {
        for f in [
            zeta_anagnostopoulos,
            zeta_mahmoud_jankowski,
            chi_ye,
            chi_hunt_crossley,
            chi_herbert_mcwhannell,
            chi_lee_wang,
            chi_lankarani_nikravesh,
            chi_gonthier,
            chi_zhiying_qishao,
            chi_flores,
            xi_jankowski,
        ] {
            assert!(f(1.0).abs() < 1e-15);
        }
        assert!(chi_papi(1.0, 0.5).abs() < 1e-15);
    }

    #[test]
    fn papi_with_alpha_equal_e_is_ye() {
        // (3/2)(1 - e^2)/(e + e^2) = (3/2)(1 - e)/e: the identity behind the energy-split reading.
        for e in [0.1, 0.4, 0.77, 0.95] {
            assert!((chi_papi(e, e) - chi_ye(e)).abs() < 1e-14 * chi_ye(e));
        }
    }
}
