//! Elements: everything that adds a force between two points of a structure.
//!
//! An [`Element`] joins two ends, each a degree of freedom or the ground ([`End`]). Its deformation is
//! `x = u_a - u_b` (m) and its rate `x'` (m/s), where `u` is the displacement of an end relative to the
//! moving ground (0 for the ground itself). The element's force `f` (N) resists a growing `x`: it acts as
//! `-f` on end `a` and `+f` on end `b`, and the element absorbs the power `f x'`.
//!
//! - a storey joins floor `j` (end `a`) to floor `j - 1` or the ground (end `b`): `x` is the drift;
//! - a contact joins a floor of the left building (`a`) to a floor of its right neighbour (`b`), so its
//!   penetration is `x - gap`; against a wall on the right of a floor, `b` is the ground; on its left, `a` is;
//! - a device (spring, dashpot, Kelvin, Maxwell, restrainer) joins its ends as a contact does, for good.
//!
//! Each element kind says what force it adds, which extra ODE states it carries (Bouc–Wen's `z`, a contact's
//! work), which event functions it watches in its current phase, and how its phase changes when one fires
//! ([`Element::apply`]). The phase is plain data; the engine ([`crate::engine`]) drives all of it.

pub mod contact;
pub mod device;
pub mod storey;

pub use contact::{Contact, ContactPiece, Engagement, LawSource};
pub use device::{Device, DeviceLaw};
pub use storey::{Storey, StoreyLaw, StoreyState};

use crate::Error;

/// One end of an element: a degree of freedom (its index in the structure) or the ground.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum End {
    /// The (moving) ground: displacement 0 relative to itself.
    Ground,
    /// Degree of freedom `i`.
    Dof(usize),
}

impl End {
    /// The degree of freedom, if the end is not the ground.
    pub fn dof(self) -> Option<usize> {
        match self {
            End::Ground => None,
            End::Dof(i) => Some(i),
        }
    }
}

/// An event an element watches: the time at which its event function reaches 0 from above is located on
/// the integrator's interpolant, and the element's phase changes there.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Event {
    /// Contact, open: the penetration reaches 0 from below (first touch of an impact).
    Touch,
    /// Contact, approach: the penetration rate reaches 0 (largest penetration).
    Turn,
    /// Contact: a kink of a bilinear contact law (force continuous, slope not).
    Kink,
    /// Contact, restitution, clamped law: the force reaches 0.
    ZeroForce,
    /// Contact, restitution: the penetration returns to 0.
    Separation,
    /// Contact, restitution: the bodies approach again.
    Reapproach,
    /// Contact, released: the penetration returns to 0.
    Rearm,
    /// Contact, released: the bodies approach again before the penetration returned to 0.
    Resume,
    /// Storey: the force reaches the upper bound of the elastic range.
    YieldUp,
    /// Storey: the force reaches the lower bound of the elastic range.
    YieldDown,
    /// Storey: the drift rate changes sign while yielding (bilinear) or at any time (Bouc–Wen).
    Reversal,
    /// Restrainer: the opening reaches the slack.
    Taut,
    /// Restrainer: the opening returns below the slack.
    Slack,
}

/// What an element holds at one instant, J, split by where the energy went.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ElementEnergy {
    /// Recoverable strain energy of a storey, J.
    pub strain: f64,
    /// Energy dissipated by a storey's hysteresis, J.
    pub hysteretic: f64,
    /// Work of a contact force on the relative motion, J.
    pub contact: f64,
    /// Energy dissipated by a viscous part that is an ODE state (a Maxwell unit's dashpot), J.
    pub damping: f64,
}

/// What the engine should do after an element changed phase.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Transition {
    /// Largest next trial step, s (an impact starts with a step well inside its time scale).
    pub h_max: Option<f64>,
    /// Stop the run here (a single impact ends with its contact).
    pub stop: bool,
}

