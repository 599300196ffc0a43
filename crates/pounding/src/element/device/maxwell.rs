//! A Maxwell unit: a spring and a dashpot in series, `f = k (x - x_d)`, `x_d' = f / c`, with the dashpot's
//! stroke `x_d` (m) and the energy it dissipated, `int f^2 / c dt` (J), as ODE states.

use super::{Device, Parameter, SpringDashpotParams};
use crate::element::{ElementEnergy, ElementLaw, Scales};
use crate::Error;

/// A Maxwell unit: stiffness `k` (N/m) in series with a dashpot of coefficient `c` (N s/m).
#[derive(Clone, Debug, PartialEq)]
pub struct Maxwell {
    k: f64,
    c: f64,
}

impl ElementLaw for Maxwell {
    fn name(&self) -> &'static str {
        "maxwell"
    }

    fn states(&self) -> usize {
        2
    }

    /// The stroke as its ends' displacements; the energy it dissipated as the structure's.
    fn state_tolerances(&self, scales: &Scales, out: &mut [f64]) {
        out[0] = scales.rtol * scales.displacement;
        out[1] = scales.rtol * scales.energy;
    }

    #[inline]
    fn evaluate(&self, x: f64, v: f64, s: &[f64], ds: &mut [f64]) -> (f64, f64) {
        let f = self.force(x, v, s);
        ds[0] = f / self.c;
        ds[1] = f * f / self.c;
        (f, 0.0)
    }

    #[inline]
    fn force(&self, x: f64, _v: f64, s: &[f64]) -> f64 {
        self.k * (x - s[0])
    }

    /// The spring's `f^2 / 2k`, and the dashpot's dissipated energy (a state).
    #[inline]
    fn energy(&self, x: f64, s: &[f64]) -> ElementEnergy {
        let f = self.force(x, 0.0, s);
        ElementEnergy {
            strain: 0.5 * f * f / self.k,
            damping: s[1],
            ..ElementEnergy::default()
        }
    }
}

/// `model = "maxwell"`: its parameters.
pub type MaxwellParams = SpringDashpotParams;

impl Device for Maxwell {
    type Params = SpringDashpotParams;

    fn from_params(p: &SpringDashpotParams) -> Result<Self, Error> {
        let (k, c) = p.checked()?;
        Ok(Self { k, c })
    }

    fn parameters(p: &SpringDashpotParams) -> Vec<Parameter> {
        p.parameters()
    }
}
