//! Contact force models (`docs/contact-models.md`).
//!
//! A [`ContactModel`] is what a user specifies: a [`Model`] from the catalogue with stiffness `k` (N/m^n),
//! exponent `n`, the requested coefficient of restitution `e_pre`, how the damping is chosen
//! ([`Damping::Formula`], the published formula, or [`Damping::Exact`], the value that delivers `e_pre`),
//! and the tension rule. [`ContactModel::prepare`] fixes the dimensionless damping parameter once
//! (calibrating it if asked); [`PreparedContact::law`] then gives the [`ForceLaw`] of one impact, which
//! depends on the effective mass and on the impact velocity.
//!
//! ```
//! use pounding::contact::{ContactModel, Damping, Model};
//! let spec = ContactModel::new(Model::Flores, 1.0e9, 0.65)?.with_damping(Damping::Exact);
//! let prepared = spec.prepare()?;
//! let (law, _) = prepared.law(1000.0, 1.0)?;
//! let e = pounding::impact::exact::e_post(&law, spec.tension(), 1000.0, 1.0).unwrap();
//! assert!((e - 0.65).abs() < 1e-10);
//! # Ok::<(), pounding::Error>(())
//! ```

pub mod calibrate;
pub mod damping;
pub mod exact;
mod law;
mod model;
mod options;
mod restitution;

pub use law::{thornton_unloading, ForceLaw, Phase, Turn};
pub use model::{Family, Formula, Model, ModelInfo, MODELS};
pub use options::{ContactOptions, OptionError};
pub use restitution::{material_e, Restitution, RestitutionTable};

use crate::error::check;
use crate::Error;

crate::named! {
    /// May the contact force become tensile (attractive) late in restitution?
    pub enum Tension: "tension" {
        /// The force follows the law into tension; the contact ends when the penetration returns to 0.
        Allow = "allow",
        /// The force is clamped at 0: the contact ends when it first reaches 0 in restitution.
        Clamp = "clamp",
    }
}

crate::named! {
    /// The two readings of the force law of Papi & Toopchi-Nezhad (2022) (docs/contact-models.md).
    pub enum Reading: "reading" {
        /// Restitution damping `chi_r = (alpha / e) chi`: restitution dissipates `alpha` times the approach.
        EnergySplit = "energy-split",
        /// The same `chi` in both phases; `alpha` enters only through eq (7).
        SameDamping = "same-damping",
    }
}

crate::named! {
    /// How the damping parameter is chosen.
    pub enum Damping: "damping" {
        /// The model's published formula.
        Formula = "formula",
        /// The value that makes the delivered `e_post` equal `e_pre` (to 1e-10).
        Exact = "exact",
    }
}

crate::named! {
    /// How `alpha` of the `papi` model is chosen, when it is not given as a number.
    pub enum AlphaWord: "alpha" {
        /// Papi & Toopchi-Nezhad (2022) eq (8) as printed ([`AlphaRule::Eq8`]).
        Eq8 = "eq8",
        /// Calibrated exactly ([`AlphaRule::Calibrate`]).
        Calibrate = "calibrate",
    }
}

/// How `alpha` of the `papi` model is chosen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AlphaRule {
    /// A given value (dimensionless, `alpha >= 0`; the paper's range is [0, 1]).
    Given(f64),
    /// Papi & Toopchi-Nezhad (2022) eq (8) as printed (flagged as a probable misprint).
    Eq8,
    /// The iterative procedure of Papi & Toopchi-Nezhad (2022) done exactly: the root of `e_post(alpha) = e_pre` in [0, 1].
    Calibrate,
}

