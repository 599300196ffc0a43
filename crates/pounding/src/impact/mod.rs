//! One impact: two bodies meeting at a relative velocity, or a ball dropped on a rigid slab.
//!
//! [`simulate`] integrates the relative motion `m d'' = m g - F(d, d')` from first touch (`d = 0`,
//! `d' = v_i`) with the adaptive Dormand–Prince method of [`crate::integrate`], and locates as events the
//! turning point (`d' = 0`, where restitution begins), kinks of the law, and the end of contact (`d = 0`,
//! or the force reaching 0 in restitution when tension is clamped). Nothing depends on a fixed time step.
//! [`exact`] holds the closed forms the integration must agree with.

mod simulate;

/// The exact single-impact relations, which live with the force laws ([`crate::contact::exact`]).
pub use crate::contact::exact;

pub use simulate::{force_at, simulate};

/// The range of an impact's scales, and what it allows in words.
pub use crate::error::{scales_allowed, SCALE_RANGE};

use crate::error::check;
use crate::Error;

/// The relative motion of one impact: effective mass, impact velocity and the gravity acting along the
/// approach direction during contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImpactSetup {
    /// Effective mass `m = m1 m2 / (m1 + m2)`, kg.
    pub mass: f64,
    /// Relative (approach) velocity at first touch, m/s.
    pub v_i: f64,
    /// Acceleration pushing the bodies together during contact, m/s^2 (gravity for a drop, else 0).
    pub gravity: f64,
}

impl ImpactSetup {
    /// Relative motion with effective mass `m` (kg) and impact velocity `v_i` (m/s), no gravity.
    pub fn relative(mass: f64, v_i: f64) -> Self {
        Self {
            mass,
            v_i,
            gravity: 0.0,
        }
    }
}

/// Two bodies: `m1` moving at `v` towards `m2` at rest (`m2` may be infinite: a rigid wall).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TwoBodies {
    /// Mass of the moving body, kg.
    pub m1: f64,
    /// Mass of the body at rest, kg (`f64::INFINITY` for a rigid wall).
    pub m2: f64,
    /// Approach velocity, m/s.
    pub v: f64,
}

impl TwoBodies {
    /// Validated two-body impact: masses > 0 (`m2` may be infinite), `v > 0`.
    pub fn new(m1: f64, m2: f64, v: f64) -> Result<Self, Error> {
        check("m1", m1, m1 > 0.0, "m1 > 0 (kg)")?;
        if m2.is_nan() || m2 <= 0.0 {
            return Err(Error::Parameter {
                name: "m2",
                value: m2,
                allowed: "m2 > 0 (kg) or inf",
            });
        }
        check("v", v, v > 0.0, "v > 0 (m/s)")?;
        Ok(Self { m1, m2, v })
    }

    /// Effective mass, kg.
    pub fn effective_mass(&self) -> f64 {
        if self.m2.is_infinite() {
            self.m1
        } else {
            self.m1 * self.m2 / (self.m1 + self.m2)
        }
    }

    /// The relative motion.
    pub fn setup(&self) -> ImpactSetup {
        ImpactSetup::relative(self.effective_mass(), self.v)
    }

    /// Velocities (m/s) of body 1 and body 2 after an impact that transmitted `impulse` (N s).
    pub fn velocities_after(&self, impulse: f64) -> (f64, f64) {
        let v2 = if self.m2.is_infinite() {
            0.0
        } else {
            impulse / self.m2
        };
        (self.v - impulse / self.m1, v2)
    }
}

/// A ball of radius `R` dropped from height `h` onto a rigid slab of the same material; Hertz stiffness
/// `k_h = (4/3) E* sqrt(R)` with `1/E* = 2 (1 - nu^2) / E` (docs/contact-models.md).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallDrop {
    /// Ball radius, m.
    pub radius: f64,
    /// Young's modulus of ball and slab, Pa.
    pub youngs_modulus: f64,
    /// Poisson's ratio of ball and slab.
    pub poisson: f64,
    /// Density of the ball, kg/m^3.
    pub density: f64,
    /// Drop height (from the ball's lowest point to the slab), m.
    pub height: f64,
    /// Gravity, m/s^2.
    pub gravity: f64,
}

impl BallDrop {
    /// Validated drop: radius, modulus, density, height > 0; `-1 < poisson < 0.5`; standard gravity.
    pub fn new(
        radius: f64,
        youngs_modulus: f64,
        poisson: f64,
        density: f64,
        height: f64,
    ) -> Result<Self, Error> {
        Ok(Self {
            radius: check("radius", radius, radius > 0.0, "radius > 0 (m)")?,
            youngs_modulus: check(
                "youngs_modulus",
                youngs_modulus,
                youngs_modulus > 0.0,
                "youngs_modulus > 0 (Pa)",
            )?,
            poisson: check(
                "poisson",
                poisson,
                poisson > -1.0 && poisson < 0.5,
                "-1 < poisson < 0.5",
            )?,
            density: check("density", density, density > 0.0, "density > 0 (kg/m^3)")?,
            height: check("height", height, height > 0.0, "height > 0 (m)")?,
            gravity: crate::units::STANDARD_GRAVITY,
        })
    }

