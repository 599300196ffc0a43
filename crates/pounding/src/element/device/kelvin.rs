//! A Kelvin–Voigt unit: a spring and a dashpot in parallel, `f = k x + c x'`.

use super::{Device, Parameter, SpringDashpotParams};
use crate::element::{Affine, ElementEnergy, ElementLaw};
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

    /// Its affine force has no constant part.
    fn constant_force(&self) -> bool {
        false
    }

    fn affine(&self) -> Option<Affine> {
        Some(Affine {
            k: self.k,
            c: self.c,
            f0: 0.0,
            viscous: self.c,
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

/// `model = "kelvin"`: its parameters.
pub type KelvinParams = SpringDashpotParams;

impl Device for Kelvin {
    type Params = SpringDashpotParams;

    fn from_params(p: &SpringDashpotParams) -> Result<Self, Error> {
        let (k, c) = p.checked()?;
        Ok(Self { k, c })
    }

    fn parameters(p: &SpringDashpotParams) -> Vec<Parameter> {
        p.parameters()
    }
}
