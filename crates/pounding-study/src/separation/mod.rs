//! Required separation over one record or a suite: the library's [`pounding::separation`] per record
//! ([`SeparationReport`]), with the mean, median and 84th percentile of each quantity over the suite, and
//! the decision beyond it: the probability of pounding against the gap over the suite (a lognormal fit and
//! the records themselves), under a stationary random ground motion ([`noise`]), its mean annual frequency
//! with a hazard curve ([`risk`]), and the design codes' gaps ([`codes`]).

pub mod codes;
pub mod noise;
pub mod options;
pub mod risk;
pub mod runs;
pub mod tables;

pub use options::{options_from_json, SeparationOptions};
pub use runs::{run_all, MAX_RECORDS};
pub use tables::{
    LevelReport, LevelStats, PairReport, PairStats, RecordReport, Refusal, Stats, SuiteStats,
};

use crate::input::from_value;
use crate::study::set_record;
use pounding::separation::suite::{empirical_gap_for, empirical_probability, GapFit};
use pounding::separation::Level;
use serde::Serialize;
use serde_json::{json, Map, Value};
use std::ops::ControlFlow;

/// The separation report: under the scenario's own record, or under each record of a suite with the
/// statistics over them.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum SeparationReport {
    /// Under one record.
    One {
        /// Its pairs.
        pairs: Vec<PairReport>,
        /// The code asked for, with its parameters.
        #[serde(skip_serializing_if = "Option::is_none")]
        code: Option<codes::CodeInfo>,
        /// The unit of each quantity.
        units: Map<String, Value>,
    },
    /// Under each record of a suite.
    Suite {
        /// Record by record.
        records: Vec<RecordReport>,
        /// Over the records.
        statistics: SuiteStats,
        /// The target probability of pounding per record, if one was given.
        #[serde(skip_serializing_if = "Option::is_none")]
        target_probability: Option<f64>,
        /// The code asked for, with its parameters.
        #[serde(skip_serializing_if = "Option::is_none")]
        code: Option<codes::CodeInfo>,
        /// The unit of each quantity.
        units: Map<String, Value>,
    },
    /// Under a stationary random ground motion.
    WhiteNoise(noise::NoiseReport),
    /// The mean annual frequency of pounding against the gap, with a hazard curve.
    Risk(risk::RiskReport),
}

impl SeparationReport {
    /// The pairs of each record (one set under one record; none under a random motion).
    pub fn runs(&self) -> Vec<&[PairReport]> {
        match self {
            SeparationReport::One { pairs, .. } => vec![pairs],
            SeparationReport::Suite { records, .. } => {
                records.iter().map(|r| r.pairs.as_slice()).collect()
            }
            SeparationReport::WhiteNoise(_) | SeparationReport::Risk(_) => Vec::new(),
        }
    }
}

fn units() -> Map<String, Value> {
    match json!({
        "peak_left": "m", "peak_right": "m", "required_gap": "m (largest u_left - u_right without contact)",
        "abs": "m", "srss": "m", "ddc": "m", "rho": "CQC correlation of the fundamental modes",
        "factor": "applied to abs, srss, ddc (aligned floors)",
        "statistics": "mean, median and 84th percentile over the records",
        "gap": "m (the contact's at rest)",
        "fit": "lognormal of the records' required gaps: median (m), dispersion (of ln), approaching of records",
        "probability": "that a record pounds at the contact's gap (from the fit)",
        "probability_empirical": "the fraction of records that pound at the contact's gap",
        "gap_for_target": "m (from the fit)", "gap_for_target_empirical": "m (from the records)",
        "code_required_gap": "m", "elastic": "m (elastic displacements of the two floors under the design spectrum)",
    }) {
        Value::Object(m) => m,
        _ => unreachable!("a JSON object"),
    }
}

/// The statistics of every pair's levels over `runs` (each record gives the same pairs and levels), with the
/// lognormal fit of the required gaps and the probability of pounding at the contact's gap (and the gap for
/// `target`, a probability per record).
fn statistics(runs: &[RecordReport], target: Option<f64>) -> SuiteStats {
    let stats = |p: usize, l: usize, q: fn(&Level) -> f64| {
        Stats::of(
            runs.iter()
                .map(|r| q(&r.pairs[p].levels[l].level))
                .collect(),
        )
    };
    let pairs = runs[0]
        .pairs
        .iter()
        .enumerate()
        .map(|(p, pair)| PairStats {
            between: pair.between.clone(),
            levels: (0..pair.levels.len())
                .map(|l| {
                    let gaps: Vec<f64> = runs
                        .iter()
                        .map(|r| r.pairs[p].levels[l].level.required_gap)
                        .collect();
                    let gap = pair.levels[l].level.gap;
                    let fit = GapFit::of(&gaps).ok();
                    LevelStats {
                        floors: pair.levels[l].level.floors,
                        point: pair.levels[l].level.point,
                        peak_left: stats(p, l, |x| x.peak_left),
                        peak_right: stats(p, l, |x| x.peak_right),
                        required_gap: stats(p, l, |x| x.required_gap),
                        abs: stats(p, l, |x| x.abs),
                        srss: stats(p, l, |x| x.srss),
                        ddc: stats(p, l, |x| x.ddc),
                        gap,
                        probability: fit.map(|f| f.probability(gap)),
                        probability_empirical: empirical_probability(&gaps, gap),
                        gap_for_target: target.and_then(|t| fit.and_then(|f| f.gap_for(t).ok())),
                        gap_for_target_empirical: target
                            .and_then(|t| empirical_gap_for(&gaps, t).ok()),
                        fit,
                        code_required_gap: None,
                        probability_at_code_gap: None,
                        probability_at_code_gap_empirical: None,
                    }
                })
                .collect(),
        })
        .collect();
    SuiteStats { pairs }
}

