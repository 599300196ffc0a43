//! Many runs in parallel: scenarios (JSON values) prepared into keyed jobs, run on worker threads (summaries
//! only, no histories), each finished run handed to the calling thread, which commits it to the store (if any)
//! and reports progress. Runs whose key the store holds are not run again.

use crate::input::{self, dict_message, Loaded};
use crate::key::{fnv1a_128, key_of};
use crate::store::{Finished, Outcome, Store, StoreError};
use crate::summary::RunSummary;
use pounding::analysis::RunOptions;
use pounding::ground_motion::Record;
use pounding::scenario::{RecordSpec, ScenarioDoc};
use serde_json::Value;
use std::collections::{HashMap, HashSet};
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
    /// The record along y, if any, unscaled, and what names it.
    y: Option<(Arc<Record>, RecordSpec)>,
    /// The supports' own records, unscaled, and what names them.
    supports: Vec<(Arc<Record>, RecordSpec)>,
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
    let specs = doc.ground_motion.spec().and_then(|x| {
        Ok((
            x,
            doc.ground_motion.spec_y()?,
            doc.support_specs()?
                .into_iter()
                .flatten()
                .collect::<Vec<_>>(),
        ))
    });
    let (spec, spec_y, spec_supports) = match specs {
        Ok(s) => s,
        Err(e) => {
            return Prepared {
                key: key_of(&canonical),
                label,
                job: Err(dict_message(Some(e.key), e.message)),
            }
        }
    };
    let loaded = cached(&spec, "ground_motion", cache).and_then(|x| {
        let y = spec_y
            .as_ref()
            .map(|sy| cached(sy, "ground_motion.y", cache))
            .transpose()?;
        let supports = spec_supports
            .iter()
            .map(|sp| cached(sp, "support", cache))
            .collect::<Result<Vec<_>, _>>()?;
        Ok((x, y, supports))
    });
    match loaded {
        Err(m) => Prepared {
            key: key_of(&canonical),
            label,
            job: Err(m),
        },
        Ok(((record, hash), y, supports)) => {
            // A record file is known by its content, not by its path: the key holds wherever the study runs.
            if spec.is_file {
                if let Some(f) = canonical.pointer_mut("/ground_motion/file") {
                    *f = Value::String(format!("fnv1a-128:{hash}"));
                }
            }
            if let (Some(sy), Some((_, hy))) = (&spec_y, &y) {
                if sy.is_file {
                    if let Some(f) = canonical.pointer_mut("/ground_motion/y/file") {
                        *f = Value::String(format!("fnv1a-128:{hy}"));
                    }
                }
            }
            // Supports' files by content too.
            let mut k = 0;
            for (i, sp) in doc.support.iter().enumerate() {
                if sp.file.is_some() {
                    if let (Some(f), Some((_, h))) = (
                        canonical.pointer_mut(&format!("/support/{i}/file")),
                        supports.get(k),
                    ) {
                        *f = Value::String(format!("fnv1a-128:{h}"));
                    }
                }
                k += usize::from(sp.own().is_some());
            }
            let y = y.zip(spec_y).map(|((r, _), s)| (r, s));
            let supports = supports
                .into_iter()
                .zip(spec_supports)
                .map(|((r, _), s)| (r, s))
                .collect();
            Prepared {
                key: key_of(&canonical),
                label,
                job: Ok(Job {
                    doc,
                    record,
                    spec,
                    y,
                    supports,
                }),
            }
        }
    }
}

/// The record `spec` names (at `at` in messages), read once per study: `(unscaled record, content hash)`.
fn cached(
    spec: &RecordSpec,
    at: &str,
    cache: &RecordCache,
) -> Result<(Arc<Record>, String), String> {
    let id = format!("{}|{:?}|{:?}", spec.source, spec.format, spec.units);
    let mut c = cache.lock().unwrap_or_else(|p| p.into_inner());
    c.entry(id)
        .or_insert_with(|| {
            let r = input::read_record(spec)
                .map_err(|e| format!("{at}: [{at}] {}", input::record_message(spec, e)))?;
            let hash = format!("{:032x}", fnv1a_128(&bytes_of(r.accelerations(), r.dt())));
            Ok((Arc::new(r), hash))
        })
        .clone()
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
    crate::key::keys_id(&keys)
}

