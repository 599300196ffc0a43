//! The bilinear storey law with kinematic hardening (OpenSees `Steel01` without isotropic hardening): an
//! elastic range of width `2 F_y` that moves with the back-force, and a post-yield slope `a k`.

use crate::element::{
    Affine, ElementEnergy, ElementLaw, Event, Notice, RateGate, Transition, Watch,
};
use crate::Error;

const YIELD_UP: Event = Event(0);
const YIELD_DOWN: Event = Event(1);
const REVERSAL: Event = Event(2);

const ELASTIC: &[Watch] = &[Watch::crossing(YIELD_UP), Watch::crossing(YIELD_DOWN)];
const YIELDING: &[Watch] = &[Watch::crossing(REVERSAL)];

/// The phase of a bilinear law: plain data, changed only at its events.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BilinearPhase {
    /// Elastic: `F = f0 + k (x - x0)` inside `[centre - F_y, centre + F_y]`.
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
    /// On the post-yield branch in direction `sign`: `F = f0 + a k (x - x0)`.
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
}

/// A bilinear law: initial stiffness `k` (N/m), yield force `F_y` (N), post-yield ratio `a`, and its phase.
#[derive(Clone, Debug, PartialEq)]
pub struct Bilinear {
    k: f64,
    yield_force: f64,
    a: f64,
    phase: BilinearPhase,
    gate: RateGate,
}

impl Bilinear {
    /// At rest, elastic: initial stiffness `k` (N/m), yield force `yield_force` (N), post-yield ratio `a`
    /// (checked by [`super::StoreyLaw::bilinear`]).
    pub fn new(k: f64, yield_force: f64, a: f64) -> Self {
        Self {
            k,
            yield_force,
            a,
            phase: BilinearPhase::Elastic {
                x0: 0.0,
                f0: 0.0,
                centre: 0.0,
                dissipated: 0.0,
            },
            gate: RateGate::default(),
        }
    }

    /// The phase.
    pub fn phase(&self) -> BilinearPhase {
        self.phase
    }

    fn change(&mut self, ev: Event, x: f64) -> Option<Notice> {
        let fy = self.yield_force;
        match (ev, self.phase) {
            (
                YIELD_UP | YIELD_DOWN,
                BilinearPhase::Elastic {
                    centre, dissipated, ..
                },
            ) => {
                let sign = if ev == YIELD_UP { 1.0 } else { -1.0 };
                // Anchored on the bound itself, so the elastic range never drifts with located times.
                self.phase = BilinearPhase::Yielding {
                    sign,
                    x0: x,
                    f0: centre + sign * fy,
                    dissipated,
                };
                Some(Notice::Yielded)
            }
            (REVERSAL, BilinearPhase::Yielding { sign, .. }) => {
                let f = self.force(x, 0.0, &[]);
                let dissipated = self.energy(x, &[]).hysteretic;
                self.phase = BilinearPhase::Elastic {
                    x0: x,
                    f0: f,
                    centre: f - sign * fy,
                    dissipated,
                };
                Some(Notice::Reversed)
            }
            _ => None,
        }
    }
}

