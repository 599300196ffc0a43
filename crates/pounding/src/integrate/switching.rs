//! The stepper of a run: explicit Dormand–Prince while the motion sets the step, the linearly implicit
//! [`Rosenbrock`] while a stiff stretch holds the explicit step at its stability limit.
//!
//! Stiffness is detected as in Hairer's DOPRI5 ([`DormandPrince::looks_stiff`]); a stiff stretch is taken
//! implicitly for [`STIFF_RETRY`] steps, then the explicit stepper is tried again (its test costs about 20
//! steps), so that a stretch that has ended does not keep the run on the order-2 formula. Systems of more
//! than [`MAX_IMPLICIT_DIM`] states stay explicit: a difference Jacobian and a dense factorisation per step
//! would cost more there than the small steps they save.

use super::{Dense, DormandPrince, OdeSystem, Rosenbrock, Tolerance};
use crate::Error;

/// Largest number of states taken implicitly in a stiff stretch.
pub const MAX_IMPLICIT_DIM: usize = 128;
/// Implicit steps after which the explicit stepper is tried again.
pub const STIFF_RETRY: usize = 200;
/// The implicit stepper's tolerances, as a fraction of the run's. Dormand–Prince advances its order-5
/// solution and controls the error of the order-4 one, so its actual error is well below the tolerance; the
/// implicit formula advances the order-2 solution whose error it controls. At a tenth of the tolerance the
/// stiff stretches keep the run's energy balance at the level of the explicit ones (measured on two floors
/// pressed by a contact of 1e14 N/m, `docs/reliability.md`: 1.8e-6 at the run's tolerance 1e-7, 7.4e-7 at a
/// tenth, for 20 % more steps).
pub const IMPLICIT_TOLERANCE: f64 = 0.1;

/// An adaptive stepper that switches between [`DormandPrince`] and [`Rosenbrock`] (see the module).
/// Working memory is allocated once, in [`Stepper::new`].
#[derive(Debug)]
pub struct Stepper {
    explicit: DormandPrince,
    implicit: Option<Rosenbrock>,
    /// The stiff stretch being taken implicitly, if any.
    stretch: Option<Stretch>,
    /// Explicit steps (accepted and rejected) before which no stretch may start, and the wait set after a
    /// stretch that did not pay.
    wait_until: usize,
    wait: usize,
}

/// A stretch taken implicitly: where it started, and the explicit step it replaces.
#[derive(Clone, Copy, Debug)]
struct Stretch {
    steps: usize,
    t0: f64,
    work0: f64,
    h_explicit: f64,
}

/// Implicit steps after which a stretch is judged: it goes on only while it advances faster, per unit of
/// work, than the explicit step it replaced.
const JUDGED_AFTER: usize = 20;
/// Explicit steps to wait after a stretch that did not pay (doubled after each further one, until one pays).
const FIRST_WAIT: usize = 1000;

impl Stepper {
    /// A stepper for a system of `tol.atol.len()` components.
    pub fn new(tol: Tolerance) -> Self {
        let implicit = (tol.atol.len() <= MAX_IMPLICIT_DIM).then(|| {
            Rosenbrock::new(Tolerance {
                rtol: IMPLICIT_TOLERANCE * tol.rtol,
                atol: tol.atol.iter().map(|a| IMPLICIT_TOLERANCE * a).collect(),
                quiet: tol.quiet.clone(),
                absolute: tol.absolute.clone(),
            })
        });
        Self {
            explicit: DormandPrince::new(tol),
            implicit,
            stretch: None,
            wait_until: 0,
            wait: FIRST_WAIT,
        }
    }

    fn active_implicit(&self) -> Option<&Rosenbrock> {
        self.stretch.and(self.implicit.as_ref())
    }

    /// (Re)starts integration at `(t0, y0)` with first trial step `h0`, with the stepper in use.
    pub fn reset<S: OdeSystem>(&mut self, sys: &S, t0: f64, y0: &[f64], h0: f64) {
        match (self.stretch, self.implicit.as_mut()) {
            (Some(_), Some(r)) => r.reset(sys, t0, y0, h0),
            _ => self.explicit.reset(sys, t0, y0, h0),
        }
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.active_implicit()
            .map_or(self.explicit.t(), Rosenbrock::t)
    }

