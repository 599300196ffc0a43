//! Elastic response spectra: the peak response of linear single-degree-of-freedom oscillators to a record.
//!
//! The oscillator of natural period `T` (s) and damping ratio `zeta`, `u'' + 2 zeta w u' + w^2 u = -a_g(t)`
//! with `w = 2 pi / T`, starts at rest at `t = 0`. The ground acceleration is the record's piecewise-linear
//! interpolation (a ramp from 0 to the first sample, then linear between samples), so on each step the
//! response is known in closed form: a particular solution linear in time plus a damped free vibration
//! (the exact piecewise-linear solution of Nigam & Jennings 1969; Chopra, *Dynamics of Structures*, section 5.2).
//! The peak displacement `SD = max |u(t)|` (m) is taken over the record's duration, between samples too: on
//! each step, wherever the velocity changes sign, its root is located (Brent) on the closed form. The pseudo
//! velocity and acceleration follow, `PSV = w SD` (m/s) and `PSA = w^2 SD` (m/s^2).

use super::Record;
use crate::error::check;
use crate::integrate::brent_root;
use crate::Error;
use std::f64::consts::PI;
use std::ops::ControlFlow;

/// A response spectrum: ordinates at each period.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Spectrum {
    /// Damping ratio of the oscillators (dimensionless).
    pub damping: f64,
    /// Natural periods, s.
    pub periods: Vec<f64>,
    /// Spectral displacement `max |u|`, m.
    pub sd: Vec<f64>,
    /// Pseudo-spectral velocity `w SD`, m/s.
    pub psv: Vec<f64>,
    /// Pseudo-spectral acceleration `w^2 SD`, m/s^2.
    pub psa: Vec<f64>,
}

/// Most periods in one spectrum.
pub const MAX_PERIODS: usize = 100_000;

/// Most work of one spectrum, in sub-steps of the closed-form solution (each record step is cut into
/// `max(1, ceil(8 dt / T))` of them, so that the velocity changes sign at most once in each): about 6 s on
/// one core here (22 to 30 ns a sub-step: 4e8 took 12 s; 20,000 periods of 1e-3 s under El Centro, 5e9,
/// took 109 s before this budget). The default spectrum of El Centro (100 periods, 0.02 to 10 s) takes 3.1e5.
pub const MAX_SPECTRUM_WORK: f64 = 2e8;

/// The sub-steps [`peak_displacement`] takes for `period` (s) over `record`.
fn work(record: &Record, period: f64) -> f64 {
    let cuts = |h: f64| (8.0 * h / period).ceil().max(1.0);
    let first = if record.t0() > 0.0 {
        cuts(record.t0())
    } else {
        0.0
    };
    first + (record.npts().saturating_sub(1)) as f64 * cuts(record.dt())
}

/// The elastic spectrum of `record` for oscillators of damping ratio `damping` (0 <= zeta < 1) at `periods`
/// (s; at least one, each from 1e-3 to 1e3 s), within [`MAX_SPECTRUM_WORK`].
pub fn spectrum(record: &Record, damping: f64, periods: &[f64]) -> Result<Spectrum, Error> {
    spectrum_with(record, damping, periods, &mut || ControlFlow::Continue(()))
}