/// The keys of the runs made by `scenario(i)` for `i` in `0..n`, prepared on `workers` threads, in order.
pub fn run_keys(
    n: usize,
    scenario: &(dyn Fn(usize) -> (Value, String) + Sync),
    workers: usize,
) -> Vec<String> {
    prepare((0..n).map(scenario).collect(), workers)
        .into_iter()
        .map(|p| p.key)
        .collect()
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
    let y = job
        .y
        .as_ref()
        .map(|(r, s)| {
            (**r)
                .clone()
                .scaled(s.scale)
                .map_err(|e| format!("ground_motion.y.scale: {e}"))
        })
        .transpose()?;
    let supports = job
        .supports
        .iter()
        .map(|(r, s)| {
            (**r)
                .clone()
                .scaled(s.scale)
                .map_err(|e| format!("support.scale: {e}"))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let loaded: Loaded = input::build(
        job.doc.clone(),
        (record, y, supports),
        &p.label,
        job.spec.source.clone(),
    )
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
    /// Runs of the study handled so far in this session: run (ok or error), found in the store, or the
    /// same as an earlier run.
    pub done: usize,
    /// Runs of the study.
    pub todo: usize,
    /// Runs found finished in the store and not run again.
    pub skipped: usize,
    /// Runs found in the store damaged (not intact, or a summary that does not read as one), run again.
    pub damaged: usize,
    /// Runs that ended with an error so far in this session.
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
    /// The operating system refused a worker thread.
    Thread(String),
}

impl std::fmt::Display for SweepError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SweepError::Cancelled => f.write_str("cancelled; finished runs are in the store"),
            SweepError::Store(e) => e.fmt(f),
            SweepError::Thread(m) => f.write_str(m),
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

/// What a study's run `i` is: its scenario and its label.
pub type Scenarios<'a> = &'a (dyn Fn(usize) -> (Value, String) + Sync);

/// What a sweep leaves: each run's key, in study order, and (without a store) each key's outcome. With a
/// store the outcomes are in it, read back by [`Swept::outcome`], so that a study of millions of runs holds
/// only its keys.
pub struct Swept {
    /// Each run's key, in study order.
    pub keys: Vec<u128>,
    outcomes: HashMap<u128, Outcome>,
}

impl Swept {
    /// Run `i`'s outcome: its summary (JSON text) or its one-line error, from the store if there is one.
    pub fn outcome(&self, i: usize, store: Option<&Store>) -> Result<Outcome, StoreError> {
        let key = self.keys[i];
        if let Some(o) = self.outcomes.get(&key) {
            return Ok(o.clone());
        }
        let stored = match store {
            Some(st) => st.get(&hex(key))?,
            None => None,
        };
        Ok(stored
            .map(|row| row.outcome)
            .unwrap_or_else(|| Err("not run".into())))
    }

    /// Run `i`'s key as stored (32 hexadecimal digits).
    pub fn key(&self, i: usize) -> String {
        hex(self.keys[i])
    }
}

/// A key as text.
fn hex(key: u128) -> String {
    format!("{key:032x}")
}

/// What a worker tells the committing thread.
enum Message {
    /// Run `index` has `key` and needs nothing more (found in the store, or an earlier run's twin).
    Keyed {
        index: usize,
        key: u128,
        stored: bool,
    },
    /// Run `index` was run.
    Ran { key: u128, finished: Finished },
}

/// One worker: takes the next run, keys it, and runs it unless the store holds it intact or another run has
/// the same key.
struct Worker<'a> {
    scenarios: Scenarios<'a>,
    len: usize,
    options: &'a RunOptions,
    next: &'a AtomicUsize,
    cancel: &'a AtomicBool,
    claimed: &'a Mutex<HashSet<u128>>,
    /// Keys the store held when the sweep began: only these are looked up in it.
    held: &'a HashSet<u128>,
    damaged: &'a AtomicUsize,
    cache: &'a RecordCache,
}

impl Worker<'_> {
    fn work(&self, reader: Option<Store>, tx: mpsc::Sender<Message>) {
        while !self.cancel.load(Ordering::Relaxed) {
            let index = self.next.fetch_add(1, Ordering::Relaxed);
            if index >= self.len {
                break;
            }
            let (value, label) = (self.scenarios)(index);
            let p = prepare_one(&value, label, self.cache);
            let key = u128::from_str_radix(&p.key, 16).unwrap_or_default();
            let first = self
                .claimed
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .insert(key);
            let stored = match (&reader, first && self.held.contains(&key)) {
                (Some(r), true) => r.get(&p.key).ok().flatten(),
                _ => None,
            };
            let in_store = stored.is_some();
            let needed = first
                && match stored {
                    None => true,
                    Some(row) => {
                        let bad = trusted(row).is_none();
                        if bad {
                            self.damaged.fetch_add(1, Ordering::Relaxed);
                        }
                        bad
                    }
                };
            let message = if needed {
                let t0 = Instant::now();
                let outcome = run_one(&p, self.options, self.cancel);
                if self.cancel.load(Ordering::Relaxed) {
                    // A run cut short is not a result.
                    break;
                }
                Message::Ran {
                    key,
                    finished: Finished {
                        key: p.key,
                        index,
                        outcome: outcome.map(|s| s.to_row()),
                        seconds: t0.elapsed().as_secs_f64(),
                    },
                }
            } else {
                Message::Keyed {
                    index,
                    key,
                    stored: first && in_store,
                }
            };
            if tx.send(message).is_err() {
                break;
            }
        }
    }
}