    /// Current state.
    pub fn y(&self) -> &[f64] {
        self.active_implicit()
            .map_or(self.explicit.y(), Rosenbrock::y)
    }

    /// Trial size of the next step.
    pub fn h(&self) -> f64 {
        self.active_implicit()
            .map_or(self.explicit.h(), Rosenbrock::h)
    }

    /// `f(t, y)` of the current state.
    pub fn dydt(&self) -> &[f64] {
        self.active_implicit()
            .map_or(self.explicit.dydt(), Rosenbrock::dydt)
    }

    /// The interpolant of the last accepted step.
    pub fn dense(&self) -> &Dense {
        self.active_implicit()
            .map_or(self.explicit.dense(), Rosenbrock::dense)
    }

    /// Number of accepted and rejected steps since construction, both steppers together.
    pub fn counts(&self) -> (usize, usize) {
        let (a, r) = self.explicit.counts();
        let (ai, ri) = self.implicit.as_ref().map_or((0, 0), Rosenbrock::counts);
        (a + ai, r + ri)
    }

    /// The work done so far in explicit steps (accepted and rejected): an implicit step counts as
    /// `implicit_step_cost` of them.
    pub fn work(&self) -> f64 {
        let (explicit, implicit) = self.attempts();
        let n = self.explicit.y().len() as f64;
        explicit as f64 + implicit as f64 * implicit_step_cost(n)
    }

    /// Steps attempted (accepted and rejected) by the explicit and by the implicit stepper.
    fn attempts(&self) -> (usize, usize) {
        let (a, r) = self.explicit.counts();
        let (ai, ri) = self.implicit.as_ref().map_or((0, 0), Rosenbrock::counts);
        (a + r, ai + ri)
    }

    /// Takes one accepted step that never passes `t_stop` (see [`DormandPrince::step_until`]), switching
    /// stepper first when the last steps call for it.
    pub fn step_until<S: OdeSystem>(&mut self, sys: &S, t_stop: f64) -> Result<(), Error> {
        self.switch(sys);
        match (self.stretch.as_mut(), self.implicit.as_mut()) {
            (Some(stretch), Some(r)) => {
                stretch.steps += 1;
                r.step_until(sys, t_stop)
            }
            _ => self.explicit.step_until(sys, t_stop),
        }
    }

    /// Takes the step from `(t0, y0)` to `t1` again with the stepper in use, and says whether it was
    /// accepted (else a shorter one was taken). An event's state then comes from a step that ends at it,
    /// held to the tolerance, not from the interpolant of a longer step (whose error nothing controls).
    pub fn redo_to<S: OdeSystem>(
        &mut self,
        sys: &S,
        (t0, y0): (f64, &[f64]),
        t1: f64,
    ) -> Result<bool, Error> {
        match (self.stretch, self.implicit.as_mut()) {
            (Some(_), Some(r)) => {
                r.reset(sys, t0, y0, t1 - t0);
                r.step_until(sys, t1)?;
                Ok(r.t() == t1)
            }
            _ => {
                if !self.explicit.restart_last(t0, y0, t1 - t0) {
                    self.explicit.reset(sys, t0, y0, t1 - t0);
                }
                self.explicit.step_until(sys, t1)?;
                Ok(self.explicit.t() == t1)
            }
        }
    }

    /// Starts a stretch when the explicit steps look stiff, and ends one after [`STIFF_RETRY`] steps, or
    /// after [`JUDGED_AFTER`] when it advances slower per unit of work than the explicit step it replaced
    /// (then no stretch starts for a while).
    fn switch<S: OdeSystem>(&mut self, sys: &S) {
        let work = self.work();
        let explicit_steps = self.attempts().0;
        let Some(r) = self.implicit.as_mut() else {
            return;
        };
        match self.stretch {
            None if self.explicit.looks_stiff() && explicit_steps >= self.wait_until => {
                let e = &self.explicit;
                r.reset(sys, e.t(), e.y(), e.h());
                self.stretch = Some(Stretch {
                    steps: 0,
                    t0: e.t(),
                    work0: work,
                    h_explicit: e.dense().t1() - e.dense().t0(),
                });
                self.explicit.clear_stiffness();
            }
            Some(s) if s.steps >= STIFF_RETRY || s.steps == JUDGED_AFTER => {
                let pays = (r.t() - s.t0) / (work - s.work0) > s.h_explicit;
                if s.steps >= STIFF_RETRY || !pays {
                    self.explicit.reset(sys, r.t(), r.y(), r.h());
                    self.explicit.clear_stiffness();
                    self.stretch = None;
                }
                if pays {
                    self.wait = FIRST_WAIT;
                } else {
                    self.wait_until = explicit_steps + self.wait;
                    self.wait = self.wait.saturating_mul(2);
                }
            }
            _ => {}
        }
    }
}

