//! Calibration that needs an integrated impact, and the preparation of a contact model.
//!
//! Most damping parameters are calibrated from closed forms ([`crate::contact::calibrate`]); Jankowski's
//! law has none, so its damping ratio is found by root finding on integrated impacts ([`crate::impact`]).
//! [`ContactModel::prepare`] fixes a model's damping parameter once, calibrating it where asked: it lives
//! here because calibration may integrate impacts, which run on the engine that contacts are elements of.

use crate::contact::calibrate::solve_decreasing;
use crate::contact::{damping, ContactModel, DampingParameter, ForceLaw, PreparedContact, Tension};
use crate::impact::{self, ImpactOptions, ImpactSetup};
use crate::Error;

pub use crate::contact::calibrate::E_TOLERANCE;

/// Delivered `e` of Jankowski's law with damping ratio `xi` and exponent `n`, by an integrated impact
/// (100 times tighter than the default tolerance), in dimensionless units (`k = m = v_i = 1`).
pub fn jankowski_e_post(xi: f64, n: f64) -> Result<f64, Error> {
    let law = ForceLaw::Jankowski {
        k: 1.0,
        n,
        c0: 2.0 * xi,
    };
    let opts = ImpactOptions {
        rtol: 1e-12,
        history: false,
    };
    Ok(impact::simulate(
        &law,
        Tension::Clamp,
        &ImpactSetup::relative(1.0, 1.0),
        &opts,
    )?
    .e_post)
}

/// Exact Jankowski damping ratio `xi` for exponent `n`.
pub fn exact_xi(e: f64, n: f64) -> Result<f64, Error> {
    let start = damping::xi_jankowski(e).max(0.1);
    solve_decreasing("xi", e, start, |x| jankowski_e_post(x, n))
}

impl ContactModel {
    /// Fixes the damping parameter, calibrating it where asked. Calibration is done once here: the
    /// parameter is dimensionless and the same for every impact (except `impact-material` with a given
    /// `d_m` and a table `e(v_i)`, calibrated per impact in [`PreparedContact::law`]: Jankowski's law then
    /// integrates impacts at each touch).
    pub fn prepare(&self) -> Result<PreparedContact, Error> {
        let parameter = if self.calibrated_per_impact() {
            None
        } else {
            Some(match self.closed_form_parameter(None)? {
                Some(p) => p,
                None => {
                    DampingParameter::Xi(exact_xi(self.restitution().at(0.0), self.exponent())?)
                }
            })
        };
        Ok(PreparedContact::new(
            self.clone(),
            parameter,
            Some(exact_xi),
        ))
    }
}
