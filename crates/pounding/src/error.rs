//! The library's error type.

/// Everything that can go wrong in the library. Every variant names what was wrong and what is allowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A parameter outside its allowed range (or NaN).
    #[error("{name} = {} is not allowed: {allowed}", crate::words::number(*value))]
    Parameter {
        /// Parameter name.
        name: &'static str,
        /// Value given.
        value: f64,
        /// What is allowed, with the unit.
        allowed: &'static str,
    },
    /// A named choice that is not one of those allowed (an unknown building, a floor that does not exist).
    #[error("{name} = {value} is not allowed: {allowed}")]
    Choice {
        /// Parameter name.
        name: &'static str,
        /// Value given.
        value: String,
        /// What is allowed.
        allowed: String,
    },
    /// A list whose length must match another's.
    #[error("{name} has {len} values, but there {} {}: give one per floor", if *expected == 1 { "is" } else { "are" }, crate::words::count(*expected, "floor", None))]
    Length {
        /// Name of the list.
        name: &'static str,
        /// Its length.
        len: usize,
        /// The length required.
        expected: usize,
    },
    /// Exact calibration (the default damping) failed: no value of the parameter delivers `e`.
    #[error("cannot calibrate {what} for e = {}: {reason}; ask an e in that range, or damping = \"formula\" (--damping formula) for the published formula", crate::words::number(*e))]
    Calibration {
        /// The parameter being calibrated.
        what: &'static str,
        /// Requested coefficient of restitution.
        e: f64,
        /// Why.
        reason: String,
    },
    /// The integrator could not take a step.
    #[error("integration step size underflow at t = {t:e} s")]
    StepSizeUnderflow {
        /// Time reached, s.
        t: f64,
    },
    /// The impact's scales of length, time, momentum or energy leave the range of `f64` (more precisely,
    /// [`SCALE_RANGE`]): the impact's `mass`, `v_i` and its law's `k` and `n` set them.
    #[error(
        "mass = {} kg, v_i = {} m/s and k = {} {} are not allowed together: {}",
        crate::words::number(*mass),
        crate::words::number(*v_i),
        crate::words::number(*k),
        crate::words::stiffness_unit(*n),
        scales_allowed("mass", "v_i")
    )]
    ScaleOutOfRange {
        /// Effective mass, kg.
        mass: f64,
        /// Impact velocity, m/s.
        v_i: f64,
        /// Stiffness of the law (its loading stiffness), N/m^n.
        k: f64,
        /// Exponent of the law.
        n: f64,
    },
    /// The analysis would take (or took) more integration steps than its budget.
    #[error("the analysis needs more than {allowed:e} integration steps ({reason}); allowed: at most {allowed:e} (the work budget, limits::MAX_WORK by default, over the number of states + 8)")]
    StepBudget {
        /// The budget, steps.
        allowed: f64,
        /// Why: the highest natural frequency, the samples of the record, or the time reached.
        reason: String,
    },
    /// The caller stopped the run (its progress callback asked to).
    #[error("the run was cancelled at t = {t:e} s")]
    Cancelled {
        /// Time reached, s.
        t: f64,
    },
    /// The caller stopped a computation other than a run (a spectrum) through its callback.
    #[error("the {what} was cancelled")]
    Interrupted {
        /// What was stopped.
        what: &'static str,
    },
    /// A result is not a finite number (the scenario's scales leave the range of `f64`).
    #[error("the result {what} is not a finite number: the scenario's scales leave the range of floating-point numbers")]
    NotFinite {
        /// Which result.
        what: String,
    },
    /// Events kept firing without time advancing.
    #[error(
        "more than 1000 events at t = {t:e} s without time advancing (a phase that keeps changing)"
    )]
    EventChatter {
        /// Time reached, s.
        t: f64,
    },
    /// The contact never ended (for example a supercritically damped contact that may pull).
    #[error(
        "the contact had not ended at t = {t:e} s: the bodies do not separate with this damping"
    )]
    ContactNeverEnds {
        /// Time reached, s.
        t: f64,
    },
}

/// `Ok(value)` if `ok` holds and `value` is finite, else a [`Error::Parameter`] naming it: the one
/// validation used at the library's edges.
pub(crate) fn check(
    name: &'static str,
    value: f64,
    ok: bool,
    allowed: &'static str,
) -> Result<f64, Error> {
    if ok && value.is_finite() {
        Ok(value)
    } else {
        Err(Error::Parameter {
            name,
            value,
            allowed,
        })
    }
}

/// The range every scale of an impact must lie in, SI units: its momentum `m v_i`, its energy `m v_i^2`,
/// its penetration `d = (m v_i^2 / k)^(1/(n+1))` and its duration `d / v_i`. [`crate::impact::simulate`]
/// controls its error at a relative tolerance down to 1e-14 of each, which must stay a normal finite number.
pub const SCALE_RANGE: (f64, f64) = (2.3e-294, 1.7e294);

/// What [`SCALE_RANGE`] allows, in words, with the mass and the velocity called `m` and `v`:
/// `m v, m v^2, d = (m v^2 / k)^(1/(n+1)) and d / v must each be from 2.3e-294 to 1.7e294 (SI units)`.
pub fn scales_allowed(m: &str, v: &str) -> String {
    format!(
        "{m} {v}, {m} {v}^2, d = ({m} {v}^2 / k)^(1/(n+1)) and d / {v} must each be from {} to {} (SI units)",
        crate::words::number(SCALE_RANGE.0),
        crate::words::number(SCALE_RANGE.1)
    )
}
