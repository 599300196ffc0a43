//! Many runs in parallel: scenarios (JSON values) prepared into keyed jobs, run on worker threads (summaries
//! only, no histories), each finished run handed to the calling thread, which commits it to the store (if any)
//! and reports progress. Runs whose key the store holds are not run again.

use crate::input::{self, dict_message, Loaded};
use crate::key::{fnv1a_128, key_of};
use crate::store::{Finished, Store, StoreError};
use crate::summary::RunSummary;
use pounding::analysis::RunOptions;
use pounding::ground_motion::Record;
use pounding::scenario::{RecordSpec, ScenarioDoc};
use serde_json::Value;
use std::collections::HashMap;
use std::ops::ControlFlow;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{mpsc, Arc, Mutex};
use std::time::{Duration, Instant};

/// A scenario ready to run: its key, and its validated document with its record, or why it cannot run.
pub struct Prepared {
    /// The run's key ([`crate::key`]): the scenario in canonical form, a record file by its content.
    pub key: String,
    /// Where it came from (shown in its summary's `scenario`).
    pub label: String,
    job: Result<Job, String>,
}

struct Job {
    doc: ScenarioDoc,
    record: Arc<Record>,
    spec: RecordSpec,
}

impl Prepared {
    /// The error that stops this scenario before it runs, if any.
    pub fn error(&self) -> Option<&str> {
        self.job.as_ref().err().map(String::as_str)
    }
}

/// Records read once per study, by source, format and units: `(unscaled record, content hash)`.
type RecordCache = Mutex<HashMap<String, Result<(Arc<Record>, String), String>>>;

fn prepare_one(value: &Value, label: String, cache: &RecordCache) -> Prepared {
    let doc = match input::parse_doc(value) {
        Ok(d) => d,
        Err((k, m)) => {
            return Prepared {
                key: key_of(value),
                label,
                job: Err(dict_message(k, m)),
            }
        }
    };
    // The key is the document with its defaults written out, so `gap = 1` and `gap = 1.0` are one run.
    let mut canonical = serde_json::to_value(&doc).unwrap_or(Value::Null);
    let spec = match doc.ground_motion.spec() {
        Ok(s) => s,
        Err(e) => {
            return Prepared {
                key: key_of(&canonical),
                label,
                job: Err(dict_message(Some(e.key), e.message)),
            }
        }
    };
    let id = format!("{}|{:?}|{:?}", spec.source, spec.format, spec.units);
    let loaded = {
        let mut c = cache.lock().unwrap_or_else(|p| p.into_inner());
        c.entry(id)
            .or_insert_with(|| {
                let r = input::read_record(&spec).map_err(|e| {
                    format!(
                        "ground_motion: [ground_motion] {}",
                        input::record_message(&spec, e)
                    )
                })?;
                let hash = format!("{:032x}", fnv1a_128(&bytes_of(r.accelerations(), r.dt())));
                Ok((Arc::new(r), hash))
            })
            .clone()
    };
    match loaded {
        Err(m) => Prepared {
            key: key_of(&canonical),
            label,
            job: Err(m),
        },
        Ok((record, hash)) => {
            // A record file is known by its content, not by its path: the key holds wherever the study runs.
            if spec.is_file {
                if let Some(f) = canonical.pointer_mut("/ground_motion/file") {
                    *f = Value::String(format!("fnv1a-128:{hash}"));
                }
            }
            Prepared {
                key: key_of(&canonical),
                label,
                job: Ok(Job { doc, record, spec }),
            }
        }
    }
}

/// The bytes that identify a record: its time step and accelerations.
fn bytes_of(acc: &[f64], dt: f64) -> Vec<u8> {
    let mut b = Vec::with_capacity(8 * (acc.len() + 1));
    b.extend_from_slice(&dt.to_le_bytes());
    for a in acc {
        b.extend_from_slice(&a.to_le_bytes());
    }
    b
}

/// `f` of every item on `workers` threads (each taking the next index), results in input order.
pub fn parallel_map<T: Sync, R: Send>(
    items: &[T],
    workers: usize,
    f: impl Fn(&T) -> R + Sync,
) -> Vec<R> {
    let next = AtomicUsize::new(0);
    let slots: Vec<Mutex<Option<R>>> = items.iter().map(|_| Mutex::new(None)).collect();
    std::thread::scope(|s| {
        for _ in 0..workers.max(1).min(items.len()) {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(item) = items.get(i) else { break };
                let r = f(item);
                *slots[i].lock().unwrap_or_else(|p| p.into_inner()) = Some(r);
            });
        }
    });
    slots
        .into_iter()
        .map(|s| {
            s.into_inner()
                .unwrap_or_else(|p| p.into_inner())
                .expect("every slot is filled")
        })
        .collect()
}

