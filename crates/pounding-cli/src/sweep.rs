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

/// The threads of `--workers`, by default the machine's cores.
fn workers(a: &SweepArgs) -> Result<usize, CliError> {
    match a.workers {
        Some(0) => Err(input(
            "--workers 0 is not allowed: at least 1 (default: the number of cores)",
        )),
        Some(n) => Ok(n),
        None => Ok(std::thread::available_parallelism().map_or(1, |n| n.get())),
    }
}

/// What a sweep's progress reports: the bar (on a terminal, without `quiet`) and the runs found in the store.
pub struct Bar {
    /// The bar, if shown.
    pub bar: Option<indicatif::ProgressBar>,
    /// Runs found in the store.
    pub skipped: usize,
}

/// A sweep's progress state and the callback that feeds it.
pub fn progress(
    quiet: bool,
) -> (
    std::rc::Rc<std::cell::RefCell<Bar>>,
    impl FnMut(Progress) -> ControlFlow<()>,
) {
    let bar = (!quiet && std::io::stderr().is_terminal()).then(|| {
        let b = indicatif::ProgressBar::new(0);
        b.set_style(
            indicatif::ProgressStyle::with_template(
                "{spinner} [{bar:40}] {pos}/{len} runs, {msg} ({elapsed}, about {eta} left)",
            )
            .expect("a valid template")
            .progress_chars("=> "),
        );
        b
    });
    let state = std::rc::Rc::new(std::cell::RefCell::new(Bar { bar, skipped: 0 }));
    let shared = state.clone();
    let report = move |p: Progress| {
        let mut s = shared.borrow_mut();
        s.skipped = p.skipped;
        if let Some(b) = &s.bar {
            b.set_length(p.todo as u64);
            b.set_position(p.done as u64);
            b.set_message(format!("{} failed, {} from the store", p.failed, p.skipped));
        }
        ControlFlow::Continue(())
    };
    (state, report)
}

pub fn command(a: &SweepArgs) -> Result<(), CliError> {
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
    let skipped = bar.borrow().skipped;
    if let Some(b) = &bar.borrow().bar {
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
        "{}: {} ok, {} failed ({} already in the store); wrote {}: study.sqlite, runs.csv",
        pounding::words::count(prepared.len(), "run", None),
        prepared.len() - failed.len(),
        failed.len(),
        skipped,
        a.out.display()
    );
    Ok(())
}

/// `pounding ida STUDY.toml --out DIR`: the runs of an IDA study as a resumable sweep, then runs.csv and
/// fragility.csv.
pub fn ida(args: &crate::args::IdaArgs) -> Result<(), CliError> {
    use pounding_study::ida::{run, Edp, Ida, IdaError};
    let a = &args.sweep;
    crate::commands::check_figures(&args.figures)?;
    let workers = workers(a)?;
    let study = Ida::read(&a.study).map_err(|e| input(e.0))?;
    let (bar, mut report) = progress(a.quiet);
    let out = run(&study, &a.out, workers, &mut report).map_err(|e| match e {
        IdaError::Input(e) => input(e.0),
        IdaError::Io(m) => CliError::Io(m),
    })?;
    drop(report);
    if let Some(b) = &bar.borrow().bar {
        b.finish_and_clear();
    }
    let v = &out.json;
    println!(
        "{} records x {} levels of {}: {} runs, {} failed",
        study.records.len(),
        study.levels.len(),
        study.measure_name(),
        v["runs"],
        v["failed"]
    );
    println!("\nlimit state                    stripes: median_m_per_s2  beta    ida: median_m_per_s2  beta");
    let cell = |f: &serde_json::Value| match (f["median"].as_f64(), f["beta"].as_f64()) {
        (Some(m), Some(b)) => format!("{m:>16.4}  {b:>6.3}"),
        _ => format!("{:>24}", "(no fit)"),
    };
    for f in v["fragility"].as_array().into_iter().flatten() {
        println!(
            "{:<30} {}    {}",
            f["limit_state"].as_str().unwrap_or(""),
            cell(&f["stripes"]),
            cell(&f["ida"])
        );
    }
    println!(
        "\nwrote {}: study.sqlite, runs.csv, fragility.csv",
        a.out.display()
    );
    // Figures: each limit state's EDP per record and level.
    let nl = study.levels.len();
    let edps: Vec<Vec<Vec<Option<f64>>>> = study
        .limit_states
        .iter()
        .map(|ls| {
            (0..study.records.len())
                .map(|i| {
                    (0..nl)
                        .map(|j| out.summaries[i * nl + j].as_ref().map(|s| ls.edp.value(s)))
                        .collect()
                })
                .collect()
        })
        .collect();
    let states: Vec<crate::plot::analyses::StateAxis> = study
        .limit_states
        .iter()
        .map(|l| crate::plot::analyses::StateAxis {
            name: l.name.clone(),
            threshold: l.threshold,
            unit: match l.edp {
                Edp::DriftRatio(_) | Edp::Pounding => "",
                Edp::Acceleration(_) => "m/s^2",
                Edp::Displacement(_) | Edp::Penetration => "m",
                Edp::PeakForce => "N",
            },
            boolean: l.edp == Edp::Pounding,
        })
        .collect();
    let short = match study.measure {
        pounding_study::ida::Measure::Pga => "PGA",
        pounding_study::ida::Measure::Sa { .. } => "Sa(T1)",
    };
    let figs = crate::plot::analyses::ida(
        &study.levels,
        &study.records,
        &edps,
        &states,
        &v["fragility"],
        (short, &study.measure_name()),
    );
    if args.figures.plots {
        let names = crate::output::write_files(
            &a.out,
            crate::output::render_figures(&figs, args.figures.png)?,
        )?;
        println!("wrote {}: {}", a.out.display(), names.join(", "));
    }
    Ok(())
}
