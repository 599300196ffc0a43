//! Storeys: the shear force of one storey as a function of its drift history (`docs/structures.md`).
//!
//! The drift `x` (m) of storey `j` is `u_j - u_{j-1}`; its force `F` (N) is the restoring force of the
//! storey's law: linear (a [`crate::element::device::Spring`]), [`Bilinear`] or [`BoucWen`]. Rayleigh damping
//! on the initial stiffness (`C = a0 M + a1 K_0`, OpenSees' `betaKinit`) adds the viscous force `a1 k x'` of
//! each storey as the element's parallel dashpot; the mass-proportional part acts between each floor and the
//! ground and belongs to the structure, not to the storey.

mod bilinear;
mod bouc_wen;

pub use bilinear::{Bilinear, BilinearPhase};
pub use bouc_wen::BoucWen;

use crate::element::device::Spring;
use crate::element::Law;
use crate::error::check;
use crate::Error;

crate::named! {
    /// The storey laws, by name (a building's `storey_model`).
    pub enum StoreyModel: "storey_model" {
        /// `F = k x`.
        Linear = "linear",
        /// Bilinear with kinematic hardening ([`StoreyLaw::Bilinear`]).
        Bilinear = "bilinear",
        /// Bouc–Wen ([`StoreyLaw::BoucWen`]).
        BoucWen = "bouc-wen",
    }
}

/// The shape parameters of the Bouc–Wen law (dimensionless): `n`, `beta`, `gamma`. Defaults `n = 1`,
/// `beta = gamma = 0.5` (a smooth transition; `beta + gamma = 1` makes `F_y` the asymptotic hysteretic
/// force).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(default, deny_unknown_fields))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct BoucWenShape {
    /// Sharpness of the transition, >= 1 (default 1).
    pub n: f64,
    /// `beta` (default 0.5).
    pub beta: f64,
    /// `gamma` (default 0.5).
    pub gamma: f64,
}

impl Default for BoucWenShape {
    fn default() -> Self {
        Self {
            n: 1.0,
            beta: 0.5,
            gamma: 0.5,
        }
    }
}

/// The force–drift law of one storey.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StoreyLaw {
    /// `F = k x`.
    Linear,
    /// Bilinear with kinematic hardening: initial stiffness `k`, yield force `F_y` (N), post-yield stiffness
    /// `a k`. The elastic range has width `2 F_y` and moves with the back-force; `a = 0` is
    /// elastic–perfectly-plastic. Equal to OpenSees `Steel01(E0 = k, Fy, b = a)` without isotropic hardening.
    Bilinear {
        /// Storey shear at first yield, N.
        yield_force: f64,
        /// Post-yield over initial stiffness `a`, in [0, 1).
        post_yield_ratio: f64,
    },
    /// Bouc–Wen (Wen 1976, normalised form, `A = 1`): `F = a k x + (1 - a) F_y z`,
    /// `z' = (x' - beta |x'| |z|^(n-1) z - gamma x' |z|^n) / d_y`, `d_y = F_y / k`.
    BoucWen {
        /// Yield force `F_y`, N (the asymptotic hysteretic force when `beta + gamma = 1`).
        yield_force: f64,
        /// Post-yield over initial stiffness `a`, in [0, 1).
        post_yield_ratio: f64,
        /// Exponent `n` (>= 1; larger is sharper).
        n: f64,
        /// `beta` (dimensionless).
        beta: f64,
        /// `gamma` (dimensionless).
        gamma: f64,
    },
}

impl StoreyLaw {
    /// A validated bilinear law: `yield_force > 0` (N), `post_yield_ratio` in [0, 1).
    pub fn bilinear(yield_force: f64, post_yield_ratio: f64) -> Result<Self, Error> {
        Ok(StoreyLaw::Bilinear {
            yield_force: check_yield(yield_force)?,
            post_yield_ratio: check_ratio(post_yield_ratio)?,
        })
    }

