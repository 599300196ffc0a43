//! Devices: permanent connections between two ends (floors of neighbouring structures, or a floor and the
//! ground beside it): springs, dashpots, Kelvin and Maxwell units, and restrainers.
//!
//! The deformation is `x = u_a - u_b` (m, closing positive, as for contacts) and the device's force `f` (N)
//! resists a growing `x`. A restrainer (a bridge's cable restrainer, after `docs/structures.md`) acts in tension only, once the opening `-x` exceeds its slack `s`:
//! `f = -k (-x - s)` then, 0 otherwise; the moment it becomes taut and the moment it becomes slack again are
//! located as events, so the kink of its law never falls inside a step.

use crate::element::Event;
use crate::error::check;
use crate::Error;

/// The force law of a device.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub enum DeviceLaw {
    /// A linear spring: `f = k x`.
    Spring {
        /// Stiffness, N/m.
        stiffness: f64,
    },
    /// A linear dashpot: `f = c x'`.
    Dashpot {
        /// Damping coefficient, N s/m.
        damping: f64,
    },
    /// Spring and dashpot in parallel (Kelvin–Voigt): `f = k x + c x'`.
    Kelvin {
        /// Stiffness, N/m.
        stiffness: f64,
        /// Damping coefficient, N s/m.
        damping: f64,
    },
    /// Spring and dashpot in series (Maxwell): `f = k (x - x_d)`, `x_d' = f / c`, with the dashpot's stroke
    /// `x_d` (m) an ODE state.
    Maxwell {
        /// Stiffness, N/m.
        stiffness: f64,
        /// Damping coefficient, N s/m.
        damping: f64,
    },
    /// A tension-only restrainer with slack: `f = -k (-x - slack)` when the opening `-x` exceeds `slack`,
    /// 0 otherwise.
    Restrainer {
        /// Stiffness once taut, N/m.
        stiffness: f64,
        /// Opening at which it becomes taut, m (>= 0).
        slack: f64,
    },
}

impl DeviceLaw {
    /// A validated law: stiffness > 0 (N/m) and damping > 0 (N s/m) where they apply, slack >= 0 (m).
    pub fn checked(self) -> Result<Self, Error> {
        let k = |k: f64| {
            check(
                "stiffness",
                k,
                k > 0.0 && k.is_finite(),
                "stiffness > 0 (N/m)",
            )
        };
        let c = |c: f64| {
            check(
                "damping",
                c,
                c > 0.0 && c.is_finite(),
                "damping > 0 (N s/m)",
            )
        };
        match self {
            DeviceLaw::Spring { stiffness } => {
                k(stiffness)?;
            }
            DeviceLaw::Dashpot { damping } => {
                c(damping)?;
            }
            DeviceLaw::Kelvin { stiffness, damping }
            | DeviceLaw::Maxwell { stiffness, damping } => {
                k(stiffness)?;
                c(damping)?;
            }
            DeviceLaw::Restrainer { stiffness, slack } => {
                k(stiffness)?;
                check(
                    "slack",
                    slack,
                    slack >= 0.0 && slack.is_finite(),
                    "slack >= 0 (m)",
                )?;
            }
        }
        Ok(self)
    }

    /// Short name: `spring`, `dashpot`, `kelvin`, `maxwell`, `restrainer`.
    pub fn name(&self) -> &'static str {
        match self {
            DeviceLaw::Spring { .. } => "spring",
            DeviceLaw::Dashpot { .. } => "dashpot",
            DeviceLaw::Kelvin { .. } => "kelvin",
            DeviceLaw::Maxwell { .. } => "maxwell",
            DeviceLaw::Restrainer { .. } => "restrainer",
        }
    }

    /// The stiffness, N/m (0 for a dashpot).
    pub fn stiffness(&self) -> f64 {
        match *self {
            DeviceLaw::Dashpot { .. } => 0.0,
            DeviceLaw::Spring { stiffness }
            | DeviceLaw::Kelvin { stiffness, .. }
            | DeviceLaw::Maxwell { stiffness, .. }
            | DeviceLaw::Restrainer { stiffness, .. } => stiffness,
        }
    }
}

/// A device element: its law, and for a restrainer whether it is taut.
#[derive(Clone, Debug)]
pub struct Device {
    law: DeviceLaw,
    taut: bool,
}

impl Device {
    /// A device at rest (a restrainer with slack starts slack; one without slack starts taut, as at rest its
    /// opening is 0 and any opening loads it).
    pub fn new(law: DeviceLaw) -> Self {
        Self { law, taut: false }
    }

    /// The law.
    pub fn law(&self) -> DeviceLaw {
        self.law
    }

    /// Whether a restrainer is taut (always false for other laws).
    pub fn taut(&self) -> bool {
        self.taut
    }

