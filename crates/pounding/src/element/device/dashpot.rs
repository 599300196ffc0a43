//! A linear dashpot, `f = c x'`: its force is viscous, counted as viscous damping in the energy balance.

use super::{damping_coefficient, Device, Parameter};
use crate::element::{Affine, ElementEnergy, ElementLaw};
use crate::Error;

/// A linear dashpot of coefficient `c` (N s/m).
#[derive(Clone, Debug, PartialEq)]
pub struct Dashpot {
    c: f64,
}

impl Dashpot {
    /// A dashpot of coefficient `c`, N s/m.
    pub fn new(c: f64) -> Self {
        Self { c }
    }
}

impl ElementLaw for Dashpot {
    fn name(&self) -> &'static str {
        "dashpot"
    }

    #[inline]
    fn evaluate(&self, _x: f64, v: f64, _s: &[f64], _ds: &mut [f64]) -> (f64, f64) {
        (0.0, self.c * v)
    }

    /// A dashpot has no elastic force.
    #[inline]
    fn force(&self, _x: f64, _v: f64, _s: &[f64]) -> f64 {
        0.0
    }

    /// Its affine force has no constant part.
    fn constant_force(&self) -> bool {
        false
    }

    fn affine(&self) -> Option<Affine> {
        Some(Affine {
            c: self.c,
            viscous: self.c,
            ..Affine::default()
        })
    }

    #[inline]
    fn energy(&self, _x: f64, _s: &[f64]) -> ElementEnergy {
        ElementEnergy::default()
    }
}

/// `model = "dashpot"`: `f = c x'`.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct DashpotParams {
    /// Damping coefficient `c`, N s/m.
    pub damping_coefficient: f64,
}

impl Device for Dashpot {
    type Params = DashpotParams;

    fn from_params(p: &DashpotParams) -> Result<Self, Error> {
        Ok(Self::new(damping_coefficient(
            p.damping_coefficient,
            "damping_coefficient > 0 (N s/m)",
        )?))
    }

    fn parameters(p: &DashpotParams) -> Vec<Parameter> {
        vec![Parameter {
            key: "damping_coefficient",
            value: p.damping_coefficient,
            unit: "N s/m",
        }]
    }
}
