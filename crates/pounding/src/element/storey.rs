//! Storeys: the shear force of one storey as a function of its drift history
//! (`docs/structures.md`).
//!
//! The drift `x` (m) of storey `j` is `u_j - u_{j-1}`; its force `F` (N) is the restoring force of the
//! storey's law. Rayleigh damping on the initial stiffness (`C = a0 M + a1 K_0`, OpenSees' `betaKinit`) adds
//! the viscous force `a1 k x'` of each storey; the mass-proportional part acts between each floor and the
//! ground and belongs to the structure, not to the storey.

use crate::element::{Event, RateGate};
use crate::error::check;
use crate::Error;

/// The force–drift law of one storey.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub enum StoreyLaw {
    /// `F = k x`.
    Linear,
    /// Bilinear with kinematic hardening: initial stiffness `k`, yield force `F_y` (N), post-yield stiffness
    /// `a k`. The elastic range has width `2 F_y` and moves with the back-force; `a = 0` is
    /// elastic–perfectly-plastic. Equal to OpenSees `Steel01(E0 = k, Fy, b = a)` without isotropic hardening.
    Bilinear {
        /// Storey shear at first yield, N.
        yield_force: f64,
        /// Post-yield over initial stiffness `a`, in [0, 1).
        post_yield_ratio: f64,
    },
    /// Bouc–Wen (Wen 1976, normalised form, `A = 1`): `F = a k x + (1 - a) F_y z`,
    /// `z' = (x' - beta |x'| |z|^(n-1) z - gamma x' |z|^n) / d_y`, `d_y = F_y / k`.
    BoucWen {
        /// Yield force `F_y`, N (the asymptotic hysteretic force when `beta + gamma = 1`).
        yield_force: f64,
        /// Post-yield over initial stiffness `a`, in [0, 1).
        post_yield_ratio: f64,
        /// Exponent `n` (>= 1; larger is sharper).
        n: f64,
        /// `beta` (dimensionless).
        beta: f64,
        /// `gamma` (dimensionless).
        gamma: f64,
    },
}

impl StoreyLaw {
    /// A validated bilinear law: `yield_force > 0` (N), `post_yield_ratio` in [0, 1).
    pub fn bilinear(yield_force: f64, post_yield_ratio: f64) -> Result<Self, Error> {
        Ok(StoreyLaw::Bilinear {
            yield_force: check_yield(yield_force)?,
            post_yield_ratio: check_ratio(post_yield_ratio)?,
        })
    }

    /// A validated Bouc–Wen law: `yield_force > 0` (N), `post_yield_ratio` in [0, 1), `n >= 1`, and
    /// `beta >= 0` with `beta + gamma > 0`, which keeps `|z|` bounded by `(1 / (beta + gamma))^(1/n)` (with
    /// `A = 1`: loading drives `z` towards that bound, and unloading never drives it away from 0 only when
    /// `beta >= 0`). The range of docs/structures.md (`beta, gamma >= 0`) is inside this one.
    pub fn bouc_wen(
        yield_force: f64,
        post_yield_ratio: f64,
        n: f64,
        beta: f64,
        gamma: f64,
    ) -> Result<Self, Error> {
        check(
            "bouc_wen.n",
            n,
            (1.0..=100.0).contains(&n),
            "1 <= n <= 100 (n < 1 makes z' non-Lipschitz at z = 0)",
        )?;
        check(
            "bouc_wen.beta",
            beta,
            beta >= 0.0,
            "beta >= 0 (beta < 0 lets |z| grow without bound on unloading)",
        )?;
        check(
            "bouc_wen.gamma",
            gamma,
            beta + gamma > 0.0,
            "beta + gamma > 0 (otherwise |z| grows without bound on loading)",
        )?;
        Ok(StoreyLaw::BoucWen {
            yield_force: check_yield(yield_force)?,
            post_yield_ratio: check_ratio(post_yield_ratio)?,
            n,
            beta,
            gamma,
        })
    }