/// The damping parameter fixed for a contact (all dimensionless).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DampingParameter {
    /// No damping (elastic models).
    None,
    /// Damping ratio of a linear dashpot, `c = 2 zeta sqrt(k m)`.
    Zeta(f64),
    /// Hunt–Crossley factor, the same in both phases.
    Chi(f64),
    /// The model of Papi & Toopchi-Nezhad (2022): `alpha`, and the resulting approach and restitution factors.
    Papi {
        /// Energy-split coefficient.
        alpha: f64,
        /// Approach factor, eq (7).
        chi: f64,
        /// Restitution factor.
        chi_r: f64,
    },
    /// Jankowski's damping ratio.
    Xi(f64),
    /// The `e` put into the bilinear loop's dissipated-energy formula.
    EDesign(f64),
    /// A material damping constant `c = D/K`, s/m (not dimensionless): the Hunt–Crossley law
    /// `F = k d^n (1 + c v)`, whose factor `chi = c v_i` grows with the impact velocity.
    DampingConstant(f64),
    /// No damping but plastic flow: Thornton's spheres of this radius (m) and yield pressure (Pa).
    Yield(Sphere),
}

/// A sphere that yields (Thornton 1997): the radius `R` (m) of the Hertz stiffness `(4/3) E* sqrt(R)`, and
/// the yield pressure `p_y` (Pa), the largest contact pressure the material bears.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// Radius, m.
    pub radius: f64,
    /// Yield pressure, Pa.
    pub yield_pressure: f64,
}

impl DampingParameter {
    /// The parameter's name (`zeta`, `chi`, `alpha`, `xi`, `e_design`) and value; `None` for no damping.
    pub fn named(&self) -> Option<(&'static str, f64)> {
        match *self {
            DampingParameter::None => None,
            DampingParameter::Zeta(z) => Some(("zeta", z)),
            DampingParameter::Chi(c) => Some(("chi", c)),
            DampingParameter::Papi { alpha, .. } => Some(("alpha", alpha)),
            DampingParameter::Xi(x) => Some(("xi", x)),
            DampingParameter::EDesign(e) => Some(("e_design", e)),
            DampingParameter::DampingConstant(c) => Some(("damping_constant", c)),
            DampingParameter::Yield(s) => Some(("yield_pressure", s.yield_pressure)),
        }
    }
}

/// A validated contact specification. Build with [`ContactModel::new`] and the `with_*` methods.
#[derive(Clone, Debug, PartialEq)]
pub struct ContactModel {
    model: Model,
    k: f64,
    n: f64,
    restitution: Restitution,
    damping: Damping,
    alpha: AlphaRule,
    reading: Reading,
    tension: Tension,
    max_penetration: Option<f64>,
    yield_ratio: f64,
    sphere: Option<Sphere>,
}

impl ContactModel {
    /// A contact of `model` with stiffness `k` (N/m^n, > 0) and requested restitution `e` (in (0, 1]);
    /// the model's default exponent and tension rule, and the defaults of [`ContactOptions::default`]
    /// (published damping formula, `alpha` calibrated and the energy-split reading for `papi`, yield ratio
    /// `a = 0.1` for `impact-material`).
    ///
    /// **Choosing the stiffness.** `k` is a property of what strikes what, not a numerical knob: for a
    /// linear law, usually the axial stiffness `E A / L` (N/m) of the floor slab that is struck; for a
    /// 3/2-power law, the Hertz stiffness of the contacting surfaces, `(4/3) E* sqrt(R)` (N/m^1.5). Peak
    /// displacements and drifts change little with `k`; the peak force of an impact grows as
    /// `k^(1/(n+1))` (`v sqrt(k m)` for an elastic linear spring) and contacts shorten as `k` grows, so a
    /// stiffer contact needs more integration steps. See `docs/contact-models.md#5-choosing-the-contact-stiffness`.
    pub fn new(model: Model, k: f64, e: f64) -> Result<Self, Error> {
        let info = model.info();
        let d = ContactOptions::default();
        Ok(Self {
            model,
            k: check("k", k, k > 0.0, "k > 0 (N/m^n)")?,
            n: info.default_n,
            restitution: Restitution::Constant(check("e", e, e > 0.0 && e <= 1.0, "0 < e <= 1")?),
            damping: d.damping,
            alpha: AlphaRule::Calibrate,
            reading: d.reading,
            tension: info.tension,
            max_penetration: d.max_penetration,
            yield_ratio: d.yield_ratio,
            sphere: None,
        })
    }

