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
use crate::element::{
    Affine, ElementEnergy, ElementLaw, Event, Notice, RateGate, Scales, Transition, Watch,
};
use crate::integrate::{brent_root, derivative, horner, DenseComponent, Piece, TERMS};
use crate::Error;

const TOUCH: Event = Event(0);
const TURN: Event = Event(1);
const KINK: Event = Event(2);
const ZERO_FORCE: Event = Event(3);
const SEPARATION: Event = Event(4);
const REAPPROACH: Event = Event(5);
const REARM: Event = Event(6);
const RESUME: Event = Event(7);
const FAST: Event = Event(8);

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
    /// Pressed: the ends close (or press) slower than `min_impact_velocity`, which is no impact but a contact
    /// under load. The elastic part of the law holds them apart, without its viscous part (built for a
    /// floored impact velocity, that part makes the pressed pair an overdamped system too stiff for any
    /// explicit step). Left when `d` returns to 0 (the impact ends), or when the ends close faster than
    /// `min_impact_velocity` (an impact at that velocity goes on from here).
    Held {
        /// The law whose elastic part holds.
        law: ForceLaw,
        /// Its last turning point.
        turn: Turn,
    },
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
/// A contact element: the impacts of one floor pair (or a floor and a wall), one after another.
#[derive(Clone, Debug)]
pub struct Contact {
    gap: f64,
    m_eff: f64,
    tension: Tension,
    source: LawSource,
    stop_at_end: bool,
    state: Engagement,
    gate: RateGate,
    /// Energy of the elastic part dropped when the force was released at a penetration (counted dissipated),
    /// less that taken up again when an impact resumed at one, J: keeps the contact's energy continuous
    /// through its changes of law ([`Contact::dissipated`]).
    dropped: f64,
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
            dropped: 0.0,
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
            dropped: 0.0,
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

    /// Energy the contact has dissipated, J, from its states `s`: the work of the viscous part of each law
    /// (its state integrates `(F - F_elastic) v`, never negative, so an elastic law dissipates exactly
    /// nothing whatever the integration error of the motion) and the elastic energy dropped when a clamped
    /// force was released at a penetration. For the bilinear loop, which has no elastic potential, its whole
    /// work. (The work of the whole force, the first state, differs from this plus the stored energy by the
    /// error of the integrated motion: a few 1e-4 of an impact's energy for stiff contacts at tolerance 1e-7,
    /// enough to make the dissipation of an elastic impact read -11 J out of 2.5e4 when it was taken from it.)
    pub fn dissipated(&self, s: &[f64]) -> f64 {
        s[1] + self.dropped
    }

