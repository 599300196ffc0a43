//! The one interface of an element's law ([`ElementLaw`]), and the words the engine and the recorders share
//! with it: events ([`Event`], [`Watch`]), what happens when one fires ([`Transition`], [`Notice`]), energies
//! ([`ElementEnergy`]) and the scales of its states ([`Scales`]).

use super::RateGate;
use crate::Error;

/// An event a law watches, numbered by the law itself: what it means is the law's business. The driver
/// locates the time at which the law's event function reaches 0 from above and hands the event back to
/// the law ([`ElementLaw::apply`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Event(pub u8);

/// A watched event and how the driver treats its event function.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Watch {
    /// The event.
    pub event: Event,
    /// The event leaves the phase as it is (a kink of the law): once past, its function stays <= 0, so it
    /// is watched only from a positive start.
    pub keeps_phase: bool,
    /// The event function is a distance that may cross 0 and come back within one step, its ends both
    /// positive: where the deformation turns inside a step as this says, the driver searches the step for
    /// the function's smallest value rather than trusting its ends.
    pub graze: Option<Graze>,
}

/// Where a distance an event watches may dip below 0 and come back inside one step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Graze {
    /// At the deformation's largest value: a touch (the ends close and part again).
    AtLargest,
    /// At its smallest: a separation (the ends part and close again).
    AtSmallest,
}

impl Graze {
    /// Whether a deformation whose rates are `va` and `vb` (m/s) at a step's ends turns there as this
    /// says.
    pub fn turns(self, va: f64, vb: f64) -> bool {
        match self {
            Graze::AtLargest => va > 0.0 && vb < 0.0,
            Graze::AtSmallest => va < 0.0 && vb > 0.0,
        }
    }
}

impl Watch {
    /// An event that changes the phase where its function crosses 0.
    pub const fn crossing(event: Event) -> Self {
        Self {
            event,
            keeps_phase: false,
            graze: None,
        }
    }

    /// A kink of the law: the phase stays, the integration restarts there.
    pub const fn kink(event: Event) -> Self {
        Self {
            event,
            keeps_phase: true,
            graze: None,
        }
    }

    /// A touch: a closing distance that may come and go within one step.
    pub const fn touch(event: Event) -> Self {
        Self {
            event,
            keeps_phase: false,
            graze: Some(Graze::AtLargest),
        }
    }

    /// A separation: an opening distance that may come and go within one step.
    pub const fn parting(event: Event) -> Self {
        Self {
            event,
            keeps_phase: false,
            graze: Some(Graze::AtSmallest),
        }
    }
}

/// What a law says happened when one of its events fired: recorders listen to notices instead of
/// re-deriving them from the sequence of events.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Notice {
    /// An impact began: a touch while closing, or closing again from rest. `resting`: it closed slower
    /// than the smallest impact velocity a contact builds its law with.
    ImpactStarted {
        /// Closing slower than the contact's smallest impact velocity.
        resting: bool,
    },
    /// The impact reached its largest penetration (the turning point).
    ImpactTurned,
    /// A clamped force reached 0 with the ends still overlapping: the impact is over, unless the ends
    /// close again before they part ([`Notice::ImpactResumed`]).
    ImpactReleased,
    /// A released impact goes on: the ends closed again before they parted.
    ImpactResumed,
    /// The ends parted: the impact is over.
    ImpactEnded,
    /// A released or resting contact's penetration returned to 0: nothing is pending.
    ContactCleared,
    /// A hysteretic law left its elastic range.
    Yielded,
    /// A hysteretic law's deformation rate changed sign (a reversal of the loading direction).
    Reversed,
    /// A tension-only law became taut.
    Taut,
    /// A tension-only law became slack.
    Slack,
    /// A damper's velocity changed sign.
    DamperReversed,
}

/// What the engine should do after an element changed phase, and what it says happened.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Transition {
    /// Largest next trial step, s (an impact starts with a step well inside its time scale).
    pub h_max: Option<f64>,
    /// Stop the run here (a single impact ends with its contact).
    pub stop: bool,
    /// What happened, for the recorders.
    pub notice: Option<Notice>,
}

impl Transition {
    /// A transition that only says `notice`.
    pub fn notice(notice: Notice) -> Self {
        Self {
            notice: Some(notice),
            ..Self::default()
        }
    }
}

/// What an element holds at one instant, J, split by where the energy went.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ElementEnergy {
    /// Recoverable strain energy, J.
    pub strain: f64,
    /// Energy dissipated by hysteresis, J.
    pub hysteretic: f64,
    /// Work of a contact force on the relative motion, J.
    pub contact: f64,
    /// Energy dissipated by a viscous part that is an ODE state (a Maxwell unit's dashpot), J.
    pub damping: f64,
}

/// A law's force in its current phase as an affine function of the deformation and its rate:
/// `f + f_v = k x + c x' + f0`, where `f + f_v` is what [`ElementLaw::evaluate`] returns (law and viscous
/// force together). While every law of a run is affine, the engine propagates the motion exactly between
/// events ([`crate::engine`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Affine {
    /// Stiffness, N/m.
    pub k: f64,
    /// Viscous coefficient, N s/m.
    pub c: f64,
    /// Force at zero deformation and rate, N.
    pub f0: f64,
    /// The part of `c` whose force `evaluate` returns as its viscous force (counted as viscous damping in
    /// the energy balance), N s/m.
    pub viscous: f64,
}

