//! Required separation over one record or a suite: the library's [`pounding::separation`] per record
//! ([`SeparationReport`]), with the mean, median and 84th percentile of each quantity over the suite.

use crate::input::from_value;
use crate::study::set_record;
use pounding::analysis::RunOptions;
use pounding::separation::{separation_with, Level};
use serde::Serialize;
use serde_json::{json, Map, Value};
use std::ops::ControlFlow;
use std::sync::atomic::{AtomicBool, Ordering};

/// The contact levels of one pair of neighbours under one record.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PairReport {
    /// The left and the right building.
    pub between: [String; 2],
    /// Its levels: floors, peaks, required gap and the rules' estimates (m).
    pub levels: Vec<Level>,
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
    fn of(mut xs: Vec<f64>) -> Stats {
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

/// The separation report: under the scenario's own record, or under each record of a suite with the
/// statistics over them.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum SeparationReport {
    /// Under one record.
    One {
        /// Its pairs.
        pairs: Vec<PairReport>,
        /// The unit of each quantity.
        units: Map<String, Value>,
    },
    /// Under each record of a suite.
    Suite {
        /// Record by record.
        records: Vec<RecordReport>,
        /// Over the records.
        statistics: SuiteStats,
        /// The unit of each quantity.
        units: Map<String, Value>,
    },
}

impl SeparationReport {
    /// The pairs of each record (one set under one record).
    pub fn runs(&self) -> Vec<&[PairReport]> {
        match self {
            SeparationReport::One { pairs, .. } => vec![pairs],
            SeparationReport::Suite { records, .. } => {
                records.iter().map(|r| r.pairs.as_slice()).collect()
            }
        }
    }
}

fn units() -> Map<String, Value> {
    match json!({
        "peak_left": "m", "peak_right": "m", "required_gap": "m (largest u_left - u_right without contact)",
        "abs": "m", "srss": "m", "ddc": "m", "rho": "CQC correlation of the fundamental modes",
        "factor": "applied to abs, srss, ddc (aligned floors)",
        "statistics": "mean, median and 84th percentile over the records",
    }) {
        Value::Object(m) => m,
        _ => unreachable!("a JSON object"),
    }
}

/// The statistics of every pair's levels over `runs` (each record gives the same pairs and levels).
fn statistics(runs: &[RecordReport]) -> SuiteStats {
    let stats = |p: usize, l: usize, q: fn(&Level) -> f64| {
        Stats::of(runs.iter().map(|r| q(&r.pairs[p].levels[l])).collect())
    };
    let pairs = runs[0]
        .pairs
        .iter()
        .enumerate()
        .map(|(p, pair)| PairStats {
            between: pair.between.clone(),
            levels: (0..pair.levels.len())
                .map(|l| LevelStats {
                    floors: pair.levels[l].floors,
                    peak_left: stats(p, l, |x| x.peak_left),
                    peak_right: stats(p, l, |x| x.peak_right),
                    required_gap: stats(p, l, |x| x.required_gap),
                    abs: stats(p, l, |x| x.abs),
                    srss: stats(p, l, |x| x.srss),
                    ddc: stats(p, l, |x| x.ddc),
                })
                .collect(),
        })
        .collect();
    SuiteStats { pairs }
}

/// Most records of one separation: each run may take up to its step budget (about 5 s), and nothing is
/// kept until the last ends.
pub const MAX_RECORDS: usize = 10_000;

/// The separation report of `scenario` (a JSON value, `label` saying where it came from), under its own
/// record or under each of `records` (sources: built-in names or file paths): one line on error.
pub fn report(
    scenario: &Value,
    label: &str,
    records: &[String],
    aligned_factor: Option<f64>,
) -> Result<SeparationReport, (Option<String>, String)> {
    report_with(scenario, label, records, aligned_factor, &mut || {
        ControlFlow::Continue(())
    })
}

/// [`report`], asking `go_on` on the calling thread about every 0.05 s whether to go on while the runs work
/// on other threads; `Break` stops every run within one progress report and ends in an error that says so.
pub fn report_with(
    scenario: &Value,
    label: &str,
    records: &[String],
    aligned_factor: Option<f64>,
    go_on: &mut dyn FnMut() -> ControlFlow<()>,
) -> Result<SeparationReport, (Option<String>, String)> {
    if records.len() > MAX_RECORDS {
        return Err((
            Some("records".into()),
            format!(
                "records: {} records is not allowed: at most {MAX_RECORDS} in one separation, which keeps nothing until it ends (a sweep or an IDA runs more, resumably)",
                records.len()
            ),
        ));
    }
    let variants: Vec<(Option<&String>, Value)> = if records.is_empty() {
        vec![(None, scenario.clone())]
    } else {
        records
            .iter()
            .map(|r| {
                let mut v = scenario.clone();
                set_record(&mut v, r);
                (Some(r), v)
            })
            .collect()
    };
    let cancel = AtomicBool::new(false);
    // Each record's run is independent: on every core, in order.
    let one =
        |(record, v): &(Option<&String>, Value)| -> Result<RecordReport, (Option<String>, String)> {
            let loaded = from_value(v, label)?;
            let names: Vec<String> = loaded
                .scenario
                .buildings()
                .iter()
                .map(|b| b.name.clone())
                .collect();
            let pairs = separation_with(
                &loaded.scenario,
                aligned_factor,
                &RunOptions::summary_only(),
                &mut |_| {
                    if cancel.load(Ordering::Relaxed) {
                        ControlFlow::Break(())
                    } else {
                        ControlFlow::Continue(())
                    }
                },
            )
            .map_err(|e| match e {
                pounding::Error::Parameter { .. } => (None, e.to_string()),
                other => (None, format!("analysis failed: {other}")),
            })?;
            Ok(RecordReport {
                record: record.map_or(loaded.record_source.clone(), |r| r.clone()),
                pairs: pairs
                    .into_iter()
                    .map(|p| PairReport {
                        between: [names[p.left].clone(), names[p.right].clone()],
                        levels: p.levels,
                    })
                    .collect(),
            })
        };
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let finished = AtomicBool::new(false);
    let work = || {
        let r = crate::sweep::parallel_map(&variants, threads, |v| {
            if cancel.load(Ordering::Relaxed) {
                Err((None, String::new()))
            } else {
                one(v)
            }
        });
        finished.store(true, Ordering::Release);
        r
    };
    let results = std::thread::scope(|s| {
        match std::thread::Builder::new().spawn_scoped(s, work) {
            Ok(h) => {
                while !finished.load(Ordering::Acquire) {
                    std::thread::sleep(std::time::Duration::from_millis(50));
                    if go_on().is_break() {
                        cancel.store(true, Ordering::Relaxed);
                    }
                }
                h.join().ok()
            }
            // No thread for the waiting: the work here, without asking.
            Err(_) => Some(work()),
        }
    });
    let Some(results) = results else {
        return Err((None, "separation failed: a worker thread stopped".into()));
    };
    if cancel.load(Ordering::Relaxed) {
        return Err((None, "separation cancelled".into()));
    }
    // The first error in record order, as a sequential loop would give.
    let mut runs = results.into_iter().collect::<Result<Vec<_>, _>>()?;
    if runs.len() == 1 {
        let run = runs.pop().expect("one run");
        return Ok(SeparationReport::One {
            pairs: run.pairs,
            units: units(),
        });
    }
    Ok(SeparationReport::Suite {
        statistics: statistics(&runs),
        records: runs,
        units: units(),
    })
}
