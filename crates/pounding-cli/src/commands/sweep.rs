//! `pounding sweep STUDY.toml --out DIR`: every scenario of a study, in parallel, committed run by run to
//! `DIR/study.sqlite` (so that a sweep stopped at any point resumes without repeating a finished run), then
//! `DIR/runs.csv`, one row of headline results per run.

use crate::args::SweepArgs;
use crate::error::{input, CliError};
use crate::progress::{progress, workers};
use pounding::analysis::RunOptions;
use pounding::scenario::Contacts;
use pounding_study::headline::{amplification, amplification_column, headline, Cell};
use pounding_study::input::write_atomic_with;
use pounding_study::store::{Fit, Store, StoreError};
use pounding_study::study::Study;
use pounding_study::summary::RunSummary;
use pounding_study::sweep::{self, Swept};
use std::collections::HashMap;

/// Each run's outcome read back from the store, one at a time, in study order: summaries are not held.
fn each_outcome(
    swept: &Swept,
    store: &Store,
    mut f: impl FnMut(usize, Result<RunSummary, String>) -> Result<(), CliError>,
) -> Result<(), CliError> {
    for i in 0..swept.keys.len() {
        let outcome = swept
            .outcome(i, Some(store))
            .map_err(|e| CliError::Io(e.to_string()))?
            .and_then(|text| RunSummary::from_json(&text));
        f(i, outcome)?;
    }
    Ok(())
}

/// The coordinates of run `i` without the `contacts` axis at `axis`: the runs a run without contact is the
/// reference of.
fn others(study: &Study, i: usize, axis: usize) -> Vec<String> {
    let mut c = study.coords(i);
    c.remove(axis);
    c
}

/// What a sweep's runs said: the failed runs' count and the first five with their messages; the count of
/// runs whose summary carries warnings, and the first.
#[derive(Default)]
struct Tally {
    failed: usize,
    first_failed: Vec<(usize, String)>,
    warned: usize,
    first_warning: Option<(usize, String)>,
}

/// Runs whose headline rows the first reading of the store keeps for the second (about 400 bytes each):
/// past it, the store is read twice and memory stays flat.
const KEPT_ROWS: usize = 50_000;

/// A run's headline row (`(column, value)`) and its first warning, or its error.
type Headline = Result<(Vec<(String, Cell)>, Option<String>), String>;

/// A run's headline as the first reading keeps it: its columns by their index in the union.
enum Kept {
    Ok(Vec<(u32, Cell)>, Option<String>),
    Err(String),
}

/// `runs.csv`: index, key, status, the axes' values, the headline results (the union of every run's
/// columns, in the order they first appear), with a `contacts` axis the amplification of each building's
/// peaks over the run without contact of the same other values, the error; written row by row. Returns
/// what the runs said ([`Tally`]).
fn write_runs_csv(
    study: &Study,
    swept: &Swept,
    store: &Store,
    path: &std::path::Path,
) -> Result<Tally, CliError> {
    let contacts_axis = study.axes.iter().position(|a| a.name == "contacts");
    let mut columns: Vec<String> = Vec::new();
    let mut index: HashMap<String, u32> = HashMap::new();
    let mut off_runs: HashMap<Vec<String>, Vec<(String, Cell)>> = HashMap::new();
    let keep = swept.keys.len() <= KEPT_ROWS;
    let mut kept = Vec::with_capacity(if keep { swept.keys.len() } else { 0 });
    each_outcome(swept, store, |i, o| {
        let summary = match o {
            Ok(summary) => summary,
            Err(e) => {
                kept.extend(keep.then_some(Kept::Err(e)));
                return Ok(());
            }
        };
        let row = headline(&summary);
        let mut cells = Vec::with_capacity(if keep { row.len() } else { 0 });
        for (c, v) in &row {
            let k = *index.entry(c.clone()).or_insert_with(|| {
                columns.push(c.clone());
                (columns.len() - 1) as u32
            });
            if keep {
                cells.push((k, *v));
            }
        }
        kept.extend(keep.then(|| Kept::Ok(cells, summary.warnings.first().cloned())));
        if let (Some(a), Contacts::Off) = (contacts_axis, summary.contacts) {
            off_runs.insert(others(study, i, a), row);
        }
        Ok(())
    })?;
    if contacts_axis.is_some() {
        let amplified: Vec<String> = columns
            .iter()
            .filter_map(|c| amplification_column(c))
            .collect();
        columns.extend(amplified);
    }
    let mut tally = Tally::default();
    let mut header = vec!["index", "key", "status"];
    header.extend(study.axes.iter().map(|a| a.name.as_str()));
    header.extend(columns.iter().map(String::as_str));
    header.push("error");
    let io = |e: std::io::Error| CliError::Io(format!("cannot write {}: {e}", path.display()));
    let mut inner = None;
    write_atomic_with(path, |w| {
        let mut wtr = csv::Writer::from_writer(w);
        let mut buf = pounding_study::format::Shortest::new();
        wtr.write_record(&header)?;
        let mut emit = |i: usize, o: Headline| {
            let csv_err = |e: csv::Error| CliError::Io(format!("cannot write runs.csv: {e}"));
            let mut row = o.as_ref().map(|(row, _)| row.clone()).unwrap_or_default();
            if let Some(off) = contacts_axis.and_then(|a| off_runs.get(&others(study, i, a))) {
                row.extend(amplification(&row, off));
            }
            wtr.write_field(i.to_string()).map_err(csv_err)?;
            wtr.write_field(swept.key(i)).map_err(csv_err)?;
            wtr.write_field(if o.is_ok() { "ok" } else { "error" })
                .map_err(csv_err)?;
            for c in study.coords(i) {
                wtr.write_field(c).map_err(csv_err)?;
            }
            for c in &columns {
                match row.iter().find(|(k, _)| k == c).map(|(_, v)| *v) {
                    Some(Cell::Number(x)) => wtr.write_field(buf.format(x)),
                    Some(Cell::Count(n)) => wtr.write_field(n.to_string()),
                    None => wtr.write_field(""),
                }
                .map_err(csv_err)?;
            }
            let error = o.as_ref().err().map_or("", String::as_str);
            wtr.write_field(error).map_err(csv_err)?;
            wtr.write_record(None::<&[u8]>).map_err(csv_err)?;
            tally.count(i, o);
            Ok(())
        };
        let r = if keep {
            let named = |cells: Vec<(u32, Cell)>| {
                let named = cells
                    .into_iter()
                    .map(|(k, v)| (columns[k as usize].clone(), v));
                named.collect()
            };
            kept.into_iter().enumerate().try_for_each(|(i, k)| match k {
                Kept::Ok(cells, warning) => emit(i, Ok((named(cells), warning))),
                Kept::Err(e) => emit(i, Err(e)),
            })
        } else {
            each_outcome(swept, store, |i, o| {
                emit(i, o.map(|s| (headline(&s), s.warnings.first().cloned())))
            })
        };
        wtr.flush()?;
        // A failure to read the store is kept to say it as it is; the file is not written.
        r.map_err(|e| {
            inner = Some(e);
            std::io::Error::other("store")
        })
    })
    .map_err(|e| inner.take().unwrap_or_else(|| io(e)))?;
    Ok(tally)
}

