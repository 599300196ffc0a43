//! Required separation over one record or a suite: the library's [`pounding::separation`] per record, as JSON,
//! with the mean, median and 84th percentile of each quantity over the suite.

use crate::input::{dict_message, from_value};
use crate::study::set_record;
use crate::summary::num;
use pounding::analysis::RunOptions;
use pounding::separation::{separation, Pair};
use serde_json::{json, Value};

fn pairs_json(names: &[String], pairs: &[Pair]) -> Value {
    Value::Array(
        pairs
            .iter()
            .map(|p| {
                json!({
                    "between": [names[p.left], names[p.right]],
                    "levels": p.levels.iter().map(|l| json!({
                        "floors": [l.floors.0, l.floors.1],
                        "peak_left": num(l.peak_left),
                        "peak_right": num(l.peak_right),
                        "required_gap": num(l.required_gap),
                        "abs": num(l.abs),
                        "srss": num(l.srss),
                        "ddc": num(l.ddc),
                        "rho": num(l.rho),
                        "factor": num(l.factor),
                    })).collect::<Vec<_>>(),
                })
            })
            .collect(),
    )
}

/// The quantities of a level that statistics are taken of.
pub const QUANTITIES: [&str; 6] = [
    "peak_left",
    "peak_right",
    "required_gap",
    "abs",
    "srss",
    "ddc",
];

/// Mean, median and 84th percentile (linear interpolation between order statistics, as numpy's default).
fn stats(mut xs: Vec<f64>) -> Value {
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
    json!({
        "mean": num(xs.iter().sum::<f64>() / n as f64),
        "median": num(q(0.5)),
        "p84": num(q(0.84)),
    })
}

/// The separation report of `scenario` (a JSON value, `label` saying where it came from), under its own
/// record or under each of `records` (sources: built-in names or file paths): one line on error.
pub fn report(
    scenario: &Value,
    label: &str,
    records: &[String],
    aligned_factor: Option<f64>,
) -> Result<Value, (Option<String>, String)> {
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
    // Each record's run is independent: on every core, in order.
    let one = |(record, v): &(Option<&String>, Value)| -> Result<(String, Value), (Option<String>, String)> {
        let loaded = from_value(v, label)?;
        let names: Vec<String> = loaded
            .scenario
            .buildings()
            .iter()
            .map(|b| b.name.clone())
            .collect();
        let pairs = separation(
            &loaded.scenario,
            aligned_factor,
            &RunOptions::summary_only(),
        )
        .map_err(|e| match e {
            pounding::Error::Parameter { .. } => (None, e.to_string()),
            other => (None, format!("analysis failed: {other}")),
        })?;
        let source = record.map_or(loaded.record_source.clone(), |r| r.clone());
        Ok((source, pairs_json(&names, &pairs)))
    };
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let results = crate::sweep::parallel_map(&variants, threads, one);
    // The first error in record order, as a sequential loop would give.
    let mut runs = results.into_iter().collect::<Result<Vec<_>, _>>()?;
    if runs.len() == 1 {
        let (_, pairs) = runs.pop().expect("one run");
        return Ok(json!({ "pairs": pairs, "units": units() }));
    }
    // Statistics level by level (every record gives the same pairs and levels).
    let first = runs[0].1.clone();
    let mut stat_pairs = Vec::new();
    for (p, pair) in first.as_array().into_iter().flatten().enumerate() {
        let mut levels = Vec::new();
        for (l, level) in pair["levels"].as_array().into_iter().flatten().enumerate() {
            let mut out = json!({ "floors": level["floors"] });
            for q in QUANTITIES {
                let xs: Vec<f64> = runs
                    .iter()
                    .filter_map(|(_, r)| r[p]["levels"][l][q].as_f64())
                    .collect();
                out[q] = stats(xs);
            }
            levels.push(out);
        }
        stat_pairs.push(json!({ "between": pair["between"], "levels": levels }));
    }
    Ok(json!({
        "records": runs.into_iter().map(|(r, pairs)| json!({ "record": r, "pairs": pairs })).collect::<Vec<_>>(),
        "statistics": { "pairs": stat_pairs },
        "units": units(),
    }))
}

fn units() -> Value {
    json!({
        "peak_left": "m", "peak_right": "m", "required_gap": "m (largest u_left - u_right without contact)",
        "abs": "m", "srss": "m", "ddc": "m", "rho": "CQC correlation of the fundamental modes",
        "factor": "applied to abs, srss, ddc (aligned floors)",
        "statistics": "mean, median and 84th percentile over the records",
    })
}

/// [`report`] with a dict's error message.
pub fn report_message(
    scenario: &Value,
    label: &str,
    records: &[String],
    aligned_factor: Option<f64>,
) -> Result<Value, String> {
    report(scenario, label, records, aligned_factor).map_err(|(k, m)| dict_message(k, m))
}
