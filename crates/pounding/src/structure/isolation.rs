//! Base isolation: the isolator as the lowest storey of a building, under its base slab.
//!
//! A building isolated at its base is a shear building whose storey 1 is the isolator: floor 1 is the base
//! slab, the isolator joins it to the ground, and the superstructure stands on the slab. Damping follows the
//! usual convention for isolated buildings (e.g. Naeim & Kelly, *Design of Seismic Isolated Structures*,
//! 1999, ch. 3; ASCE 7-22 §17.6): the superstructure is damped classically on its fixed-base modes
//! (Rayleigh, `C_s = a0 M_s + a1 K_s` with the ratio `damping_ratio` on its modes 1 and 2, floor 1 held
//! fixed), so that its mass-proportional part acts on the velocities relative to the base slab, not to the
//! ground; the isolator dissipates by its hysteresis only, plus an optional viscous coefficient of its own.
//! Rayleigh damping of the whole building would add mass-proportional damping to the isolation mode, which
//! the isolator does not have.

use crate::element::StoreyLaw;
use crate::error::check;
use crate::Error;

crate::named! {
    /// The isolator laws, by name (an isolator's `model`).
    pub enum IsolatorKind: "model" {
        /// A linear bearing ([`IsolatorModel::Linear`]).
        Linear = "linear",
        /// A bilinear bearing ([`IsolatorModel::Bilinear`]).
        Bilinear = "bilinear",
        /// A Bouc–Wen bearing ([`IsolatorModel::BoucWen`]).
        BoucWen = "bouc-wen",
        /// A friction pendulum ([`IsolatorModel::FrictionPendulum`]).
        FrictionPendulum = "friction-pendulum",
    }
}

/// The force–displacement law of an isolator (serialised as `{"model": name, its parameters}`).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(tag = "model", rename_all = "kebab-case"))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub enum IsolatorModel {
    /// A linear (elastomeric) bearing: `F = k d`.
    Linear {
        /// Stiffness, N/m.
        stiffness: f64,
    },
    /// A bilinear bearing with kinematic hardening (a lead-rubber bearing; OpenSees `Steel01`), as the
    /// bilinear storey law ([`StoreyLaw::Bilinear`]).
    Bilinear {
        /// Initial stiffness, N/m.
        stiffness: f64,
        /// Yield force, N.
        yield_force: f64,
        /// Post-yield over initial stiffness, in [0, 1).
        post_yield_ratio: f64,
    },
    /// A Bouc–Wen bearing ([`StoreyLaw::BoucWen`]).
    BoucWen {
        /// Initial stiffness, N/m.
        stiffness: f64,
        /// Yield force, N.
        yield_force: f64,
        /// Post-yield over initial stiffness, in [0, 1).
        post_yield_ratio: f64,
        /// Exponent n (>= 1).
        n: f64,
        /// beta (dimensionless).
        beta: f64,
        /// gamma (dimensionless).
        gamma: f64,
    },
    /// A single concave friction pendulum (Zayas, Low & Mahin 1990; Constantinou et al.): restoring
    /// stiffness `W / R` and friction `mu W`, `F = (W / R) d + mu W z`, with `W` the weight of everything
    /// above the isolator and `z` a Bouc–Wen variable (A = 1, beta = gamma = 0.5, n = 2) of yield
    /// displacement `d_y`, the customary smooth stand-in for rigid–plastic friction. This is exactly
    /// [`StoreyLaw::BoucWen`] with initial stiffness `k = W / R + mu W / d_y`, yield force `k d_y` and
    /// post-yield ratio `(W / R) / k`. Friction independent of velocity and pressure; no uplift.
    FrictionPendulum {
        /// Radius of curvature of the sliding surface, m.
        radius: f64,
        /// Coefficient of friction (dimensionless).
        mu: f64,
        /// Yield displacement of the friction variable, m.
        yield_displacement: f64,
    },
}

/// Default yield displacement of a friction pendulum's friction variable, m (a few tenths of a millimetre
/// is customary; smaller is closer to rigid–plastic friction and stiffer to integrate).
pub const FRICTION_YIELD_DISPLACEMENT: f64 = 2.5e-4;

impl IsolatorModel {
    /// Its kind.
    pub fn kind(&self) -> IsolatorKind {
        match self {
            IsolatorModel::Linear { .. } => IsolatorKind::Linear,
            IsolatorModel::Bilinear { .. } => IsolatorKind::Bilinear,
            IsolatorModel::BoucWen { .. } => IsolatorKind::BoucWen,
            IsolatorModel::FrictionPendulum { .. } => IsolatorKind::FrictionPendulum,
        }
    }

