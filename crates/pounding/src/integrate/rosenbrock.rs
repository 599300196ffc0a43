//! An L-stable linearly implicit stepper for stiff stretches of a run.
//!
//! The modified Rosenbrock formula of Shampine & Reichelt (1997), *The MATLAB ODE suite*, SIAM J. Sci.
//! Comput. 18(1), section 3.1 (MATLAB's `ode23s`): order 2, L-stable, with an order-3 error estimate that
//! reuses the first evaluation of the next step. With `W = I - h d J`, `d = 1 / (2 + sqrt 2)`,
//! `J = df/dy`, `T = df/dt`:
//!
//! ```text
//! F0 = f(t0, y0)                 k1 = W^-1 (F0 + h d T)
//! F1 = f(t0 + h/2, y0 + h k1/2)  k2 = W^-1 (F1 - k1) + k1
//! y1 = y0 + h k2                 F2 = f(t0 + h, y1)
//! k3 = W^-1 (F2 - e32 (k2 - F1) - 2 (k1 - F0) + h d T),  e32 = 6 + sqrt 2
//! error = h (k1 - 2 k2 + k3) / 6
//! ```
//!
//! `J` and `T` are forward differences, one evaluation per state component. A stiff stretch is one where an
//! explicit step is held to a tiny size by a fast, strongly damped mode the motion does not follow (a very
//! stiff contact with its law's large approach damping under sustained load): this step takes the slow
//! motion at the size its accuracy needs. Interpolation between steps is the formula's own quadratic
//! (order 2), in the same form as the explicit stepper's.

use super::lu;
use super::{Dense, OdeSystem, Tolerance};
use crate::Error;

/// The increment of a state in its difference quotient, relative to the larger of the state and its scale
/// (`atol / rtol`). Far below the textbook `sqrt(eps)`: the laws see the states through differences
/// (deformations, penetrations) many orders of magnitude smaller than the states, and the increment must be
/// small against those. The rounding of such a difference is `eps |y|`, so this leaves a relative error of
/// about `eps / 1e-12 = 2e-4` in a derivative. (`sqrt(eps)` made a damper in series with a spring of 1e13 N/m
/// take steps of 5e-10 s on a Jacobian 3 % wrong.)
const JACOBIAN_INCREMENT: f64 = 1e-12;
/// `d = 1 / (2 + sqrt 2)`.
const D: f64 = 0.292_893_218_813_452_5;
/// `e32 = 6 + sqrt 2`.
const E32: f64 = 7.414_213_562_373_095;

/// An adaptive linearly implicit stepper (see the module). Working memory is allocated once, in
/// [`Rosenbrock::new`]; stepping allocates nothing.
#[derive(Debug)]
pub struct Rosenbrock {
    n: usize,
    controlled: usize,
    tol: Tolerance,
    /// Each component's relative tolerance ([`Tolerance::relative`]).
    rel: Vec<f64>,
    t: f64,
    h: f64,
    y: Vec<f64>,
    ynew: Vec<f64>,
    ytmp: Vec<f64>,
    /// `f` at the current state, then at the end of a trial step (swapped on acceptance).
    f0: Vec<f64>,
    f1: Vec<f64>,
    f2: Vec<f64>,
    dfdt: Vec<f64>,
    k: [Vec<f64>; 3],
    /// `J` (row-major), computed once per step start and kept through rejections.
    jac: Vec<f64>,
    w: Vec<f64>,
    piv: Vec<usize>,
    dense: Dense,
    accepted: usize,
    rejected: usize,
}