    /// The sphere of `thornton`: radius `R` (m, > 0) and yield pressure `p_y` (Pa, > 0); the stiffness
    /// `k` is its Hertz stiffness `(4/3) E* sqrt(R)`, from which `E*` follows.
    pub fn with_sphere(mut self, radius: f64, yield_pressure: f64) -> Result<Self, Error> {
        self.sphere = Some(Sphere {
            radius: check("radius", radius, radius > 0.0, "radius > 0 (m)")?,
            yield_pressure: check(
                "yield_pressure",
                yield_pressure,
                yield_pressure > 0.0,
                "yield_pressure > 0 (Pa)",
            )?,
        });
        Ok(self)
    }

    /// The sphere of `thornton`, if given.
    pub fn sphere(&self) -> Option<Sphere> {
        self.sphere
    }

    /// Sets the exponent `n` (> 0; linear models accept only 1).
    pub fn with_exponent(mut self, n: f64) -> Result<Self, Error> {
        let info = self.model.info();
        if info.n_fixed && info.default_n == 1.0 {
            check("n", n, n == 1.0, "n = 1 (a linear model)")?;
        }
        if info.n_fixed && info.default_n == 1.5 {
            check("n", n, n == 1.5, "n = 1.5 (Hertz spheres)")?;
        }
        self.n = check("n", n, n > 0.0, "n > 0")?;
        Ok(self)
    }

    /// Chooses the published damping formula or exact calibration. For `papi`, `Exact` means `alpha`
    /// is calibrated.
    pub fn with_damping(mut self, damping: Damping) -> Self {
        self.damping = damping;
        if damping == Damping::Exact && self.model == Model::Papi {
            self.alpha = AlphaRule::Calibrate;
        }
        self
    }

    /// Chooses `alpha` for `papi` (a given value must be finite and >= 0).
    pub fn with_alpha(mut self, alpha: AlphaRule) -> Result<Self, Error> {
        if let AlphaRule::Given(a) = alpha {
            check(
                "alpha",
                a,
                a >= 0.0,
                "alpha >= 0 (the paper's range is 0..1)",
            )?;
        }
        self.alpha = alpha;
        Ok(self)
    }