impl Tally {
    /// Counts run `i`'s outcome: failed, or with a warning (its first).
    fn count(&mut self, i: usize, o: Headline) {
        match o {
            Err(e) => {
                self.failed += 1;
                if self.first_failed.len() < 5 {
                    self.first_failed.push((i, e));
                }
            }
            Ok((_, Some(w))) => {
                self.warned += 1;
                if self.first_warning.is_none() {
                    self.first_warning = Some((i, w));
                }
            }
            Ok(_) => {}
        }
    }
}

/// `pounding sweep`.
pub fn run(a: &SweepArgs) -> Result<(), CliError> {
    let workers = workers(a.runs.workers)?;
    crate::files::check_out_dir(&a.out, false)?;
    let mut study = Study::read(&a.study).map_err(|e| input(e.0))?;
    if a.runs.no_contact {
        study.without_contact().map_err(|e| input(e.0))?;
    }
    let n = study.len();
    let id = study.id();
    let scenario = |i: usize| {
        let (value, label, _) = study.variant(i);
        (value, label)
    };
    // Every run's key: what a store of the first layout knew this study by, and what an earlier study's
    // store must hold no more than to grow into this one's.
    // Made at most once, for the check and the opening alike.
    let made = std::cell::OnceCell::new();
    let keys = || {
        made.get_or_init(|| sweep::run_keys(n, &scenario, workers))
            .clone()
    };
    let store_path = a.out.join("study.sqlite");
    let store_err = |e: StoreError| match e {
        StoreError::Mismatch(m) => input(m),
        StoreError::Io(m) => CliError::Io(m),
    };
    // Everything about the input is checked before the folder or the store is touched.
    Store::check(&store_path, &id, n, &keys).map_err(store_err)?;
    std::fs::create_dir_all(&a.out)
        .map_err(|e| CliError::Io(format!("cannot create {}: {e}", a.out.display())))?;
    let mut store = Store::open(&store_path, &id, n, &keys).map_err(store_err)?;

    if let Fit::Grows { stored, of } = store.fit {
        eprintln!(
            "{} grew from a study of {of} runs into this one of {n}: its {stored} stored runs are kept",
            store_path.display()
        );
    }
    let (bar, mut report) = progress(a.runs.quiet);
    let swept = sweep::run(
        n,
        &scenario,
        workers,
        &RunOptions::summary_only(),
        Some(&mut store),
        &mut report,
    )
    .map_err(|e| crate::progress::ended_early(e, &store_path, &bar.borrow()))?;
    drop(report);
    bar.borrow().finish();
    let skipped = bar.borrow().skipped;
    let t = write_runs_csv(&study, &swept, &store, &a.out.join("runs.csv"))?;
    for (i, e) in &t.first_failed {
        eprintln!("run {i}: {e}");
    }
    if t.failed > t.first_failed.len() {
        eprintln!(
            "... and {} more failed runs (see runs.csv)",
            t.failed - t.first_failed.len()
        );
    }
    if let Some((i, w)) = &t.first_warning {
        eprintln!(
            "warning: {} carry warnings in their summaries (study.sqlite); the first, run {i}: {w}",
            pounding::words::count(t.warned, "run", None)
        );
    }
    println!(
        "{}: {} ok, {} failed ({} already in the store); wrote {}: study.sqlite, runs.csv",
        pounding::words::count(n, "run", None),
        n - t.failed,
        t.failed,
        skipped,
        a.out.display()
    );
    if t.failed > 0 {
        return Err(CliError::Failed(format!(
            "{} of {n} runs failed; why: the error column of {} (the first five above); the others are written",
            t.failed,
            a.out.join("runs.csv").display()
        )));
    }
    Ok(())
}
