//! Devices: permanent connections between two ends (floors of neighbouring structures, or a floor and the
//! ground beside it), each model a law of its own file: [`Spring`], [`Dashpot`], [`Kelvin`] and
//! [`Maxwell`] units, [`Restrainer`]s and [`FluidViscous`] dampers.
//!
//! The deformation is `x = u_a - u_b` (m, closing positive, as for contacts) and the device's force `f` (N)
//! resists a growing `x`. A device model is its law plus its parameters as a scenario gives them
//! ([`Device::Params`]); the list of models is `element/registry.rs` ([`crate::element::DeviceLaw`]).

mod dashpot;
mod fluid_viscous;
mod kelvin;
mod maxwell;
mod restrainer;
mod spring;

pub use dashpot::{Dashpot, DashpotParams};
pub use fluid_viscous::{FluidViscous, FluidViscousParams};
pub use kelvin::{Kelvin, KelvinParams};
pub use maxwell::{Maxwell, MaxwellParams};
pub use restrainer::{Restrainer, RestrainerParams};
pub use spring::{Spring, SpringParams};

use crate::element::ElementLaw;
use crate::error::check;
use crate::Error;

/// One parameter of a device, for messages and tables: its key in a scenario, its value and its unit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Parameter {
    /// The key (`stiffness`, `damping_coefficient`, ...).
    pub key: &'static str,
    /// Its value, in `unit`.
    pub value: f64,
    /// Its unit (`N/m`, `N s/m`, ...).
    pub unit: &'static str,
}

/// A device model: a law built from the parameters a scenario gives.
pub trait Device: ElementLaw + Sized {
    /// The parameters (the keys of a `[[device]]` entry besides its name, ends and floors), SI units.
    type Params: Clone + std::fmt::Debug + PartialEq;

    /// The law, at rest, of a device with parameters `p`, checked: a value out of range is an
    /// [`Error::Parameter`] naming its key.
    fn from_params(p: &Self::Params) -> Result<Self, Error>;

    /// The parameters with their keys and units, in the order a table shows them.
    fn parameters(p: &Self::Params) -> Vec<Parameter>;
}

/// The parameters of a spring and a linear dashpot: `model = "kelvin"` (in parallel) and `"maxwell"` (in
/// series).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct SpringDashpotParams {
    /// Stiffness `k`, N/m.
    pub stiffness: f64,
    /// Damping coefficient `c`, N s/m.
    pub damping_coefficient: f64,
}

impl SpringDashpotParams {
    /// `(k, c)` (N/m, N s/m), checked.
    pub(crate) fn checked(&self) -> Result<(f64, f64), Error> {
        Ok((
            stiffness(self.stiffness)?,
            damping_coefficient(self.damping_coefficient, "damping_coefficient > 0 (N s/m)")?,
        ))
    }

    /// The two parameters with their keys and units.
    pub(crate) fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter {
                key: "stiffness",
                value: self.stiffness,
                unit: "N/m",
            },
            Parameter {
                key: "damping_coefficient",
                value: self.damping_coefficient,
                unit: "N s/m",
            },
        ]
    }
}

/// A stiffness `k > 0` (N/m), checked under the key `stiffness`.
pub(crate) fn stiffness(k: f64) -> Result<f64, Error> {
    check(
        "stiffness",
        k,
        k > 0.0 && k.is_finite(),
        "stiffness > 0 (N/m)",
    )
}

/// A damping coefficient `c > 0`, checked under the key `damping_coefficient` (`unit` as it applies).
pub(crate) fn damping_coefficient(c: f64, allowed: &'static str) -> Result<f64, Error> {
    check("damping_coefficient", c, c > 0.0 && c.is_finite(), allowed)
}