    /// Yield force, N (`None` for a linear storey).
    pub fn yield_force(&self) -> Option<f64> {
        match *self {
            StoreyLaw::Linear => None,
            StoreyLaw::Bilinear { yield_force, .. } | StoreyLaw::BoucWen { yield_force, .. } => {
                Some(yield_force)
            }
        }
    }

    /// Whether the law dissipates energy by hysteresis.
    pub fn is_inelastic(&self) -> bool {
        !matches!(self, StoreyLaw::Linear)
    }

    /// Short name: `linear`, `bilinear`, `bouc-wen`.
    pub fn name(&self) -> &'static str {
        match self {
            StoreyLaw::Linear => "linear",
            StoreyLaw::Bilinear { .. } => "bilinear",
            StoreyLaw::BoucWen { .. } => "bouc-wen",
        }
    }
}

fn check_yield(f: f64) -> Result<f64, Error> {
    check("yield_forces", f, f > 0.0, "yield_forces > 0 (N)")
}

fn check_ratio(a: f64) -> Result<f64, Error> {
    check(
        "post_yield_ratio",
        a,
        (0.0..1.0).contains(&a),
        "0 <= post_yield_ratio < 1",
    )
}

/// The phase of a storey: plain data, changed only at events.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StoreyState {
    /// A linear storey.
    Linear,
    /// Bilinear, elastic: `F = f0 + k (x - x0)` inside `[centre - F_y, centre + F_y]`.
    Elastic {
        /// Drift at the anchor, m.
        x0: f64,
        /// Force at the anchor, N.
        f0: f64,
        /// Centre of the elastic range (the back-force), N.
        centre: f64,
        /// Hysteretic energy dissipated so far, J.
        dissipated: f64,
    },
    /// Bilinear, on the post-yield branch in direction `sign`: `F = f0 + a k (x - x0)`.
    Yielding {
        /// +1 loading towards positive drift, -1 towards negative.
        sign: f64,
        /// Drift at yield, m.
        x0: f64,
        /// Force at yield, N.
        f0: f64,
        /// Hysteretic energy dissipated before this branch, J.
        dissipated: f64,
    },
    /// Bouc–Wen: the sign of the drift rate (so that `|x'| = sign x'` between reversals and the
    /// right-hand side is smooth).
    BoucWen {
        /// +1 or -1.
        sign: f64,
    },
}

/// A storey element: initial stiffness, law, stiffness-proportional damping and phase.
#[derive(Clone, Debug)]
pub struct Storey {
    k: f64,
    law: StoreyLaw,
    c: f64,
    state: StoreyState,
    pub(super) gate: RateGate,
}

impl Storey {
    /// A storey of initial stiffness `k` (N/m) with `law`, at rest, and viscous coefficient `c` (N s/m) on
    /// its drift rate (`a1 k` for Rayleigh damping on the initial stiffness).
    pub fn new(k: f64, law: StoreyLaw, c: f64) -> Self {
        let state = match law {
            StoreyLaw::Linear => StoreyState::Linear,
            StoreyLaw::Bilinear { .. } => StoreyState::Elastic {
                x0: 0.0,
                f0: 0.0,
                centre: 0.0,
                dissipated: 0.0,
            },
            StoreyLaw::BoucWen { .. } => StoreyState::BoucWen { sign: 1.0 },
        };
        Self {
            k,
            law,
            c,
            state,
            gate: RateGate::default(),
        }
    }

    /// The reversal's event function without its slack ([`RateGate`]): the drift rate in the phase's
    /// direction, m/s.
    pub(super) fn rate_event(&self, v: f64) -> Option<f64> {
        match self.state {
            StoreyState::Yielding { sign, .. } | StoreyState::BoucWen { sign } => Some(sign * v),
            _ => None,
        }
    }

    /// Initial stiffness, N/m.
    pub fn stiffness(&self) -> f64 {
        self.k
    }
    /// The law.
    pub fn law(&self) -> StoreyLaw {
        self.law
    }
    /// The phase.
    pub fn state(&self) -> StoreyState {
        self.state
    }
    /// Yield drift `F_y / k`, m (`None` for a linear storey).
    pub fn yield_drift(&self) -> Option<f64> {
        self.law.yield_force().map(|f| f / self.k)
    }