/// [`spectrum`], asking `go_on` after every period and every 4096 record steps whether to go on: `Break`
/// stops it with [`Error::Interrupted`] (Ctrl-C from Python or a terminal).
pub fn spectrum_with(
    record: &Record,
    damping: f64,
    periods: &[f64],
    go_on: &mut dyn FnMut() -> ControlFlow<()>,
) -> Result<Spectrum, Error> {
    check(
        "damping",
        damping,
        (0.0..1.0).contains(&damping),
        "0 <= damping < 1 (a damping ratio)",
    )?;
    if periods.is_empty() || periods.len() > MAX_PERIODS {
        return Err(Error::Choice {
            name: "periods",
            value: format!("{} periods", periods.len()),
            allowed: "1 to 100000 periods (s)".into(),
        });
    }
    for &t in periods {
        check(
            "periods",
            t,
            (1e-3..=1e3).contains(&t),
            "each period from 1e-3 to 1e3 (s)",
        )?;
    }
    let total: f64 = periods.iter().map(|&t| work(record, t)).sum();
    if total > MAX_SPECTRUM_WORK {
        return Err(Error::Choice {
            name: "periods",
            value: format!(
                "{} periods over {} record steps ({total:.3e} sub-steps)",
                periods.len(),
                record.npts()
            ),
            allowed: "at most 2e8 sub-steps (MAX_SPECTRUM_WORK; a record step is cut into 8 per period it spans): fewer or longer periods, or a shorter record".into(),
        });
    }
    let mut sd = Vec::with_capacity(periods.len());
    for &t in periods {
        sd.push(
            peak_displacement_with(record, t, damping, go_on)
                .ok_or(Error::Interrupted { what: "spectrum" })?,
        );
    }
    let w = |t: f64| 2.0 * PI / t;
    Ok(Spectrum {
        damping,
        periods: periods.to_vec(),
        psv: sd.iter().zip(periods).map(|(d, &t)| w(t) * d).collect(),
        psa: sd
            .iter()
            .zip(periods)
            .map(|(d, &t)| w(t) * w(t) * d)
            .collect(),
        sd,
    })
}

/// The closed-form response over one step of linear ground acceleration, from `(u0, v0)`.
pub(crate) struct Step {
    w: f64,
    zeta: f64,
    wd: f64,
    /// Particular solution `alpha + beta tau`.
    alpha: f64,
    beta: f64,
    /// Free vibration `e^(-zeta w tau) (c1 cos wd tau + c2 sin wd tau)`.
    c1: f64,
    c2: f64,
}

impl Step {
    /// The step where the ground acceleration goes linearly from `a0` to `a1` over `h` s.
    pub(crate) fn new(w: f64, zeta: f64, u0: f64, v0: f64, a0: f64, a1: f64, h: f64) -> Self {
        let wd = w * (1.0 - zeta * zeta).sqrt();
        // Forcing per unit mass p = -a_g = p0 + s tau.
        let (p0, s) = (-a0, -(a1 - a0) / h);
        let beta = s / (w * w);
        let alpha = (p0 - 2.0 * zeta * w * beta) / (w * w);
        let c1 = u0 - alpha;
        let c2 = (v0 - beta + zeta * w * c1) / wd;
        Step {
            w,
            zeta,
            wd,
            alpha,
            beta,
            c1,
            c2,
        }
    }

    /// Displacement and velocity at `tau` s into the step.
    pub(crate) fn at(&self, tau: f64) -> (f64, f64) {
        let e = (-self.zeta * self.w * tau).exp();
        let (s, c) = (self.wd * tau).sin_cos();
        let zw = self.zeta * self.w;
        let u = self.alpha + self.beta * tau + e * (self.c1 * c + self.c2 * s);
        let v = self.beta
            + e * ((-zw * self.c1 + self.wd * self.c2) * c
                + (-zw * self.c2 - self.wd * self.c1) * s);
        (u, v)
    }
}

/// `max |u(t)|` (m) of the oscillator of period `period` (s) and damping ratio `zeta` under `record`, over
/// the record's duration.
pub fn peak_displacement(record: &Record, period: f64, zeta: f64) -> f64 {
    peak_displacement_with(record, period, zeta, &mut || ControlFlow::Continue(()))
        .unwrap_or(f64::NAN)
}

