//! Physical constants the library shares, in SI units.

/// Standard gravity, m/s^2 (the conventional value, 3rd CGPM 1901): what a record in g is scaled by, and
/// the acceleration under a dropped ball or a friction pendulum's weight.
pub const STANDARD_GRAVITY: f64 = 9.80665;