/// Most worker threads per core a sweep or an IDA may start: more only adds memory and switching, and
/// thousands of threads can exhaust what the OS gives a process.
pub const MAX_WORKERS_PER_CORE: usize = 16;

/// `workers` checked against 1 ..= [`MAX_WORKERS_PER_CORE`] times this machine's cores; the error names
/// `key` (`--workers`, `workers`) and what is allowed.
pub fn check_workers(key: &str, workers: usize) -> Result<usize, String> {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let most = MAX_WORKERS_PER_CORE * cores;
    if (1..=most).contains(&workers) {
        Ok(workers)
    } else {
        Err(format!(
            "{key} {workers} is not allowed: 1 to {most} ({MAX_WORKERS_PER_CORE} per core on this machine; default: the number of cores)"
        ))
    }
}

/// Prepares `values` (with their labels) on `workers` threads: parsed, keyed, records read once each.
pub fn prepare(values: Vec<(Value, String)>, workers: usize) -> Vec<Prepared> {
    let cache = RecordCache::default();
    parallel_map(&values, workers, |(v, label)| {
        prepare_one(v, label.clone(), &cache)
    })
}

/// The identity of a study: the hash of its run keys, in order.
pub fn study_id(prepared: &[Prepared]) -> String {
    let keys: Vec<&str> = prepared.iter().map(|p| p.key.as_str()).collect();
    format!("{:032x}", fnv1a_128(keys.join("\n").as_bytes()))
}

/// Runs one prepared scenario: its summary, or the one-line message.
pub fn run_one(
    p: &Prepared,
    options: &RunOptions,
    cancel: &AtomicBool,
) -> Result<RunSummary, String> {
    let job = p.job.as_ref().map_err(Clone::clone)?;
    let record = (*job.record)
        .clone()
        .scaled(job.spec.scale)
        .map_err(|e| format!("ground_motion.scale: {e}"))?;
    let loaded: Loaded = input::build(job.doc.clone(), record, &p.label, job.spec.source.clone())
        .map_err(|(k, m)| dict_message(k, m))?;
    let results = loaded
        .scenario
        .run_with_options(options, &mut |_| {
            if cancel.load(Ordering::Relaxed) {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        })
        .map_err(|e| format!("analysis failed: {e}"))?;
    RunSummary::new(&loaded, &results)
}

/// Where a sweep stands, given to the progress callback.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Progress {
    /// Runs finished so far in this session (ok or error).
    pub done: usize,
    /// Runs this session has to do (the study's distinct runs not yet in the store).
    pub todo: usize,
    /// Runs found finished in the store and not run again.
    pub skipped: usize,
    /// Runs found in the store with a summary that does not read as one (damaged), run again.
    pub damaged: usize,
    /// Runs that ended with an error so far.
    pub failed: usize,
    /// Wall time since the runs began, s.
    pub elapsed: f64,
}

/// How a sweep ended early.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SweepError {
    /// The progress callback asked to stop; everything finished until then is in the store.
    Cancelled,
    /// The store failed.
    Store(StoreError),
}

impl std::fmt::Display for SweepError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SweepError::Cancelled => f.write_str("cancelled; finished runs are in the store"),
            SweepError::Store(e) => e.fmt(f),
        }
    }
}

/// What a stored row says a run gave, if it can be trusted: intact ([`crate::store::Stored::intact`]) and,
/// if ok, a summary that reads back as one.
pub fn trusted(row: crate::store::Stored) -> Option<Result<RunSummary, String>> {
    if !row.intact {
        return None;
    }
    match row.outcome {
        Ok(text) => RunSummary::from_json(&text).ok().map(Ok),
        Err(e) => Some(Err(e)),
    }
}