/// [`peak_displacement`], asking `go_on` every 4096 record steps and at the end whether to go on: `None` if
/// it said `Break`.
fn peak_displacement_with(
    record: &Record,
    period: f64,
    zeta: f64,
    go_on: &mut dyn FnMut() -> ControlFlow<()>,
) -> Option<f64> {
    let w = 2.0 * PI / period;
    let (mut u, mut v, mut peak) = (0.0f64, 0.0f64, 0.0f64);
    // Sub-steps short enough (an eighth of the period) that the velocity changes sign at most once in each.
    let mut advance = |a0: f64, a1: f64, h: f64, u: &mut f64, v: &mut f64| {
        let step = Step::new(w, zeta, *u, *v, a0, a1, h);
        let m = ((8.0 * h / period).ceil() as usize).max(1);
        let (mut t_prev, mut v_prev) = (0.0, *v);
        for j in 1..=m {
            let t = h * j as f64 / m as f64;
            let (uj, vj) = step.at(t);
            peak = peak.max(uj.abs());
            if v_prev * vj < 0.0 {
                let vel = |tau: f64| step.at(tau).1;
                if let Some(r) = brent_root(vel, t_prev, t, v_prev, vj, 1e-12 * h.max(1e-300)) {
                    peak = peak.max(step.at(r).0.abs());
                }
            }
            (t_prev, v_prev) = (t, vj);
            if j == m {
                (*u, *v) = (uj, vj);
            }
        }
    };
    let acc = record.accelerations();
    if record.t0() > 0.0 {
        advance(0.0, acc[0], record.t0(), &mut u, &mut v);
    }
    for k in 1..acc.len() {
        advance(acc[k - 1], acc[k], record.dt(), &mut u, &mut v);
        if k % 4096 == 0 && go_on().is_break() {
            return None;
        }
    }
    go_on().is_continue().then_some(peak)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fine-step integration of the same oscillator (classical Runge–Kutta, 200 steps per sample), which
    /// shares nothing with the closed form but the equation.
    fn rk4_peak(record: &Record, period: f64, zeta: f64) -> f64 {
        let w = 2.0 * PI / period;
        let f = |t: f64, y: [f64; 2]| [y[1], -record.at(t) - 2.0 * zeta * w * y[1] - w * w * y[0]];
        let n = (200.0 * record.duration() / record.dt()).round() as usize;
        let h = record.duration() / n as f64;
        let (mut y, mut peak) = ([0.0, 0.0], 0.0f64);
        for i in 0..n {
            let t = i as f64 * h;
            let k1 = f(t, y);
            let k2 = f(
                t + h / 2.0,
                [y[0] + h / 2.0 * k1[0], y[1] + h / 2.0 * k1[1]],
            );
            let k3 = f(
                t + h / 2.0,
                [y[0] + h / 2.0 * k2[0], y[1] + h / 2.0 * k2[1]],
            );
            let k4 = f(t + h, [y[0] + h * k3[0], y[1] + h * k3[1]]);
            for c in 0..2 {
                y[c] += h / 6.0 * (k1[c] + 2.0 * k2[c] + 2.0 * k3[c] + k4[c]);
            }
            peak = peak.max(y[0].abs());
        }
        peak
    }

    #[test]
    fn el_centro_matches_a_fine_step_integration() {
        let r = Record::el_centro_1940();
        for (t, z) in [(0.2, 0.05), (1.0, 0.02), (3.0, 0.0)] {
            let exact = peak_displacement(&r, t, z);
            let fine = rk4_peak(&r, t, z);
            // RK4 at dt/200 samples u every 1e-4 s: its peak is low by at most (w h)^2 / 8 relative.
            assert!(
                (exact - fine).abs() / exact < 2e-6,
                "T {t}: {exact} against {fine}"
            );
        }
    }

    #[test]
    fn el_centro_at_1_s_and_2_percent_is_the_textbook_value() {
        // Chopra, Dynamics of Structures, Fig. 6.4.1 / Example 6.3: D = 6.00 in = 0.1524 m (El Centro N-S,
        // Tn = 1 s, zeta = 2 %), read from a figure to about 1 %.
        let d = peak_displacement(&Record::el_centro_1940(), 1.0, 0.02);
        assert!((d - 0.1524).abs() < 0.01 * 0.1524, "{d}");
    }

    #[test]
    fn an_undamped_oscillator_under_a_constant_acceleration_reaches_twice_the_static_displacement()
    {
        // A step of a0 (after a short ramp): u = -(a0 / w^2) (1 - cos w t), so max |u| = 2 a0 / w^2.
        let a0 = 1.0;
        let r = Record::new("step", 1e-4, 1e-4, vec![a0; 20_001]).unwrap();
        let t = 0.5;
        let w = 2.0 * PI / t;
        let d = peak_displacement(&r, t, 0.0);
        // The 1e-4 s ramp shifts the response by at most a0 h^2 w^2 / 24 relative: far below 1e-6.
        assert!((d - 2.0 * a0 / (w * w)).abs() / d < 1e-6, "{d}");
    }

    #[test]
    fn a_sine_pulse_matches_its_closed_form() {
        // Undamped oscillator, half-sine ground acceleration a(t) = A sin(pi t / td) for t < td, then free
        // vibration; with w = 2 pi / T and W = pi / td (W != w), during the pulse
        // u(t) = -A / (w^2 - W^2) (sin W t - (W / w) sin w t). The peak over the pulse is checked against the
        // closed form maximised on a fine grid (and refined), the spectrum taken over the pulse only.
        let (amp, td, t_n) = (2.0f64, 0.5f64, 0.4f64);
        let dt = 1e-3f64;
        let n = (td / dt).round() as usize;
        let acc: Vec<f64> = (0..=n)
            .map(|k| amp * (PI * k as f64 * dt / td).sin())
            .collect();
        let r = Record::new("pulse", dt, 0.0, acc).unwrap();
        let (w, big_w) = (2.0 * PI / t_n, PI / td);
        let u = |t: f64| {
            -amp / (w * w - big_w * big_w) * ((big_w * t).sin() - big_w / w * (w * t).sin())
        };
        let exact = (0..=200_000)
            .map(|i| u(td * i as f64 / 200_000.0).abs())
            .fold(0.0, f64::max);
        let d = peak_displacement(&r, t_n, 0.0);
        // The record is the sine sampled every 1 ms and interpolated linearly: an error of order
        // (W dt)^2 / 8 = 2.5e-6 in the forcing.
        assert!((d - exact).abs() / exact < 1e-5, "{d} against {exact}");
    }

    #[test]
    fn bad_inputs_are_refused() {
        let r = Record::el_centro_1940();
        assert!(spectrum(&r, -0.01, &[1.0]).is_err());
        assert!(spectrum(&r, 1.0, &[1.0]).is_err());
        assert!(spectrum(&r, 0.05, &[]).is_err());
        assert!(spectrum(&r, 0.05, &[0.0]).is_err());
        let s = spectrum(&r, 0.05, &[0.5, 1.0]).unwrap();
        let w = 2.0 * PI / 0.5;
        assert_eq!(s.psa[0], w * w * s.sd[0]);
    }

    #[test]
    fn the_work_budget_refuses_before_and_the_callback_stops_within() {
        let r = Record::el_centro_1940();
        // El Centro: 1,559 samples at 0.02 s, first sample at t0 = 0.02 s. At T = 1e-3 s each step is cut in
        // ceil(8 x 0.02 / 1e-3) = 160: (1 + 1558) x 160 sub-steps a period.
        assert_eq!(work(&r, 1e-3), 1559.0 * 160.0);
        let default: Vec<f64> = (0..100)
            .map(|i| 0.02 * (500.0f64).powf(i as f64 / 99.0))
            .collect();
        // Python: sum(1559 * max(1, ceil(8 * 0.02 / T)) for the 100 periods) = 313359.
        let w: f64 = default.iter().map(|&t| work(&r, t)).sum();
        assert_eq!(w, 313359.0);
        let many = vec![1e-3; 2000];
        match spectrum(&r, 0.05, &many) {
            Err(Error::Choice { name, value, .. }) => {
                assert_eq!(name, "periods");
                assert!(value.contains("4.989e8 sub-steps"), "{value}");
            }
            other => panic!("{other:?}"),
        }
        // El Centro has fewer than 4096 steps: asked once, after the first period, and stopped there.
        let mut asked = 0;
        let stopped = spectrum_with(&r, 0.05, &[0.5, 1.0, 2.0], &mut || {
            asked += 1;
            ControlFlow::Break(())
        });
        assert_eq!(stopped, Err(Error::Interrupted { what: "spectrum" }));
        assert_eq!(asked, 1);
    }
}
