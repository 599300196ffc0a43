//! The Bouc–Wen storey law (Wen 1976, normalised form, `A = 1`): `F = a k x + (1 - a) F_y z`,
//! `z' = (x' - beta |x'| |z|^(n-1) z - gamma x' |z|^n) / d_y`, `d_y = F_y / k`.

use crate::element::{
    ElementEnergy, ElementLaw, Event, Notice, RateGate, Scales, Transition, Watch,
};
use crate::Error;

const REVERSAL: Event = Event(0);

const WATCHED: &[Watch] = &[Watch::crossing(REVERSAL)];

/// A Bouc–Wen law and its phase, the sign of the drift rate (so that `|x'| = sign x'` between reversals and
/// the right-hand side is smooth). Its states: `z` (dimensionless) and the work of its hysteretic part,
/// `int (1 - a) F_y z x' dt` (J).
#[derive(Clone, Debug, PartialEq)]
pub struct BoucWen {
    k: f64,
    yield_force: f64,
    a: f64,
    n: f64,
    beta: f64,
    gamma: f64,
    sign: f64,
    gate: RateGate,
}

impl BoucWen {
    /// At rest, loading towards positive drift: initial stiffness `k` (N/m), yield force `F_y` (N),
    /// post-yield ratio `a`, exponent `n`, `beta`, `gamma` (checked by [`super::StoreyLaw::bouc_wen`]).
    pub fn new(k: f64, yield_force: f64, a: f64, n: f64, beta: f64, gamma: f64) -> Self {
        Self {
            k,
            yield_force,
            a,
            n,
            beta,
            gamma,
            sign: 1.0,
            gate: RateGate::default(),
        }
    }

    /// The sign of the drift rate the phase assumes: +1 or -1.
    pub fn sign(&self) -> f64 {
        self.sign
    }
}

impl ElementLaw for BoucWen {
    fn name(&self) -> &'static str {
        "bouc-wen"
    }

    fn states(&self) -> usize {
        2
    }

    /// `z` is of order 1; the work of its hysteretic part is an energy.
    fn state_tolerances(&self, scales: &Scales, out: &mut [f64]) {
        out[0] = scales.rtol;
        out[1] = scales.rtol * scales.energy;
    }

    #[inline]
    fn evaluate(&self, x: f64, v: f64, s: &[f64], ds: &mut [f64]) -> (f64, f64) {
        let (fy, a, n) = (self.yield_force, self.a, self.n);
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
        ds[0] = v * (1.0 - (self.beta * self.sign * z.signum() + self.gamma) * zn) * self.k / fy;
        let fz = (1.0 - a) * fy * z;
        ds[1] = fz * v;
        (a * self.k * x + fz, 0.0)
    }

    #[inline]
    fn force(&self, x: f64, _v: f64, s: &[f64]) -> f64 {
        self.a * self.k * x + (1.0 - self.a) * self.yield_force * s[0]
    }

    /// Recoverable `a k x^2 / 2 + (1 - a) F_y d_y z^2 / 2`; the rest of the work of the hysteretic part is
    /// dissipated.
    #[inline]
    fn energy(&self, x: f64, s: &[f64]) -> ElementEnergy {
        let (fy, a) = (self.yield_force, self.a);
        let held = 0.5 * (1.0 - a) * fy * fy / self.k * s[0] * s[0];
        ElementEnergy {
            strain: 0.5 * a * self.k * x * x + held,
            hysteretic: s[1] - held,
            ..ElementEnergy::default()
        }
    }

    fn watched(&self) -> &'static [Watch] {
        WATCHED
    }

    fn events_read_states(&self) -> bool {
        false
    }

    #[inline]
    fn event_value(&self, _ev: Event, _x: f64, v: f64, _s: &[f64]) -> f64 {
        self.sign * v + self.gate.slack()
    }

    fn apply(
        &mut self,
        _ev: Event,
        x: f64,
        v: f64,
        s: &[f64],
        _h: f64,
    ) -> Result<Transition, Error> {
        self.sign = -self.sign;
        self.gate.enter(self.rate_event(x, v, s));
        Ok(Transition::notice(Notice::Reversed))
    }

    fn gate(&self) -> Option<&RateGate> {
        Some(&self.gate)
    }

    fn gate_mut(&mut self) -> Option<&mut RateGate> {
        Some(&mut self.gate)
    }

    fn rate_event(&self, _x: f64, v: f64, _s: &[f64]) -> Option<f64> {
        Some(self.sign * v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_reversal_entered_at_rest_waits_for_the_rate_to_clear_the_resolution() {
        // A Bouc–Wen storey whose drift rate is noise around 0 (found by fuzzing: reversals at one instant).
        let mut st = BoucWen::new(1.0e7, 1.0e5, 0.05, 1.0, 0.5, 0.5);
        st.gate.set_resolution(1e-6);
        // Loading in +x; a reversal at x' = 0 turns it to unloading in -x.
        st.apply(REVERSAL, 0.0, 0.0, &[0.0, 0.0], 0.0).unwrap();
        // Entered at x' = 0: noise of either sign below the resolution is no reversal back.
        for v in [1e-9, -1e-9, 9e-7] {
            assert!(st.event_value(REVERSAL, 0.0, v, &[]) > 0.0, "{v}");
        }
        assert!(st.event_value(REVERSAL, 0.0, 1.1e-6, &[]) <= 0.0);
        // Once the rate has cleared the resolution in -x, the next reversal is located at x' = 0 exactly.
        st.gate.rearm(st.rate_event(0.0, -2e-6, &[]));
        assert_eq!(st.event_value(REVERSAL, 0.0, 0.0, &[]), 0.0);
    }
}
