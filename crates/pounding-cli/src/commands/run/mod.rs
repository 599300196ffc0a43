//! `pounding run`: a scenario file in; modal properties and a summary on the terminal; summary.json,
//! response.csv, impacts.csv, impact-loops.csv and energy.csv in the output folder (the study crate's typed
//! tables), and the figures and report made from them.

mod plan;
mod setup;
mod tables;

use crate::args::RunArgs;
use crate::error::{input, CliError};
use crate::files::{check_figures, render_figures};
use crate::output_set::{DataFile, OutputSet};
use crate::run_data::RunData;
use crate::scenario::load;
use pounding::analysis::Results;
use pounding::scenario::Contacts;
use pounding_study::input::Loaded;
use pounding_study::summary::RunSummary;
use pounding_study::tables::{
    write_energy, write_response, write_rows, EnergyRow, ImpactRow, LoopRow, Table, TableError,
};
use std::io::IsTerminal;

/// `pounding run`.
pub fn run(a: &RunArgs) -> Result<(), CliError> {
    let (mut loaded, mut text) = load(&a.scenario)?;
    if let Some(t) = a.tolerance {
        loaded.scenario = loaded.scenario.with_tolerance(t).map_err(CliError::from)?;
    }
    if a.no_contact && loaded.doc.contacts.is_on() {
        loaded.doc.contacts = Contacts::Off;
        loaded.scenario = loaded.scenario.with_contacts_off();
        // The copy of the scenario in the output folder runs as this run did.
        text = no_contact_text(&text);
    }
    // The output folder must be new, empty or an earlier run's, checked before any work.
    OutputSet::check(&a.out)?;
    crate::files::check_out_dir(&a.out, true)?;
    check_figures(&a.figures)?;
    if !a.json {
        setup::print(&loaded, &a.scenario);
    }
    let results = analyse(&loaded, a.quiet)?;
    let summary = RunSummary::new(&loaded, &results).map_err(input)?;
    // Accuracy that holds itself to account: the summary's warnings are said on stderr too.
    for w in &summary.warnings {
        eprintln!("warning: {w}");
    }
    // The whole set is written into a folder beside --out and appears there in one rename.
    let set = OutputSet::begin(&a.out)?;
    let mut written = write_data(&set, &loaded, &results, &summary, text)?;
    if a.figures.plots || a.report {
        // Figures and report are made from the files just written, exactly as `pounding report` makes them.
        let data = RunData::load(set.dir())?;
        let figs = crate::plot::figures::run(&data);
        if a.figures.plots {
            for (name, bytes) in render_figures(&figs, a.figures.png)? {
                set.write(&name, &bytes)?;
                written.push(name);
            }
        }
        if a.report {
            written.push(crate::report::write(
                &data,
                &figs,
                &set.dir().join("report.html"),
            )?);
        }
    }
    set.commit()?;
    if a.json {
        print!("{}", summary.to_json());
    } else {
        tables::print(&loaded.scenario, &results);
        println!("\nwrote {}: {}", a.out.display(), written.join(", "));
    }
    Ok(())
}

/// The scenario file's `text` with `contacts = "off"`: the key added before the first table, or the one the
/// file gives replaced.
fn no_contact_text(text: &str) -> String {
    const OFF: &str = "contacts = \"off\"  # --no-contact";
    let mut lines: Vec<&str> = text.lines().collect();
    let key = |l: &&str| {
        let t = l.trim_start();
        t.strip_prefix("contacts")
            .is_some_and(|r| r.trim_start().starts_with('='))
    };
    let table = |l: &&str| l.trim_start().starts_with('[');
    match lines.iter().take_while(|l| !table(l)).position(key) {
        Some(i) => lines[i] = OFF,
        None => {
            let i = lines.iter().position(table).unwrap_or(lines.len());
            lines.insert(i, OFF);
        }
    }
    lines.join("\n") + "\n"
}

/// Runs the analysis, with a progress bar on a terminal (unless `quiet`).
fn analyse(loaded: &Loaded, quiet: bool) -> Result<Results, CliError> {
    let scenario = &loaded.scenario;
    let bar = (!quiet && std::io::stderr().is_terminal()).then(|| {
        let b = indicatif::ProgressBar::new(1000);
        b.set_style(
            indicatif::ProgressStyle::with_template(
                "{spinner} [{bar:40}] t = {msg} ({elapsed} of about {duration})",
            )
            .expect("a valid template")
            .progress_chars("=> "),
        );
        b
    });
    let record_end = scenario.record().t0() + scenario.record().duration();
    let results = scenario.run_with(&mut |p| {
        if let Some(b) = &bar {
            let work = expected_work(p.t, record_end) / expected_work(p.duration, record_end);
            b.set_position((1000.0 * work) as u64);
            b.set_message(format!(
                "{:.2} s, {}",
                p.t,
                pounding::words::count(p.impacts, "impact", None)
            ));
        }
        crate::interrupt::go_on()
    });
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    results.map_err(|e| match e {
        pounding::Error::Cancelled { .. } => e.into(),
        e => input(format!("analysis failed: {e}")),
    })
}

/// How much of a run's cost lies before time `t` (s), in record-seconds: a second of free vibration after
/// the record ends costs about a third of a second under it (fewer steps, fewer impacts; measured 0.2 to
/// 0.4 on the examples run three times longer than their record), so the progress bar's estimate of the
/// time left does not count it in full.
fn expected_work(t: f64, record_end: f64) -> f64 {
    t.min(record_end) + 0.3 * (t - record_end).max(0.0)
}

/// Writes the run's data files into `set`: the scenario as run, summary.json and the tables. Returns their
/// names. response.csv (the most bytes) is formatted and written on a thread of its own while this one writes
/// the rest.
fn write_data(
    set: &OutputSet,
    loaded: &Loaded,
    r: &Results,
    summary: &RunSummary,
    scenario_text: String,
) -> Result<Vec<String>, CliError> {
    let s = &loaded.scenario;
    let table = |name: &str, w: &dyn Fn(&mut DataFile) -> Result<(), TableError>| {
        let mut f = set.create(name)?;
        w(&mut f).map_err(|e| match e {
            TableError::Io(e) => set.error(name, e),
            TableError::Invalid(m) => CliError::Io(format!("cannot write {name}: {m}")),
        })?;
        set.finish(f)
    };
    let files = [
        "scenario.toml",
        "summary.json",
        "response.csv",
        ImpactRow::FILE,
        LoopRow::FILE,
        EnergyRow::FILE,
    ];
    std::thread::scope(|scope| {
        let response =
            scope.spawn(|| table(files[2], &|f| write_response(f, summary, &r.histories)));
        set.write_data(files[0], scenario_text.as_bytes())?;
        set.write_data(files[1], summary.to_json().as_bytes())?;
        table(files[3], &|f| write_rows(f, &ImpactRow::all(s, r)))?;
        table(files[4], &|f| write_rows(f, &LoopRow::all(s, r)))?;
        table(files[5], &|f| write_energy(f, &r.histories))?;
        response
            .join()
            .map_err(|_| CliError::Io("the thread writing response.csv failed".into()))?
    })?;
    Ok(files.iter().map(|f| f.to_string()).collect())
}
