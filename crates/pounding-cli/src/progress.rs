//! What the studies (sweep, IDA) share on the command line: their worker threads and their progress bar on a
//! terminal.

use crate::error::{input, CliError};
use pounding_study::sweep::Progress;
use std::io::IsTerminal;
use std::ops::ControlFlow;

/// What a sweep's progress reports: the bar (on a terminal, without `quiet`) and the runs found in the store.
pub struct Bar {
    /// The bar, if shown.
    pub bar: Option<indicatif::ProgressBar>,
    /// Runs found in the store.
    pub skipped: usize,
    /// Runs found damaged in the store, and run again.
    pub damaged: usize,
    /// Runs handled so far (run, or found in the store), and of the study.
    pub done: (usize, usize),
}

impl Bar {
    /// Clears the bar and says how many stored runs were found damaged and run again.
    pub fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
        if self.damaged > 0 {
            eprintln!(
                "{} stored in study.sqlite did not read back as stored (damaged, or of an older version) and ran again",
                pounding::words::count(self.damaged, "run", None)
            );
        }
    }
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
    let state = std::rc::Rc::new(std::cell::RefCell::new(Bar {
        bar,
        skipped: 0,
        damaged: 0,
        done: (0, 0),
    }));
    let shared = state.clone();
    let report = move |p: Progress| {
        let mut s = shared.borrow_mut();
        s.skipped = p.skipped;
        s.damaged = p.damaged;
        s.done = (p.done, p.todo);
        if let Some(b) = &s.bar {
            b.set_length(p.todo as u64);
            b.set_position(p.done as u64);
            b.set_message(format!("{} failed, {} from the store", p.failed, p.skipped));
        }
        crate::interrupt::go_on()
    };
    (state, report)
}

/// The error of a sweep or an IDA that ended early: Ctrl-C (how many runs the store kept), or the store's
/// failure.
pub fn ended_early(
    e: pounding_study::sweep::SweepError,
    store: &std::path::Path,
    bar: &Bar,
) -> CliError {
    match e {
        pounding_study::sweep::SweepError::Cancelled => {
            let (done, todo) = bar.done;
            CliError::Interrupted(format!(
                "{done} of {todo} runs are in {} ({} of them from before); the same command resumes from there",
                store.display(),
                bar.skipped
            ))
        }
        other => CliError::Io(other.to_string()),
    }
}

/// The threads of `--workers`, by default the machine's cores.
pub fn workers(workers: Option<usize>) -> Result<usize, CliError> {
    match workers {
        Some(n) => pounding_study::sweep::check_workers("--workers", n).map_err(input),
        None => Ok(std::thread::available_parallelism().map_or(1, |n| n.get())),
    }
}
