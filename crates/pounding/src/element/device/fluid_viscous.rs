//! A fluid viscous damper, `F = c |v|^alpha sgn(v)` (Constantinou & Symans 1993; ASCE 7-22 ch. 18; OpenSees
//! `ViscousDamper`), alone or in series with a spring (the Maxwell form of a real damper and its brackets).
//!
//! Alone, `v` is the rate of the deformation `x'` and the force is all viscous: its power `c |v|^(1+alpha)`
//! is counted as viscous damping in the energy balance. With `alpha < 1` the slope `dF/dv` is infinite at
//! `v = 0`, so each reversal of the velocity is located as an event and no step straddles it.
//!
//! In series with a spring of stiffness `k`, the damper's stroke `x_d` is a state: `F = k (x - x_d)` and
//! `x_d' = sgn(F) (|F| / c)^(1/alpha)`; the energy the damper dissipates, `int F x_d' dt`, is a second
//! state. The damper reverses where `F` changes sign, located as an event too (`|F|^(1/alpha)` is smooth
//! enough to integrate, but not to expand in a Taylor series across the reversal). With `alpha = 1` the law
//! is linear and watches no event: alone it is the linear dashpot, in series the Maxwell unit.

use super::{damping_coefficient, stiffness, Device, Parameter};
use crate::element::{
    Affine, ElementEnergy, ElementLaw, Event, Notice, RateGate, Scales, Transition, Watch,
};
use crate::error::check;
use crate::Error;

const REVERSAL: Event = Event(0);
const WATCHED: &[Watch] = &[Watch::crossing(REVERSAL)];

/// A fluid viscous damper: coefficient `c` (N (s/m)^alpha), velocity exponent `alpha` in (0, 1], an optional
/// spring in series (N/m), and the sign of the damper's velocity in the current phase.
#[derive(Clone, Debug, PartialEq)]
pub struct FluidViscous {
    c: f64,
    alpha: f64,
    k: Option<f64>,
    sign: f64,
    gate: RateGate,
}

impl FluidViscous {
    /// `|r|^alpha sgn(r)` (the damper's force per unit `c` at velocity `r`), without `powf` for `alpha = 1`.
    #[inline]
    fn power(&self, r: f64) -> f64 {
        if self.alpha == 1.0 {
            r
        } else {
            r.abs().powf(self.alpha).copysign(r)
        }
    }

    /// The damper's velocity, m/s: the deformation rate alone, the stroke rate in series.
    #[inline]
    fn damper_rate(&self, x: f64, v: f64, s: &[f64]) -> f64 {
        match self.k {
            None => v,
            Some(k) => {
                let f = k * (x - s[0]);
                let r = (f.abs() / self.c).powf(1.0 / self.alpha);
                r.copysign(f)
            }
        }
    }
}

impl ElementLaw for FluidViscous {
    fn name(&self) -> &'static str {
        "fluid-viscous"
    }

    /// In series: the stroke `x_d` (m) and the energy the damper dissipated (J).
    fn states(&self) -> usize {
        if self.k.is_some() {
            2
        } else {
            0
        }
    }

    fn state_tolerances(&self, scales: &Scales, out: &mut [f64]) {
        if self.k.is_some() {
            out[0] = scales.rtol * scales.displacement;
            out[1] = scales.rtol * scales.energy;
        }
    }

    /// A damper of exponent 1 without a spring is a linear dashpot.
    /// Its affine force has no constant part.
    fn constant_force(&self) -> bool {
        false
    }

    fn affine(&self) -> Option<Affine> {
        (self.alpha == 1.0 && self.k.is_none()).then_some(Affine {
            c: self.c,
            viscous: self.c,
            ..Affine::default()
        })
    }

    #[inline]
    fn evaluate(&self, x: f64, v: f64, s: &[f64], ds: &mut [f64]) -> (f64, f64) {
        match self.k {
            None => (0.0, self.c * self.power(v)),
            Some(k) => {
                let f = k * (x - s[0]);
                let rate = self.damper_rate(x, v, s);
                ds[0] = rate;
                ds[1] = f * rate;
                (f, 0.0)
            }
        }
    }

    /// The spring's force in series (alone, the force is all viscous: 0 here), N.
    #[inline]
    fn force(&self, x: f64, _v: f64, s: &[f64]) -> f64 {
        match self.k {
            None => 0.0,
            Some(k) => k * (x - s[0]),
        }
    }

    /// In series: the spring's `F^2 / 2k`, and the damper's dissipated energy (a state).
    #[inline]
    fn energy(&self, x: f64, s: &[f64]) -> ElementEnergy {
        match self.k {
            None => ElementEnergy::default(),
            Some(k) => {
                let f = k * (x - s[0]);
                ElementEnergy {
                    strain: 0.5 * f * f / k,
                    damping: s[1],
                    ..ElementEnergy::default()
                }
            }
        }
    }

    /// The reversal, where the law has a kink (`alpha < 1`); with `alpha = 1` the damper is linear and
    /// smooth, and watches nothing.
    fn watched(&self) -> &'static [Watch] {
        if self.alpha < 1.0 {
            WATCHED
        } else {
            &[]
        }
    }

    /// The damper's velocity in the phase's direction (m/s), passed by its rate resolution while disarmed.
    #[inline]
    fn event_value(&self, _ev: Event, x: f64, v: f64, s: &[f64]) -> f64 {
        self.sign * self.damper_rate(x, v, s) + self.gate.slack()
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
        Ok(Transition::notice(Notice::DamperReversed))
    }

    fn gate(&self) -> Option<&RateGate> {
        Some(&self.gate)
    }

    fn gate_mut(&mut self) -> Option<&mut RateGate> {
        Some(&mut self.gate)
    }

    fn rate_event(&self, x: f64, v: f64, s: &[f64]) -> Option<f64> {
        Some(self.sign * self.damper_rate(x, v, s))
    }
}