    /// Short name: `linear`, `bilinear`, `bouc-wen`, `friction-pendulum`.
    pub fn name(&self) -> &'static str {
        self.kind().name()
    }

    /// The initial stiffness (N/m) and storey law of the isolator carrying the weight `weight` (N).
    pub fn storey(&self, weight: f64) -> Result<(f64, StoreyLaw), Error> {
        let k = |k: f64| {
            check(
                "isolator.stiffness",
                k,
                k > 0.0 && k.is_finite(),
                "isolator stiffness > 0 (N/m)",
            )
        };
        match *self {
            IsolatorModel::Linear { stiffness } => Ok((k(stiffness)?, StoreyLaw::Linear)),
            IsolatorModel::Bilinear {
                stiffness,
                yield_force,
                post_yield_ratio,
            } => Ok((
                k(stiffness)?,
                StoreyLaw::bilinear(yield_force, post_yield_ratio)?,
            )),
            IsolatorModel::BoucWen {
                stiffness,
                yield_force,
                post_yield_ratio,
                n,
                beta,
                gamma,
            } => Ok((
                k(stiffness)?,
                StoreyLaw::bouc_wen(yield_force, post_yield_ratio, n, beta, gamma)?,
            )),
            IsolatorModel::FrictionPendulum {
                radius,
                mu,
                yield_displacement,
            } => {
                check(
                    "isolator.radius",
                    radius,
                    radius > 0.0 && radius.is_finite(),
                    "radius > 0 (m)",
                )?;
                check("isolator.mu", mu, mu > 0.0 && mu < 1.0, "0 < mu < 1")?;
                check(
                    "isolator.yield_displacement",
                    yield_displacement,
                    yield_displacement > 0.0 && yield_displacement < 0.1,
                    "0 < yield_displacement < 0.1 (m)",
                )?;
                check(
                    "isolator",
                    weight,
                    weight > 0.0 && weight.is_finite(),
                    "a friction pendulum carries the weight of the masses above it (N), which must be > 0",
                )?;
                let k_r = weight / radius;
                let k0 = k_r + mu * weight / yield_displacement;
                Ok((
                    k0,
                    StoreyLaw::bouc_wen(k0 * yield_displacement, k_r / k0, 2.0, 0.5, 0.5)?,
                ))
            }
        }
    }
}

/// An isolator under a building's base slab.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Isolator {
    /// Its force–displacement law.
    pub model: IsolatorModel,
    /// Height of the isolation storey, m (for elevations and drift ratios).
    pub height: f64,
    /// Viscous coefficient of the isolator itself, N s/m (0: hysteresis only).
    pub damping: f64,
    /// Displacement capacity (the clearance to stops, or the bearing's limit), m; the run's isolator
    /// displacement is reported against it.
    pub clearance: Option<f64>,
}

impl Isolator {
    /// An isolator with `model`, 0.5 m high, no viscous damping, no clearance given.
    pub fn new(model: IsolatorModel) -> Self {
        Self {
            model,
            height: 0.5,
            damping: 0.0,
            clearance: None,
        }
    }

    pub(crate) fn check(&self) -> Result<(), Error> {
        check(
            "isolator.height",
            self.height,
            (1e-3..=1e4).contains(&self.height),
            "isolator height from 1e-3 to 1e4 m",
        )?;
        check(
            "isolator.damping",
            self.damping,
            self.damping >= 0.0 && self.damping.is_finite(),
            "isolator damping >= 0 (N s/m)",
        )?;
        if let Some(c) = self.clearance {
            check(
                "isolator.clearance",
                c,
                c > 0.0 && c.is_finite(),
                "clearance > 0 (m)",
            )?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_friction_pendulum_is_a_bouc_wen_law_with_the_pendulum_stiffness_and_the_friction_force() {
        // W = 1e7 N, R = 2 m, mu = 0.05, d_y = 2.5e-4 m: post-yield stiffness W/R = 5e6 N/m, and the force
        // at a displacement d far beyond d_y (z = 1) is W/R d + mu W.
        let fp = IsolatorModel::FrictionPendulum {
            radius: 2.0,
            mu: 0.05,
            yield_displacement: 2.5e-4,
        };
        let (k0, law) = fp.storey(1.0e7).unwrap();
        let StoreyLaw::BoucWen {
            yield_force,
            post_yield_ratio: a,
            ..
        } = law
        else {
            panic!("{law:?}")
        };
        assert!((a * k0 - 5.0e6).abs() < 1e-6);
        assert!(((1.0 - a) * yield_force - 0.05 * 1.0e7).abs() < 1e-6);
        assert!((yield_force / k0 - 2.5e-4).abs() < 1e-18);
        // Without weight above it, a friction pendulum has no force.
        assert!(fp.storey(0.0).is_err());
    }
}
