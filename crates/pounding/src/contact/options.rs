//! The options that choose and tune a contact model, as a scenario file or a command line gives them, with
//! the rules that tie them together (an option that applies to one model only, options that conflict).

use super::{AlphaRule, ContactModel, Damping, Model, Reading, Restitution, Tension};
use crate::Error;

/// A contact model's options, before they are checked against each other.
#[derive(Clone, Debug, PartialEq)]
pub struct ContactOptions {
    /// The model.
    pub model: Model,
    /// What the contact is to deliver: `e_pre` (0 < e <= 1, dimensionless), a table `e(v_i)`, or a
    /// material damping constant (s/m).
    pub e: Restitution,
    /// Exponent `n` of the force law (dimensionless); `None` for the model's own.
    pub exponent: Option<f64>,
    /// The published damping formula, or the exact value that delivers `e`.
    pub damping: Damping,
    /// `alpha` of `papi` (dimensionless); `None` for calibration.
    pub alpha: Option<AlphaRule>,
    /// Reading of `papi`'s force law.
    pub reading: Reading,
    /// May the force become tensile late in restitution; `None` for the model's default.
    pub tension: Option<Tension>,
    /// `impact-material`: expected maximum penetration `d_m`, m; `None` for the elastic Hertz penetration.
    pub max_penetration: Option<f64>,
    /// `impact-material`: yield ratio `a = d_y / d_m`, 0 < a < 1 (dimensionless).
    pub yield_ratio: f64,
    /// `thornton` (required by it, refused by the others): the spheres' radius `R`, m.
    pub radius: Option<f64>,
    /// `thornton` (required by it, refused by the others): the yield pressure `p_y`, Pa.
    pub yield_pressure: Option<f64>,
}

impl Default for ContactOptions {
    /// The one place of a contact's defaults: `papi` at `e = 0.65` (concrete on concrete), damping
    /// calibrated exactly (every impact of two free bodies delivers `e`; the published formula is
    /// `Damping::Formula`), `alpha` calibrated and the energy-split reading (for `papi`), the model's own
    /// exponent and tension rule, the elastic Hertz penetration and a yield ratio of 0.1 (for
    /// `impact-material`).
    fn default() -> Self {
        ContactOptions {
            model: Model::Papi,
            e: Restitution::Constant(0.65),
            exponent: None,
            damping: Damping::Exact,
            alpha: None,
            reading: Reading::EnergySplit,
            tension: None,
            max_penetration: None,
            yield_ratio: 0.1,
            radius: None,
            yield_pressure: None,
        }
    }
}

impl ContactOptions {
    /// The defaults ([`ContactOptions::default`]) of model `model` with restitution `e`.
    pub fn new(model: Model, e: f64) -> Self {
        ContactOptions {
            model,
            e: Restitution::Constant(e),
            ..Self::default()
        }
    }

    /// The exponent in use: the one given, else the model's.
    pub fn exponent(&self) -> f64 {
        self.exponent.unwrap_or(self.model.info().default_n)
    }