/// The separation report of `scenario` (a JSON value, `label` saying where it came from), under its own
/// record or under each of `records` (sources: built-in names or file paths): one line on error.
pub fn report(
    scenario: &Value,
    label: &str,
    records: &[String],
    aligned_factor: Option<f64>,
) -> Result<SeparationReport, (Option<String>, String)> {
    let options = SeparationOptions {
        records: records.to_vec(),
        aligned_factor,
        ..SeparationOptions::default()
    };
    report_with(scenario, label, &options, &mut || ControlFlow::Continue(()))
}

fn refuse(key: &str, msg: String) -> Refusal {
    (Some(key.into()), msg)
}

/// [`report`] with every option, asking `go_on` on the calling thread about every 0.05 s whether to go on
/// while the runs work on other threads; `Break` stops every run within one progress report and ends in an
/// error that says so.
pub fn report_with(
    scenario: &Value,
    label: &str,
    options: &SeparationOptions,
    go_on: &mut dyn FnMut() -> ControlFlow<()>,
) -> Result<SeparationReport, Refusal> {
    let records = &options.records;
    if records.len() > MAX_RECORDS {
        return Err(refuse(
            "records",
            format!(
                "records: {} records is not allowed: at most {MAX_RECORDS} in one separation, which keeps nothing until it ends (a sweep or an IDA runs more, resumably)",
                records.len()
            ),
        ));
    }
    if let Some(p) = options.target_probability {
        if !(p > 0.0 && p < 1.0) {
            return Err(refuse(
                "target_probability",
                format!(
                    "target_probability = {} is not allowed: 0 < target_probability < 1",
                    pounding::words::number(p)
                ),
            ));
        }
    }
    match (&options.white_noise, &options.risk, records.is_empty()) {
        (Some(_), _, false) | (Some(_), Some(_), _) => {
            return Err(refuse(
                "white_noise",
                "white_noise is not allowed with records or a hazard curve: give one, a random motion (white_noise) or records (with a hazard curve for annual frequencies)".into(),
            ))
        }
        (None, Some(_), true) => {
            return Err(refuse(
                "hazard",
                "hazard needs records: the suite scaled to each intensity level".into(),
            ))
        }
        _ => {}
    }
    let base = from_value(scenario, label)?;
    // Codes and the white-noise model see buildings in one line; buildings in plan get the gap each contact
    // point needed from their runs without contact (their corners, where the façades' closing peaks).
    // The linear models (white noise, codes) hold buildings in one line on a fixed base under one ground
    // motion; others get their gaps from runs.
    let beyond = base.scenario.buildings().iter().find_map(|b| {
        let st = &b.structure;
        (st.plan().is_some()).then_some("buildings in plan").or(st
            .foundation()
            .is_some()
            .then_some("buildings on soil springs"))
    });
    let beyond = beyond.or(base
        .scenario
        .multi_support()
        .then_some("supports of their own"));
    if let Some(what) = beyond {
        let key = match (&options.white_noise, &options.code) {
            (Some(_), _) => Some("white_noise"),
            (None, Some(_)) => Some("code"),
            _ => None,
        };
        if let Some(key) = key {
            return Err(refuse(
                key,
                format!("{key} is not allowed for {what} yet: their separation comes from runs without contact, each contact's largest closing (give records, or none for the scenario's own)"),
            ));
        }
    }
    let code = codes::CodeInfo::of(&base.scenario, options.code.as_ref())?;
    if let Some(noise) = &options.white_noise {
        return noise::report(&base.scenario, noise, options.target_probability, code)
            .map(SeparationReport::WhiteNoise);
    }
    if let Some(risk) = &options.risk {
        return risk::report(
            scenario,
            label,
            &options.records,
            (options.aligned_factor, options.target_probability),
            risk,
            code,
            go_on,
        )
        .map(SeparationReport::Risk);
    }
    let variants: Vec<(Option<String>, Value)> = if records.is_empty() {
        vec![(None, scenario.clone())]
    } else {
        records
            .iter()
            .map(|r| {
                let mut v = scenario.clone();
                set_record(&mut v, r);
                (Some(r.clone()), v)
            })
            .collect()
    };
    let mut runs = run_all(&variants, label, options.aligned_factor, go_on)?;
    if runs.len() == 1 {
        let mut run = runs.pop().expect("one run");
        if let Some(c) = &code {
            c.fill(&mut run.pairs);
        }
        return Ok(SeparationReport::One {
            pairs: run.pairs,
            code,
            units: units(),
        });
    }
    let mut statistics = statistics(&runs, options.target_probability);
    if let Some(c) = &code {
        c.fill_stats(&mut statistics, &runs);
    }
    Ok(SeparationReport::Suite {
        statistics,
        records: runs,
        target_probability: options.target_probability,
        code,
        units: units(),
    })
}

/// A refusal as one line: the message, prefixed by its key unless it starts with it.
pub fn message((key, msg): Refusal) -> String {
    match key {
        Some(k) if !msg.starts_with(k.as_str()) => format!("{k}: {msg}"),
        _ => msg,
    }
}
