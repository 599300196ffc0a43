//! Contact elements: one impact after another between two ends (two floors, or a floor and a wall).
//!
//! The penetration is `d = x - gap` with `x = u_a - u_b` (m), its rate `v = x'` (m/s). Each impact is one
//! touch: its onset is located as an event, so `v_i` is the rate at the moment of touch, and the law is
//! built afresh for it ([`crate::contact::PreparedContact::law`], with the element's effective mass). Within
//! an impact the phase follows the rate (restitution from each turning point `v = 0`, approach again when `v`
//! turns positive, within the element's rate resolution, see [`crate::element::RateGate`]), as in OpenSees'
//! impact materials; a bilinear law reloads elastically up to its last turning point. The impact
//! ends when `d` returns to 0, or, for a law whose force is clamped, when the force first reaches 0 in
//! restitution; the contact then carries no force until `d` returns to 0 (if the ends approach again before
//! that, the same impact resumes).

use crate::contact::{ForceLaw, Phase, PreparedContact, Tension, Turn};
use crate::element::{Event, RateGate, Transition};
use crate::engine::Piece;
use crate::integrate::DenseComponent;
use crate::Error;

/// What a contact element is doing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Engagement {
    /// Apart (or touching without force): waiting for `d` to exceed 0.
    Open,
    /// In contact, with the law of the current impact.
    Contact {
        /// The law of this impact.
        law: ForceLaw,
        /// Approach or restitution.
        phase: Phase,
        /// The last turning point.
        turn: Turn,
    },
    /// Touching without closing: the penetration reached 0 while the ends were not approaching (a grazing
    /// touch, or ends at rest against each other). No force until they close (an impact starts) or part
    /// (`d <= 0`).
    Resting,
    /// A clamped force reached zero while `d > 0`: no force until `d <= 0` (or the ends approach again).
    Released {
        /// The law of the impact that was released.
        law: ForceLaw,
        /// Its last turning point.
        turn: Turn,
    },
}

/// Where the law of each impact comes from.
#[derive(Clone, Debug)]
pub enum LawSource {
    /// Built at every touch from a prepared contact model, with the impact velocity floored at
    /// `min_impact_velocity` (m/s).
    Prepared {
        /// The contact model with its damping parameter fixed.
        contact: PreparedContact,
        /// Smallest impact velocity used to build a law, m/s.
        min_impact_velocity: f64,
    },
    /// One given law (a single impact that starts engaged).
    Fixed,
}

/// A contact element.
#[derive(Clone, Debug)]
pub struct Contact {
    gap: f64,
    m_eff: f64,
    tension: Tension,
    source: LawSource,
    stop_at_end: bool,
    state: Engagement,
    pub(super) gate: RateGate,
}

impl Contact {
    /// An open contact with gap `gap` (m) at rest and effective mass `m_eff` (kg: `m_a m_b / (m_a + m_b)`, or
    /// the floor's mass against a rigid wall).
    pub fn new(contact: PreparedContact, gap: f64, m_eff: f64, min_impact_velocity: f64) -> Self {
        Self {
            gap,
            m_eff,
            tension: contact.spec().tension(),
            source: LawSource::Prepared {
                contact,
                min_impact_velocity,
            },
            stop_at_end: false,
            state: Engagement::Open,
            gate: RateGate::default(),
        }
    }

    /// A contact already touching (gap 0) at the start of an approach with `law`; the run stops when the
    /// impact ends.
    pub fn engaged(law: ForceLaw, tension: Tension, m_eff: f64) -> Self {
        Self {
            gap: 0.0,
            m_eff,
            tension,
            source: LawSource::Fixed,
            stop_at_end: true,
            state: Engagement::Contact {
                law,
                phase: Phase::Approach,
                turn: Turn::default(),
            },
            gate: RateGate::default(),
        }
    }

    /// The state's change-of-direction event function without its slack ([`RateGate`]), m/s: `v` while
    /// approaching, `-v` otherwise; `None` while open.
    pub(super) fn rate_event(&self, v: f64) -> Option<f64> {
        match self.state {
            Engagement::Open => None,
            Engagement::Contact {
                phase: Phase::Approach,
                ..
            } => Some(v),
            _ => Some(-v),
        }
    }

    /// Gap at rest, m.
    pub fn gap(&self) -> f64 {
        self.gap
    }
    /// Effective mass of an impact, kg.
    pub fn effective_mass(&self) -> f64 {
        self.m_eff
    }
    /// Tension rule.
    pub fn tension(&self) -> Tension {
        self.tension
    }
    /// What the contact is doing.
    pub fn state(&self) -> Engagement {
        self.state
    }

    /// Contact force, N (positive pushes the ends apart), at deformation `x` and rate `v`: the law continued
    /// smoothly past the end of contact, which is located as an event.
    #[inline]
    pub fn force(&self, x: f64, v: f64) -> f64 {
        match self.state {
            Engagement::Contact { law, phase, turn } => law.force(x - self.gap, v, phase, &turn),
            _ => 0.0,
        }
    }