/// The resolution of an element's deformation rate, and whether its next change of direction (a contact's
/// turn or new approach, a storey's reversal) is armed. A phase entered at a rate within the resolution of 0
/// (every turning point; a touch, release or reversal at a vanishing rate) arms its next change only once the
/// rate is clear of 0 by the resolution; until then that change needs the rate to pass 0 by the resolution.
/// Floors pressed together at rest, or a stiff storey between floors that move together, have a rate at the
/// integrator's noise, whose sign flipped the phase back and forth at one instant. Changes after a real swing
/// are located exactly at a rate of 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RateGate {
    v_res: f64,
    armed: bool,
}

impl Default for RateGate {
    fn default() -> Self {
        Self {
            v_res: 0.0,
            armed: true,
        }
    }
}

impl RateGate {
    /// Sets the resolution, m/s.
    pub fn set_resolution(&mut self, v_res: f64) {
        self.v_res = v_res;
    }
    /// Whether the next change of direction is located at a rate of exactly 0.
    pub fn armed(&self) -> bool {
        self.armed
    }
    /// What a change-of-direction event function adds while disarmed, m/s.
    #[inline]
    pub fn slack(&self) -> f64 {
        if self.armed {
            0.0
        } else {
            self.v_res
        }
    }
    /// After a change of phase: armed if the new phase's change-of-direction function `g` (m/s; `None` if
    /// it has none) is already clear of 0.
    pub fn enter(&mut self, g: Option<f64>) {
        self.armed = g.is_none_or(|g| g > self.v_res);
    }
    /// After a step: arms once `g` is clear of 0.
    pub fn rearm(&mut self, g: Option<f64>) {
        if !self.armed {
            self.enter(g);
        }
    }
}

/// What kind of element, with its law and phase.
#[derive(Clone, Debug)]
pub enum Kind {
    /// A storey of a shear building.
    Storey(Storey),
    /// A contact (impact) element.
    Contact(Contact),
    /// A device between two ends.
    Device(Device),
}

/// An element: two ends and a kind.
#[derive(Clone, Debug)]
pub struct Element {
    /// End `a` (deformation `x = u_a - u_b`).
    pub a: End,
    /// End `b`.
    pub b: End,
    /// The element's law and phase.
    pub kind: Kind,
}

impl Element {
    /// A storey from floor `top` down to `bottom` (a floor or the ground).
    pub fn storey(top: usize, bottom: End, storey: Storey) -> Self {
        Self {
            a: End::Dof(top),
            b: bottom,
            kind: Kind::Storey(storey),
        }
    }

    /// A device whose deformation is `u_a - u_b`.
    pub fn device(a: End, b: End, device: Device) -> Self {
        Self {
            a,
            b,
            kind: Kind::Device(device),
        }
    }

    /// A contact whose penetration is `u_a - u_b - gap`.
    pub fn contact(a: End, b: End, contact: Contact) -> Self {
        Self {
            a,
            b,
            kind: Kind::Contact(contact),
        }
    }

    /// Number of extra ODE states the element carries.
    pub fn states(&self) -> usize {
        match &self.kind {
            Kind::Storey(s) => s.states(),
            Kind::Contact(_) => 1,
            Kind::Device(d) => d.states(),
        }
    }

    /// The element's forces at deformation `x` (m), rate `v` (m/s) and states `s`: `(f, f_viscous)`, N, the
    /// force of its law and the viscous force it adds (Rayleigh damping of a storey); the rates of its states
    /// go to `ds`.
    #[inline]
    pub fn evaluate(&self, x: f64, v: f64, s: &[f64], ds: &mut [f64]) -> (f64, f64) {
        match &self.kind {
            Kind::Storey(st) => st.evaluate(x, v, s, ds),
            Kind::Contact(c) => {
                let f = c.force(x, v);
                ds[0] = f * v;
                (f, 0.0)
            }
            Kind::Device(d) => d.evaluate(x, v, s, ds),
        }
    }