/// Runs the `len` runs that `scenarios` makes on demand, on `workers` threads, and commits each finished run
/// to `store` (if any). A run whose key the store holds intact, with a summary that reads as one, is not run
/// again; a damaged row is run again and replaced (counted in [`Progress::damaged`]); runs of equal key are
/// run once. Runs are made, keyed and run as the workers reach them: the first run starts at once whatever
/// the study's size, and memory holds one key per run. `progress` is called on this thread at least every
/// 0.2 s; returning `Break` cancels the sweep.
pub fn run(
    len: usize,
    scenarios: Scenarios<'_>,
    workers: usize,
    options: &RunOptions,
    mut store: Option<&mut Store>,
    progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
) -> Result<Swept, SweepError> {
    let mut keys = vec![0u128; len];
    let mut outcomes: HashMap<u128, Outcome> = HashMap::new();
    let (cancel, next, damaged) = (
        AtomicBool::new(false),
        AtomicUsize::new(0),
        AtomicUsize::new(0),
    );
    let claimed = Mutex::new(HashSet::new());
    let held: HashSet<u128> = match store.as_deref().map(Store::finished_keys).transpose() {
        Ok(keys) => keys.unwrap_or_default(),
        Err(e) => return Err(SweepError::Store(e)),
    };
    let cache = RecordCache::default();
    let worker = Worker {
        scenarios,
        len,
        options,
        next: &next,
        cancel: &cancel,
        claimed: &claimed,
        held: &held,
        damaged: &damaged,
        cache: &cache,
    };
    let (tx, rx) = mpsc::channel::<Message>();
    let start = Instant::now();
    let mut state = Progress {
        done: 0,
        todo: len,
        skipped: 0,
        damaged: 0,
        failed: 0,
        elapsed: 0.0,
    };
    let mut failure = None;
    std::thread::scope(|s| {
        for n in 0..workers.clamp(1, len.max(1)) {
            let reader = match store.as_deref().map(Store::reader).transpose() {
                Ok(r) => r,
                Err(e) => {
                    failure = Some(SweepError::Store(e));
                    break;
                }
            };
            let tx = tx.clone();
            let w = &worker;
            let spawned = std::thread::Builder::new()
                .name(format!("pounding-worker-{n}"))
                .spawn_scoped(s, move || w.work(reader, tx));
            if let Err(e) = spawned {
                // Runs go on with the workers there are; none at all is an error.
                if n == 0 {
                    failure = Some(SweepError::Thread(format!(
                        "the operating system refused a worker thread: {e}; allowed: fewer --workers"
                    )));
                }
                break;
            }
        }
        if failure.is_some() {
            cancel.store(true, Ordering::Relaxed);
        }
        drop(tx);
        let mut batch: Vec<Finished> = Vec::new();
        let mut last = Instant::now();
        let mut open = true;
        while open {
            let mut take = |m: Message, batch: &mut Vec<Finished>| match m {
                Message::Keyed { index, key, stored } => {
                    keys[index] = key;
                    state.done += 1;
                    state.skipped += usize::from(stored);
                }
                Message::Ran { key, finished } => {
                    keys[finished.index] = key;
                    batch.push(finished);
                }
            };
            match rx.recv_timeout(Duration::from_millis(100)) {
                Ok(m) => {
                    take(m, &mut batch);
                    // Whatever else has finished goes into the same transaction.
                    for m in rx.try_iter() {
                        take(m, &mut batch);
                    }
                }
                Err(mpsc::RecvTimeoutError::Timeout) => {}
                Err(mpsc::RecvTimeoutError::Disconnected) => open = false,
            }
            if !batch.is_empty() {
                if let Some(st) = store.as_deref_mut() {
                    if let Err(e) = st.commit(&batch) {
                        failure.get_or_insert(SweepError::Store(e));
                        cancel.store(true, Ordering::Relaxed);
                    }
                }
                for f in batch.drain(..) {
                    state.done += 1;
                    state.failed += usize::from(f.outcome.is_err());
                    if store.is_none() {
                        outcomes.insert(keys[f.index], f.outcome);
                    }
                }
            }
            if last.elapsed() >= Duration::from_millis(100) || !open {
                last = Instant::now();
                state.elapsed = start.elapsed().as_secs_f64();
                state.damaged = damaged.load(Ordering::Relaxed);
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
    Ok(Swept { keys, outcomes })
}