    /// Asks for `r` instead of one `e`: a table `e(v_i)` (a damped model), or a material damping constant (a
    /// model of the Hunt–Crossley family, [`Formula::Chi`], whose laws all become `F = k d^n (1 + c v)`).
    pub fn with_restitution(mut self, r: Restitution) -> Result<Self, Error> {
        let info = self.model.info();
        let refuse = |name: &'static str, value: String, allowed: String| {
            Err(Error::Choice {
                name,
                value,
                allowed,
            })
        };
        match &r {
            Restitution::Constant(e) => {
                check("e", *e, *e > 0.0 && *e <= 1.0, "0 < e <= 1")?;
            }
            Restitution::Table(t) if info.parameter.is_none() => {
                return refuse(
                    "e.table",
                    crate::words::count(t.points().len(), "row", None),
                    format!(
                        "only with a damped model, not {} ({})",
                        info.name,
                        self.model.asks_no_e().unwrap_or_default()
                    ),
                )
            }
            Restitution::Table(_) => {}
            Restitution::DampingConstant(c) => {
                check(
                    "damping_constant",
                    *c,
                    *c >= 0.0,
                    "damping_constant >= 0 (s/m)",
                )?;
                if !matches!(info.formula, Formula::Chi(_)) {
                    return refuse(
                        "damping_constant",
                        crate::words::number(*c),
                        format!(
                            "only with a model of the Hunt-Crossley family (ye, hunt-crossley, herbert-mcwhannell, \
                             lee-wang, lankarani-nikravesh, gonthier, zhiying-qishao, flores, hertzdamp), not {}",
                            info.name
                        ),
                    );
                }
            }
        }
        self.restitution = r;
        Ok(self)
    }

    /// Chooses the reading of the paper's model.
    pub fn with_reading(mut self, reading: Reading) -> Self {
        self.reading = reading;
        self
    }

    /// Sets the tension rule.
    pub fn with_tension(mut self, tension: Tension) -> Self {
        self.tension = tension;
        self
    }

    /// Sets the expected maximum penetration `d_m` (m, > 0) of `impact-material`; by default the elastic
    /// Hertz penetration of each impact.
    pub fn with_max_penetration(mut self, d_m: f64) -> Result<Self, Error> {
        self.max_penetration = Some(check(
            "max_penetration",
            d_m,
            d_m > 0.0,
            "max_penetration > 0 (m)",
        )?);
        Ok(self)
    }

    /// Sets the yield ratio `a = d_y / d_m` of `impact-material` (0 < a < 1).
    pub fn with_yield_ratio(mut self, a: f64) -> Result<Self, Error> {
        self.yield_ratio = check("yield_ratio", a, a > 0.0 && a < 1.0, "0 < yield_ratio < 1")?;
        Ok(self)
    }

    /// The model.
    pub fn model(&self) -> Model {
        self.model
    }
    /// Stiffness `k`, N/m^n.
    pub fn stiffness(&self) -> f64 {
        self.k
    }
    /// Exponent `n`.
    pub fn exponent(&self) -> f64 {
        self.n
    }
    /// What the contact is asked to deliver: one `e`, a table `e(v_i)` or a material damping constant.
    pub fn restitution(&self) -> &Restitution {
        &self.restitution
    }
    /// The one coefficient of restitution this contact is built to deliver, `e_pre`; `None` for an elastic
    /// model (hooke, hertz), which has no damping to calibrate and delivers 1 whatever `e` it was given,
    /// and for a table or a damping constant ([`ContactModel::asked`]).
    pub fn asked_restitution(&self) -> Option<f64> {
        self.asked().and_then(Restitution::constant)
    }
    /// What a damped contact is asked to deliver; `None` for an elastic model.
    pub fn asked(&self) -> Option<&Restitution> {
        self.model.info().parameter.map(|_| &self.restitution)
    }
    /// Damping choice.
    pub fn damping(&self) -> Damping {
        self.damping
    }
    /// Tension rule.
    pub fn tension(&self) -> Tension {
        self.tension
    }
    /// Reading of the paper's model.
    pub fn reading(&self) -> Reading {
        self.reading
    }
    /// Rule for `alpha`.
    pub fn alpha_rule(&self) -> AlphaRule {
        self.alpha
    }

    /// Whether the damping parameter is calibrated per impact (`impact-material` with exact damping and a
    /// given `d_m`: the ratio of `d_m` to each impact's elastic penetration changes the calibration).
    pub(crate) fn calibrated_per_impact(&self) -> bool {
        let d_m = self.model == Model::ImpactMaterial
            && self.damping == Damping::Exact
            && self.max_penetration.is_some();
        // A table asks each impact its own e.
        d_m || (matches!(self.restitution, Restitution::Table(_)) && self.model.is_damped())
    }

    /// The damping parameter from its formula or a closed-form calibration; `impact` gives `(m, v_i)` for
    /// `impact-material` with a given `d_m`. `None` when the calibration needs integrated impacts
    /// (Jankowski's law with exact damping: [`crate::calibration`]).
    pub(crate) fn closed_form_parameter(
        &self,
        impact: Option<(f64, f64)>,
    ) -> Result<Option<DampingParameter>, Error> {
        let e = match (&self.restitution, impact) {
            (Restitution::Constant(e), _) => *e,
            (Restitution::Table(t), Some((_, v_i))) => t.at(v_i),
            // A table is read per impact ([`ContactModel::calibrated_per_impact`]); before one, at rest.
            (Restitution::Table(t), None) => t.at(0.0),
            (Restitution::DampingConstant(c), _) => {
                return Ok(Some(match self.model.info().formula {
                    Formula::None => DampingParameter::None,
                    _ => DampingParameter::DampingConstant(*c),
                }))
            }
        };
        let exact = self.damping == Damping::Exact;
        Ok(Some(match self.model.info().formula {
            Formula::None => DampingParameter::None,
            Formula::Zeta(f) => DampingParameter::Zeta(if exact {
                calibrate::exact_zeta(e, self.model.info().restitution_damped, self.tension)?
            } else {
                f(e)
            }),
            Formula::Chi(f) => DampingParameter::Chi(if exact {
                calibrate::exact_chi(e)?
            } else {
                f(e)
            }),
            Formula::Papi => {
                let alpha = match self.alpha {
                    AlphaRule::Given(a) => a,
                    AlphaRule::Eq8 => damping::alpha_eq8(e),
                    AlphaRule::Calibrate => calibrate::papi_alpha(e, self.reading)?,
                };
                let (chi, chi_r) = papi_factors(e, alpha, self.reading);
                DampingParameter::Papi { alpha, chi, chi_r }
            }
            Formula::Thornton => DampingParameter::Yield(self.sphere.ok_or(Error::Choice {
                name: "yield_pressure",
                value: "missing".into(),
                allowed: "model thornton needs radius (m) and yield_pressure (Pa)".into(),
            })?),
            Formula::Xi(_) if exact => return Ok(None),
            Formula::Xi(f) => DampingParameter::Xi(f(e)),
            Formula::Bilinear => DampingParameter::EDesign(if exact {
                let ratio = match impact {
                    Some((m, v_i)) => {
                        self.max_penetration_for(m, v_i)
                            / hertz_max_penetration(1.0, self.n, m, v_i, self.k)
                    }
                    None => 1.0,
                };
                calibrate::exact_e_design(e, self.n, self.yield_ratio, ratio)?
            } else {
                e
            }),
        }))
    }

    fn max_penetration_for(&self, m: f64, v_i: f64) -> f64 {
        self.max_penetration
            .unwrap_or_else(|| hertz_max_penetration(1.0, self.n, m, v_i, self.k))
    }

    /// The force law of one impact with parameter `p`, effective mass `m` (kg) and impact velocity `v_i`
    /// (m/s). Pure arithmetic. The parameter names its law (each model's [`Formula`] gives one kind), so
    /// every kind is handled here and no model can fall back to another law.
    fn law_with(&self, p: DampingParameter, m: f64, v_i: f64) -> ForceLaw {
        let (k, n) = (self.k, self.n);
        match p {
            DampingParameter::None => ForceLaw::Elastic { k, n },
            DampingParameter::Zeta(z) => {
                let c = 2.0 * z * (k * m).sqrt();
                let c_r = if self.model.info().restitution_damped {
                    c
                } else {
                    0.0
                };
                ForceLaw::LinearViscous { k, c, c_r }
            }
            DampingParameter::Chi(chi) => ForceLaw::HuntCrossley {
                k,
                n,
                chi,
                chi_r: chi,
                v_i,
            },
            DampingParameter::Yield(s) => thornton_law(k, s),
            // F = k d^n (1 + c v) is the normalised law with chi = c v_i.
            DampingParameter::DampingConstant(c) => ForceLaw::HuntCrossley {
                k,
                n,
                chi: c * v_i,
                chi_r: c * v_i,
                v_i,
            },
            DampingParameter::Papi { chi, chi_r, .. } => ForceLaw::HuntCrossley {
                k,
                n,
                chi,
                chi_r,
                v_i,
            },
            DampingParameter::Xi(xi) => ForceLaw::Jankowski {
                k,
                n,
                c0: 2.0 * xi * (k * m).sqrt(),
            },
            DampingParameter::EDesign(e_d) => {
                let BilinearLoop { k1, k2, d_y } = bilinear_law(
                    k,
                    n,
                    e_d,
                    self.yield_ratio,
                    self.max_penetration_for(m, v_i),
                );
                ForceLaw::Bilinear { k1, k2, d_y }
            }
        }
    }
}