    /// Extra ODE states: Bouc–Wen's `z` and the work of its hysteretic part, `int (1 - a) F_y z x' dt` (J).
    pub fn states(&self) -> usize {
        match self.law {
            StoreyLaw::BoucWen { .. } => 2,
            _ => 0,
        }
    }

    /// Restoring force, N, at drift `x` (m) with states `s`.
    #[inline]
    pub fn force(&self, x: f64, s: &[f64]) -> f64 {
        match (self.law, self.state) {
            (StoreyLaw::Bilinear { .. }, StoreyState::Elastic { x0, f0, .. }) => {
                f0 + self.k * (x - x0)
            }
            (
                StoreyLaw::Bilinear {
                    post_yield_ratio: a,
                    ..
                },
                StoreyState::Yielding { x0, f0, .. },
            ) => f0 + a * self.k * (x - x0),
            (
                StoreyLaw::BoucWen {
                    yield_force,
                    post_yield_ratio: a,
                    ..
                },
                _,
            ) => a * self.k * x + (1.0 - a) * yield_force * s[0],
            _ => self.k * x,
        }
    }

    /// Restoring and viscous force, N; the rates of `z` and of the hysteretic work go to `ds`.
    #[inline]
    pub fn evaluate(&self, x: f64, v: f64, s: &[f64], ds: &mut [f64]) -> (f64, f64) {
        let fv = self.c * v;
        if let (
            StoreyLaw::BoucWen {
                yield_force,
                post_yield_ratio: a,
                n,
                beta,
                gamma,
            },
            StoreyState::BoucWen { sign },
        ) = (self.law, self.state)
        {
            let z = s[0];
            let az = z.abs();
            let zn = if n == 1.0 {
                az
            } else if n == 2.0 {
                az * az
            } else {
                az.powf(n)
            };
            // beta |x'| |z|^(n-1) z = beta sign x' sgn(z) |z|^n while x' has the phase's sign (up to the rate
            // resolution just after a reversal).
            ds[0] = v * (1.0 - (beta * sign * z.signum() + gamma) * zn) * self.k / yield_force;
            let fz = (1.0 - a) * yield_force * z;
            ds[1] = fz * v;
            return (a * self.k * x + fz, fv);
        }
        (self.force(x, s), fv)
    }

    /// Recoverable strain energy and hysteretic energy dissipated so far, J. Bilinear: recoverable
    /// `F^2 / (2k)` (elastic unloading to zero force); Bouc–Wen: `a k x^2 / 2 + (1 - a) F_y d_y z^2 / 2`,
    /// the rest of the work of the hysteretic part being dissipated.
    pub fn energy(&self, x: f64, s: &[f64]) -> (f64, f64) {
        match (self.law, self.state) {
            (StoreyLaw::Linear, _) => (0.5 * self.k * x * x, 0.0),
            (StoreyLaw::Bilinear { .. }, StoreyState::Elastic { dissipated, .. }) => {
                let f = self.force(x, s);
                (0.5 * f * f / self.k, dissipated)
            }
            (
                StoreyLaw::Bilinear {
                    post_yield_ratio: a,
                    ..
                },
                StoreyState::Yielding {
                    x0, f0, dissipated, ..
                },
            ) => {
                let f = self.force(x, s);
                let dx = x - x0;
                // int F dx - d(F^2 / 2k) along F = f0 + a k dx.
                (
                    0.5 * f * f / self.k,
                    dissipated + (1.0 - a) * dx * (f0 + 0.5 * a * self.k * dx),
                )
            }
            (
                StoreyLaw::BoucWen {
                    yield_force,
                    post_yield_ratio: a,
                    ..
                },
                _,
            ) => {
                let held = 0.5 * (1.0 - a) * yield_force * yield_force / self.k * s[0] * s[0];
                (0.5 * a * self.k * x * x + held, s[1] - held)
            }
            _ => (0.5 * self.k * x * x, 0.0),
        }
    }