    /// A validated Bouc–Wen law: `yield_force > 0` (N), `post_yield_ratio` in [0, 1), `n >= 1`, and
    /// `beta >= 0` with `beta + gamma > 0`, which keeps `|z|` bounded by `(1 / (beta + gamma))^(1/n)` (with
    /// `A = 1`: loading drives `z` towards that bound, and unloading never drives it away from 0 only when
    /// `beta >= 0`). The range of docs/structures.md (`beta, gamma >= 0`) is inside this one.
    pub fn bouc_wen(
        yield_force: f64,
        post_yield_ratio: f64,
        n: f64,
        beta: f64,
        gamma: f64,
    ) -> Result<Self, Error> {
        check(
            "bouc_wen.n",
            n,
            (1.0..=100.0).contains(&n),
            "1 <= n <= 100 (n < 1 makes z' non-Lipschitz at z = 0)",
        )?;
        check(
            "bouc_wen.beta",
            beta,
            beta >= 0.0,
            "beta >= 0 (beta < 0 lets |z| grow without bound on unloading)",
        )?;
        check(
            "bouc_wen.gamma",
            gamma,
            beta + gamma > 0.0,
            "beta + gamma > 0 (otherwise |z| grows without bound on loading)",
        )?;
        Ok(StoreyLaw::BoucWen {
            yield_force: check_yield(yield_force)?,
            post_yield_ratio: check_ratio(post_yield_ratio)?,
            n,
            beta,
            gamma,
        })
    }

    /// Yield force, N (`None` for a linear storey).
    pub fn yield_force(&self) -> Option<f64> {
        match *self {
            StoreyLaw::Linear => None,
            StoreyLaw::Bilinear { yield_force, .. } | StoreyLaw::BoucWen { yield_force, .. } => {
                Some(yield_force)
            }
        }
    }

    /// The same law with yield force `f` (N; a linear law stays linear).
    pub fn with_yield_force(mut self, f: f64) -> Self {
        match &mut self {
            StoreyLaw::Linear => {}
            StoreyLaw::Bilinear { yield_force, .. } | StoreyLaw::BoucWen { yield_force, .. } => {
                *yield_force = f
            }
        }
        self
    }

    /// Whether the law dissipates energy by hysteresis.
    pub fn is_inelastic(&self) -> bool {
        self.yield_force().is_some()
    }

    /// The element law of a storey of initial stiffness `k` (N/m) with this law, at rest.
    pub fn law(&self, k: f64) -> Law {
        match *self {
            StoreyLaw::Linear => Law::Spring(Spring::new(k)),
            StoreyLaw::Bilinear {
                yield_force,
                post_yield_ratio,
            } => Law::Bilinear(Bilinear::new(k, yield_force, post_yield_ratio)),
            StoreyLaw::BoucWen {
                yield_force,
                post_yield_ratio,
                n,
                beta,
                gamma,
            } => Law::BoucWen(BoucWen::new(
                k,
                yield_force,
                post_yield_ratio,
                n,
                beta,
                gamma,
            )),
        }
    }

    /// Its model.
    pub fn model(&self) -> StoreyModel {
        match self {
            StoreyLaw::Linear => StoreyModel::Linear,
            StoreyLaw::Bilinear { .. } => StoreyModel::Bilinear,
            StoreyLaw::BoucWen { .. } => StoreyModel::BoucWen,
        }
    }

    /// Short name: `linear`, `bilinear`, `bouc-wen`.
    pub fn name(&self) -> &'static str {
        self.model().name()
    }
}

fn check_yield(f: f64) -> Result<f64, Error> {
    check("yield_forces", f, f > 0.0, "yield_forces > 0 (N)")
}

fn check_ratio(a: f64) -> Result<f64, Error> {
    check(
        "post_yield_ratio",
        a,
        (0.0..1.0).contains(&a),
        "0 <= post_yield_ratio < 1",
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn invalid_laws_are_refused_with_their_key() {
        let name = |r: Result<StoreyLaw, Error>| match r {
            Err(Error::Parameter { name, .. }) => name,
            other => panic!("{other:?}"),
        };
        assert_eq!(name(StoreyLaw::bilinear(0.0, 0.05)), "yield_forces");
        assert_eq!(name(StoreyLaw::bilinear(1.0, 1.0)), "post_yield_ratio");
        assert_eq!(name(StoreyLaw::bilinear(1.0, -0.1)), "post_yield_ratio");
        assert_eq!(
            name(StoreyLaw::bouc_wen(1.0, 0.0, 1.0, -0.1, 0.5)),
            "bouc_wen.beta"
        );
        assert_eq!(
            name(StoreyLaw::bouc_wen(1.0, 0.0, 1.0, 0.2, -0.3)),
            "bouc_wen.gamma"
        );
        assert_eq!(
            name(StoreyLaw::bouc_wen(1.0, 0.0, 0.5, 0.5, 0.5)),
            "bouc_wen.n"
        );
        assert!(StoreyLaw::bouc_wen(1.0, 0.0, 2.0, 0.9, -0.1).is_ok());
    }
}
