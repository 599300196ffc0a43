//! Exact single-impact relations (`docs/contact-models.md`): the coefficient of
//! restitution an ideal impact delivers, in closed form or by solving one scalar equation. All are
//! independent of stiffness, mass and impact velocity (and, for Hunt–Crossley laws, of the exponent).

use super::{ForceLaw, Tension};
use std::f64::consts::PI;

/// `(chi - ln(1 + chi)) / chi^2`: the approach-phase energy integral of a Hunt–Crossley law, in units of
/// `m v_i^2`, with `d_max^(n+1) = (n + 1) E m v_i^2 / k`. Tends to 1/2 as `chi -> 0`.
pub fn hc_approach_integral(chi: f64) -> f64 {
    if chi < 1e-3 {
        // Series of (chi - ln(1+chi))/chi^2 = sum_{j>=0} (-1)^j chi^j / (j + 2); cancellation-free.
        let mut s = 0.0;
        let mut p = 1.0;
        for j in 0..12 {
            s += p / (j as f64 + 2.0);
            p *= -chi;
        }
        s
    } else {
        (chi - chi.ln_1p()) / (chi * chi)
    }
}

/// `u - 1 + exp(-u)` without cancellation for small `u`.
fn g_u(u: f64) -> f64 {
    if u < 0.1 {
        // u^2/2 - u^3/6 + u^4/24 - ...
        let mut term = u * u / 2.0;
        let mut s: f64 = 0.0;
        let mut j = 2.0;
        while term.abs() > 1e-18 * s.abs().max(1e-300) {
            s += term;
            j += 1.0;
            term *= -u / j;
        }
        s
    } else {
        u + (-u).exp_m1()
    }
}

/// Delivered `e` of a Hunt–Crossley-type impact with damping factor `chi` in approach and `chi_r` in
/// restitution: `y = chi_r e` solves `(-y - ln(1 - y)) / chi_r^2 = E(chi)`; with `chi_r = 0`, `e = sqrt(2E)`.
/// Solved in the robust form `u - 1 + exp(-u) = E chi_r^2`, `y = 1 - exp(-u)`.
pub fn hc_e_post(chi: f64, chi_r: f64) -> f64 {
    let big_e = hc_approach_integral(chi);
    let s = big_e * chi_r * chi_r;
    if s < 1e-300 {
        return (2.0 * big_e).sqrt();
    }
    // Newton on the convex increasing g(u) = s from an upper-side start converges monotonically.
    let mut u = if s < 0.5 {
        (2.0 * s).sqrt() * (1.0 + (2.0 * s).sqrt() / 3.0) + 1e-300
    } else {
        s + 1.0
    };
    // Stop when the step no longer shrinks (round-off reached) or is below a few ulps.
    let mut last = f64::INFINITY;
    for _ in 0..60 {
        let f = g_u(u) - s;
        let df = -(-u).exp_m1();
        let du = f / df;
        u -= du;
        if du.abs() <= 4.0 * f64::EPSILON * u || du.abs() >= last {
            break;
        }
        last = du.abs();
    }
    -(-u).exp_m1() / chi_r
}

/// Time at which a unit linear oscillator `d'' + 2 zeta d' + d = 0`, `d(0) = 0`, `d'(0) = 1` first has
/// `d + 2 zeta d' = 0` after turning (the force of a Kelvin–Voigt contact reaches zero). Dimensionless.
fn kv_zero_force_time(zeta: f64) -> f64 {
    let q = 1.0 - zeta * zeta;
    if q > 0.0 {
        let w = q.sqrt();
        (2.0 * zeta * w).atan2(2.0 * zeta * zeta - 1.0) / w
    } else if q < 0.0 {
        let w = (-q).sqrt();
        (2.0 * zeta * w / (2.0 * zeta * zeta - 1.0)).atanh() / w
    } else {
        2.0
    }
}