    /// Energy stored in the elastic part of the law at deformation `x` (m), J: 0 unless engaged.
    fn stored(&self, x: f64) -> f64 {
        match self.state {
            Engagement::Contact { law, .. } | Engagement::Held { law, .. } => {
                law.elastic(x - self.gap).map_or(0.0, |(_, e)| e)
            }
            _ => 0.0,
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

    /// Contact force, N (positive pushes the ends apart), at deformation `x` and rate `v`: the law continued
    /// smoothly past the end of contact, which is located as an event.
    // Always: on the hint alone the compiler stopped inlining it into the right-hand side when other code
    // changed, 1.5 % more instructions on contact-heavy runs (callgrind, `isolated-moat`).
    #[inline(always)]
    fn law_force(&self, x: f64, v: f64) -> f64 {
        match self.state {
            Engagement::Contact { law, phase, turn } => law.force(x - self.gap, v, phase, &turn),
            Engagement::Held { law, .. } => law.elastic(x - self.gap).map_or(0.0, |(f, _)| f),
            _ => 0.0,
        }
    }

    /// Whether an approach at rate `v` (m/s) is held rather than an impact: slower than
    /// `min_impact_velocity`, with a law that has an elastic part to hold with.
    fn holds(&self, law: &ForceLaw, v: f64) -> bool {
        v < self.min_impact_velocity() && law.elastic(0.0).is_some()
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

    /// Changes the state for `ev` at deformation `x` and rate `v` (`h`: the integrator's next step, s), and
    /// says what happened to the impact.
    fn change(&mut self, ev: Event, x: f64, v: f64, h: f64) -> Result<Transition, Error> {
        let d = x - self.gap;
        let mut out = Transition::default();
        let started = Notice::ImpactStarted {
            resting: v < self.min_impact_velocity(),
        };
        let contact = |law, phase, turn| Engagement::Contact { law, phase, turn };
        let (state, notice) = match (self.state, ev) {
            // A touch while the ends are not closing starts no impact (a grazing touch, or resting contact).
            (Engagement::Open, TOUCH) if v <= 0.0 => (Engagement::Resting, None),
            (Engagement::Open, TOUCH) | (Engagement::Resting, RESUME) => {
                match self.impact_law(v, h, &mut out)? {
                    Some(law) if self.holds(&law, v) => (
                        Engagement::Held {
                            law,
                            turn: Turn::default(),
                        },
                        Some(started),
                    ),
                    Some(law) => (
                        contact(law, Phase::Approach, Turn::default()),
                        Some(started),
                    ),
                    None => return Ok(out),
                }
            }
            (Engagement::Held { .. }, SEPARATION) => {
                out.stop = self.stop_at_end;
                (Engagement::Open, Some(Notice::ImpactEnded))
            }
            // Closing as fast as an impact: the law approaches again (a law held from a touch at rest was
            // built for this velocity, the floor of impact velocities).
            (Engagement::Held { law, turn }, FAST) => (contact(law, Phase::Approach, turn), None),
            // Approaching again slower than an impact: held until it is one.
            (Engagement::Contact { law, turn, .. }, REAPPROACH) if self.holds(&law, v) => {
                (Engagement::Held { law, turn }, None)
            }
            (Engagement::Resting, REARM) => (Engagement::Open, Some(Notice::ContactCleared)),
            (Engagement::Contact { law, .. }, TURN) => {
                let force = law.force(d, v, Phase::Approach, &Turn::default());
                (
                    contact(law, Phase::Restitution, Turn { d, force }),
                    Some(Notice::ImpactTurned),
                )
            }
            (Engagement::Contact { law, turn, .. }, REAPPROACH) => {
                (contact(law, Phase::Approach, turn), None)
            }
            (Engagement::Contact { law, turn, .. }, ZERO_FORCE) => {
                out.stop = self.stop_at_end;
                (
                    Engagement::Released { law, turn },
                    Some(Notice::ImpactReleased),
                )
            }
            (Engagement::Contact { .. }, SEPARATION) => {
                out.stop = self.stop_at_end;
                (Engagement::Open, Some(Notice::ImpactEnded))
            }
            (Engagement::Released { .. }, REARM) => {
                (Engagement::Open, Some(Notice::ContactCleared))
            }
            (Engagement::Released { law, turn, .. }, RESUME) => (
                contact(law, Phase::Approach, turn),
                Some(Notice::ImpactResumed),
            ),
            (state, _) => (state, None),
        };
        // Dissipated + stored is continuous, as the work is: what a change of law adds to or takes from the
        // stored energy at this penetration is taken from or added to the dissipated.
        let before = self.stored(x);
        self.state = state;
        self.dropped += before - self.stored(x);
        out.notice = notice;
        Ok(out)
    }

    /// The piece of force history on `span` with the interpolants of the deformation and its rate, if the
    /// contact is engaged.
    pub fn piece(
        &self,
        span: (f64, f64),
        x: DenseComponent,
        v: DenseComponent,
    ) -> Option<ContactPiece> {
        let (law, phase, turn, held) = match self.state {
            Engagement::Contact { law, phase, turn } => (law, phase, turn, false),
            Engagement::Held { law, turn } => (law, Phase::Approach, turn, true),
            _ => return None,
        };
        Some(ContactPiece {
            span,
            x,
            v,
            law,
            phase,
            turn,
            held,
            gap: self.gap,
            tension: self.tension,
        })
    }
}

const TURN_W: Watch = Watch::crossing(TURN);
const KINK_W: Watch = Watch::kink(KINK);
const SEPARATION_W: Watch = Watch::crossing(SEPARATION);
/// In restitution the ends may part and close again within one step.
const PARTING_W: Watch = Watch::parting(SEPARATION);
const ZERO_FORCE_W: Watch = Watch::crossing(ZERO_FORCE);
const REAPPROACH_W: Watch = Watch::crossing(REAPPROACH);
const OPEN_W: &[Watch] = &[Watch::touch(TOUCH)];
const IDLE_W: &[Watch] = &[Watch::crossing(REARM), Watch::crossing(RESUME)];
const HELD_W: &[Watch] = &[SEPARATION_W, Watch::crossing(FAST)];

impl ElementLaw for Contact {
    fn name(&self) -> &'static str {
        "contact"
    }

    /// The work of the contact force on the relative motion (the energy balance's), and the work of its
    /// viscous part ([`Contact::dissipated`]; the whole force for a law without an elastic potential), J.
    fn states(&self) -> usize {
        2
    }

    /// Both works are of the order of the kinetic energy of an impact, `m_eff v^2`.
    fn state_tolerances(&self, scales: &Scales, out: &mut [f64]) {
        out[0] = scales.rtol * self.m_eff * scales.velocity * scales.velocity;
        out[1] = out[0];
    }

    /// Both works grow impact after impact: each impact is held as closely as the first.
    fn work_states(&self) -> std::ops::Range<usize> {
        0..2
    }

    #[inline(always)]
    fn evaluate(&self, x: f64, v: f64, _s: &[f64], ds: &mut [f64]) -> (f64, f64) {
        let f = self.law_force(x, v);
        let elastic = match self.state {
            Engagement::Contact { law, .. } | Engagement::Held { law, .. } => {
                law.elastic(x - self.gap).map_or(0.0, |(fe, _)| fe)
            }
            _ => 0.0,
        };
        ds[0] = f * v;
        ds[1] = (f - elastic) * v;
        (f, 0.0)
    }

    /// The force as reported: never negative for a clamped law, N.
    #[inline]
    fn force(&self, x: f64, v: f64, _s: &[f64]) -> f64 {
        let f = self.law_force(x, v);
        match self.tension {
            Tension::Clamp => f.max(0.0),
            Tension::Allow => f,
        }
    }

    #[inline]
    fn energy(&self, _x: f64, s: &[f64]) -> ElementEnergy {
        ElementEnergy {
            contact: s[0],
            ..ElementEnergy::default()
        }
    }

    /// A constant force `f0 = -k gap` only with a gap and a law linear while engaged (Hooke, Kelvin–Voigt):
    /// a Hertz-type contact is affine only open, where its force is 0, and takes no component of the exact
    /// state.
    fn constant_force(&self) -> bool {
        let linear = |law: ForceLaw| {
            law.linear(Phase::Approach).is_some() || law.linear(Phase::Restitution).is_some()
        };
        self.gap != 0.0
            && match &self.source {
                LawSource::Prepared { contact, .. } => contact
                    .law(self.m_eff, 1.0)
                    .map_or(true, |(law, _)| linear(law)),
                LawSource::Fixed => true,
            }
    }

    fn affine(&self) -> Option<Affine> {
        let (k, c) = match self.state {
            Engagement::Open | Engagement::Resting | Engagement::Released { .. } => (0.0, 0.0),
            Engagement::Contact { law, phase, .. } => law.linear(phase)?,
            Engagement::Held { law, .. } => (law.linear(Phase::Approach)?.0, 0.0),
        };
        Some(Affine {
            k,
            c,
            f0: -k * self.gap,
            viscous: 0.0,
        })
    }

    /// The work `f x'` and its viscous part `(f - f_elastic) x'` of a linear law (its elastic force
    /// `k (x - gap)`, so the viscous part is `c x'^2`).
    fn affine_rates(&self, a: &Affine, out: &mut [[f64; 3]]) -> bool {
        // Open, the force and its `f0 = -k gap` are 0: no work.
        let open = a.k == 0.0 && a.c == 0.0;
        out[0] = [a.k, a.c, if open { 0.0 } else { 1.0 }];
        out[1] = [0.0, a.c, 0.0];
        true
    }

    fn watched(&self) -> &'static [Watch] {
        let kinked = |law: &ForceLaw| law.kink(0.0, Phase::Approach, &Turn::default()).is_some();
        match self.state {
            Engagement::Open => OPEN_W,
            Engagement::Contact {
                law,
                phase: Phase::Approach,
                ..
            } => {
                if kinked(&law) {
                    &[TURN_W, KINK_W]
                } else {
                    &[TURN_W]
                }
            }
            Engagement::Contact {
                law,
                phase: Phase::Restitution,
                ..
            } => match (self.tension, kinked(&law)) {
                (Tension::Clamp, true) => &[PARTING_W, ZERO_FORCE_W, REAPPROACH_W, KINK_W],
                (Tension::Clamp, false) => &[PARTING_W, ZERO_FORCE_W, REAPPROACH_W],
                (Tension::Allow, true) => &[PARTING_W, REAPPROACH_W, KINK_W],
                (Tension::Allow, false) => &[PARTING_W, REAPPROACH_W],
            },
            Engagement::Released { .. } | Engagement::Resting => IDLE_W,
            Engagement::Held { .. } => HELD_W,
        }
    }

    fn events_read_states(&self) -> bool {
        false
    }

    #[inline]
    fn event_value(&self, ev: Event, x: f64, v: f64, _s: &[f64]) -> f64 {
        let d = x - self.gap;
        let (law, phase, turn) = match self.state {
            Engagement::Contact { law, phase, turn } => (Some(law), phase, turn),
            Engagement::Released { law, turn, .. } => (Some(law), Phase::Restitution, turn),
            Engagement::Held { law, turn } => (Some(law), Phase::Approach, turn),
            Engagement::Open | Engagement::Resting => (None, Phase::Approach, Turn::default()),
        };
        match ev {
            TOUCH => -d,
            TURN => v + self.gate.slack(),
            KINK => law.and_then(|l| l.kink(d, phase, &turn)).unwrap_or(1.0),
            ZERO_FORCE => law.map_or(1.0, |l| l.release_value(d, v, phase, &turn)),
            // Held floors part when `d` returns to 0 while they part: a hold that began at `d = 0` with the
            // floors closing at a vanishing rate does not end at once (it chattered between touch and end).
            SEPARATION if matches!(self.state, Engagement::Held { .. }) => d.max(v),
            SEPARATION | REARM => d,
            // A bilinear law reloads along its unloading line up to the last turning point, where the ends
            // must still be approaching.
            REAPPROACH => match law.and_then(|l| l.reload_limit(&turn)) {
                Some(limit) => (limit - d).max(self.gate.slack() - v),
                None => self.gate.slack() - v,
            },
            RESUME => self.gate.slack() - v,
            FAST => self.min_impact_velocity() - v,
            _ => 1.0,
        }
    }

    fn apply(&mut self, ev: Event, x: f64, v: f64, s: &[f64], h: f64) -> Result<Transition, Error> {
        let out = self.change(ev, x, v, h)?;
        self.gate.enter(self.rate_event(x, v, s));
        Ok(out)
    }

    fn gate(&self) -> Option<&RateGate> {
        Some(&self.gate)
    }

    fn gate_mut(&mut self) -> Option<&mut RateGate> {
        Some(&mut self.gate)
    }

    /// `v` while approaching, `-v` otherwise; `None` while open.
    fn rate_event(&self, _x: f64, v: f64, _s: &[f64]) -> Option<f64> {
        match self.state {
            Engagement::Open | Engagement::Held { .. } => None,
            Engagement::Contact {
                phase: Phase::Approach,
                ..
            } => Some(v),
            _ => Some(-v),
        }
    }
}

/// The force of a contact over one segment of a run, kept for locating its peak
/// ([`crate::integrate::PeakTracker`]).
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
    /// Pressed: the elastic part alone.
    held: bool,
    gap: f64,
    tension: Tension,
}