    /// Mass of the ball, kg.
    pub fn mass(&self) -> f64 {
        4.0 / 3.0 * std::f64::consts::PI * self.radius.powi(3) * self.density
    }

    /// Hertz stiffness `k_h = (4/3) E* sqrt(R)`, N/m^1.5.
    pub fn hertz_stiffness(&self) -> f64 {
        let e_star = self.youngs_modulus / (2.0 * (1.0 - self.poisson * self.poisson));
        4.0 / 3.0 * e_star * self.radius.sqrt()
    }

    /// Stiffness (N/m^n) of a force law of exponent `n` equivalent to this ball's Hertz contact; see
    /// [`equivalent_stiffness`].
    pub fn equivalent_stiffness(&self, n: f64) -> f64 {
        equivalent_stiffness(
            self.hertz_stiffness(),
            self.mass(),
            self.impact_velocity(),
            n,
        )
    }

    /// Impact velocity `sqrt(2 g h)`, m/s.
    pub fn impact_velocity(&self) -> f64 {
        (2.0 * self.gravity * self.height).sqrt()
    }

    /// The relative motion, with gravity acting during contact.
    pub fn setup(&self) -> ImpactSetup {
        ImpactSetup {
            mass: self.mass(),
            v_i: self.impact_velocity(),
            gravity: self.gravity,
        }
    }
}

/// Stiffness (N/m^n) of a force law of exponent `n` equivalent to a Hertz contact of stiffness `k_h`
/// (N/m^1.5) for an impact of effective mass `mass` (kg) at `v_i` (m/s): `k_h` for `n = 3/2`, otherwise
/// `k_h d_h^(3/2 - n)`, the same force as Hertz at the elastic Hertz penetration
/// `d_h = (5 m v_i^2 / (4 k_h))^(2/5)`. Our choice, used to put models of different `n` on one impact (the
/// paper does not say which linear stiffness it used).
///
/// ```
/// // A linear spring equivalent to Hertz reaches the same force at d_h, F = k_h d_h^1.5.
/// let (k_h, m, v) = (1.0e10_f64, 1.0e5_f64, 1.0_f64);
/// let d_h = (5.0 * m * v * v / (4.0 * k_h)).powf(0.4);
/// let k_1 = pounding::impact::equivalent_stiffness(k_h, m, v, 1.0);
/// assert!((k_1 * d_h - k_h * d_h.powf(1.5)).abs() < 1e-9 * k_1 * d_h);
/// ```
pub fn equivalent_stiffness(k_h: f64, mass: f64, v_i: f64, n: f64) -> f64 {
    let d_h = crate::contact::hertz_max_penetration(1.0, 1.5, mass, v_i, k_h);
    k_h * d_h.powf(1.5 - n)
}

/// Accuracy and output options of [`simulate`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImpactOptions {
    /// Relative tolerance of the integrator (dimensionless); absolute tolerances are this times the
    /// natural scales of penetration, velocity, impulse and energy. Default 1e-12, which keeps `e_post`
    /// within about 1e-10 of the exact value down to `e = 0.05` (the error grows with damping).
    pub rtol: f64,
    /// Record the time history.
    pub history: bool,
}

impl Default for ImpactOptions {
    fn default() -> Self {
        Self {
            rtol: 1e-12,
            history: false,
        }
    }
}

/// Time history of one impact, at every accepted integration step and event, and at the located peak of
/// the force (so the largest force of the history is [`ImpactResult::peak_force`]).
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct History {
    /// Time since first touch, s.
    pub t: Vec<f64>,
    /// Penetration, m.
    pub penetration: Vec<f64>,
    /// Penetration rate, m/s.
    pub rate: Vec<f64>,
    /// Contact force, N.
    pub force: Vec<f64>,
}

/// Result of one impact.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ImpactResult {
    /// Delivered coefficient of restitution `-v_out / v_i`.
    pub e_post: f64,
    /// Largest contact force, N.
    pub peak_force: f64,
    /// Time of the largest force since touch, s.
    pub time_of_peak_force: f64,
    /// Largest penetration, m.
    pub max_penetration: f64,
    /// Time from touch to the end of contact, s.
    pub contact_duration: f64,
    /// Work done by the contact force on the relative motion, `int F d' dt`, J (the energy dissipated).
    pub dissipated_energy: f64,
    /// Impulse transmitted, `int F dt`, N s.
    pub impulse: f64,
    /// Relative velocity at the end of contact, m/s (negative: separating).
    pub v_out: f64,
    /// Accepted integration steps.
    pub steps: usize,
    /// Time history, if asked for.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub history: Option<History>,
}

/// The coefficient of restitution an impact of `law` delivers: by the exact relation when there is one
/// (and no gravity), otherwise by [`simulate`] with default accuracy.
pub fn delivered_e(
    law: &crate::contact::ForceLaw,
    tension: crate::contact::Tension,
    setup: &ImpactSetup,
) -> Result<f64, Error> {
    if setup.gravity == 0.0 {
        if let Some(e) = exact::e_post(law, tension, setup.mass, setup.v_i) {
            return Ok(e);
        }
    }
    Ok(simulate(law, tension, setup, &ImpactOptions::default())?.e_post)
}
