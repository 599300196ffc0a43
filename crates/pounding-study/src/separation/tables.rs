//! The tables of a separation over records: each record's levels, and the statistics over a suite.

use pounding::separation::suite::GapFit;
use pounding::separation::Level;
use serde::Serialize;

/// An error of the separation's options: `(key, message)`, the message naming the key.
pub type Refusal = (Option<String>, String);

/// The contact levels of one pair of neighbours under one record.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PairReport {
    /// The left and the right building.
    pub between: [String; 2],
    /// Its levels: floors, peaks, required gap and the rules' estimates (m).
    pub levels: Vec<LevelReport>,
}

/// One contact level under one record, with a code's gap beside it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LevelReport {
    /// The run's answer and the rules' estimates.
    #[serde(flatten)]
    pub level: Level,
    /// The gap the code asked for requires here, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub code_required_gap: Option<f64>,
}

/// Every pair under one record of a suite.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RecordReport {
    /// The record's source.
    pub record: String,
    /// Its pairs.
    pub pairs: Vec<PairReport>,
}

/// Mean, median and 84th percentile of a quantity over the records, in its unit.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Stats {
    /// Mean.
    pub mean: f64,
    /// Median.
    pub median: f64,
    /// 84th percentile (linear interpolation between order statistics, as numpy's default).
    pub p84: f64,
}

impl Stats {
    /// The statistics of `xs` (not empty).
    pub fn of(mut xs: Vec<f64>) -> Stats {
        xs.sort_by(f64::total_cmp);
        let n = xs.len();
        let q = |p: f64| {
            let x = p * (n - 1) as f64;
            let (i, f) = (x.floor() as usize, x - x.floor());
            if i + 1 < n {
                xs[i] * (1.0 - f) + xs[i + 1] * f
            } else {
                xs[i]
            }
        };
        Stats {
            mean: xs.iter().sum::<f64>() / n as f64,
            median: q(0.5),
            p84: q(0.84),
        }
    }
}

/// The statistics of one level over the records, m.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LevelStats {
    /// Floors (of the left building, of the right), from 1.
    pub floors: (usize, usize),
    /// Between buildings in plan: the level's point on the façade, `(x, y)` in the site's frame, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub point: Option<(f64, f64)>,
    /// Peak displacement of the left floor.
    pub peak_left: Stats,
    /// Peak displacement of the right floor.
    pub peak_right: Stats,
    /// The gap each record needed.
    pub required_gap: Stats,
    /// The ABS rule.
    pub abs: Stats,
    /// The SRSS rule.
    pub srss: Stats,
    /// The DDC rule.
    pub ddc: Stats,
    /// The contact's gap at rest, m.
    pub gap: f64,
    /// The lognormal fitted to the records' required gaps (absent with fewer than two approaching).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fit: Option<GapFit>,
    /// Probability that a record of the suite pounds at the contact's gap, from the fit.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub probability: Option<f64>,
    /// The fraction of the records that pound at the contact's gap.
    pub probability_empirical: f64,
    /// The gap for the target probability, from the fit, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gap_for_target: Option<f64>,
    /// The smallest gap at which at most the target fraction of records pound, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gap_for_target_empirical: Option<f64>,
    /// The gap the code asked for requires here, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub code_required_gap: Option<f64>,
    /// Probability that a record pounds at the code's gap, from the fit.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub probability_at_code_gap: Option<f64>,
    /// The fraction of the records that pound at the code's gap.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub probability_at_code_gap_empirical: Option<f64>,
}

/// The statistics of one pair's levels over the records.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PairStats {
    /// The left and the right building.
    pub between: [String; 2],
    /// Its levels.
    pub levels: Vec<LevelStats>,
}

/// The statistics over a suite.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SuiteStats {
    /// Pair by pair.
    pub pairs: Vec<PairStats>,
}
