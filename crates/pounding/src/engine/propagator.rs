//! The propagator of a run: exact while every law is affine ([`Exact`]), the adaptive [`Stepper`]
//! otherwise; the two hand over at events.

use super::exact::Exact;
use super::System;
use crate::integrate::{Dense, Stepper, Tolerance};
use crate::Error;

crate::named! {
    /// How a run advances between events (`[analysis] propagation`).
    pub enum Propagation: "propagation" {
        /// Exactly while every law is affine (linear storeys, devices and isolators, a bilinear branch, an
        /// open contact or a closed Hooke or Kelvin–Voigt one) under one record or two on one grid;
        /// adaptive Runge–Kutta otherwise (the default).
        Exact = "exact",
        /// Adaptive Runge–Kutta throughout (Dormand–Prince, Rosenbrock on stiff stretches).
        Stepping = "stepping",
    }
}

// `named!` derives the enum's traits itself, so its default is written out.
#[allow(clippy::derivable_impls)]
impl Default for Propagation {
    fn default() -> Self {
        Propagation::Exact
    }
}

/// Both steppers and which one is in use.
pub(super) struct Propagator {
    dp: Stepper,
    exact: Option<Exact>,
    on_exact: bool,
    /// The exact stepper left a stretch to the Runge–Kutta stepper (not a whole record interval, in a
    /// configuration that takes only those), or its configuration waits to last ([`Exact::waiting`]): it
    /// is tried again at the next whole one.
    retry: bool,
}

impl Propagator {
    pub fn new(sys: &System, tol: Tolerance, how: Propagation) -> Self {
        let exact = match how {
            Propagation::Exact => Exact::new(sys, &tol),
            Propagation::Stepping => None,
        };
        Self {
            dp: Stepper::new(tol),
            exact,
            on_exact: false,
            retry: false,
        }
    }

    /// (Re)starts at `(t0, y0)`: exactly if the laws allow it now, else with trial step `h0`.
    pub fn reset(&mut self, sys: &System, t0: f64, y0: &[f64], h0: f64) {
        self.on_exact = self.exact.as_mut().is_some_and(|e| e.reset(sys, t0, y0));
        // A configuration left to the stepper until it lasts is tried again at each whole interval.
        self.retry = self.exact.as_ref().is_some_and(Exact::waiting);
        if !self.on_exact {
            self.dp.reset(sys, t0, y0, h0);
        }
    }

    /// The exact stepper, while it is the one in use.
    fn active(&self) -> Option<&Exact> {
        self.exact.as_ref().filter(|_| self.on_exact)
    }

    /// Whether the exact stepper is the one in use.
    pub fn is_exact(&self) -> bool {
        self.active().is_some()
    }

    pub fn t(&self) -> f64 {
        self.active().map_or_else(|| self.dp.t(), Exact::t)
    }
    pub fn y(&self) -> &[f64] {
        self.active().map_or_else(|| self.dp.y(), Exact::y)
    }
    pub fn dydt(&self) -> &[f64] {
        self.active().map_or_else(|| self.dp.dydt(), Exact::dydt)
    }
    pub fn dense(&self) -> &Dense {
        self.active().map_or_else(|| self.dp.dense(), Exact::dense)
    }
    /// The next trial step of the Runge–Kutta stepper, s; during an exact stretch, the exact step's length.
    pub fn h(&self) -> f64 {
        self.active()
            .map_or_else(|| self.dp.h(), Exact::last_length)
    }

    /// One step that never passes `t_stop`.
    pub fn step_until(&mut self, sys: &System, t_stop: f64) -> Result<(), Error> {
        let Some(e) = self.exact.as_mut() else {
            return self.dp.step_until(sys, t_stop);
        };
        if self.on_exact {
            if e.step_until(sys, t_stop) {
                return Ok(());
            }
            // Left to the Runge–Kutta stepper, from where the exact one stands.
            self.on_exact = false;
            self.retry = true;
            // A trial step of a few per interval: the last one (an impact's) may be far shorter than what
            // the free motion needs.
            let span = t_stop - e.t();
            let h0 = match self.dp.h() {
                h if h > 0.0 && h.is_finite() => h.max(span / 8.0).min(span),
                _ => span / 8.0,
            };
            self.dp.reset(sys, e.t(), e.y(), h0);
        } else if self.retry
            && e.is_interval(self.dp.t(), t_stop)
            && e.resume(sys, self.dp.t(), self.dp.y())
            && e.step_until(sys, t_stop)
        {
            // Back on the exact stepper at a whole interval; else the Runge–Kutta one goes on.
            self.on_exact = true;
            return Ok(());
        }
        self.dp.step_until(sys, t_stop)
    }

    /// The state at an event's time `te` inside the last step, which started at `(t0, y0)`, to `out`: on
    /// the exact solution, or from the Runge–Kutta step taken again to end at `te`. False when that step
    /// was refused and a shorter one taken instead (the event then lies beyond the step).
    pub fn settle_at(
        &mut self,
        sys: &System,
        (t0, y0): (f64, &[f64]),
        te: f64,
        out: &mut [f64],
    ) -> Result<bool, Error> {
        if self.is_exact() || te == self.t() || te <= t0 {
            self.state_at(sys, te, out);
            return Ok(true);
        }
        let reached = self.dp.redo_to(sys, (t0, y0), te)?;
        if reached {
            out.copy_from_slice(self.dp.y());
        }
        Ok(reached)
    }

    /// The state at `t` inside the last step (an event's).
    pub fn state_at(&mut self, sys: &System, t: f64, out: &mut [f64]) {
        match (&mut self.exact, self.on_exact) {
            (Some(e), true) => e.state_at(sys, t, out),
            _ => self.dp.dense().eval(t, out),
        }
    }

    /// Accepted and rejected steps (an exact step counts as one accepted).
    pub fn counts(&self) -> (usize, usize) {
        let (a, r) = self.dp.counts();
        (a + self.exact.as_ref().map_or(0, Exact::steps), r)
    }

    /// Work done, in explicit steps ([`Stepper::work`]; an exact step counts as one).
    pub fn work(&self) -> f64 {
        self.dp.work() + self.exact.as_ref().map_or(0, Exact::steps) as f64
    }
}