    /// The contact model with stiffness `k` (N/m^n; how to choose it: [`ContactModel::new`] and
    /// `docs/contact-models.md#5-choosing-the-contact-stiffness`).
    pub fn build(&self, k: f64) -> Result<ContactModel, OptionError> {
        if self.alpha.is_some() && self.model != Model::Papi {
            return Err(OptionError::NotFor {
                option: "alpha",
                applies_to: "papi",
                model: self.model,
            });
        }
        if matches!(self.alpha, Some(AlphaRule::Given(_) | AlphaRule::Eq8))
            && self.damping == Damping::Exact
        {
            return Err(OptionError::Conflict {
                option: "alpha",
                with: "damping",
                value: "exact",
                why: "exact damping calibrates alpha",
            });
        }
        if self.max_penetration.is_some() && self.model != Model::ImpactMaterial {
            return Err(OptionError::NotFor {
                option: "max-penetration",
                applies_to: "impact-material",
                model: self.model,
            });
        }
        let thornton = self.model == Model::Thornton;
        for (option, given, with) in [
            ("radius", self.radius, "yield-pressure"),
            ("yield-pressure", self.yield_pressure, "radius"),
        ] {
            match (thornton, given) {
                (false, Some(_)) => {
                    return Err(OptionError::NotFor {
                        option,
                        applies_to: "thornton",
                        model: self.model,
                    })
                }
                (true, None) => {
                    return Err(OptionError::Required {
                        option,
                        with,
                        model: self.model,
                        what: "the spheres' radius (m) and yield pressure (Pa)",
                    })
                }
                _ => {}
            }
        }
        let mut s = ContactModel::new(self.model, k, 1.0)?.with_restitution(self.e.clone())?;
        if let Some(n) = self.exponent {
            s = s.with_exponent(n)?;
        }
        s = s
            .with_damping(self.damping)
            .with_reading(self.reading)
            .with_yield_ratio(self.yield_ratio)?;
        if let Some(alpha) = self.alpha {
            s = s.with_alpha(alpha)?;
        }
        if let Some(t) = self.tension {
            s = s.with_tension(t);
        }
        if let Some(d_m) = self.max_penetration {
            s = s.with_max_penetration(d_m)?;
        }
        if let (Some(r), Some(p_y)) = (self.radius, self.yield_pressure) {
            s = s.with_sphere(r, p_y)?;
        }
        Ok(s)
    }
}

/// Why a set of [`ContactOptions`] is refused. Option names are written with dashes (`max-penetration`);
/// a scenario file spells them with underscores, a command line with `--`.
#[derive(Clone, Debug, PartialEq)]
pub enum OptionError {
    /// An option given to a model it does not apply to.
    NotFor {
        /// The option.
        option: &'static str,
        /// The model(s) it applies to.
        applies_to: &'static str,
        /// The model it was given to.
        model: Model,
    },
    /// An option the model cannot do without.
    Required {
        /// The option.
        option: &'static str,
        /// The option that goes with it.
        with: &'static str,
        /// The model that needs it.
        model: Model,
        /// What it and its companions describe.
        what: &'static str,
    },
    /// Two options that cannot be given together.
    Conflict {
        /// The first option.
        option: &'static str,
        /// The option it conflicts with.
        with: &'static str,
        /// The value of `with` that conflicts.
        value: &'static str,
        /// Why.
        why: &'static str,
    },
    /// A value out of range.
    Value(Error),
}

impl From<Error> for OptionError {
    fn from(e: Error) -> Self {
        OptionError::Value(e)
    }
}

impl OptionError {
    /// The option the error concerns (`max-penetration`, `e`), if it names one.
    pub fn key(&self) -> Option<&'static str> {
        match self {
            OptionError::NotFor { option, .. }
            | OptionError::Required { option, .. }
            | OptionError::Conflict { option, .. } => Some(option),
            OptionError::Value(
                Error::Parameter { name, .. }
                | Error::Choice { name, .. }
                | Error::Length { name, .. },
            ) => Some(name),
            OptionError::Value(_) => None,
        }
    }

    /// The message, with option names spelled by `name` (for example `|k| format!("--{k}")`).
    pub fn message(&self, name: impl Fn(&str) -> String) -> String {
        match self {
            OptionError::NotFor {
                option,
                applies_to,
                model,
            } => format!(
                "{} applies to {applies_to} only, not to {model}",
                name(option)
            ),
            OptionError::Required {
                option,
                with,
                model,
                what,
            } => format!(
                "{} is required by model {model}, with {}: {what}",
                name(option),
                name(with)
            ),
            OptionError::Conflict {
                option,
                with,
                value,
                why,
            } => format!(
                "{} conflicts with {} {value} ({why}); drop one",
                name(option),
                name(with)
            ),
            OptionError::Value(e) => e.to_string(),
        }
    }
}
