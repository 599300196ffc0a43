//! The runs of a separation: one run without contact per record (and per intensity level), on every core.

use super::tables::{LevelReport, PairReport, RecordReport, Refusal};
use crate::input::from_value;
use pounding::analysis::RunOptions;
use pounding::separation::separation_with;
use serde_json::Value;
use std::ops::ControlFlow;
use std::sync::atomic::{AtomicBool, Ordering};

/// Most records of one separation: each run may take up to its step budget (about 5 s), and nothing is
/// kept until the last ends.
pub const MAX_RECORDS: usize = 10_000;

/// Runs each of `variants` (a record's label, if it replaces the scenario's, and the scenario) without
/// contact, on every core, asking `go_on` about every 0.05 s: each record's pairs, in order.
pub fn run_all(
    variants: &[(Option<String>, Value)],
    label: &str,
    aligned_factor: Option<f64>,
    go_on: &mut dyn FnMut() -> ControlFlow<()>,
) -> Result<Vec<RecordReport>, Refusal> {
    let cancel = AtomicBool::new(false);
    // Each record's run is independent: on every core, in order.
    let one = |(record, v): &(Option<String>, Value)| -> Result<RecordReport, Refusal> {
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
            record: record.clone().unwrap_or(loaded.record_source.clone()),
            pairs: pairs
                .into_iter()
                .map(|p| PairReport {
                    between: [names[p.left].clone(), names[p.right].clone()],
                    levels: p
                        .levels
                        .into_iter()
                        .map(|level| LevelReport {
                            level,
                            code_required_gap: None,
                        })
                        .collect(),
                })
                .collect(),
        })
    };
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let finished = AtomicBool::new(false);
    let work = || {
        let r = crate::sweep::parallel_map(variants, threads, |v| {
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
    results.into_iter().collect()
}