/// The cost of an implicit step of `n` states in explicit steps: its `n + 3` evaluations of the right-hand side
/// against the explicit step's 6, its factorisation (`n^3 / 3` multiply-adds, fast against an evaluation) and
/// one for its solves. Measured on a chain of springs with a cheap right-hand side (the ratio of an implicit
/// to an explicit step): 2.9 at 8 states (formula 2.9), 9.0 at 32 (6.8), 17 at 64 (18), 42 at 128 (49).
fn implicit_step_cost(n: f64) -> f64 {
    1.0 + (n + 3.0) / 6.0 + n * n * n / (600.0 * (n + 8.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `u'' + c u' + k u = 0`: with c = 2e6 /s and k = 1e9 /s^2 (zeta about 32) the slow mode decays at about
    /// k / c = 500 /s and the fast one at 2e6 /s; with c = 0.1, k = 1 an ordinary oscillator.
    struct Oscillator {
        c: f64,
        k: f64,
    }
    impl OdeSystem for Oscillator {
        fn dim(&self) -> usize {
            2
        }
        fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = y[1];
            dy[1] = -self.c * y[1] - self.k * y[0];
        }
    }

    /// Runs from u = 1e-3 at rest to `t_end`; returns the worst error against the exact solution at the step
    /// ends and the stepper.
    fn run(sys: &Oscillator, t_end: f64, rtol: f64) -> (f64, Stepper) {
        let (u0, c, k) = (1e-3, sys.c, sys.k);
        let exact = |t: f64| {
            let disc = c * c - 4.0 * k;
            if disc > 0.0 {
                let (l1, l2) = (0.5 * (-c + disc.sqrt()), 0.5 * (-c - disc.sqrt()));
                let a = -l2 * u0 / (l1 - l2);
                a * (l1 * t).exp() + (u0 - a) * (l2 * t).exp()
            } else {
                let (s, w) = (-0.5 * c, 0.5 * (-disc).sqrt());
                (s * t).exp() * u0 * ((w * t).cos() - s / w * (w * t).sin())
            }
        };
        let mut st = Stepper::new(Tolerance::new(rtol, vec![rtol * u0, rtol * u0 * k.sqrt()]));
        st.reset(sys, 0.0, &[u0, 0.0], 1e-9);
        let mut worst: f64 = 0.0;
        while st.t() < t_end {
            st.step_until(sys, t_end).unwrap();
            worst = worst.max((st.y()[0] - exact(st.t())).abs() / u0);
        }
        (worst, st)
    }

    #[test]
    fn a_stiff_stretch_is_taken_implicitly_and_stays_accurate() {
        let sys = Oscillator { c: 2e6, k: 1e9 };
        let (worst, st) = run(&sys, 0.05, 1e-7);
        // A modest multiple of the tolerance, as for the explicit stepper alone.
        assert!(worst < 100.0 * 1e-7, "error {worst}");
        // Explicit steps alone need about 0.05 * 2e6 / 3.3 = 30,000.
        let (accepted, rejected) = st.counts();
        assert!(accepted + rejected < 3_000, "{accepted} + {rejected} steps");
        assert!(st.implicit.as_ref().unwrap().counts().0 > 0);
    }

    #[test]
    fn an_ordinary_oscillation_stays_explicit() {
        let sys = Oscillator { c: 0.1, k: 1.0 };
        let (worst, st) = run(&sys, 20.0, 1e-9);
        assert!(worst < 100.0 * 1e-9, "error {worst}");
        assert_eq!(st.implicit.as_ref().unwrap().counts(), (0, 0));
    }
}
