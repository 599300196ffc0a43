//! Elements: everything that adds a force between two points of a structure, each a law behind one
//! interface ([`ElementLaw`]).
//!
//! An [`Element`] joins two ends, each a degree of freedom or the ground ([`End`]). Its deformation is
//! `x = u_a - u_b` (m) and its rate `x'` (m/s), where `u` is the displacement of an end relative to the
//! moving ground (0 for the ground itself). The element's force `f` (N) resists a growing `x`: it acts as
//! `-f` on end `a` and `+f` on end `b`, and the element absorbs the power `f x'`.
//!
//! - a storey joins floor `j` (end `a`) to floor `j - 1` or the ground (end `b`): `x` is the drift; its law
//!   is linear (a [`device::Spring`]), [`storey::Bilinear`] or [`storey::BoucWen`];
//! - a contact ([`Contact`]) joins a floor of the left building (`a`) to a floor of its right neighbour
//!   (`b`), so its penetration is `x - gap`; against a wall on the right of a floor, `b` is the ground; on its
//!   left, `a` is;
//! - a device ([`device`]) joins its ends as a contact does, for good.
//!
//! A law owns its phase and its ODE states (Bouc–Wen's `z`, a contact's work): it says what force it adds,
//! which event functions it watches in its current phase, what happens when one fires
//! ([`ElementLaw::apply`]), and what it has to say about it ([`Notice`]: an impact started, a storey
//! yielded). The list of laws is one place, `registry.rs` ([`Law`]); the engine ([`crate::engine`]) drives
//! them all without knowing any.

mod contact;
pub mod device;
mod ends;
mod gate;
mod law;
mod registry;
pub mod storey;

pub use contact::{Contact, ContactPiece, Engagement, LawSource};
pub use ends::{Element, End, Point};
pub use gate::RateGate;
pub use law::{Affine, ElementEnergy, ElementLaw, Event, Graze, Notice, Scales, Transition, Watch};
pub use registry::{DeviceLaw, Law};
pub use storey::{BoucWenShape, StoreyLaw, StoreyModel};