    /// Extra ODE states: a Maxwell unit's dashpot stroke (m) and the energy its dashpot dissipated (J).
    pub fn states(&self) -> usize {
        match self.law {
            DeviceLaw::Maxwell { .. } => 2,
            _ => 0,
        }
    }

    /// Elastic force, N, at deformation `x` (m) with states `s`.
    #[inline]
    pub fn force(&self, x: f64, s: &[f64]) -> f64 {
        match self.law {
            DeviceLaw::Spring { stiffness } | DeviceLaw::Kelvin { stiffness, .. } => stiffness * x,
            DeviceLaw::Dashpot { .. } => 0.0,
            DeviceLaw::Maxwell { stiffness, .. } => stiffness * (x - s[0]),
            DeviceLaw::Restrainer { stiffness, slack } => {
                if self.taut {
                    stiffness * (x + slack)
                } else {
                    0.0
                }
            }
        }
    }

    /// Elastic and viscous force, N (the viscous part of a dashpot or Kelvin unit is counted as viscous
    /// damping in the energy balance); the rates of a Maxwell unit's states go to `ds`.
    #[inline]
    pub fn evaluate(&self, x: f64, v: f64, s: &[f64], ds: &mut [f64]) -> (f64, f64) {
        match self.law {
            DeviceLaw::Dashpot { damping } => (0.0, damping * v),
            DeviceLaw::Kelvin { stiffness, damping } => (stiffness * x, damping * v),
            DeviceLaw::Maxwell { damping, .. } => {
                let f = self.force(x, s);
                ds[0] = f / damping;
                ds[1] = f * f / damping;
                (f, 0.0)
            }
            _ => (self.force(x, s), 0.0),
        }
    }

    /// Recoverable strain energy and energy dissipated by a Maxwell unit's dashpot, J.
    pub fn energy(&self, x: f64, s: &[f64]) -> (f64, f64) {
        let k = self.law.stiffness();
        match self.law {
            DeviceLaw::Dashpot { .. } => (0.0, 0.0),
            DeviceLaw::Maxwell { .. } => {
                let f = self.force(x, s);
                (0.5 * f * f / k, s[1])
            }
            _ => {
                let f = self.force(x, s);
                (if k > 0.0 { 0.5 * f * f / k } else { 0.0 }, 0.0)
            }
        }
    }

    /// Events watched: a restrainer's becoming taut or slack.
    pub fn watched(&self) -> &'static [Event] {
        match (self.law, self.taut) {
            (DeviceLaw::Restrainer { .. }, false) => &[Event::Taut],
            (DeviceLaw::Restrainer { .. }, true) => &[Event::Slack],
            _ => &[],
        }
    }

    /// Event function of `ev` at deformation `x` (m): positive before the event.
    #[inline]
    pub fn event_value(&self, ev: Event, x: f64) -> f64 {
        match (ev, self.law) {
            // Slack - opening, then opening - slack.
            (Event::Taut, DeviceLaw::Restrainer { slack, .. }) => slack + x,
            (Event::Slack, DeviceLaw::Restrainer { slack, .. }) => -x - slack,
            _ => 1.0,
        }
    }

    /// Applies `ev`.
    pub fn apply(&mut self, ev: Event) {
        match ev {
            Event::Taut => self.taut = true,
            Event::Slack => self.taut = false,
            _ => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_restrainer_pulls_only_beyond_its_slack() {
        let law = DeviceLaw::Restrainer {
            stiffness: 1e6,
            slack: 0.02,
        };
        let mut d = Device::new(law.checked().unwrap());
        // Opening 0.01 m (x = -0.01): slack, no force; the taut event is 0.01 m away.
        assert_eq!(d.force(-0.01, &[]), 0.0);
        assert!((d.event_value(Event::Taut, -0.01) - 0.01).abs() < 1e-15);
        assert_eq!(d.event_value(Event::Taut, -0.02), 0.0);
        d.apply(Event::Taut);
        // Opening 0.05 m: 3 cm beyond the slack, a pull of 3e4 N (negative: it resists the opening).
        assert!((d.force(-0.05, &[]) + 3e4).abs() < 1e-9);
        assert!((d.energy(-0.05, &[]).0 - 0.5 * 1e6 * 0.03 * 0.03).abs() < 1e-9);
        assert!(d.event_value(Event::Slack, -0.05) > 0.0);
        assert!(d.event_value(Event::Slack, -0.01) < 0.0);
    }

    #[test]
    fn invalid_devices_are_refused_with_their_key() {
        let name = |law: DeviceLaw| match law.checked() {
            Err(Error::Parameter { name, .. }) => name,
            other => panic!("{other:?}"),
        };
        assert_eq!(name(DeviceLaw::Spring { stiffness: 0.0 }), "stiffness");
        assert_eq!(name(DeviceLaw::Dashpot { damping: -1.0 }), "damping");
        assert_eq!(
            name(DeviceLaw::Restrainer {
                stiffness: 1.0,
                slack: -0.1
            }),
            "slack"
        );
    }
}
