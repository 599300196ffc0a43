//! A linear spring, `f = k x`: a spring device, and the law of a linear storey or a linear isolator.

use super::{stiffness, Device, Parameter};
use crate::element::{Affine, ElementEnergy, ElementLaw};
use crate::Error;

/// A linear spring of stiffness `k` (N/m).
#[derive(Clone, Debug, PartialEq)]
pub struct Spring {
    k: f64,
}

impl Spring {
    /// A spring of stiffness `k`, N/m.
    pub fn new(k: f64) -> Self {
        Self { k }
    }
}

impl ElementLaw for Spring {
    fn name(&self) -> &'static str {
        "spring"
    }

    #[inline]
    fn evaluate(&self, x: f64, _v: f64, _s: &[f64], _ds: &mut [f64]) -> (f64, f64) {
        (self.k * x, 0.0)
    }

    #[inline]
    fn force(&self, x: f64, _v: f64, _s: &[f64]) -> f64 {
        self.k * x
    }

    /// Its affine force has no constant part.
    fn constant_force(&self) -> bool {
        false
    }

    fn affine(&self) -> Option<Affine> {
        Some(Affine {
            k: self.k,
            ..Affine::default()
        })
    }

    #[inline]
    fn energy(&self, x: f64, _s: &[f64]) -> ElementEnergy {
        ElementEnergy {
            strain: 0.5 * self.k * x * x,
            ..ElementEnergy::default()
        }
    }
}

/// `model = "spring"`: `f = k x`.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct SpringParams {
    /// Stiffness `k`, N/m.
    pub stiffness: f64,
}

impl Device for Spring {
    type Params = SpringParams;

    fn from_params(p: &SpringParams) -> Result<Self, Error> {
        Ok(Self::new(stiffness(p.stiffness)?))
    }

    fn parameters(p: &SpringParams) -> Vec<Parameter> {
        vec![Parameter {
            key: "stiffness",
            value: p.stiffness,
            unit: "N/m",
        }]
    }
}