    /// The force as reported: never negative for a clamped law, N.
    #[inline]
    pub fn reported_force(&self, x: f64, v: f64) -> f64 {
        let f = self.force(x, v);
        match self.tension {
            Tension::Clamp => f.max(0.0),
            Tension::Allow => f,
        }
    }

    /// The events to watch in the current state.
    pub fn watched(&self) -> &'static [Event] {
        let kinked = |law: &ForceLaw| law.kink(0.0, Phase::Approach, &Turn::default()).is_some();
        match self.state {
            Engagement::Open => &[Event::Touch],
            Engagement::Contact {
                law,
                phase: Phase::Approach,
                ..
            } => {
                if kinked(&law) {
                    &[Event::Turn, Event::Kink]
                } else {
                    &[Event::Turn]
                }
            }
            Engagement::Contact {
                law,
                phase: Phase::Restitution,
                ..
            } => match (self.tension, kinked(&law)) {
                (Tension::Clamp, true) => &[
                    Event::Separation,
                    Event::ZeroForce,
                    Event::Reapproach,
                    Event::Kink,
                ],
                (Tension::Clamp, false) => {
                    &[Event::Separation, Event::ZeroForce, Event::Reapproach]
                }
                (Tension::Allow, true) => &[Event::Separation, Event::Reapproach, Event::Kink],
                (Tension::Allow, false) => &[Event::Separation, Event::Reapproach],
            },
            Engagement::Released { .. } | Engagement::Resting => &[Event::Rearm, Event::Resume],
        }
    }

    /// Event function of `ev` at deformation `x` and rate `v`: positive before the event, <= 0 after.
    #[inline]
    pub fn event_value(&self, ev: Event, x: f64, v: f64) -> f64 {
        let d = x - self.gap;
        let (law, phase, turn) = match self.state {
            Engagement::Contact { law, phase, turn } => (Some(law), phase, turn),
            Engagement::Released { law, turn } => (Some(law), Phase::Restitution, turn),
            Engagement::Open | Engagement::Resting => (None, Phase::Approach, Turn::default()),
        };
        match ev {
            Event::Touch => -d,
            Event::Turn => v + self.gate.slack(),
            Event::Kink => law.and_then(|l| l.kink(d, phase, &turn)).unwrap_or(1.0),
            Event::ZeroForce => law.map_or(1.0, |l| l.force(d, v, phase, &turn)),
            Event::Separation | Event::Rearm => d,
            // A bilinear law reloads along its unloading line up to the last turning point, where the ends
            // must still be approaching.
            Event::Reapproach => match law {
                Some(ForceLaw::Bilinear { .. }) => (turn.d - d).max(self.gate.slack() - v),
                _ => self.gate.slack() - v,
            },
            Event::Resume => self.gate.slack() - v,
            _ => 1.0,
        }
    }

    /// Smallest impact velocity used to build a law, m/s (0 for a fixed law).
    pub fn min_impact_velocity(&self) -> f64 {
        match &self.source {
            LawSource::Prepared {
                min_impact_velocity,
                ..
            } => *min_impact_velocity,
            LawSource::Fixed => 0.0,
        }
    }

    /// The law of an impact starting at rate `v` (m/s), and the first step inside its time scale; `None` for
    /// a fixed law (it does not re-engage).
    fn impact_law(&self, v: f64, h: f64, out: &mut Transition) -> Result<Option<ForceLaw>, Error> {
        let LawSource::Prepared {
            contact,
            min_impact_velocity,
        } = &self.source
        else {
            return Ok(None);
        };
        let v_law = v.max(*min_impact_velocity);
        let (law, _) = contact.law(self.m_eff, v_law)?;
        // Start each impact with a step well inside its time scale (far inside for a law that is not smooth
        // at touch, see `impact::simulate`).
        let tau = law.length_scale(self.m_eff, v_law) / v_law;
        let f = if law.smooth_at_touch() { 1e-2 } else { 1e-8 };
        out.h_max = Some(h.min(f * tau));
        Ok(Some(law))
    }

    /// Applies `ev` at deformation `x` and rate `v`; `h` is the step the integrator would take next (s).
    pub fn apply(&mut self, ev: Event, x: f64, v: f64, h: f64) -> Result<Transition, Error> {
        let out = self.change(ev, x, v, h)?;
        self.gate.enter(self.rate_event(v));
        Ok(out)
    }

    fn change(&mut self, ev: Event, x: f64, v: f64, h: f64) -> Result<Transition, Error> {
        let d = x - self.gap;
        let mut out = Transition::default();
        self.state = match (self.state, ev) {
            // A touch while the ends are not closing starts no impact (a grazing touch, or resting contact).
            (Engagement::Open, Event::Touch) if v <= 0.0 => Engagement::Resting,
            (Engagement::Open, Event::Touch) | (Engagement::Resting, Event::Resume) => {
                match self.impact_law(v, h, &mut out)? {
                    Some(law) => Engagement::Contact {
                        law,
                        phase: Phase::Approach,
                        turn: Turn::default(),
                    },
                    None => return Ok(out),
                }
            }
            (Engagement::Resting, Event::Rearm) => Engagement::Open,
            (Engagement::Contact { law, .. }, Event::Turn) => Engagement::Contact {
                law,
                phase: Phase::Restitution,
                turn: Turn {
                    d,
                    force: law.force(d, v, Phase::Approach, &Turn::default()),
                },
            },
            (Engagement::Contact { law, turn, .. }, Event::Reapproach) => Engagement::Contact {
                law,
                phase: Phase::Approach,
                turn,
            },
            (Engagement::Contact { law, turn, .. }, Event::ZeroForce) => {
                out.stop = self.stop_at_end;
                Engagement::Released { law, turn }
            }
            (Engagement::Contact { .. }, Event::Separation) => {
                out.stop = self.stop_at_end;
                Engagement::Open
            }
            (Engagement::Released { .. }, Event::Rearm) => Engagement::Open,
            (Engagement::Released { law, turn }, Event::Resume) => Engagement::Contact {
                law,
                phase: Phase::Approach,
                turn,
            },
            (state, _) => state,
        };
        Ok(out)
    }
}

