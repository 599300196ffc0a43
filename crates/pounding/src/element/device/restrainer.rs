//! A tension-only restrainer with slack (a bridge's cable restrainer, after `docs/structures.md`): it acts
//! once the opening `-x` exceeds its slack `s`, `f = -k (-x - s)`, and not otherwise. The moment it becomes
//! taut and the moment it becomes slack again are located as events, so the kink of its law never falls
//! inside a step.

use super::{stiffness, Device, Parameter};
use crate::element::{Affine, ElementEnergy, ElementLaw, Event, Notice, Transition, Watch};
use crate::error::check;
use crate::Error;

const TAUT: Event = Event(0);
const SLACK: Event = Event(1);

const WATCH_TAUT: &[Watch] = &[Watch::crossing(TAUT)];
const WATCH_SLACK: &[Watch] = &[Watch::crossing(SLACK)];

/// A restrainer: stiffness once taut `k` (N/m), slack `s` (m), and whether it is taut.
#[derive(Clone, Debug, PartialEq)]
pub struct Restrainer {
    k: f64,
    slack: f64,
    taut: bool,
}

impl Restrainer {
    /// Whether it is taut.
    pub fn taut(&self) -> bool {
        self.taut
    }
}

impl ElementLaw for Restrainer {
    fn name(&self) -> &'static str {
        "restrainer"
    }

    #[inline]
    fn evaluate(&self, x: f64, v: f64, s: &[f64], _ds: &mut [f64]) -> (f64, f64) {
        (self.force(x, v, s), 0.0)
    }

    #[inline]
    fn force(&self, x: f64, _v: f64, _s: &[f64]) -> f64 {
        if self.taut {
            self.k * (x + self.slack)
        } else {
            0.0
        }
    }

    fn affine(&self) -> Option<Affine> {
        let k = if self.taut { self.k } else { 0.0 };
        Some(Affine {
            k,
            c: 0.0,
            f0: k * self.slack,
            viscous: 0.0,
        })
    }

    #[inline]
    fn energy(&self, x: f64, s: &[f64]) -> ElementEnergy {
        let f = self.force(x, 0.0, s);
        ElementEnergy {
            strain: 0.5 * f * f / self.k,
            ..ElementEnergy::default()
        }
    }

    fn watched(&self) -> &'static [Watch] {
        if self.taut {
            WATCH_SLACK
        } else {
            WATCH_TAUT
        }
    }

    fn events_read_states(&self) -> bool {
        false
    }

    /// Slack minus opening while slack; opening minus slack while taut (m).
    #[inline]
    fn event_value(&self, ev: Event, x: f64, _v: f64, _s: &[f64]) -> f64 {
        match ev {
            TAUT => self.slack + x,
            SLACK => -x - self.slack,
            _ => 1.0,
        }
    }

    fn apply(
        &mut self,
        ev: Event,
        _x: f64,
        _v: f64,
        _s: &[f64],
        _h: f64,
    ) -> Result<Transition, Error> {
        self.taut = ev == TAUT;
        Ok(Transition::notice(if self.taut {
            Notice::Taut
        } else {
            Notice::Slack
        }))
    }
}

/// `model = "restrainer"`: tension only, beyond its slack.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct RestrainerParams {
    /// Stiffness once taut `k`, N/m.
    pub stiffness: f64,
    /// Opening at which it becomes taut, m (default 0: taut as soon as the ends part).
    #[cfg_attr(feature = "serde", serde(default))]
    pub slack: f64,
}

impl Device for Restrainer {
    type Params = RestrainerParams;

    /// At rest, slack (one without slack becomes taut as soon as the ends part).
    fn from_params(p: &RestrainerParams) -> Result<Self, Error> {
        Ok(Self {
            k: stiffness(p.stiffness)?,
            slack: check(
                "slack",
                p.slack,
                p.slack >= 0.0 && p.slack.is_finite(),
                "slack >= 0 (m)",
            )?,
            taut: false,
        })
    }

    fn parameters(p: &RestrainerParams) -> Vec<Parameter> {
        vec![
            Parameter {
                key: "stiffness",
                value: p.stiffness,
                unit: "N/m",
            },
            Parameter {
                key: "slack",
                value: p.slack,
                unit: "m",
            },
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_restrainer_pulls_only_beyond_its_slack() {
        let p = RestrainerParams {
            stiffness: 1e6,
            slack: 0.02,
        };
        let mut d = Restrainer::from_params(&p).unwrap();
        // Opening 0.01 m (x = -0.01): slack, no force; the taut event is 0.01 m away.
        assert_eq!(d.force(-0.01, 0.0, &[]), 0.0);
        assert!((d.event_value(TAUT, -0.01, 0.0, &[]) - 0.01).abs() < 1e-15);
        assert_eq!(d.event_value(TAUT, -0.02, 0.0, &[]), 0.0);
        assert_eq!(
            d.apply(TAUT, -0.02, 0.0, &[], 0.0).unwrap().notice,
            Some(Notice::Taut)
        );
        // Opening 0.05 m: 3 cm beyond the slack, a pull of 3e4 N (negative: it resists the opening).
        assert!((d.force(-0.05, 0.0, &[]) + 3e4).abs() < 1e-9);
        assert!((d.energy(-0.05, &[]).strain - 0.5 * 1e6 * 0.03 * 0.03).abs() < 1e-9);
        assert!(d.event_value(SLACK, -0.05, 0.0, &[]) > 0.0);
        assert!(d.event_value(SLACK, -0.01, 0.0, &[]) < 0.0);
    }

    #[test]
    fn invalid_devices_are_refused_with_their_key() {
        let name = |r: Result<Restrainer, Error>| match r {
            Err(Error::Parameter { name, .. }) => name,
            other => panic!("{other:?}"),
        };
        let p = |stiffness, slack| RestrainerParams { stiffness, slack };
        assert_eq!(name(Restrainer::from_params(&p(0.0, 0.0))), "stiffness");
        assert_eq!(name(Restrainer::from_params(&p(1.0, -0.1))), "slack");
    }
}