/// `model = "fluid-viscous"`: `F = c |v|^alpha sgn(v)`, alone or in series with a spring.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct FluidViscousParams {
    /// Damping coefficient `c`, N (s/m)^alpha.
    pub damping_coefficient: f64,
    /// Velocity exponent `alpha`, in (0, 1] (1: a linear dashpot; 0.3 to 0.5 for typical seismic dampers).
    #[cfg_attr(feature = "serde", serde(default = "one"))]
    pub velocity_exponent: f64,
    /// Stiffness of a spring in series (the damper's brackets and fluid), N/m; none: the damper alone.
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub stiffness: Option<f64>,
}

#[cfg(feature = "serde")]
fn one() -> f64 {
    1.0
}

impl Device for FluidViscous {
    type Params = FluidViscousParams;

    /// At rest; the first phase assumes a positive velocity (a first motion the other way is a reversal at
    /// once).
    fn from_params(p: &FluidViscousParams) -> Result<Self, Error> {
        let alpha = check(
            "velocity_exponent",
            p.velocity_exponent,
            p.velocity_exponent > 0.0 && p.velocity_exponent <= 1.0,
            "0 < velocity_exponent <= 1",
        )?;
        Ok(Self {
            c: damping_coefficient(
                p.damping_coefficient,
                "damping_coefficient > 0 (N (s/m)^velocity_exponent)",
            )?,
            alpha,
            k: p.stiffness.map(stiffness).transpose()?,
            sign: 1.0,
            gate: RateGate::default(),
        })
    }

    fn parameters(p: &FluidViscousParams) -> Vec<Parameter> {
        let mut out = vec![
            Parameter {
                key: "damping_coefficient",
                value: p.damping_coefficient,
                unit: "N (s/m)^alpha",
            },
            Parameter {
                key: "velocity_exponent",
                value: p.velocity_exponent,
                unit: "",
            },
        ];
        if let Some(k) = p.stiffness {
            out.push(Parameter {
                key: "stiffness",
                value: k,
                unit: "N/m",
            });
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn damper(alpha: f64, k: Option<f64>) -> FluidViscous {
        FluidViscous::from_params(&FluidViscousParams {
            damping_coefficient: 2.0e6,
            velocity_exponent: alpha,
            stiffness: k,
        })
        .unwrap()
    }

    #[test]
    fn its_force_is_c_times_the_velocity_to_the_power_alpha() {
        // c = 2e6 N (s/m)^0.5, v = -0.25 m/s: F = -2e6 * 0.5 = -1e6 N, all viscous.
        let d = damper(0.5, None);
        assert_eq!(d.evaluate(0.1, -0.25, &[], &mut []), (0.0, -1.0e6));
        // alpha = 1 is a linear dashpot.
        assert_eq!(damper(1.0, None).evaluate(0.0, 0.3, &[], &mut []).1, 6.0e5);
    }

    #[test]
    fn in_series_the_stroke_moves_at_the_force_over_c_to_the_power_one_over_alpha() {
        // k = 1e8 N/m, x = 0.01 m, x_d = 0.002 m: F = 8e5 N; x_d' = (8e5 / 2e6)^2 = 0.16 m/s for alpha = 0.5;
        // the damper dissipates F x_d' = 1.28e5 W.
        let d = damper(0.5, Some(1e8));
        let mut ds = [0.0; 2];
        let (f, fv) = d.evaluate(0.01, 0.0, &[0.002, 0.0], &mut ds);
        assert!((f - 8e5).abs() < 1e-6 && fv == 0.0);
        assert!((ds[0] - 0.16).abs() < 1e-15 && (ds[1] - 1.28e5).abs() < 1e-9);
        // The reversal is where the force, and so the stroke rate, changes sign.
        assert!(d.event_value(REVERSAL, 0.002, 0.0, &[0.002, 0.0]).abs() < 1e-30);
    }

    #[test]
    fn bad_parameters_are_refused_with_their_key() {
        let name = |alpha: f64, c: f64, k: Option<f64>| match FluidViscous::from_params(
            &FluidViscousParams {
                damping_coefficient: c,
                velocity_exponent: alpha,
                stiffness: k,
            },
        ) {
            Err(Error::Parameter { name, .. }) => name,
            other => panic!("{other:?}"),
        };
        assert_eq!(name(0.0, 1.0, None), "velocity_exponent");
        assert_eq!(name(1.5, 1.0, None), "velocity_exponent");
        assert_eq!(name(0.5, -1.0, None), "damping_coefficient");
        assert_eq!(name(0.5, 1.0, Some(0.0)), "stiffness");
    }
}