/// Thornton's law for Hertz stiffness `k` (N/m^1.5) and sphere `s`: `E* = 3 k / (4 sqrt(R))`,
/// `d_y = R (pi p_y / (2 E*))^2`, `f_y = k d_y^(3/2)`, `k_p = pi p_y R`.
pub fn thornton_law(k: f64, s: Sphere) -> ForceLaw {
    let (r, p_y) = (s.radius, s.yield_pressure);
    let e_star = 0.75 * k / r.sqrt();
    let d_y = r * (std::f64::consts::PI * p_y / (2.0 * e_star)).powi(2);
    ForceLaw::Thornton {
        k,
        e_star,
        p_y,
        d_y,
        f_y: k * d_y * d_y.sqrt(),
        k_p: std::f64::consts::PI * p_y * r,
    }
}

/// `papi` approach and restitution factors for `e`, `alpha` and a reading.
pub fn papi_factors(e: f64, alpha: f64, reading: Reading) -> (f64, f64) {
    let chi = damping::chi_papi(e, alpha);
    let chi_r = match reading {
        Reading::EnergySplit => alpha / e * chi,
        Reading::SameDamping => chi,
    };
    (chi, chi_r)
}

/// Elastic maximum penetration (m) of `F = k_scale k d^n` for effective mass `m` (kg) and impact velocity
/// `v_i` (m/s): `((n + 1) m v_i^2 / (2 k))^(1/(n+1))`.
pub fn hertz_max_penetration(k_scale: f64, n: f64, m: f64, v_i: f64, k: f64) -> f64 {
    (0.5 * (n + 1.0) * m * v_i * v_i / (k_scale * k)).powf(1.0 / (n + 1.0))
}