impl ContactPiece {
    /// Penetration (m), rate (m/s) and reported force (N) at `t`.
    pub fn at(&self, t: f64) -> (f64, f64, f64) {
        let (d, v) = (self.x.eval(t) - self.gap, self.v.eval(t));
        let f = if self.held {
            self.law.elastic(d).map_or(0.0, |(f, _)| f)
        } else {
            self.law.force(d, v, self.phase, &self.turn)
        };
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
    /// On an exact step of one piece under a linear law (`F = k d + c v`: Hooke, Kelvin–Voigt), the force is
    /// a polynomial in time: its largest value is at an end or where its rate, a polynomial too, turns from
    /// rising to falling (Brent's method on the rate), not searched by golden section.
    fn peak(&self) -> Option<(f64, f64)> {
        let (DenseComponent::Series { t0, c: x }, DenseComponent::Series { t0: tv, c: v }) =
            (self.x, self.v)
        else {
            return None;
        };
        let (k, c) = self.law.linear(self.phase).filter(|_| !self.held)?;
        if t0 != tv {
            return None;
        }
        let mut f: [f64; TERMS] = std::array::from_fn(|j| k * x[j] + c * v[j]);
        f[0] -= k * self.gap;
        let rate = derivative(&f);
        let clamp = |f: f64| match self.tension {
            Tension::Clamp => f.max(0.0),
            Tension::Allow => f,
        };
        let (ta, tb) = self.span;
        let (fa, fb) = (self.value(ta), self.value(tb));
        let mut best = if fb > fa { (tb, fb) } else { (ta, fa) };
        let r = |t: f64| horner(&rate, t - t0);
        let (ra, rb) = (r(ta), r(tb));
        if ra > 0.0 && rb < 0.0 {
            let tol = 4.0 * f64::EPSILON * tb.abs();
            if let Some(tm) = brent_root(r, ta, tb, ra, rb, tol) {
                let fm = clamp(horner(&f, tm - t0));
                if fm > best.1 {
                    best = (tm, fm);
                }
            }
        }
        Some(best)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::{ContactModel, Damping, Model};

    #[test]
    fn a_linear_laws_peak_on_an_exact_step_is_the_polynomial_s_extremum() {
        // x = gap + a t - b t^2, v = a - 2 b t on [0, 0.01] s: a Kelvin–Voigt force k (x - gap) + c v peaks
        // where k v + c v' = 0, t* = (k a - 2 b c) / (2 b k): found to rounding, and golden section on the
        // force agrees to its own accuracy (1e-12 of the force in value).
        let (gap, a, b, k, c) = (0.02, 0.4, 30.0, 2.0e9, 5.0e6);
        let mut cx = [0.0; TERMS];
        let mut cv = [0.0; TERMS];
        (cx[0], cx[1], cx[2]) = (gap, a, -b);
        (cv[0], cv[1]) = (a, -2.0 * b);
        let piece = ContactPiece {
            span: (1.0, 1.01),
            x: DenseComponent::Series { t0: 1.0, c: cx },
            v: DenseComponent::Series { t0: 1.0, c: cv },
            law: ForceLaw::LinearViscous { k, c, c_r: c },
            phase: Phase::Approach,
            turn: Turn::default(),
            held: false,
            gap,
            tension: Tension::Clamp,
        };
        let ts = (k * a - 2.0 * b * c) / (2.0 * b * k);
        let fs = k * (a * ts - b * ts * ts) + c * (a - 2.0 * b * ts);
        let (t, f) = piece.peak().expect("a linear law on an exact step");
        assert!((t - (1.0 + ts)).abs() < 1e-13, "{t} vs {}", 1.0 + ts);
        assert!((f - fs).abs() < 1e-15 * fs, "{f} vs {fs}");
        let (_, g) = crate::integrate::golden_max(|t| piece.value(t), 1.0, 1.01, 1e-14);
        assert!((g - f).abs() < 1e-12 * f, "{g} vs {f}");
        // A nonlinear law, or a held contact: searched by golden section.
        let hertz = ContactPiece {
            law: ForceLaw::Elastic { k, n: 1.5 },
            ..piece
        };
        assert!(hertz.peak().is_none());
    }

    fn contact(model: Model, k: f64) -> Contact {
        // The published formula: impact-material cannot deliver e = 0.5 at its default yield ratio.
        let law = ContactModel::new(model, k, 0.5).unwrap();
        let mut c = Contact::new(
            law.with_damping(Damping::Formula).prepare().unwrap(),
            0.0,
            1.0e5,
            1e-3,
        );
        c.gate.set_resolution(1e-6);
        c
    }

    #[test]
    fn a_contact_s_event_functions_do_not_read_its_states() {
        // The driver reads a law's states along a step while locating an event only if the law says its
        // event functions read them (`events_read_states`): a contact's never do, open or engaged.
        let mut c = contact(Model::KelvinVoigt, 2e9);
        assert!(!c.events_read_states());
        // Open, then approaching after a touch, then rebounding after the turn.
        for (ev, x, v) in [(TOUCH, 0.0, 1.0), (TURN, 1e-3, 0.0), (TOUCH, 0.0, 0.0)] {
            for w in c.watched() {
                for (x, v) in [(-1e-3, 0.5), (1e-3, -0.2), (0.0, 0.0), (2e-3, 1.5)] {
                    let (a, b) = (
                        c.event_value(w.event, x, v, &[0.0, 0.0]),
                        c.event_value(w.event, x, v, &[7.0, -3.0]),
                    );
                    assert_eq!(a, b, "{:?} at {x}, {v}", w.event);
                }
            }
            if c.watched().iter().any(|w| w.event == ev) {
                c.apply(ev, x, v, &[0.0, 0.0], 1e-4).unwrap();
            }
        }
        assert!(matches!(
            c.state,
            Engagement::Contact {
                phase: Phase::Restitution,
                ..
            }
        ));
    }

    #[test]
    fn only_a_gap_closed_by_a_law_linear_while_engaged_has_a_constant_force() {
        // f0 = -k gap while engaged: Hooke and Kelvin-Voigt with a gap have one; the same without a gap,
        // and Hertz-type laws (affine only open, force 0), have none.
        let with_gap = |model: Model, k: f64, gap: f64| {
            let law = ContactModel::new(model, k, 0.6).unwrap();
            Contact::new(law.prepare().unwrap(), gap, 1.0e5, 1e-3).constant_force()
        };
        assert!(with_gap(Model::Hooke, 2e9, 0.01));
        assert!(with_gap(Model::KelvinVoigt, 2e9, 0.01));
        assert!(!with_gap(Model::Hooke, 2e9, 0.0));
        assert!(!with_gap(Model::KelvinVoigt, 2e9, 0.0));
        for model in [Model::Hertz, Model::Hertzdamp] {
            assert!(!with_gap(model, 2e10, 0.01), "{model}");
        }
    }

    #[test]
    fn a_turn_at_rest_waits_for_the_rate_to_clear_the_resolution() {
        // Floors pressed together at rest: approach and restitution flipped at one instant (gap 0,
        // k = 1e12 N/m, e = 0.01), and a bilinear law flipped between turn and reload (found by fuzzing).
        for model in [Model::Papi, Model::ImpactMaterial] {
            let mut c = contact(model, 1e12);
            c.apply(TOUCH, 1e-9, 0.1, &[], 1e-3).unwrap();
            // Touched at 0.1 m/s: the turn is located at v = 0 exactly.
            assert_eq!(c.event_value(TURN, 2e-9, 0.0, &[]), 0.0);
            c.apply(TURN, 2e-9, 0.0, &[], 1e-3).unwrap();
            // Turned at v = 0: a rate of either sign below the resolution is no new approach.
            for v in [1e-9, -1e-9, 9e-7] {
                assert!(c.event_value(REAPPROACH, 2e-9, v, &[]) > 0.0, "{model} {v}");
            }
            assert!(c.event_value(REAPPROACH, 2e-9, 1.1e-6, &[]) <= 0.0);
            // Once the ends part by more than the resolution, a new approach is located at v = 0 (and, for the
            // bilinear law, at the last turning point).
            c.gate.rearm(c.rate_event(0.0, -2e-6, &[]));
            assert_eq!(c.event_value(REAPPROACH, 2e-9, 0.0, &[]), 0.0);
        }
    }

    #[test]
    fn notices_follow_the_impact() {
        // Touch, turn, separation of a tension-allowing law: started, turned, ended.
        let spec = ContactModel::new(Model::KelvinVoigt, 1e9, 0.5).unwrap();
        let mut c = Contact::new(spec.prepare().unwrap(), 0.0, 1.0e5, 1e-3);
        let n = |t: Transition| t.notice;
        assert_eq!(
            n(c.apply(TOUCH, 0.0, 0.5, &[], 1e-3).unwrap()),
            Some(Notice::ImpactStarted { resting: false })
        );
        assert_eq!(
            n(c.apply(TURN, 1e-3, 0.0, &[], 1e-3).unwrap()),
            Some(Notice::ImpactTurned)
        );
        assert_eq!(
            n(c.apply(SEPARATION, 0.0, -0.3, &[], 1e-3).unwrap()),
            Some(Notice::ImpactEnded)
        );
        // A touch slower than the smallest impact velocity is a resting contact.
        assert_eq!(
            n(c.apply(TOUCH, 0.0, 5e-4, &[], 1e-3).unwrap()),
            Some(Notice::ImpactStarted { resting: true })
        );
    }
}