/// Time at which the same oscillator first has `d' = 0` (end of approach). Dimensionless.
fn turning_time(zeta: f64) -> f64 {
    let q = 1.0 - zeta * zeta;
    if zeta == 0.0 {
        PI / 2.0
    } else if q > 0.0 {
        let w = q.sqrt();
        (w / zeta).atan() / w
    } else if q < 0.0 {
        let w = (-q).sqrt();
        (w / zeta).atanh() / w
    } else {
        1.0
    }
}

/// Delivered `e` of a linear Kelvin–Voigt impact with damping ratio `zeta` in both phases.
/// With tension allowed and separation at `d = 0`: `exp(-pi zeta / sqrt(1 - zeta^2))`, and 0 for
/// `zeta >= 1` (the contact never separates). Clamped at zero force: `exp(-zeta t_end)`, where `t_end`
/// (dimensionless, `omega t`) is the first zero of the force in restitution.
pub fn kv_e_post(zeta: f64, tension: Tension) -> f64 {
    match tension {
        Tension::Allow => {
            if zeta >= 1.0 {
                0.0
            } else {
                (-PI * zeta / (1.0 - zeta * zeta).sqrt()).exp()
            }
        }
        Tension::Clamp => (-zeta * kv_zero_force_time(zeta)).exp(),
    }
}

/// Delivered `e` of a linear contact damped (ratio `zeta`) in approach only (Mahmoud & Jankowski):
/// `exp(-zeta / sqrt(1 - zeta^2) atan(sqrt(1 - zeta^2) / zeta))`, continued through `zeta = 1`.
pub fn mj_e_post(zeta: f64) -> f64 {
    (-zeta * turning_time(zeta)).exp()
}

/// Maximum penetration (m) of a bilinear loading path (`K1` up to `d_y`, then `K2`, both N/m) that stores
/// the kinetic energy `ke` (J).
pub fn bilinear_max_penetration(k1: f64, k2: f64, d_y: f64, ke: f64) -> f64 {
    let w_y = 0.5 * k1 * d_y * d_y;
    if ke <= w_y {
        return (2.0 * ke / k1).sqrt();
    }
    // K1 d_y x + K2 x^2 / 2 = ke - w_y, in the cancellation-free root form.
    let r = ke - w_y;
    let b = k1 * d_y;
    d_y + 2.0 * r / (b + (b * b + 2.0 * k2 * r).sqrt())
}

/// Delivered `e` of the bilinear loop for kinetic energy `ke` (J) of the relative motion: the loop is a
/// parallelogram of area `(K1 - K2) d_y (d_max - d_y)`, so `e^2 = 1 - area / ke`.
pub fn bilinear_e_post(k1: f64, k2: f64, d_y: f64, ke: f64) -> f64 {
    let d_max = bilinear_max_penetration(k1, k2, d_y, ke);
    let area = if d_max > d_y {
        (k1 - k2) * d_y * (d_max - d_y)
    } else {
        0.0
    };
    (1.0 - area / ke).max(0.0).sqrt()
}

/// The exact delivered `e` of an impact with this law, effective mass `m` (kg) and impact velocity `v_i`
/// (m/s), without gravity, where a closed form or scalar equation exists; `None` otherwise (Jankowski, or
/// linear laws damped differently in the two phases). Laws with restitution damping end at zero force
/// when `tension` is `Clamp`.
pub fn e_post(law: &ForceLaw, tension: Tension, m: f64, v_i: f64) -> Option<f64> {
    match *law {
        ForceLaw::Elastic { .. } => Some(1.0),
        ForceLaw::LinearViscous { k, c, c_r } => {
            let zeta = c / (2.0 * (k * m).sqrt());
            if c_r == c {
                Some(kv_e_post(zeta, tension))
            } else if c_r == 0.0 {
                Some(mj_e_post(zeta))
            } else {
                None
            }
        }
        ForceLaw::HuntCrossley { chi, chi_r, .. } => Some(hc_e_post(chi, chi_r)),
        ForceLaw::Jankowski { .. } => None,
        ForceLaw::Bilinear { k1, k2, d_y } => {
            Some(bilinear_e_post(k1, k2, d_y, 0.5 * m * v_i * v_i))
        }
        ForceLaw::Thornton { .. } => Some(thornton_turn(law, 0.5 * m * v_i * v_i).2),
    }
}

