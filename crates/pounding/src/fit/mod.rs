//! Contact laws fitted to measurements (docs/contact-models.md section 2.8): restitution measured against
//! the impact velocity ([`restitution`]), and the force history of one impact ([`force_history()`]). Each
//! fit is least squares ([`least_squares`]) and gives its parameters under their scenario key names, with
//! standard errors from the fit's Jacobian and the residual.

pub mod force_history;
pub mod least_squares;
pub mod restitution;

pub use force_history::{force_history, HistoryFit, HistorySetup};

/// One fitted parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct Estimate {
    /// Its name: the scenario key it goes under (`damping_constant`, `stiffness`, `e`, ...), or what it is
    /// (`yield_velocity`, `touch_time`).
    pub key: &'static str,
    /// The estimate, in `unit`.
    pub value: f64,
    /// Its standard error, in `unit` (infinite when the data leave no degree of freedom for it).
    pub std_error: f64,
    /// Its unit (`s/m`, `N/m^1.5`; empty for a dimensionless one).
    pub unit: String,
}

impl Estimate {
    /// An estimate of `key` with its standard error, in `unit`.
    pub fn new(key: &'static str, value: f64, std_error: f64, unit: impl Into<String>) -> Self {
        Self {
            key,
            value,
            std_error,
            unit: unit.into(),
        }
    }
}

/// A fit: its parameters and how well it fits.
#[derive(Clone, Debug, PartialEq)]
pub struct Fit {
    /// The parameters.
    pub estimates: Vec<Estimate>,
    /// Root mean square of the residuals, in the unit of the data fitted (dimensionless for `e`, N for a
    /// force).
    pub rms_residual: f64,
    /// The residual relative to the data: `sqrt(sum r^2 / sum y^2)` (dimensionless; the "normalised error"
    /// force-history fits in the literature report).
    pub normalised_residual: f64,
    /// Data points used.
    pub points: usize,
    /// Iterations of the least-squares solver (0 for a closed form).
    pub iterations: usize,
}

impl Fit {
    /// The fit of `estimates`, leaving `residuals` on the data `observed`.
    pub fn new(
        estimates: Vec<Estimate>,
        residuals: &[f64],
        observed: impl Iterator<Item = f64>,
        iterations: usize,
    ) -> Self {
        let rss: f64 = residuals.iter().map(|r| r * r).sum();
        let sum_sq: f64 = observed.map(|y| y * y).sum();
        let n = residuals.len().max(1) as f64;
        Self {
            estimates,
            rms_residual: (rss / n).sqrt(),
            normalised_residual: if sum_sq > 0.0 {
                (rss / sum_sq).sqrt()
            } else {
                0.0
            },
            points: residuals.len(),
            iterations,
        }
    }

    /// The estimate of `key`, if the fit has one.
    pub fn get(&self, key: &str) -> Option<&Estimate> {
        self.estimates.iter().find(|e| e.key == key)
    }
}
