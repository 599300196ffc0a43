//! Contact laws fitted to measurements (`pounding::fit`). The synthetic data are made here, independently
//! of the library's laws: the material restitution by bisection on its defining relation, Thornton's `e`
//! from the check values of next-physics.md, a Kelvin–Voigt force history from its closed form, and a
//! Hunt–Crossley history by a fine fixed-step Runge–Kutta integration.

use pounding::contact::{ContactOptions, Model, Restitution, Tension};
use pounding::fit::{force_history, restitution, HistorySetup};

/// A deterministic uniform number in [-1, 1) (a 64-bit LCG, Knuth's MMIX constants).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

/// The `e` of the Hunt–Crossley law with material damping at `chi = c v_i`: the root of
/// `chi - ln(1 + chi) = -chi e - ln(1 - chi e)` (next-physics.md section 1), by bisection.
fn material_e_by_bisection(chi: f64) -> f64 {
    let lhs = chi - (1.0 + chi).ln();
    let g = |e: f64| -chi * e - (1.0 - chi * e).ln() - lhs;
    // g rises with e on (0, 1/chi): g(0) < 0 <= g(1) for chi > 0.
    let (mut lo, mut hi) = (0.0f64, 1.0f64.min(1.0 / chi - 1e-15));
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if g(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

fn velocities() -> Vec<f64> {
    (0..20).map(|k| 0.05 * 1.25f64.powi(k)).collect()
}

#[test]
fn a_damping_constant_is_recovered_from_clean_points() {
    let pts: Vec<(f64, f64)> = velocities()
        .into_iter()
        .map(|v| (v, material_e_by_bisection(0.3 * v)))
        .collect();
    let fit = restitution::damping_constant(&pts).unwrap();
    let c = fit.get("damping_constant").unwrap();
    assert!((c.value - 0.3).abs() < 1e-6, "{c:?}");
    assert_eq!(c.unit, "s/m");
    assert!(fit.rms_residual < 1e-9);
}

/// With 2 % noise on e the estimate lies within its stated uncertainty, and the stated uncertainty is the
/// scatter of the estimates over many noisy data sets (what a standard error means).
#[test]
fn a_damping_constant_from_noisy_points_lies_within_its_stated_uncertainty() {
    let clean: Vec<(f64, f64)> = velocities()
        .into_iter()
        .map(|v| (v, material_e_by_bisection(0.3 * v)))
        .collect();
    let mut rng = Lcg(7);
    let (mut estimates, mut stated) = (Vec::new(), Vec::new());
    for _ in 0..200 {
        // Uniform noise of half-width 2 % sqrt(3): standard deviation 2 % of e.
        let noisy: Vec<(f64, f64)> = clean
            .iter()
            .map(|&(v, e)| (v, (e * (1.0 + 0.02 * 3f64.sqrt() * rng.next())).min(1.0)))
            .collect();
        let c = restitution::damping_constant(&noisy)
            .unwrap()
            .get("damping_constant")
            .cloned()
            .unwrap();
        estimates.push(c.value);
        stated.push(c.std_error);
    }
    let n = estimates.len() as f64;
    let mean = estimates.iter().sum::<f64>() / n;
    let sd = (estimates.iter().map(|c| (c - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
    let typical = stated.iter().sum::<f64>() / n;
    assert!(
        (mean - 0.3).abs() < 3.0 * sd / n.sqrt(),
        "mean {mean}, sd {sd}"
    );
    assert!(
        (typical / sd - 1.0).abs() < 0.25,
        "stated {typical} vs scatter {sd}"
    );
    let within = estimates
        .iter()
        .zip(&stated)
        .filter(|(c, s)| (*c - 0.3).abs() <= 2.0 * *s)
        .count();
    assert!(within as f64 > 0.9 * n, "{within} of {n} within 2 sigma");
}

/// Thornton's check values of next-physics.md (six digits), at v_y = 0.2 m/s.
#[test]
fn a_yield_velocity_is_recovered_from_thorntons_values() {
    let v_y = 0.2;
    let pts: Vec<(f64, f64)> = [
        (1.5, 0.971239),
        (2.0, 0.930626),
        (5.0, 0.773337),
        (10.0, 0.658558),
        (20.0, 0.557109),
        (50.0, 0.444606),
        (100.0, 0.374299),
    ]
    .iter()
    .map(|&(r, e)| (r * v_y, e))
    .collect();
    let fit = restitution::yield_velocity(&pts).unwrap();
    let got = fit.get("yield_velocity").unwrap().value;
    assert!((got / v_y - 1.0).abs() < 2e-5, "{got}");
}

#[test]
fn a_constant_e_is_the_mean_and_a_table_follows_the_points() {
    let pts = [(0.1, 0.7), (0.5, 0.6), (1.0, 0.65), (2.0, 0.55)];
    let fit = restitution::constant(&pts).unwrap();
    let e = fit.get("e").unwrap();
    assert!((e.value - 0.625).abs() < 1e-15);
    // sd of (0.7, 0.6, 0.65, 0.55) is sqrt(0.0125 / 3); over sqrt(4).
    assert!((e.std_error - (0.0125f64 / 3.0).sqrt() / 2.0).abs() < 1e-15);
    let (t, _) = restitution::table(&pts, None, false).unwrap();
    assert_eq!(t.points(), &pts);
    let (t, _) = restitution::table(&pts, None, true).unwrap();
    assert_eq!(t.points().len(), 3);
}

#[test]
fn bad_points_name_their_row() {
    for (pts, says) in [
        (vec![(0.1, 0.9)], "at least 2 rows"),
        (vec![(0.1, 0.9), (0.2, 1.2)], "row 2 [0.2, 1.2]"),
        (vec![(0.1, 0.9), (-0.2, 0.8)], "row 2"),
        (vec![(0.1, 1.0), (0.2, 1.0)], "every e = 1"),
    ] {
        let msg = restitution::damping_constant(&pts).unwrap_err().to_string();
        assert!(msg.starts_with("data = ") && msg.contains(says), "{msg}");
    }
}

/// A Kelvin–Voigt impact against a rigid wall in closed form: `d = (v / w_d) exp(-zeta w t) sin(w_d t)`,
/// `F = k d + c d'` while `d > 0` (tension allowed, kelvin-voigt's default), with
/// `e = exp(-pi zeta / sqrt(1 - zeta^2))`.
#[test]
fn a_kelvin_voigt_history_gives_back_its_stiffness_and_e() {
    let (m, v, k, e): (f64, f64, f64, f64) = (20.0, 1.5, 4.0e7, 0.6);
    let ln_e = f64::ln(e);
    let zeta = -ln_e / (std::f64::consts::PI.powi(2) + ln_e * ln_e).sqrt();
    let w = (k / m).sqrt();
    let wd = w * (1.0 - zeta * zeta).sqrt();
    let c = 2.0 * zeta * (k * m).sqrt();
    let t_end = std::f64::consts::PI / wd;
    let t_touch = 3.0e-4; // s, on the data's clock
    let data: Vec<(f64, f64)> = (0..120)
        .map(|j| {
            let t = -2e-4 + f64::from(j) * 1.2 * t_end / 100.0;
            let s = t - t_touch;
            let f = if s > 0.0 && s < t_end {
                let d = v / wd * (-zeta * w * s).exp() * (wd * s).sin();
                let dv =
                    v * (-zeta * w * s).exp() * ((wd * s).cos() - zeta * w / wd * (wd * s).sin());
                k * d + c * dv
            } else {
                0.0
            };
            (t, f)
        })
        .collect();
    let setup = HistorySetup {
        options: ContactOptions::new(Model::KelvinVoigt, 0.5),
        mass: m,
        v_i: v,
        exponent: None,
        damping_constant: false,
    };
    let r = force_history(&data, &setup).unwrap();
    let get = |key: &str| r.fit.get(key).unwrap().value;
    assert!((get("stiffness") / k - 1.0).abs() < 1e-4, "{:?}", r.fit);
    assert!((get("e") - e).abs() < 1e-4, "{:?}", r.fit);
    assert!((get("touch_time") - t_touch).abs() < 1e-4 * t_end);
    assert!(r.fit.normalised_residual < 1e-4);
    assert!(r.fit.get("exponent").is_none());
}

/// `F = k d^n (1 + c d')` integrated by classical RK4 at 1/20000 of the contact: the fit returns k, n and c.
#[test]
fn a_hunt_crossley_history_gives_back_stiffness_exponent_and_damping_constant() {
    let (m, v, k, n, c) = (5.0, 2.0, 3.0e9, 1.4, 0.25);
    let force = |d: f64, dv: f64| (k * d.max(0.0).powf(n) * (1.0 + c * dv)).max(0.0);
    let acc = |d: f64, dv: f64| -force(d, dv) / m;
    // Duration scale: the elastic Hertz-like impact.
    let d_max = ((n + 1.0) * m * v * v / (2.0 * k)).powf(1.0 / (n + 1.0));
    let h = 4.0 * d_max / v / 20000.0;
    let (mut t, mut d, mut dv) = (0.0f64, 0.0f64, v);
    let mut path = vec![(0.0, 0.0)];
    while d >= 0.0 && force(d, dv) >= 0.0 && t < 10.0 * d_max / v {
        let (k1d, k1v) = (dv, acc(d, dv));
        let (k2d, k2v) = (
            dv + 0.5 * h * k1v,
            acc(d + 0.5 * h * k1d, dv + 0.5 * h * k1v),
        );
        let (k3d, k3v) = (
            dv + 0.5 * h * k2v,
            acc(d + 0.5 * h * k2d, dv + 0.5 * h * k2v),
        );
        let (k4d, k4v) = (dv + h * k3v, acc(d + h * k3d, dv + h * k3v));
        d += h / 6.0 * (k1d + 2.0 * k2d + 2.0 * k3d + k4d);
        dv += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        t += h;
        path.push((t, if d > 0.0 { force(d, dv) } else { 0.0 }));
    }
    let stride = path.len() / 80;
    let data: Vec<(f64, f64)> = path.iter().step_by(stride).copied().collect();
    let setup = HistorySetup {
        options: ContactOptions {
            e: Restitution::DampingConstant(0.1),
            ..ContactOptions::new(Model::HuntCrossley, 0.5)
        },
        mass: m,
        v_i: v,
        exponent: None,
        damping_constant: true,
    };
    let r = force_history(&data, &setup).unwrap();
    let get = |key: &str| r.fit.get(key).unwrap().value;
    assert!((get("stiffness") / k - 1.0).abs() < 1e-4, "{:?}", r.fit);
    assert!((get("exponent") / n - 1.0).abs() < 1e-4, "{:?}", r.fit);
    assert!(
        (get("damping_constant") / c - 1.0).abs() < 1e-4,
        "{:?}",
        r.fit
    );
    assert_eq!(Tension::Clamp, Model::HuntCrossley.info().tension);
}

#[test]
fn a_history_of_too_few_samples_is_refused() {
    let setup = HistorySetup {
        options: ContactOptions::new(Model::Papi, 0.5),
        mass: 1.0,
        v_i: 1.0,
        exponent: None,
        damping_constant: false,
    };
    let msg = force_history(&[(0.0, 1.0)], &setup)
        .unwrap_err()
        .to_string();
    assert!(
        msg.starts_with("data = 1 sample") && msg.contains("at least 5"),
        "{msg}"
    );
}