/// Runs every prepared scenario not already in `store`, on `workers` threads, and returns every run's outcome
/// in input order (its summary or the error message; runs of equal key share one outcome). A stored summary
/// or row that is not intact or does not read back as one is not trusted: that run is run again and stored anew. `progress` is
/// called on this thread at least every 0.2 s; returning `Break` cancels the sweep.
pub fn run(
    prepared: &[Prepared],
    workers: usize,
    options: &RunOptions,
    mut store: Option<&mut Store>,
    progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
) -> Result<Vec<Result<RunSummary, String>>, SweepError> {
    let mut outcomes: HashMap<&str, Result<RunSummary, String>> = HashMap::new();
    let mut damaged = 0;
    if let Some(st) = store.as_deref() {
        // The study's own key strings (borrowed from `prepared`), found by value.
        let keys: std::collections::HashSet<&str> =
            prepared.iter().map(|p| p.key.as_str()).collect();
        for row in st.all().map_err(SweepError::Store)? {
            let Some(key) = keys.get(row.key.as_str()) else {
                continue;
            };
            match trusted(row) {
                Some(outcome) => {
                    outcomes.insert(*key, outcome);
                }
                None => damaged += 1,
            }
        }
    }
    let skipped = outcomes.len();
    // One run per distinct key not yet finished, in study order.
    let mut todo: Vec<usize> = Vec::new();
    let mut seen: std::collections::HashSet<&str> = outcomes.keys().copied().collect();
    for (i, p) in prepared.iter().enumerate() {
        if seen.insert(p.key.as_str()) {
            todo.push(i);
        }
    }
    let cancel = AtomicBool::new(false);
    let next = AtomicUsize::new(0);
    let (tx, rx) = mpsc::channel::<Finished>();
    let start = Instant::now();
    let mut state = Progress {
        done: 0,
        todo: todo.len(),
        skipped,
        damaged,
        failed: 0,
        elapsed: 0.0,
    };
    let mut failure = None;
    std::thread::scope(|s| {
        for _ in 0..workers.max(1).min(todo.len().max(1)) {
            let tx = tx.clone();
            let (todo, next, cancel) = (&todo, &next, &cancel);
            s.spawn(move || loop {
                if cancel.load(Ordering::Relaxed) {
                    break;
                }
                let Some(&i) = todo.get(next.fetch_add(1, Ordering::Relaxed)) else {
                    break;
                };
                let t0 = Instant::now();
                let outcome = run_one(&prepared[i], options, cancel);
                if cancel.load(Ordering::Relaxed) {
                    // A run cut short is not a result.
                    break;
                }
                let f = Finished {
                    key: prepared[i].key.clone(),
                    index: i,
                    outcome: outcome.map(|s| s.to_value().to_string()),
                    seconds: t0.elapsed().as_secs_f64(),
                };
                if tx.send(f).is_err() {
                    break;
                }
            });
        }
        drop(tx);
        let mut batch: Vec<Finished> = Vec::new();
        let mut last = Instant::now();
        let mut open = true;
        while open {
            match rx.recv_timeout(Duration::from_millis(100)) {
                Ok(f) => {
                    batch.push(f);
                    // Whatever else has finished goes into the same transaction.
                    batch.extend(rx.try_iter());
                }
                Err(mpsc::RecvTimeoutError::Timeout) => {}
                Err(mpsc::RecvTimeoutError::Disconnected) => open = false,
            }
            if !batch.is_empty() {
                if let Some(st) = store.as_deref_mut() {
                    if let Err(e) = st.commit(&batch) {
                        failure = Some(SweepError::Store(e));
                        cancel.store(true, Ordering::Relaxed);
                    }
                }
                for f in batch.drain(..) {
                    state.done += 1;
                    state.failed += usize::from(f.outcome.is_err());
                    let outcome = f.outcome.and_then(|text| RunSummary::from_json(&text));
                    outcomes.insert(prepared[f.index].key.as_str(), outcome);
                }
            }
            if last.elapsed() >= Duration::from_millis(100) || !open {
                last = Instant::now();
                state.elapsed = start.elapsed().as_secs_f64();
                if progress(state).is_break() && failure.is_none() {
                    failure = Some(SweepError::Cancelled);
                    cancel.store(true, Ordering::Relaxed);
                }
            }
        }
    });
    if let Some(f) = failure {
        return Err(f);
    }
    Ok(prepared
        .iter()
        .map(|p| {
            outcomes
                .get(p.key.as_str())
                .cloned()
                .unwrap_or_else(|| Err("not run".into()))
        })
        .collect())
}