/// The force of a contact over one segment of a run, kept for locating its peak
/// ([`crate::engine::PeakTracker`]).
#[derive(Clone, Copy, Debug)]
pub struct ContactPiece {
    /// Start and end of the segment, s.
    pub span: (f64, f64),
    /// Deformation `x`, m.
    pub x: DenseComponent,
    /// Its rate, m/s.
    pub v: DenseComponent,
    law: ForceLaw,
    phase: Phase,
    turn: Turn,
    gap: f64,
    tension: Tension,
}

impl ContactPiece {
    /// Penetration (m), rate (m/s) and reported force (N) at `t`.
    pub fn at(&self, t: f64) -> (f64, f64, f64) {
        let (d, v) = (self.x.eval(t) - self.gap, self.v.eval(t));
        let f = self.law.force(d, v, self.phase, &self.turn);
        let f = match self.tension {
            Tension::Clamp => f.max(0.0),
            Tension::Allow => f,
        };
        (d, v, f)
    }
}

impl Piece for ContactPiece {
    fn span(&self) -> (f64, f64) {
        self.span
    }
    fn value(&self, t: f64) -> f64 {
        self.at(t).2
    }
}

impl Contact {
    /// The piece of force history on `span` with the interpolants of the deformation and its rate, if the
    /// contact is engaged.
    pub fn piece(
        &self,
        span: (f64, f64),
        x: DenseComponent,
        v: DenseComponent,
    ) -> Option<ContactPiece> {
        match self.state {
            Engagement::Contact { law, phase, turn } => Some(ContactPiece {
                span,
                x,
                v,
                law,
                phase,
                turn,
                gap: self.gap,
                tension: self.tension,
            }),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::{ContactModel, Model};

    fn contact(model: Model, k: f64) -> Contact {
        let mut c = Contact::new(
            ContactModel::new(model, k, 0.5).unwrap().prepare().unwrap(),
            0.0,
            1.0e5,
            1e-3,
        );
        c.gate.set_resolution(1e-6);
        c
    }

    #[test]
    fn a_turn_at_rest_waits_for_the_rate_to_clear_the_resolution() {
        // Floors pressed together at rest: approach and restitution flipped at one instant (gap 0,
        // k = 1e12 N/m, e = 0.01), and a bilinear law flipped between turn and reload (found by fuzzing).
        for model in [Model::Papi, Model::ImpactMaterial] {
            let mut c = contact(model, 1e12);
            c.apply(Event::Touch, 1e-9, 0.1, 1e-3).unwrap();
            // Touched at 0.1 m/s: the turn is located at v = 0 exactly.
            assert_eq!(c.event_value(Event::Turn, 2e-9, 0.0), 0.0);
            c.apply(Event::Turn, 2e-9, 0.0, 1e-3).unwrap();
            // Turned at v = 0: a rate of either sign below the resolution is no new approach.
            for v in [1e-9, -1e-9, 9e-7] {
                assert!(
                    c.event_value(Event::Reapproach, 2e-9, v) > 0.0,
                    "{model} {v}"
                );
            }
            assert!(c.event_value(Event::Reapproach, 2e-9, 1.1e-6) <= 0.0);
            // Once the ends part by more than the resolution, a new approach is located at v = 0 (and, for the
            // bilinear law, at the last turning point).
            c.gate.rearm(c.rate_event(-2e-6));
            assert_eq!(c.event_value(Event::Reapproach, 2e-9, 0.0), 0.0);
        }
    }
}
