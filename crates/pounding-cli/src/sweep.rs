//! `pounding sweep STUDY.toml --out DIR`: every scenario of a study, in parallel, committed run by run to
//! `DIR/study.sqlite` (so that a sweep stopped at any point resumes without repeating a finished run), then
//! `DIR/runs.csv`, one row of headline results per run.

use crate::args::SweepArgs;
use crate::commands::input;
use crate::output::write_atomic;
use crate::CliError;
use pounding::analysis::RunOptions;
use pounding_study::headline::{csv_field, csv_value, headline};
use pounding_study::store::{Store, StoreError};
use pounding_study::study::Study;
use pounding_study::sweep::{self, Progress};
use std::io::IsTerminal;
use std::ops::ControlFlow;

/// Threads to use when `--workers` is not given: the machine's.
fn default_workers() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

pub fn command(a: &SweepArgs) -> Result<(), CliError> {
    let workers = match a.workers {
        Some(0) => {
            return Err(input(
                "--workers 0 is not allowed: at least 1 (default: the number of cores)",
            ))
        }
        Some(n) => n,
        None => default_workers(),
    };
    let study = Study::read(&a.study).map_err(|e| input(e.0))?;
    let prepared = sweep::prepare(study.scenarios(), workers);
    let id = sweep::study_id(&prepared);
    let store_path = a.out.join("study.sqlite");
    let store_err = |e: StoreError| match e {
        StoreError::Mismatch(m) => input(m),
        StoreError::Io(m) => CliError::Io(m),
    };
    // Everything about the input is checked before the folder or the store is touched.
    Store::check(&store_path, &id, prepared.len()).map_err(store_err)?;
    std::fs::create_dir_all(&a.out)
        .map_err(|e| CliError::Io(format!("cannot create {}: {e}", a.out.display())))?;
    let mut store = Store::open(&store_path, &id, prepared.len()).map_err(store_err)?;

    let show = !a.quiet && std::io::stderr().is_terminal();
    let bar = show.then(|| {
        let b = indicatif::ProgressBar::new(prepared.len() as u64);
        b.set_style(
            indicatif::ProgressStyle::with_template(
                "{spinner} [{bar:40}] {pos}/{len} runs, {msg} ({elapsed}, about {eta} left)",
            )
            .expect("a valid template")
            .progress_chars("=> "),
        );
        b
    });
    let mut skipped = 0;
    let mut report = |p: Progress| {
        skipped = p.skipped;
        if let Some(b) = &bar {
            b.set_length(p.todo as u64);
            b.set_position(p.done as u64);
            b.set_message(format!("{} failed, {} from the store", p.failed, p.skipped));
        }
        ControlFlow::Continue(())
    };
    let outcomes = sweep::run(
        &prepared,
        workers,
        &RunOptions::summary_only(),
        Some(&mut store),
        &mut report,
    )
    .map_err(|e| CliError::Io(e.to_string()))?;
    if let Some(b) = &bar {
        b.finish_and_clear();
    }

    // runs.csv: index, key, status, the axes, the headline results, the error.
    let summaries: Vec<Option<serde_json::Value>> = outcomes
        .iter()
        .map(|o| o.as_ref().ok().and_then(|s| serde_json::from_str(s).ok()))
        .collect();
    let mut columns: Vec<String> = Vec::new();
    for s in summaries.iter().flatten() {
        for (c, _) in headline(s) {
            if !columns.contains(&c) {
                columns.push(c);
            }
        }
    }
    let mut csv = String::from("index,key,status");
    for axis in &study.axes {
        csv.push(',');
        csv.push_str(&csv_field(&axis.name));
    }
    for c in &columns {
        csv.push(',');
        csv.push_str(&csv_field(c));
    }
    csv.push_str(",error\n");
    let mut failed = Vec::new();
    for (i, ((p, o), s)) in prepared.iter().zip(&outcomes).zip(&summaries).enumerate() {
        csv.push_str(&format!(
            "{i},{},{}",
            p.key,
            if o.is_ok() { "ok" } else { "error" }
        ));
        for c in &study.variants[i].coords {
            csv.push(',');
            csv.push_str(&csv_field(c));
        }
        let row = s.as_ref().map(headline).unwrap_or_default();
        for c in &columns {
            csv.push(',');
            if let Some((_, v)) = row.iter().find(|(k, _)| k == c) {
                csv.push_str(&csv_value(v));
            }
        }
        csv.push(',');
        if let Err(e) = o {
            csv.push_str(&csv_field(e));
            failed.push((i, e));
        }
        csv.push('\n');
    }
    let runs_csv = a.out.join("runs.csv");
    write_atomic(&runs_csv, csv.as_bytes())
        .map_err(|e| CliError::Io(format!("cannot write {}: {e}", runs_csv.display())))?;
    for (i, e) in failed.iter().take(5) {
        eprintln!("run {i}: {e}");
    }
    if failed.len() > 5 {
        eprintln!(
            "... and {} more failed runs (see runs.csv)",
            failed.len() - 5
        );
    }
    println!(
        "{} runs: {} ok, {} failed ({} distinct runs were in the store already); wrote {}: study.sqlite, runs.csv",
        prepared.len(),
        prepared.len() - failed.len(),
        failed.len(),
        skipped,
        a.out.display()
    );
    Ok(())
}