    /// Events watched in the current phase.
    pub fn watched(&self) -> &'static [Event] {
        match self.state {
            StoreyState::Linear => &[],
            StoreyState::Elastic { .. } => &[Event::YieldUp, Event::YieldDown],
            StoreyState::Yielding { .. } | StoreyState::BoucWen { .. } => &[Event::Reversal],
        }
    }

    /// Event function of `ev` at drift `x` and rate `v`: positive before the event.
    #[inline]
    pub fn event_value(&self, ev: Event, x: f64, v: f64) -> f64 {
        let fy = self.law.yield_force().unwrap_or(f64::INFINITY);
        match (ev, self.state) {
            (Event::YieldUp, StoreyState::Elastic { centre, .. }) => {
                centre + fy - self.force(x, &[])
            }
            (Event::YieldDown, StoreyState::Elastic { centre, .. }) => {
                self.force(x, &[]) - (centre - fy)
            }
            (Event::Reversal, StoreyState::Yielding { sign, .. })
            | (Event::Reversal, StoreyState::BoucWen { sign }) => sign * v + self.gate.slack(),
            _ => 1.0,
        }
    }

    /// Applies `ev` at drift `x` (m) and rate `v` (m/s).
    pub fn apply(&mut self, ev: Event, x: f64, v: f64) {
        self.change(ev, x);
        self.gate.enter(self.rate_event(v));
    }

    fn change(&mut self, ev: Event, x: f64) {
        let fy = self.law.yield_force().unwrap_or(f64::INFINITY);
        self.state = match (ev, self.state) {
            (
                Event::YieldUp | Event::YieldDown,
                StoreyState::Elastic {
                    centre, dissipated, ..
                },
            ) => {
                let sign = if ev == Event::YieldUp { 1.0 } else { -1.0 };
                // Anchored on the bound itself, so the elastic range never drifts with located times.
                StoreyState::Yielding {
                    sign,
                    x0: x,
                    f0: centre + sign * fy,
                    dissipated,
                }
            }
            (Event::Reversal, StoreyState::Yielding { sign, .. }) => {
                let f = self.force(x, &[]);
                let (_, dissipated) = self.energy(x, &[]);
                StoreyState::Elastic {
                    x0: x,
                    f0: f,
                    centre: f - sign * fy,
                    dissipated,
                }
            }
            (Event::Reversal, StoreyState::BoucWen { sign }) => {
                StoreyState::BoucWen { sign: -sign }
            }
            (_, state) => state,
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Drives a bilinear storey quasi-statically along the drifts of `path` and returns the final force. Between
    /// events the law is linear in the drift, so each event is located exactly by linear interpolation; the
    /// direction changes at the path's corners are reversals.
    fn follow(path: &[f64]) -> Storey {
        let law = StoreyLaw::bilinear(1.0e5, 0.1).unwrap();
        let mut st = Storey::new(1.0e7, law, 0.0);
        for w in path.windows(2) {
            let (mut x, b) = (w[0], w[1]);
            let v = (b - x).signum();
            if st.event_value(Event::Reversal, x, v) <= 0.0 && st.watched() == [Event::Reversal] {
                st.apply(Event::Reversal, x, v);
            }
            let fired = st
                .watched()
                .iter()
                .copied()
                .find(|&ev| st.event_value(ev, b, v) <= 0.0);
            if let Some(ev) = fired {
                let (g0, g1) = (st.event_value(ev, x, v), st.event_value(ev, b, v));
                x += (b - x) * g0 / (g0 - g1);
                st.apply(ev, x, v);
            }
        }
        st
    }

    #[test]
    fn bilinear_loop_is_the_kinematic_hardening_parallelogram() {
        // k = 1e7 N/m, F_y = 1e5 N (d_y = 0.01 m), a = 0.1. Loading to 0.03 m: F = F_y + a k (0.03 - 0.01)
        // = 1.2e5 N. Unloading is elastic over 2 F_y, to -0.8e5 N at x = 0.03 - 0.02 = 0.01 m, then yields:
        // at x = -0.03, F = -0.8e5 - a k 0.04 = -1.2e5 N (the loop is point-symmetric); reloading is elastic
        // up to 0.8e5 N at x = -0.01, and hardening brings it back to 1.2e5 N at 0.03.
        let force = |path: &[f64]| {
            let st = follow(path);
            st.force(*path.last().unwrap(), &[])
        };
        let close = |a: f64, b: f64| assert!((a - b).abs() < 1e-6, "{a} vs {b}");
        close(force(&[0.0, 0.03]), 1.2e5);
        close(force(&[0.0, 0.03, 0.01]), -0.8e5);
        close(force(&[0.0, 0.03, -0.03]), -1.2e5);
        close(force(&[0.0, 0.03, -0.03, -0.01]), 0.8e5);
        close(force(&[0.0, 0.03, -0.03, 0.03]), 1.2e5);
        // Hysteretic energy after the first loading: int F dx - F^2 / 2k
        // = (1e5 * 0.01 / 2 + (1e5 + 1.2e5) / 2 * 0.02) - 1.2e5^2 / 2e7 = 2700 - 720 = 1980 J.
        let st = follow(&[0.0, 0.03]);
        let (strain, hyst) = st.energy(0.03, &[]);
        close(strain, 720.0);
        close(hyst, 1980.0);
        // A full cycle dissipates the area of the parallelogram (0.03, 1.2e5), (0.01, -0.8e5), (-0.03, -1.2e5),
        // (-0.01, 0.8e5): 7200 J by the shoelace formula.
        let st = follow(&[0.0, 0.03, -0.03, 0.03]);
        let (_, h1) = st.energy(0.03, &[]);
        let cycle = h1 - 1980.0;
        close(cycle, 7200.0);
    }

    #[test]
    fn a_reversal_entered_at_rest_waits_for_the_rate_to_clear_the_resolution() {
        // A Bouc–Wen storey whose drift rate is noise around 0 (found by fuzzing: reversals at one instant).
        let law = StoreyLaw::bouc_wen(1.0e5, 0.05, 1.0, 0.5, 0.5).unwrap();
        let mut st = Storey::new(1.0e7, law, 0.0);
        st.gate.set_resolution(1e-6);
        // Loading in +x; a reversal at x' = 0 turns it to unloading in -x.
        st.apply(Event::Reversal, 0.0, 0.0);
        // Entered at x' = 0: noise of either sign below the resolution is no reversal back.
        for v in [1e-9, -1e-9, 9e-7] {
            assert!(st.event_value(Event::Reversal, 0.0, v) > 0.0, "{v}");
        }
        assert!(st.event_value(Event::Reversal, 0.0, 1.1e-6) <= 0.0);
        // Once the rate has cleared the resolution in -x, the next reversal is located at x' = 0 exactly.
        st.gate.rearm(st.rate_event(-2e-6));
        assert_eq!(st.event_value(Event::Reversal, 0.0, 0.0), 0.0);
    }

    #[test]
    fn invalid_laws_are_refused_with_their_key() {
        let name = |r: Result<StoreyLaw, Error>| match r {
            Err(Error::Parameter { name, .. }) => name,
            other => panic!("{other:?}"),
        };
        assert_eq!(name(StoreyLaw::bilinear(0.0, 0.05)), "yield_forces");
        assert_eq!(name(StoreyLaw::bilinear(1.0, 1.0)), "post_yield_ratio");
        assert_eq!(name(StoreyLaw::bilinear(1.0, -0.1)), "post_yield_ratio");
        assert_eq!(
            name(StoreyLaw::bouc_wen(1.0, 0.0, 1.0, -0.1, 0.5)),
            "bouc_wen.beta"
        );
        assert_eq!(
            name(StoreyLaw::bouc_wen(1.0, 0.0, 1.0, 0.2, -0.3)),
            "bouc_wen.gamma"
        );
        assert_eq!(
            name(StoreyLaw::bouc_wen(1.0, 0.0, 0.5, 0.5, 0.5)),
            "bouc_wen.n"
        );
        assert!(StoreyLaw::bouc_wen(1.0, 0.0, 2.0, 0.9, -0.1).is_ok());
    }
}
