//! `pounding sweep STUDY.toml --out DIR`: every scenario of a study, in parallel, committed run by run to
//! `DIR/study.sqlite` (so that a sweep stopped at any point resumes without repeating a finished run), then
//! `DIR/runs.csv`, one row of headline results per run.

use crate::args::SweepArgs;
use crate::error::{input, CliError};
use crate::progress::{progress, workers};
use pounding::analysis::RunOptions;
use pounding_study::headline::{headline, Cell};
use pounding_study::input::write_atomic;
use pounding_study::store::{Store, StoreError};
use pounding_study::study::Study;
use pounding_study::summary::RunSummary;
use pounding_study::sweep;

/// `runs.csv`: index, key, status, the axes' values, the headline results (the union of every run's
/// columns, in the order they first appear), the error.
fn runs_csv(
    study: &Study,
    prepared: &[sweep::Prepared],
    outcomes: &[Result<RunSummary, String>],
) -> Result<Vec<u8>, csv::Error> {
    let rows: Vec<Option<Vec<(String, Cell)>>> = outcomes
        .iter()
        .map(|o| o.as_ref().ok().map(headline))
        .collect();
    let mut columns: Vec<&str> = Vec::new();
    for (c, _) in rows.iter().flatten().flatten() {
        if !columns.contains(&c.as_str()) {
            columns.push(c);
        }
    }
    let mut wtr = csv::Writer::from_writer(Vec::new());
    let mut header = vec!["index", "key", "status"];
    header.extend(study.axes.iter().map(|a| a.name.as_str()));
    header.extend(columns.iter().copied());
    header.push("error");
    wtr.write_record(&header)?;
    let mut buf = pounding_study::format::Shortest::new();
    for (i, ((p, o), row)) in prepared.iter().zip(outcomes).zip(&rows).enumerate() {
        wtr.write_field(i.to_string())?;
        wtr.write_field(&p.key)?;
        wtr.write_field(if o.is_ok() { "ok" } else { "error" })?;
        for c in &study.variants[i].coords {
            wtr.write_field(c)?;
        }
        for c in &columns {
            let cell = row.iter().flatten().find(|(k, _)| k == c).map(|(_, v)| *v);
            match cell {
                Some(Cell::Number(x)) => wtr.write_field(buf.format(x))?,
                Some(Cell::Count(n)) => wtr.write_field(n.to_string())?,
                None => wtr.write_field("")?,
            }
        }
        wtr.write_field(o.as_ref().err().map_or("", String::as_str))?;
        wtr.write_record(None::<&[u8]>)?;
    }
    wtr.into_inner().map_err(|e| e.into_error().into())
}

/// `pounding sweep`.
pub fn run(a: &SweepArgs) -> Result<(), CliError> {
    let workers = workers(a)?;
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

    let (bar, mut report) = progress(a.quiet);
    let outcomes = sweep::run(
        &prepared,
        workers,
        &RunOptions::summary_only(),
        Some(&mut store),
        &mut report,
    )
    .map_err(|e| CliError::Io(e.to_string()))?;
    drop(report);
    bar.borrow().finish();
    let skipped = bar.borrow().skipped;
    let runs_csv = a.out.join("runs.csv");
    let text = runs_csv_bytes(&study, &prepared, &outcomes)?;
    write_atomic(&runs_csv, &text)
        .map_err(|e| CliError::Io(format!("cannot write {}: {e}", runs_csv.display())))?;
    let failed: Vec<(usize, &String)> = outcomes
        .iter()
        .enumerate()
        .filter_map(|(i, o)| o.as_ref().err().map(|e| (i, e)))
        .collect();
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
        "{}: {} ok, {} failed ({} already in the store); wrote {}: study.sqlite, runs.csv",
        pounding::words::count(prepared.len(), "run", None),
        prepared.len() - failed.len(),
        failed.len(),
        skipped,
        a.out.display()
    );
    Ok(())
}

/// `runs.csv`'s bytes, or the failure to format them.
fn runs_csv_bytes(
    study: &Study,
    prepared: &[sweep::Prepared],
    outcomes: &[Result<RunSummary, String>],
) -> Result<Vec<u8>, CliError> {
    runs_csv(study, prepared, outcomes)
        .map_err(|e| CliError::Io(format!("cannot write runs.csv: {e}")))
}
