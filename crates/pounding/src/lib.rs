//! # pounding
//!
//! Contact force models for collisions between bodies and earthquake-induced pounding between adjacent
//! structures, with exact calibration of their damping and event-located single-impact analysis.
//!
//! Units are SI throughout: m, s, kg, N; a contact stiffness `k` of exponent `n` is in N/m^n.
//!
//! - [`contact`]: the catalogue of models (`shared/design/contact-models.md`), their damping formulas and
//!   exact calibration, including the Papi & Toopchi-Nezhad (2022) model (the "seed").
//! - [`impact`]: one impact (two bodies, or a ball dropped on a slab), integrated with located events, and
//!   the exact relations it must agree with.
//! - [`element`]: everything that adds a force: storeys (linear, bilinear, Bouc–Wen) and contacts.
//! - [`engine`]: degrees of freedom, elements and the one driver that locates every event.
//! - [`integrate`]: the adaptive Dormand–Prince stepper with dense output and Brent's root finder.
//! - [`ground_motion`]: records (AT2, time/acceleration, values; built-in El Centro 1940), PGA/PGV/PGD.
//! - [`structure`]: lumped-mass shear buildings, their modes and Rayleigh damping.
//! - [`analysis`]: time-history analysis of pounding between adjacent buildings under a ground motion.
//! - [`paper`]: the reproduction of the seed's comparison (its Table 1).
//!
//! The library does no file or terminal I/O; the `pounding` command-line tool does.

pub(crate) mod error;

pub mod analysis;
pub mod contact;
pub mod element;
pub mod engine;
pub mod fragility;
pub mod ground_motion;
pub mod impact;
pub mod integrate;
pub mod limits;
pub mod paper;
#[cfg(feature = "serde")]
pub mod scenario;
pub mod separation;
pub mod structure;
pub mod words;

pub use error::Error;