/// The constants of a Muthukumar & DesRoches bilinear loop ([`ForceLaw::Bilinear`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BilinearLoop {
    /// Loading stiffness up to `d_y`, and unloading stiffness, N/m.
    pub k1: f64,
    /// Loading stiffness past `d_y`, N/m.
    pub k2: f64,
    /// Yield penetration, m.
    pub d_y: f64,
}

/// The Muthukumar & DesRoches bilinear law from Hertz stiffness `k` (N/m^n), exponent `n`, design
/// restitution `e_d`, yield ratio `a` and expected maximum penetration `d_m` (m).
pub fn bilinear_law(k: f64, n: f64, e_d: f64, a: f64, d_m: f64) -> BilinearLoop {
    let k_eff = k * d_m.powf(n - 1.0);
    let de = k * d_m.powf(n + 1.0) * (1.0 - e_d * e_d) / (n + 1.0);
    BilinearLoop {
        k1: k_eff + de / (a * d_m * d_m),
        k2: k_eff - de / ((1.0 - a) * d_m * d_m),
        d_y: a * d_m,
    }
}

/// Jankowski's exact damping ratio `xi` for `(e, n)`, found on integrated impacts
/// ([`crate::calibration::exact_xi`]); handed to a prepared contact that needs it per impact.
pub(crate) type XiCalibration = fn(f64, f64) -> Result<f64, Error>;

/// A [`ContactModel`] with its damping parameter fixed.
#[derive(Clone, Debug)]
pub struct PreparedContact {
    spec: ContactModel,
    parameter: Option<DampingParameter>,
    xi: Option<XiCalibration>,
}

impl PreparedContact {
    /// A prepared contact of `spec` with its damping `parameter` (`None`: calibrated per impact, with `xi`
    /// where that needs integrated impacts).
    pub(crate) fn new(
        spec: ContactModel,
        parameter: Option<DampingParameter>,
        xi: Option<XiCalibration>,
    ) -> Self {
        Self {
            spec,
            parameter,
            xi,
        }
    }

    /// The specification.
    pub fn spec(&self) -> &ContactModel {
        &self.spec
    }

    /// The damping parameter, if it does not depend on the impact.
    pub fn parameter(&self) -> Option<DampingParameter> {
        self.parameter
    }

    /// The force law and damping parameter of one impact with effective mass `m` (kg) and impact velocity
    /// `v_i` (m/s), both > 0.
    pub fn law(&self, m: f64, v_i: f64) -> Result<(ForceLaw, DampingParameter), Error> {
        let p = match self.parameter {
            Some(p) => p,
            None => match self.spec.closed_form_parameter(Some((m, v_i)))? {
                Some(p) => p,
                None => {
                    let e = self.spec.restitution.at(v_i);
                    let xi = self.xi.ok_or(Error::Calibration {
                        what: "damping",
                        e,
                        reason: "no calibration was prepared for this law".into(),
                    })?;
                    DampingParameter::Xi(xi(e, self.spec.n)?)
                }
            },
        };
        Ok((self.spec.law_with(p, m, v_i), p))
    }
}