impl Rosenbrock {
    /// A stepper for a system of `tol.atol.len()` components.
    pub fn new(tol: Tolerance) -> Self {
        let n = tol.atol.len();
        let controlled = tol.atol.iter().filter(|a| a.is_finite()).count().max(1);
        let v = || vec![0.0; n];
        Self {
            n,
            controlled,
            rel: tol.relative(),
            tol,
            t: 0.0,
            h: 0.0,
            y: v(),
            ynew: v(),
            ytmp: v(),
            f0: v(),
            f1: v(),
            f2: v(),
            dfdt: v(),
            k: [v(), v(), v()],
            jac: vec![0.0; n * n],
            w: vec![0.0; n * n],
            piv: vec![0; n],
            dense: Dense::zeros(n),
            accepted: 0,
            rejected: 0,
        }
    }

    /// (Re)starts integration at `(t0, y0)` with first trial step `h0`.
    pub fn reset<S: OdeSystem>(&mut self, sys: &S, t0: f64, y0: &[f64], h0: f64) {
        self.t = t0;
        self.y.copy_from_slice(y0);
        self.h = h0;
        sys.rhs(t0, &self.y, &mut self.f0);
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Current state.
    pub fn y(&self) -> &[f64] {
        &self.y
    }

    /// Trial size of the next step.
    pub fn h(&self) -> f64 {
        self.h
    }

    /// `f(t, y)` of the current state.
    pub fn dydt(&self) -> &[f64] {
        &self.f0
    }

    /// The interpolant of the last accepted step.
    pub fn dense(&self) -> &Dense {
        &self.dense
    }

    /// Number of accepted and rejected steps since construction.
    pub fn counts(&self) -> (usize, usize) {
        (self.accepted, self.rejected)
    }

    /// Forward-difference `J = df/dy` and `T = df/dt` at the current state; `h` bounds the time increment
    /// so that it stays inside the coming step (a record's kink is never crossed).
    fn jacobian<S: OdeSystem>(&mut self, sys: &S, h: f64) {
        let (n, t) = (self.n, self.t);
        self.ytmp.copy_from_slice(&self.y);
        for j in 0..n {
            // The increment: relative to the component, or to its scale where it is near 0.
            let atol = self.tol.atol[j];
            let typical = if atol.is_finite() && self.tol.rtol > 0.0 {
                atol / self.tol.rtol
            } else {
                1.0
            };
            let yj = self.y[j];
            let mut dj = JACOBIAN_INCREMENT * yj.abs().max(typical);
            // The increment as represented (so that the quotient uses the step actually taken).
            dj = (yj + dj) - yj;
            if dj == 0.0 {
                dj = f64::MIN_POSITIVE.sqrt();
            }
            self.ytmp[j] = yj + dj;
            sys.rhs(t, &self.ytmp, &mut self.f1);
            self.ytmp[j] = yj;
            for i in 0..n {
                self.jac[i * n + j] = (self.f1[i] - self.f0[i]) / dj;
            }
        }
        let dt = (f64::EPSILON.sqrt() * t.abs().max(h)).min(0.5 * h);
        let dt = (t + dt) - t;
        sys.rhs(t + dt, &self.y, &mut self.f1);
        for i in 0..n {
            self.dfdt[i] = (self.f1[i] - self.f0[i]) / dt;
        }
    }

    /// Never steps past `t_stop` (see [`super::DormandPrince::step_until`]); the step size proposed before a
    /// cut is kept for the next step.
    pub fn step_until<S: OdeSystem>(&mut self, sys: &S, t_stop: f64) -> Result<(), Error> {
        let (t, n) = (self.t, self.n);
        let h_wanted = self.h;
        // J and T at the step's start, kept through rejections.
        let mut have_jacobian = false;
        loop {
            let cut = t + 1.01 * self.h >= t_stop;
            let h = if cut { t_stop - t } else { self.h };
            if !(h.is_finite() && h > 0.0) || t + h == t {
                return Err(Error::StepSizeUnderflow { t });
            }
            if !have_jacobian {
                self.jacobian(sys, h);
                have_jacobian = true;
            }
            for (i, w) in self.w.iter_mut().enumerate() {
                let diag = if i % (n + 1) == 0 { 1.0 } else { 0.0 };
                *w = diag - h * D * self.jac[i];
            }
            if !lu::factor(&mut self.w, &mut self.piv, n) {
                self.rejected += 1;
                self.h = 0.5 * h;
                continue;
            }
            let hd = h * D;
            let [k1, k2, k3] = &mut self.k;
            for ((k, f), dt) in k1.iter_mut().zip(&self.f0).zip(&self.dfdt) {
                *k = f + hd * dt;
            }
            lu::solve(&self.w, &self.piv, k1);
            for ((z, y), k) in self.ytmp.iter_mut().zip(&self.y).zip(k1.iter()) {
                *z = y + 0.5 * h * k;
            }
            sys.rhs(t + 0.5 * h, &self.ytmp, &mut self.f1);
            for i in 0..n {
                k2[i] = self.f1[i] - k1[i];
            }
            lu::solve(&self.w, &self.piv, k2);
            for i in 0..n {
                k2[i] += k1[i];
                self.ynew[i] = self.y[i] + h * k2[i];
            }
            sys.rhs(t + h, &self.ynew, &mut self.f2);
            for i in 0..n {
                k3[i] = self.f2[i] - E32 * (k2[i] - self.f1[i]) - 2.0 * (k1[i] - self.f0[i])
                    + hd * self.dfdt[i];
            }
            lu::solve(&self.w, &self.piv, k3);
            let mut err = 0.0;
            for i in 0..n {
                let e = h / 6.0 * (k1[i] - 2.0 * k2[i] + k3[i]);
                let sc = self.tol.atol[i] + self.rel[i] * self.y[i].abs().max(self.ynew[i].abs());
                err += (e / sc) * (e / sc);
            }
            let counted = if self.tol.quiet.is_empty() {
                self.controlled
            } else {
                self.tol
                    .counted(self.controlled, &self.y, &[&k1[..], &k2[..], &k3[..]])
            };
            let err = (err / counted as f64).sqrt();
            if !err.is_finite() {
                self.rejected += 1;
                self.h = 0.2 * h;
                continue;
            }
            // Exponent 1/3 for the order-3 error estimate, safety 0.9.
            let fac = if err == 0.0 {
                5.0
            } else {
                (0.9 * err.powf(-1.0 / 3.0)).clamp(0.2, 5.0)
            };
            if err > 1.0 {
                self.rejected += 1;
                self.h = h * fac.min(1.0);
                continue;
            }
            // The formula's own quadratic (Shampine & Reichelt, eq. 3.2), in the explicit stepper's form:
            // y0 + h [s (1 - s) k1 + s (s - 2d) k2] / (1 - 2d). It is built from the filtered k1, k2: a cubic
            // Hermite of the end rates would carry lambda times the states' tiny distance from the slow motion.
            let d = &mut self.dense;
            d.t0 = t;
            d.h = h;
            let (k1, k2) = (&self.k[0], &self.k[1]);
            for i in 0..n {
                d.r[0][i] = self.y[i];
                d.r[1][i] = self.ynew[i] - self.y[i];
                d.r[2][i] = -h * (k2[i] - k1[i]) / (1.0 - 2.0 * D);
                d.r[3][i] = 0.0;
                d.r[4][i] = 0.0;
            }
            self.t = if cut { t_stop } else { t + h };
            std::mem::swap(&mut self.y, &mut self.ynew);
            std::mem::swap(&mut self.f0, &mut self.f2);
            self.h = h * fac;
            if cut {
                self.h = self.h.max(h_wanted);
            }
            self.accepted += 1;
            return Ok(());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Prothero–Robinson: y' = lambda (y - sin t) + cos t, exact solution sin t from y(0) = 0, stiff for
    /// large -lambda.
    struct ProtheroRobinson(f64);
    impl OdeSystem for ProtheroRobinson {
        fn dim(&self) -> usize {
            1
        }
        fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = self.0 * (y[0] - t.sin()) + t.cos();
        }
    }

    /// A stiff damped oscillator, u'' + c u' + k u = 0 with c = 2e6 /s and k = 1e9 /s^2 (zeta about 32, as a
    /// very stiff contact's approach): the slow mode decays at about k / c = 500 /s, the fast one at 2e6 /s.
    struct Overdamped;
    const C: f64 = 2e6;
    const K: f64 = 1e9;
    impl OdeSystem for Overdamped {
        fn dim(&self) -> usize {
            2
        }
        fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = y[1];
            dy[1] = -C * y[1] - K * y[0];
        }
    }

    fn fixed_step_error(h: f64) -> f64 {
        // A huge tolerance accepts every step: the error of fixed steps of h, at t = 1.
        let sys = ProtheroRobinson(-1.0);
        let mut r = Rosenbrock::new(Tolerance::new(1e3, vec![1e3]));
        r.reset(&sys, 0.0, &[0.0], h);
        while r.t() < 1.0 - 1e-12 {
            r.step_until(&sys, 1.0).unwrap();
            r.h = h;
        }
        (r.y()[0] - 1f64.sin()).abs()
    }

    #[test]
    fn the_formula_is_second_order() {
        // Halving a fixed step divides the global error by about 4.
        let ratio = fixed_step_error(0.02) / fixed_step_error(0.01);
        assert!(ratio > 3.6 && ratio < 4.4, "ratio {ratio}");
    }

    #[test]
    fn a_very_stiff_problem_is_followed_with_large_steps() {
        // lambda = -1e8: an explicit step would need h < 3e-8; the exact solution is smooth.
        let sys = ProtheroRobinson(-1e8);
        let mut r = Rosenbrock::new(Tolerance::new(1e-8, vec![1e-8]));
        r.reset(&sys, 0.0, &[0.0], 1e-6);
        let mut worst: f64 = 0.0;
        let mut out = [0.0];
        while r.t() < 2.0 {
            r.step_until(&sys, 2.0).unwrap();
            let d = r.dense();
            let tm = 0.5 * (d.t0() + d.t1());
            d.eval(tm, &mut out);
            worst = worst.max((r.y()[0] - r.t().sin()).abs());
            worst = worst.max((out[0] - tm.sin()).abs());
        }
        let (accepted, rejected) = r.counts();
        assert!(worst < 1e-6, "error {worst}");
        assert!(
            accepted + rejected < 20_000,
            "{accepted} + {rejected} steps"
        );
    }

    #[test]
    fn the_slow_mode_of_a_stiff_overdamped_oscillator_is_exact_to_tolerance() {
        // Exact solution from u(0) = 1e-3, u'(0) = 0: a sum of two exponentials.
        let disc = (C * C - 4.0 * K).sqrt();
        let (l1, l2) = (0.5 * (-C + disc), 0.5 * (-C - disc));
        let (u0, v0) = (1e-3, 0.0);
        let a = (v0 - l2 * u0) / (l1 - l2);
        let b = u0 - a;
        let exact = |t: f64| a * (l1 * t).exp() + b * (l2 * t).exp();
        let mut r = Rosenbrock::new(Tolerance::new(1e-7, vec![1e-7 * u0, 1e-7 * u0 * 500.0]));
        r.reset(&Overdamped, 0.0, &[u0, v0], 1e-9);
        let mut worst: f64 = 0.0;
        while r.t() < 0.05 {
            r.step_until(&Overdamped, 0.05).unwrap();
            worst = worst.max((r.y()[0] - exact(r.t())).abs());
        }
        let (accepted, rejected) = r.counts();
        assert!(worst < 1e-5 * u0, "error {worst}");
        // An explicit step would need about 0.05 * 2e6 / 3.3 = 30,000 steps.
        assert!(accepted + rejected < 3_000, "{accepted} + {rejected} steps");
    }
}