/// Maximum penetration (m) in closed form where one exists (no gravity): linear laws, Hunt–Crossley laws
/// (`d_max^(n+1) = (n + 1) E(chi) m v_i^2 / k`), elastic and bilinear laws.
pub fn max_penetration(law: &ForceLaw, m: f64, v_i: f64) -> Option<f64> {
    match *law {
        ForceLaw::Elastic { k, n } => {
            Some((0.5 * (n + 1.0) * m * v_i * v_i / k).powf(1.0 / (n + 1.0)))
        }
        ForceLaw::LinearViscous { k, c, .. } => {
            let zeta = c / (2.0 * (k * m).sqrt());
            // d = v_i / omega * exp(-zeta t1) at the turning time t1 (the sine factor there is 1).
            Some(v_i * (m / k).sqrt() * (-zeta * turning_time(zeta)).exp())
        }
        ForceLaw::HuntCrossley { k, n, chi, .. } => {
            let e = hc_approach_integral(chi);
            Some(((n + 1.0) * e * m * v_i * v_i / k).powf(1.0 / (n + 1.0)))
        }
        ForceLaw::Jankowski { .. } => None,
        ForceLaw::Bilinear { k1, k2, d_y } => {
            Some(bilinear_max_penetration(k1, k2, d_y, 0.5 * m * v_i * v_i))
        }
        ForceLaw::Thornton { .. } => Some(thornton_turn(law, 0.5 * m * v_i * v_i).0),
    }
}

/// The impact velocity (m/s) at which a Thornton contact of effective mass `m` (kg) just reaches first yield:
/// the Hertz energy up to yield, `(2/5) F_y d_y`, equals `m v_y^2 / 2`. `None` for another law.
pub fn thornton_yield_velocity(law: &ForceLaw, m: f64) -> Option<f64> {
    match *law {
        ForceLaw::Thornton { d_y, f_y, .. } => Some((0.8 * f_y * d_y / m).sqrt()),
        _ => None,
    }
}

/// Thornton's (1997) closed form of the restitution of elastic–perfectly-plastic spheres at impact velocity
/// `v_i = speed * v_y` (`speed` = `v_i / v_y`, dimensionless): 1 up to yield, then with `r = 1 / speed`
/// `e = (6 sqrt(3) / 5)^(1/2) [1 - r^2 / 6]^(1/2) { r / (r + 2 sqrt(6/5 - r^2/5)) }^(1/4)`
/// (docs/contact-models.md section 2.7; the law's own energy balance, [`thornton_turn`], gives the same).
pub fn thornton_e(speed: f64) -> f64 {
    if speed <= 1.0 {
        return 1.0;
    }
    let r = 1.0 / speed;
    let c = (6.0 * 3f64.sqrt() / 5.0).sqrt();
    c * (1.0 - r * r / 6.0).sqrt() * (r / (r + 2.0 * (1.2 - r * r / 5.0).sqrt())).powf(0.25)
}