/// Scales of the motion of an element's ends, from which a law sets the absolute tolerances of its own
/// states for the integrator's error control: the relative tolerance times the state's scale.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Scales {
    /// The relative tolerance of the integration (dimensionless).
    pub rtol: f64,
    /// Displacement the ends can reach, m.
    pub displacement: f64,
    /// Velocity that goes with it, m/s.
    pub velocity: f64,
    /// Energy the structure can take in, J.
    pub energy: f64,
}

/// The law of an element: its force as a function of the deformation `x = u_a - u_b` (m), its rate
/// `x'` (m/s) and its own ODE states; the events it watches and what they change; the energy it holds and
/// dissipates. The law and its phase are one value: a law is always in a phase of its own.
///
/// Every law of the library is a variant of [`crate::element::Law`], the one list (`element/registry.rs`);
/// the engine and the recorders see a law only through this interface.
pub trait ElementLaw {
    /// The law's name (`bilinear`, `contact`, `restrainer`, ...).
    fn name(&self) -> &'static str;

    /// Number of extra ODE states the law carries (Bouc–Wen's `z`, a contact's work).
    fn states(&self) -> usize {
        0
    }

    /// The absolute tolerance of each of its states, in its unit: the relative tolerance times the state's
    /// scale, from the scales of its ends' motion; written to `out` (one per state).
    fn state_tolerances(&self, _scales: &Scales, _out: &mut [f64]) {}

    /// Those of its states that accumulate a work over the whole run (J), held to their absolute tolerance
    /// alone ([`crate::integrate::Tolerance::absolute`]).
    fn work_states(&self) -> std::ops::Range<usize> {
        0..0
    }

    /// The force of the law and the viscous force it adds (N, resisting a growing `x`) at deformation `x`
    /// (m), rate `v` (m/s) and states `s`; the rates of its states go to `ds`. The viscous part is counted
    /// as viscous damping in the energy balance.
    fn evaluate(&self, x: f64, v: f64, s: &[f64], ds: &mut [f64]) -> (f64, f64);

    /// The force of the law as reported (a storey's shear, a contact's force, never tensile for a clamped
    /// contact), N, without a viscous part.
    fn force(&self, x: f64, v: f64, s: &[f64]) -> f64;

    /// The energy the law holds and has dissipated at deformation `x` (m) with states `s`, J.
    fn energy(&self, x: f64, s: &[f64]) -> ElementEnergy;

    /// The force of the current phase as an affine function of the deformation and its rate, valid until
    /// the law's next event ([`Affine`]); `None` for a nonlinear phase. A law answers only if its own
    /// states, if any, do not enter its force: their rates (a work, a dissipated energy) are then
    /// integrated along the exact motion.
    fn affine(&self) -> Option<Affine> {
        None
    }

    /// Whether [`Self::affine`] may answer a nonzero `f0` in some phase (a bilinear branch, a taut cable,
    /// a closed contact); `false` for a law whose affine force is always `k x + c x'` (the exact
    /// propagation then carries no constant force for it).
    fn constant_force(&self) -> bool {
        true
    }

    /// While [`Self::affine`] answers `a`, the rates of the law's states as `[p, q, r]` per state (written to
    /// `out`): `s' = p x x' + q x'^2 + r f0 x'` (x in m, x' in m/s, `f0` = `a.f0` in N; a power, W). What
    /// the engine integrates exactly over a whole record interval; `false` if the law cannot say (the
    /// default for a law with states), and then such intervals are stepped.
    fn affine_rates(&self, _a: &Affine, _out: &mut [[f64; 3]]) -> bool {
        self.states() == 0
    }

    /// The events watched in the current phase.
    fn watched(&self) -> &'static [Watch] {
        &[]
    }

    /// The event function of `ev` at deformation `x` (m), rate `v` (m/s) and states `s`: positive before
    /// the event, <= 0 at and after it.
    fn event_value(&self, _ev: Event, _x: f64, _v: f64, _s: &[f64]) -> f64 {
        1.0
    }

    /// Whether [`Self::event_value`] reads the states `s`: the driver reads them along a step while it
    /// locates an event only if so (on an exact step each reading integrates them to that time). A law
    /// whose event functions ignore them says `false`.
    fn events_read_states(&self) -> bool {
        true
    }

    /// Applies `ev`, located at deformation `x`, rate `v` and states `s`; `h` is the step the integrator
    /// would take next (s).
    fn apply(
        &mut self,
        _ev: Event,
        _x: f64,
        _v: f64,
        _s: &[f64],
        _h: f64,
    ) -> Result<Transition, Error> {
        Ok(Transition::default())
    }

    /// The law's rate gate, if its changes of direction are gated ([`RateGate`]).
    fn gate(&self) -> Option<&RateGate> {
        None
    }

    /// The law's rate gate, to change.
    fn gate_mut(&mut self) -> Option<&mut RateGate> {
        None
    }

    /// The change-of-direction event function of the current phase without its slack (m/s): what the rate
    /// gate waits on; `None` if the phase has none.
    fn rate_event(&self, _x: f64, _v: f64, _s: &[f64]) -> Option<f64> {
        None
    }
}