impl ElementLaw for Bilinear {
    fn name(&self) -> &'static str {
        "bilinear"
    }

    #[inline]
    fn evaluate(&self, x: f64, v: f64, s: &[f64], _ds: &mut [f64]) -> (f64, f64) {
        (self.force(x, v, s), 0.0)
    }

    #[inline]
    fn force(&self, x: f64, _v: f64, _s: &[f64]) -> f64 {
        match self.phase {
            BilinearPhase::Elastic { x0, f0, .. } => f0 + self.k * (x - x0),
            BilinearPhase::Yielding { x0, f0, .. } => f0 + self.a * self.k * (x - x0),
        }
    }

    fn affine(&self) -> Option<Affine> {
        let (k, x0, f0) = match self.phase {
            BilinearPhase::Elastic { x0, f0, .. } => (self.k, x0, f0),
            BilinearPhase::Yielding { x0, f0, .. } => (self.a * self.k, x0, f0),
        };
        Some(Affine {
            k,
            c: 0.0,
            f0: f0 - k * x0,
            viscous: 0.0,
        })
    }

    /// Recoverable `F^2 / (2k)` (elastic unloading to zero force) and the hysteretic energy dissipated.
    #[inline]
    fn energy(&self, x: f64, s: &[f64]) -> ElementEnergy {
        let f = self.force(x, 0.0, s);
        let hysteretic = match self.phase {
            BilinearPhase::Elastic { dissipated, .. } => dissipated,
            BilinearPhase::Yielding {
                x0, f0, dissipated, ..
            } => {
                let dx = x - x0;
                // int F dx - d(F^2 / 2k) along F = f0 + a k dx.
                dissipated + (1.0 - self.a) * dx * (f0 + 0.5 * self.a * self.k * dx)
            }
        };
        ElementEnergy {
            strain: 0.5 * f * f / self.k,
            hysteretic,
            ..ElementEnergy::default()
        }
    }

    fn watched(&self) -> &'static [Watch] {
        match self.phase {
            BilinearPhase::Elastic { .. } => ELASTIC,
            BilinearPhase::Yielding { .. } => YIELDING,
        }
    }

    #[inline]
    fn event_value(&self, ev: Event, x: f64, v: f64, s: &[f64]) -> f64 {
        match (ev, self.phase) {
            (YIELD_UP, BilinearPhase::Elastic { centre, .. }) => {
                centre + self.yield_force - self.force(x, v, s)
            }
            (YIELD_DOWN, BilinearPhase::Elastic { centre, .. }) => {
                self.force(x, v, s) - (centre - self.yield_force)
            }
            (REVERSAL, BilinearPhase::Yielding { sign, .. }) => sign * v + self.gate.slack(),
            _ => 1.0,
        }
    }

    fn apply(
        &mut self,
        ev: Event,
        x: f64,
        v: f64,
        s: &[f64],
        _h: f64,
    ) -> Result<Transition, Error> {
        let notice = self.change(ev, x);
        self.gate.enter(self.rate_event(x, v, s));
        Ok(Transition {
            notice,
            ..Transition::default()
        })
    }

    fn gate(&self) -> Option<&RateGate> {
        Some(&self.gate)
    }

    fn gate_mut(&mut self) -> Option<&mut RateGate> {
        Some(&mut self.gate)
    }

    fn rate_event(&self, _x: f64, v: f64, _s: &[f64]) -> Option<f64> {
        match self.phase {
            BilinearPhase::Yielding { sign, .. } => Some(sign * v),
            BilinearPhase::Elastic { .. } => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Drives a bilinear law quasi-statically along the drifts of `path`. Between events the law is linear
    /// in the drift, so each event is located exactly by linear interpolation; the direction changes at the
    /// path's corners are reversals.
    fn follow(path: &[f64]) -> Bilinear {
        let mut st = Bilinear::new(1.0e7, 1.0e5, 0.1);
        for w in path.windows(2) {
            let (mut x, b) = (w[0], w[1]);
            let v = (b - x).signum();
            if st.event_value(REVERSAL, x, v, &[]) <= 0.0 && st.watched() == YIELDING {
                st.apply(REVERSAL, x, v, &[], 0.0).unwrap();
            }
            let fired = st
                .watched()
                .iter()
                .map(|w| w.event)
                .find(|&ev| st.event_value(ev, b, v, &[]) <= 0.0);
            if let Some(ev) = fired {
                let (g0, g1) = (st.event_value(ev, x, v, &[]), st.event_value(ev, b, v, &[]));
                x += (b - x) * g0 / (g0 - g1);
                st.apply(ev, x, v, &[], 0.0).unwrap();
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
            st.force(*path.last().unwrap(), 0.0, &[])
        };
        let close = |a: f64, b: f64| assert!((a - b).abs() < 1e-6, "{a} vs {b}");
        close(force(&[0.0, 0.03]), 1.2e5);
        close(force(&[0.0, 0.03, 0.01]), -0.8e5);
        close(force(&[0.0, 0.03, -0.03]), -1.2e5);
        close(force(&[0.0, 0.03, -0.03, -0.01]), 0.8e5);
        close(force(&[0.0, 0.03, -0.03, 0.03]), 1.2e5);
        // Hysteretic energy after the first loading: int F dx - F^2 / 2k
        // = (1e5 * 0.01 / 2 + (1e5 + 1.2e5) / 2 * 0.02) - 1.2e5^2 / 2e7 = 2700 - 720 = 1980 J.
        let e = follow(&[0.0, 0.03]).energy(0.03, &[]);
        close(e.strain, 720.0);
        close(e.hysteretic, 1980.0);
        // A full cycle dissipates the area of the parallelogram (0.03, 1.2e5), (0.01, -0.8e5), (-0.03, -1.2e5),
        // (-0.01, 0.8e5): 7200 J by the shoelace formula.
        let h1 = follow(&[0.0, 0.03, -0.03, 0.03])
            .energy(0.03, &[])
            .hysteretic;
        close(h1 - 1980.0, 7200.0);
    }
}