/// A Thornton impact of kinetic energy `ke` (J): its turning point `(d_p` m, `F_p` N) and its delivered `e`,
/// from the energy balance of the law (section 2.7 of docs/contact-models.md). Loading stores
/// `W_y = (2/5) f_y d_y` up to yield, then `f_y D + k_p D^2 / 2` more over `D = d_p - d_y`; Hertzian unloading
/// returns `(2/5) F_p (d_p - d_f)`, so `e^2` is that over `ke`. Below yield, the elastic Hertz impact (e = 1).
/// `(0, 0, 1)` for another law.
pub fn thornton_turn(law: &ForceLaw, ke: f64) -> (f64, f64, f64) {
    let ForceLaw::Thornton {
        k,
        e_star,
        p_y,
        d_y,
        f_y,
        k_p,
    } = *law
    else {
        return (0.0, 0.0, 1.0);
    };
    let w_y = 0.4 * f_y * d_y;
    if ke <= w_y {
        let d = (2.5 * ke / k).powf(0.4);
        return (d, k * d.powf(1.5), 1.0);
    }
    // Root of k_p D^2 / 2 + f_y D - (ke - w_y) = 0, in the form without cancellation.
    let w = ke - w_y;
    let big_d = 2.0 * w / (f_y + (f_y * f_y + 2.0 * k_p * w).sqrt());
    let (d_p, f_p) = (d_y + big_d, f_y + k_p * big_d);
    let (_, d_f) = super::thornton_unloading(e_star, p_y, f_y, d_p, f_p);
    (d_p, f_p, (0.4 * f_p * (d_p - d_f) / ke).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hc_relation_satisfies_its_defining_equation() {
        for (chi, chi_r) in [(0.5, 0.5), (3.0, 1.2), (1e-5, 1e-5), (8.0, 8.0), (2.0, 0.0)] {
            let e = hc_e_post(chi, chi_r);
            let big_e = hc_approach_integral(chi);
            if chi_r == 0.0 {
                assert!((e * e / 2.0 - big_e).abs() < 1e-15);
            } else {
                let y = chi_r * e;
                // -y - ln(1 - y) = sum_{j>=2} y^j / j, summed directly to avoid cancellation.
                let num = if y < 0.1 {
                    (2..40).map(|j| y.powi(j) / j as f64).sum::<f64>()
                } else {
                    -y - (-y).ln_1p()
                };
                let lhs = num / (chi_r * chi_r);
                assert!(
                    (lhs - big_e).abs() < 1e-12 * big_e,
                    "{chi} {chi_r}: {lhs} vs {big_e}"
                );
            }
        }
    }

    /// The law's energy balance and Thornton's printed closed form are one function of `v_i / v_y`.
    #[test]
    fn thornton_energy_balance_is_the_closed_form() {
        let law = crate::contact::thornton_law(
            2.0e10,
            crate::contact::Sphere {
                radius: 0.1,
                yield_pressure: 1.0e8,
            },
        );
        let m = 50.0;
        let v_y = thornton_yield_velocity(&law, m).unwrap();
        for speed in [0.5, 1.0, 1.0001, 1.3, 2.0, 7.0, 40.0, 1e3, 1e5] {
            let v = speed * v_y;
            let balance = thornton_turn(&law, 0.5 * m * v * v).2;
            let closed = thornton_e(speed);
            assert!(
                (balance - closed).abs() < 1e-12,
                "{speed}: {balance} vs {closed}"
            );
        }
    }

    #[test]
    fn approach_integral_series_joins_closed_form() {
        // Just below the switch the series must agree with the closed form (accurate there to ~1e-12).
        let c = 0.999e-3f64;
        let closed = (c - c.ln_1p()) / (c * c);
        assert!((hc_approach_integral(c) - closed).abs() < 1e-11);
    }

    #[test]
    fn linear_relations_are_continuous_through_critical_damping() {
        for f in [
            |z| kv_e_post(z, Tension::Clamp),
            mj_e_post as fn(f64) -> f64,
        ] {
            let (a, b, c) = (f(1.0 - 1e-7), f(1.0), f(1.0 + 1e-7));
            assert!((a - b).abs() < 1e-6 && (c - b).abs() < 1e-6);
        }
        // At zeta = 1: clamped e = exp(-2), approach-only e = exp(-1) (docs/contact-models.md).
        assert!((kv_e_post(1.0, Tension::Clamp) - (-2f64).exp()).abs() < 1e-15);
        assert!((mj_e_post(1.0) - (-1f64).exp()).abs() < 1e-15);
    }
}
