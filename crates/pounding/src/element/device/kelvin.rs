//! A Kelvin–Voigt unit: a spring and a dashpot in parallel, `f = k x + c x'`.

use super::{damping_coefficient, stiffness, Device, Parameter};
use crate::element::{ElementEnergy, ElementLaw};
use crate::Error;

/// A Kelvin unit: stiffness `k` (N/m) and damping coefficient `c` (N s/m) in parallel.
#[derive(Clone, Debug, PartialEq)]
pub struct Kelvin {
    k: f64,
    c: f64,
}

impl ElementLaw for Kelvin {
    fn name(&self) -> &'static str {
        "kelvin"
    }

    #[inline]
    fn evaluate(&self, x: f64, v: f64, _s: &[f64], _ds: &mut [f64]) -> (f64, f64) {
        (self.k * x, self.c * v)
    }

    /// The spring's force (the dashpot's is viscous), N.
    #[inline]
    fn force(&self, x: f64, _v: f64, _s: &[f64]) -> f64 {
        self.k * x
    }

    #[inline]
    fn energy(&self, x: f64, _s: &[f64]) -> ElementEnergy {
        ElementEnergy {
            strain: 0.5 * self.k * x * x,
            ..ElementEnergy::default()
        }
    }
}

/// `model = "kelvin"`: `f = k x + c x'`.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct KelvinParams {
    /// Stiffness `k`, N/m.
    pub stiffness: f64,
    /// Damping coefficient `c`, N s/m.
    pub damping_coefficient: f64,
}

impl Device for Kelvin {
    type Params = KelvinParams;

    fn from_params(p: &KelvinParams) -> Result<Self, Error> {
        Ok(Self {
            k: stiffness(p.stiffness)?,
            c: damping_coefficient(p.damping_coefficient, "damping_coefficient > 0 (N s/m)")?,
        })
    }

    fn parameters(p: &KelvinParams) -> Vec<Parameter> {
        vec![
            Parameter {
                key: "stiffness",
                value: p.stiffness,
                unit: "N/m",
            },
            Parameter {
                key: "damping_coefficient",
                value: p.damping_coefficient,
                unit: "N s/m",
            },
        ]
    }
}