    /// The force of the element's law (without viscous damping), N.
    #[inline]
    pub fn force(&self, x: f64, v: f64, s: &[f64]) -> f64 {
        match &self.kind {
            Kind::Storey(st) => st.force(x, s),
            Kind::Contact(c) => c.force(x, v),
            Kind::Device(d) => d.force(x, s),
        }
    }

    /// Energy held or dissipated by the element's law, J.
    pub fn energy(&self, x: f64, s: &[f64]) -> ElementEnergy {
        match &self.kind {
            Kind::Storey(st) => {
                let (strain, hysteretic) = st.energy(x, s);
                ElementEnergy {
                    strain,
                    hysteretic,
                    ..ElementEnergy::default()
                }
            }
            Kind::Contact(_) => ElementEnergy {
                contact: s[0],
                ..ElementEnergy::default()
            },
            Kind::Device(d) => {
                let (strain, damping) = d.energy(x, s);
                ElementEnergy {
                    strain,
                    damping,
                    ..ElementEnergy::default()
                }
            }
        }
    }

    /// The events watched in the current phase.
    pub fn watched(&self) -> &'static [Event] {
        match &self.kind {
            Kind::Storey(s) => s.watched(),
            Kind::Contact(c) => c.watched(),
            Kind::Device(d) => d.watched(),
        }
    }

    /// Event function of `ev`: positive before the event, <= 0 at and after it.
    #[inline]
    pub fn event_value(&self, ev: Event, x: f64, v: f64) -> f64 {
        match &self.kind {
            Kind::Storey(s) => s.event_value(ev, x, v),
            Kind::Contact(c) => c.event_value(ev, x, v),
            Kind::Device(d) => d.event_value(ev, x),
        }
    }

    /// Whether `ev` leaves the phase as it is (a kink): once past, its function stays <= 0, so it is
    /// watched only from a positive start.
    pub fn keeps_phase(&self, ev: Event) -> bool {
        ev == Event::Kink
    }

    /// Sets the resolution of the deformation rate, m/s ([`RateGate`]).
    pub fn set_rate_resolution(&mut self, v_res: f64) {
        if let Some(g) = self.gate_mut() {
            g.set_resolution(v_res);
        }
    }

    /// The rate gate of a storey or contact (devices change phase on positions only).
    fn gate_mut(&mut self) -> Option<&mut RateGate> {
        match &mut self.kind {
            Kind::Storey(s) => Some(&mut s.gate),
            Kind::Contact(c) => Some(&mut c.gate),
            Kind::Device(_) => None,
        }
    }

    /// Arms the next change of direction once the rate `v` (m/s) is clear of 0 (called after every step
    /// while disarmed); returns whether it is still disarmed.
    #[inline]
    pub fn rearm(&mut self, v: f64) -> bool {
        let g = match &self.kind {
            Kind::Storey(s) => s.rate_event(v),
            Kind::Contact(c) => c.rate_event(v),
            Kind::Device(_) => None,
        };
        match self.gate_mut() {
            Some(gate) => {
                gate.rearm(g);
                !gate.armed()
            }
            None => false,
        }
    }

    /// Whether the next change of direction is located at a rate of exactly 0 ([`RateGate`]).
    pub fn armed(&self) -> bool {
        match &self.kind {
            Kind::Storey(s) => s.gate.armed(),
            Kind::Contact(c) => c.gate.armed(),
            Kind::Device(_) => true,
        }
    }

    /// Applies `ev` at deformation `x` and rate `v`.
    pub fn apply(&mut self, ev: Event, x: f64, v: f64, h: f64) -> Result<Transition, Error> {
        match &mut self.kind {
            Kind::Storey(s) => {
                s.apply(ev, x, v);
                Ok(Transition::default())
            }
            Kind::Contact(c) => c.apply(ev, x, v, h),
            Kind::Device(d) => {
                d.apply(ev);
                Ok(Transition::default())
            }
        }
    }
}
